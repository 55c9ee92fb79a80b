/* dv_cli_league: diskval league: every engine on the same real objects. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "cli_args.h"
#include "engine_choose.h"
#include "exec_mpi.h"
#include "exec_pool.h"
#include "io_lock.h"
#include "io_owned.h"
#include "league.h"
#include "league_run.h"
#include "league_words.h"
#include "run_progress.h"
#include "run_scenario.h"

static const char HELP[] =
    "usage: diskval league [DIR|FILES...] [--engines LIST] [--targets T1,T2,...] [--out DIR]\n"
    "                      [--jobs N] [--cost-cap S] [--cause quick|full|none] [--timeout S]\n"
    "                      [--set section.key=value]...\n"
    "\n"
    "Every engine on the same objects (scenario files; default: the shipped league/ folder,\n"
    "a quick set; league/more/ holds the rest), for each accuracy target T (rad of theta;\n"
    "default 1e-3) with the matching path target (the scene's path limit scaled as its theta\n"
    "limit is scaled to T): the cheapest settings that reach both (best's search, stopped\n"
    "where a run would cost more than S s of wall a simulated s, default 20, or where the\n"
    "error stops falling with the step), their cost, the observed order over the search's\n"
    "runs, and, where none reaches them, why (every run failed and how, the cost cap, the\n"
    "error's floor) with the cause from attribution. Each cell is backed by a compare at its\n"
    "settings with the targets as its limits (DIR/compare/OBJECT/ENGINE-T/OBJECT/).\n"
    "Default engines: every contact engine diskval engines lists, adapters included (one\n"
    "that cannot run is listed with why). Writes into DIR (default league-report):\n"
    "league.json, league.csv, league.md, league.html, overview.svg and\n"
    "work_precision_OBJECT.svg; the cells are kept in DIR/cells/, so running again into\n"
    "the same DIR resumes where a league stopped (a cell is reused while its object file,\n"
    "engine version, target, cost cap and --set are the same, and what it claims is what\n"
    "its backing report says). No object may lie in DIR/cells/ or DIR/compare/.\n"
    "--jobs N: pairs of object and engine at a time (default: the cores); under mpirun the\n"
    "ranks share them. At most 64 objects and 6 targets (each in (0, pi) rad).\n"
    "--quiet: no progress line on a terminal, no warning before a long league.\n"
    "--timeout S: s of wall time a pair of object and engine (its cells at every target) may\n"
    "take (default 0: no limit; none under mpirun); its cells not ended then are errors.\n"
    "A cell's claim re-runs with the league's --set overrides too (league.json: overrides);\n"
    "a --set of a key the league gives each cell (an engine's step or choice, which the\n"
    "search varies, or the theta limit, a target) is refused.\n"
    "Exit status: 0 every cell ran, 1 a cell ended in an error, 2 bad input, 130 stopped by\n"
    "a signal (what finished is written and kept).\n";

/* "1e-2,1e-3" into targets: each in (0, pi) rad, told apart by the name of its files */
static int parse_targets(const char *list, double *targets, size_t *n) {
  *n = 0;
  for (const char *p = list;;) {
    char *end;
    const double v = strtod(p, &end);
    if (end == p || (*end && *end != ',') || !(v > 0.0 && v < M_PI))
      return dv_cli_usage_error("league", "--targets: '%s' is no list of numbers in (0, pi) rad",
                                list);
    if (*n == DV_LEAGUE_MAX_TARGETS)
      return dv_cli_usage_error("league", "--targets: at most %d", DV_LEAGUE_MAX_TARGETS);
    for (size_t k = 0; k < *n; k++) {
      char a[32], b[32];
      snprintf(a, sizeof a, "%g", targets[k]), snprintf(b, sizeof b, "%g", v);
      if (!strcmp(a, b))
        return dv_cli_usage_error("league", "--targets: %s and %.17g are one target (%s)", a, v, b);
    }
    targets[(*n)++] = v;
    if (!*end) return DV_EXIT_OK;
    p = end + 1;
  }
}

