/* dv_cli_sweep: diskval sweep: speed against error over a grid of settings. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cli_args.h"
#include "exec_mpi.h"
#include "io_file.h"
#include "io_owned.h"
#include "report_suite_run.h"
#include "run_progress.h"
#include "search_sweep.h"

static const char HELP[] =
    "usage: diskval sweep SCENARIO --engine NAME --vary KEY=VALUES [--vary ...] [--out DIR]\n"
    "                     [--jobs N] [--set section.key=value]...\n"
    "\n"
    "Run SCENARIO in one engine at every point of a grid of settings and record the\n"
    "error against the reference and the cost (wall seconds per simulated second).\n"
    "VALUES is a list, v1,v2,..., or a log range, a..b:n (timestep=1e-2..1e-5:10);\n"
    "KEY is a key of [engines.NAME] or section.key. Writes DIR (default: sweep):\n"
    "sweep.csv (pareto = 1 where no point is both cheaper and more accurate),\n"
    "sweep.json (with the fitted order of convergence of each curve),\n"
    "work_precision.svg (with the reference's integrators over rtol 1e-6..1e-13) and,\n"
    "when a timestep varies, error_vs_timestep.svg.\n"
    "--quiet: no progress line on a terminal (points done, time left), no warning\n"
    "before a sweep longer than a minute.\n";

/* every varied value is a valid scenario value before anything runs */
static int check_values(const dv_scenario *sc, const dv_vary *v, dv_error *err) {
  dv_scenario *with = malloc(sizeof *with);
  if (!with) return dv_fail(err, DV_ESYSTEM, "out of memory");
  int status = DV_OK;
  for (size_t i = 0; !status && i < v->n; i++) {
    char text[256];
    const char *over[1] = {text};
    snprintf(text, sizeof text, "%.100s=%.100s", v->key, v->values[i]);
    dv_error e = {{0}};
    if (dv_scenario_with(sc, over, 1, with, &e))
      status = dv_fail(err, DV_EINPUT, "--vary %s=%s: %s", v->key, v->values[i], e.msg);
  }
  free(with);
  return status;
}

/* a key of another contact engine's section: no point of engine's sweep runs it */
static const dv_engine_type *other_engine(const char *key, const dv_engine_type *engine) {
  const char *dot = strrchr(key, '.');
  if (strncmp(key, "engines.", 8) || !dot) return NULL;
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++)
    if (*e != engine && (*e)->role == DV_ENGINE_CONTACT &&
        strlen((*e)->name) == (size_t)(dot - key - 8) &&
        !strncmp(key + 8, (*e)->name, (size_t)(dot - key - 8)))
      return *e;
  return NULL;
}

/* the reference's own work-precision curves, for a contact engine's sweep */
static int reference_curves(const dv_scenario *sc, int jobs, dv_sweep *ref, dv_error *err) {
  const dv_engine_type *e = dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
  const dv_setting_spec *choice = dv_settings_find(e->settings, e->search->choice_key);
  char spec[512];
  int len = snprintf(spec, sizeof spec, "%s=", choice->key);
  for (size_t j = 0; dv_setting_choice(choice, j); j++)
    len += snprintf(spec + len, sizeof spec - (size_t)len, "%s%s", j ? "," : "",
                    dv_setting_choice(choice, j));
  dv_vary rv[2];
  if (dv_search_vary_parse(spec, e->name, &rv[0], err) ||
      dv_search_vary_parse(e->search->work_precision, e->name, &rv[1], err))
    return DV_EINPUT;
  return dv_search_sweep_run(sc, e->name, rv, 2, jobs, ref, err);
}

/* one line a point: its values, theta error, cost, Pareto mark and verdict */
static void print_points(const dv_sweep *s) {
  printf("%-40s %12s %12s %8s %s\n", "settings", "theta err", "s / sim s", "pareto", "verdict");
  for (size_t k = 0; k < s->n; k++) {
    char label[160] = "";
    for (size_t v = 0; v < s->nvary; v++)
      snprintf(label + strlen(label), sizeof label - strlen(label), "%s%s", v ? " " : "",
               s->p[k].values[v]);
    printf("%-40s %12.3e %12.4g %8s %s\n", label, s->p[k].metric[DV_THETA_MAX_ERR],
           s->p[k].wall_per_sim_s, s->p[k].pareto ? "*" : "", dv_run_verdict_name(s->p[k].verdict));
  }
}

/* per curve: the order where the errors fall, and the accuracy floor with its cause */
static void print_curves(const dv_sweep *s) {
  const dv_engine_type *e = dv_engine_find(s->engine);
  if (!dv_search_sweep_fits_order(s)) { /* e.g. disk.radius: no order, no floor */
    if (e && e->search && s->nvary)
      printf("no order of convergence: %s is not %s's step (engines.%s.%s)\n",
             s->vary[dv_search_sweep_curve_key(s)].key, s->engine, e->search->section,
             e->search->step_key);
    return;
  }
  for (size_t k = 0; k < s->n; k++) {
    char label[96];
    dv_step_fit fit;
    if (!dv_search_sweep_curve_first(s, k) || dv_search_sweep_curve_fit(s, k, &fit)) continue;
    dv_search_sweep_curve_label(s, k, label, sizeof label);
    printf("%s: order ", label);
    printf(isnan(fit.order) ? "none (no falling errors)" : "%.2f over %zu points", fit.order,
           fit.nfalling);
    if (!isnan(fit.floor)) {
      const char *cause = dv_search_sweep_floor_cause(s, label);
      printf(
          "; accuracy floor %.3g rad: the errors stop falling at steps <= %.4g (%zu points); "
          "cause: %s",
          fit.floor, fit.floor_step, fit.nfloor, cause ? cause : "not attributed");
    }
    printf("\n");
  }
}

/* the command once its options are read; s and ref are the caller's */
static int sweep(const char *scenario, const dv_cli_list *sets, const char *engine_name,
                 const dv_cli_list *specs, const char *out, int jobs, dv_sweep *s, dv_sweep *ref,
                 dv_scenario *sc) {
  if (!engine_name) return dv_cli_usage_error("sweep", "no --engine given");
  const dv_engine_type *engine = dv_engine_find(engine_name);
  if (!engine) return dv_cli_unknown_engine("sweep", engine_name);
  dv_cli_probe_only(engine);
  if (!specs->n) return dv_cli_usage_error("sweep", "no --vary given");
  if (specs->n > DV_SWEEP_MAX_VARY)
    return dv_cli_usage_error("sweep", "at most %d --vary options", DV_SWEEP_MAX_VARY);
  dv_vary vary[DV_SWEEP_MAX_VARY];
  dv_error err = {{0}};
  /* read once: every point is this scenario with its settings (a file edited
   * during the sweep, or a pipe, changes nothing) */
  if (dv_cli_load_scenario("sweep", scenario, sets, sc, &err))
    return dv_cli_error("sweep", "%s", err.msg);
  for (size_t v = 0; v < specs->n; v++) {
    if (dv_search_vary_parse(specs->items[v], engine->name, &vary[v], &err) ||
        check_values(sc, &vary[v], &err))
      return dv_cli_error("sweep", "%s", err.msg);
    const dv_engine_type *other = other_engine(vary[v].key, engine);
    if (other)
      return dv_cli_usage_error("sweep", "--vary %s: a %s sweep never runs %s", specs->items[v],
                                engine->name, other->name);
    for (size_t w = 0; w < v; w++) /* the later would silently win at every point */
      if (!strcmp(vary[w].key, vary[v].key))
        return dv_cli_usage_error("sweep", "--vary %s: %s is varied twice", specs->items[v],
                                  vary[v].key);
  }
  /* the output directory before any run: a bad --out fails at once */
  static const char *const outputs[] = {"sweep.csv", "sweep.json", "work_precision.svg",
                                        "error_vs_timestep.svg", NULL};
  if (dv_io_check_inputs(out, outputs, &scenario, 1, &err) ||
      (dv_exec_mpi_rank() == 0 && dv_io_own_dir(out, outputs, &err)))
    return dv_cli_error("sweep", "%s", err.msg);
  if (dv_exec_mpi_size() > 1) s->checkpoint_dir = out; /* rank 0 keeps the tables current */
  if (dv_search_sweep_run(sc, engine->name, vary, specs->n, jobs, s, &err) < 0)
    return dv_cli_error("sweep", "%s", err.msg);
  /* not after an interrupted MPI run, whose ranks are going */
  const int with_ref = engine->role == DV_ENGINE_CONTACT && !s->interrupted;
  if (with_ref && reference_curves(sc, jobs, ref, &err) < 0)
    return dv_cli_error("sweep", "reference: %s", err.msg);
  if (dv_exec_mpi_rank() != 0) return DV_EXIT_OK; /* rank 0 writes */
  if (!s->interrupted && dv_search_sweep_floor_causes(sc, s, &err))
    return dv_cli_error("sweep", "%s", err.msg);
  if (dv_search_sweep_write(out, s, with_ref ? ref : NULL, &err))
    return dv_cli_error("sweep", "%s", err.msg);
  print_points(s);
  print_curves(s);
  printf("sweep: %s/sweep.csv, %s/work_precision.svg\n", out, out);
  if (s->interrupted) {
    dv_cli_error("sweep", "interrupted: the points not run are marked missing, their metrics NaN");
    return 130; /* 128 + SIGINT, as shells report it, and as an interrupted suite exits */
  }
  return DV_EXIT_OK;
}

int dv_cli_sweep(int argc, char **argv) {
  const char *engine = NULL, *out = "sweep";
  int jobs = dv_cli_default_jobs();
  dv_cli_list specs = {0};
  const dv_cli_option options[] = {
      {"engine", DV_CLI_TEXT, &engine, 0, 0},
      {"out", DV_CLI_TEXT, &out, 0, 0},
      {"jobs", DV_CLI_INT, &jobs, 1, 1024},
      {"vary", DV_CLI_LIST, &specs, 0, 0},
  };
  const dv_cli_command cmd = {"sweep", HELP, options, 4, 1, 1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_run_progress_start("sweep", a.quiet, 0);
  dv_sweep s = {0}, ref = {0};
  dv_scenario *sc = malloc(sizeof *sc);
  const int code = sc ? sweep(a.args.items[0], &a.sets, engine, &specs, out, jobs, &s, &ref, sc)
                      : dv_cli_error("sweep", "out of memory");
  free(sc);
  dv_search_sweep_free(&s);
  dv_search_sweep_free(&ref);
  dv_cli_args_free(&cmd, &a);
  return code;
}