/* whether objects a and b would write one figure (or are one object) */
static int same_figure(const char *a, const char *b) {
  char fa[128], fb[128];
  dv_league_figure_file(a, fa, sizeof fa), dv_league_figure_file(b, fb, sizeof fb);
  return !strcmp(a, b) || !strcmp(fa, fb);
}

/* every contact engine, outside ones too (NULL list), or the list's */
static int engine_list(const char *list, const dv_engine_type **engines) {
  dv_error err = {{0}};
  if (list) {
    if (dv_engine_parse_list(list, engines, DV_MAX_ENGINES + 1, &err))
      return dv_cli_error("league", "%s", err.msg);
    for (const dv_engine_type **e = engines; *e; e++)
      if ((*e)->role != DV_ENGINE_CONTACT)
        return dv_cli_usage_error("league", "--engines: %s is a reference, not a contact engine",
                                  (*e)->name);
  } else {
    size_t n = 0;
    for (const dv_engine_type *const *e = dv_engine_list(); *e && n < DV_MAX_ENGINES; e++)
      if ((*e)->role == DV_ENGINE_CONTACT) engines[n++] = *e;
    engines[n] = NULL;
  }
  return DV_EXIT_OK;
}

/* one line per engine and target: reached of run, the geometric-mean cost */
static void print_summary(const dv_league *lg) {
  for (size_t t = 0; t < lg->ntargets; t++)
    for (size_t e = 0; e < lg->nengines; e++) {
      const dv_league_engine *g = &lg->engines[e];
      if (!g->available) {
        if (!t) printf("%-10s not available: %s\n", g->name, g->why);
        continue;
      }
      dv_league_summary s;
      dv_league_summarize(lg, g->name, lg->targets[t], &s);
      printf("%-10s target %-8g reached %zu of %zu", g->name, lg->targets[t], s.reached,
             s.reached + s.not_reached + s.cannot_model + s.not_run);
      if (s.reached) printf(", %.3g s a simulated s (geometric mean)", s.geomean_wall_per_sim_s);
      printf("\n");
    }
}

/* the league's objects: the files args names, or the shipped folder */
static int object_files(const dv_cli_list *args, dv_cli_list *files) {
  dv_cli_list def = {0};
  const char *dir = access(DV_LEAGUE_SOURCE_DIR, R_OK) == 0 ? DV_LEAGUE_SOURCE_DIR
                                                             : DV_LEAGUE_INSTALL_DIR;
  if (args->n) return dv_cli_scenario_files("league", args, files);
  if (dv_cli_list_push(&def, dir)) return dv_cli_error("league", "out of memory");
  const int code = dv_cli_scenario_files("league", &def, files);
  free(def.items);
  return code;
}

static int run(const dv_cli_args *a, const char *out, const char *list, const char *targets_text,
               double cost_cap, const char *cause, int jobs, double timeout) {
  double targets[DV_LEAGUE_MAX_TARGETS];
  size_t ntargets = 0;
  const dv_engine_type *engines[DV_MAX_ENGINES + 1];
  dv_report_explain explain;
  dv_cli_list files = {0};
  int code = parse_targets(targets_text, targets, &ntargets);
  if (!code) code = dv_cli_explainer("league", cause, &a->sets, &explain);
  if (!code) code = engine_list(list, engines);
  dv_error set_err = {{0}};
  if (!code && dv_league_check_overrides(engines, (const char *const *)a->sets.items, a->sets.n,
                                         &set_err))
    code = dv_cli_usage_error("league", "%s", set_err.msg);
  if (!code) code = object_files(&a->args, &files);
  if (!code && files.n > DV_LEAGUE_MAX_OBJECTS)
    code = dv_cli_error("league", "%zu objects: a league takes at most %d", files.n,
                        DV_LEAGUE_MAX_OBJECTS);
  /* loaded without a settings probe: every run of a search gives its own step and integrator */
  static const dv_engine_type *const none[] = {NULL};
  dv_engine_choose_only(none);
  dv_scenario *objects = code ? NULL : calloc(files.n, sizeof *objects);
  if (!code && !objects) code = dv_cli_error("league", "out of memory");
  for (size_t i = 0; !code && i < files.n; i++) {
    dv_error err = {{0}};
    if (dv_cli_load_scenario("league", files.items[i], &a->sets, &objects[i], &err))
      code = (fprintf(stderr, "%s\n", err.msg), DV_EXIT_ERROR);
    for (size_t k = 0; !code && k < i; k++)
      if (same_figure(objects[k].name, objects[i].name))
        code = dv_cli_error("league", "%s and %s name their objects '%s' and '%s': one figure's name",
                            objects[k].path, objects[i].path, objects[k].name, objects[i].name);
  }
  if (!code) dv_engine_choose_only(engines);
  dv_league lg = {0};
  dv_error err = {{0}};
  int lock = -1;
  const dv_league_request rq = {objects, files.n, engines, targets, ntargets, cost_cap,
                                a->sets.items, a->sets.n, out, jobs, &explain, timeout};
  const int rank0 = dv_exec_mpi_rank() == 0;
  if (!code && rank0) {
    /* the outputs' names need the objects' names: the league's header first */
    char (*names)[96] = calloc(files.n + 1, sizeof *names);
    const char **all = calloc(files.n + 9, sizeof *all);
    for (size_t o = 0; names && all && o < files.n; o++)
      snprintf(lg.objects[o].name, sizeof lg.objects[o].name, "%s", objects[o].name);
    lg.nobjects = files.n;
    if (!names || !all)
      code = dv_cli_error("league", "out of memory");
    else {
      dv_league_output_names(&lg, names, all);
      /* no input is an output, before anything is written */
      const char *const *inputs = (const char *const *)files.items;
      if (dv_io_check_inputs(out, all, inputs, files.n, &err) ||
          dv_league_check_inputs(out, inputs, files.n, &err) || dv_io_own_dir(out, all, &err) ||
          dv_io_lock_dir(out, &lock, &err))
        code = dv_cli_error("league", "%s", err.msg);
    }
    free(names), free(all);
  }
  if (!code) {
    const int status = dv_league_run(&rq, &lg, &err);
    if (status == DV_LEAGUE_WORKER)
      code = DV_EXIT_OK;
    else if (status != DV_OK && status != DV_EVENT)
      code = dv_cli_error("league", "%s", err.msg);
    else if (dv_league_write_all(out, &lg, &err))
      code = dv_cli_error("league", "%s", err.msg);
    else {
      print_summary(&lg);
      size_t failed = 0;
      for (size_t k = 0; k < lg.ncells; k++)
        failed += lg.cells[k].outcome == DV_LEAGUE_NOT_RUN || !strncmp(lg.cells[k].why, "error:", 6);
      printf("league: %s/league.html (%zu cells%s)\n", out, lg.ncells,
             status == DV_EVENT ? ", stopped by a signal: run again to resume" : "");
      code = status == DV_EVENT ? 130 : failed ? DV_EXIT_FAIL : DV_EXIT_OK;
    }
  }
  dv_io_unlock_dir(out, lock);
  dv_league_free(&lg);
  free(objects);
  for (size_t i = 0; i < files.n; i++) free((char *)files.items[i]);
  free(files.items);
  return code;
}

int dv_cli_league(int argc, char **argv) {
  const char *out = "league-report", *list = NULL, *targets = "1e-3", *cause = NULL;
  double cost_cap = DV_LEAGUE_COST_CAP;
  int jobs = dv_cli_default_jobs();
  double timeout = 0.0;
  const dv_cli_option options[] = {
      {"out", DV_CLI_TEXT, &out, 0, 0},         {"engines", DV_CLI_TEXT, &list, 0, 0},
      {"targets", DV_CLI_TEXT, &targets, 0, 0}, {"cost-cap", DV_CLI_REAL, &cost_cap, 1e-3, 1e6},
      {"cause", DV_CLI_TEXT, &cause, 0, 0},     {"jobs", DV_CLI_INT, &jobs, 1, 1024},
      {"timeout", DV_CLI_REAL, &timeout, 0, 1e9},
  };
  const dv_cli_command cmd = {"league", HELP, options, 7, 0, (size_t)-1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_run_progress_start("league", a.quiet, 0);
  dv_exec_hold_stops();
  const int code = run(&a, out, list, targets, cost_cap, cause, jobs, timeout);
  dv_cli_args_free(&cmd, &a);
  return code;
}
