/* dv_cli_simulate: diskval simulate SCENARIO --engine NAME [--set k=v] [--out FILE]. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "cli_args.h"
#include "dv_engine.h"
#include "run_meta.h"
#include "io_file.h"
#include "io_lock.h"
#include "run_progress.h"
#include "run_trajectory.h"
#include "run_within.h"

static const char HELP[] =
    "usage: diskval simulate SCENARIO --engine NAME [--set section.key=value]... [--out FILE]\n"
    "                        [--forces FILE] [--timeout S]\n"
    "\n"
    "Simulate SCENARIO with one engine and write its trajectory as CSV:\n"
    "  " DV_CSV_HEADER
    "\n"
    "one row every output_dt (and a last row where an event ends the run).\n"
    "  --engine NAME   engine to run (diskval engines lists them)\n"
    "  --set S.K=V     override key K of section S, e.g. --set engines.reduced.rtol=1e-10\n"
    "  --out FILE      write to FILE (default, or '-': stdout); written whole or not at all,\n"
    "                  with FILE.json beside it: engine, versions, settings, outcome, stats\n"
    "                  (not beside a device or /dev/stdout; a FILE.json that is not\n"
    "                  simulate's is refused); a symbolic link is written through\n"
    "  --forces FILE   the contact force along the run (references: the force rolling needs)\n"
    "                  as t,force_x,force_y,force_z,friction_ratio (N; NaN where unknown)\n"
    "  --timeout S     stop the run after S s of wall time, its settings probes included\n"
    "                  (exit 2, nothing written); one whose probed cost is more than twice\n"
    "                  S is not started (default 0: none)\n"
    "  --quiet         no progress line (shown when stderr is a terminal and the CSV is\n"
    "                  not) and no warning before a run longer than a minute\n"
    "A run that fails (diverged, lost contact, library error) exits 2 and writes no CSV.\n";

/* the up-front estimate of engine's run (ctx) over sc, probed with the settings */
static double forecast_run(const dv_scenario *sc, void *ctx) {
  return dv_run_progress_estimate_run(sc, ctx);
}

/* the command once its options are read */
static int simulate(const char *scenario, const dv_cli_list *sets, const char *engine_name,
                    const char *out_path, const char *forces_path, double timeout) {
  if (!engine_name) return dv_cli_usage_error("simulate", "no --engine given");
  const dv_engine_type *engine = dv_engine_find(engine_name);
  if (!engine) return dv_cli_unknown_engine("simulate", engine_name);
  dv_cli_probe_only(engine);
  char meta_path[1100];
  snprintf(meta_path, sizeof meta_path, "%s.json", out_path);
  const char *const outputs[] = {out_path, forces_path, meta_path};
  const char *const what[] = {"--out", "--forces", "the metadata file --out writes beside it"};
  const size_t nout = strcmp(out_path, "-") ? 3 : 2;
  for (size_t i = 0; i < nout; i++) /* no output over the input, or over another output */
    if (outputs[i] && strcmp(outputs[i], "-")) {
      if (dv_io_same_file(outputs[i], scenario))
        return dv_cli_usage_error("simulate", "%s '%s' is the scenario file", what[i], outputs[i]);
      for (size_t k = 0; k < i; k++)
        if (outputs[k] && strcmp(outputs[k], "-") && dv_io_same_file(outputs[i], outputs[k]))
          return dv_cli_usage_error("simulate", "%s '%s' is %s '%s': they name the same file",
                                    what[i], outputs[i], what[k], outputs[k]);
    }
  if (forces_path && !strcmp(forces_path, "-") && !strcmp(out_path, "-"))
    return dv_cli_usage_error("simulate", "--out and --forces name the same file: stdout");
  dv_scenario sc;
  dv_error err = {{0}};
  int timed_out;
  if (dv_cli_load_scenario_within("simulate", scenario, sets, timeout, forecast_run, (void *)engine,
                                  &sc, &timed_out, &err)) {
    if (timed_out) /* as a run killed at the limit says it */
      fprintf(stderr, "diskval simulate: %s: %s: error: %s\n", sc.name, engine->name, err.msg);
    else
      fprintf(stderr, "%s\n", err.msg);
    return DV_EXIT_ERROR;
  }
  dv_io_file out, forces = {0};
  /* metadata only beside a regular file, and never over a user's file */
  if (dv_io_open(&out, out_path, &err) || (forces_path && dv_io_open(&forces, forces_path, &err)) ||
      (out.fp != stdout && !out.direct && dv_run_meta_check_replaceable(meta_path, &err))) {
    dv_io_abort(&out);
    dv_io_abort(&forces);
    fprintf(stderr, "diskval simulate: %s\n", err.msg);
    return DV_EXIT_ERROR;
  }
  dv_engine_stats stats;
  int status = dv_run_write_csv_within(engine, &sc, out.fp, forces.fp, timeout, &stats, &err);
  if (status < 0) {
    dv_io_abort(&out);
    dv_io_abort(&forces);
    fprintf(stderr, "diskval simulate: %s: %s: %s: %s\n", sc.name, engine->name,
            dv_outcome_name(stats.outcome), err.msg);
    return DV_EXIT_ERROR;
  }
  /* the CSV and its metadata go into place together: another run writing the
   * same names waits, so the pair is always one run's */
  const int held = dv_io_hold_dir_of(out.path[0] ? out.path : ".");
  /* checked again now the directory is held: a user's file of that name may
   * have come while the run went, and is never replaced */
  const int meta = strcmp(out_path, "-") != 0 && !out.direct;
  int bad = meta && dv_run_meta_check_replaceable(meta_path, &err);
  if (bad) dv_io_abort(&out);
  bad = bad || dv_io_commit(&out, &err) || (forces_path && dv_io_commit(&forces, &err));
  dv_io_abort(&forces);
  if (!bad && meta) /* metadata beside a regular file */
    bad = dv_run_meta_write(meta_path, engine, &sc, &stats, &err);
  dv_io_release_dir(held);
  if (bad) {
    fprintf(stderr, "diskval simulate: %s\n", err.msg);
    return DV_EXIT_ERROR;
  }
  if (status == DV_EVENT)
    fprintf(stderr, "diskval simulate: %s: %s: the run ended early: %s\n", sc.name, engine->name,
            stats.detail);
  return DV_EXIT_OK;
}

int dv_cli_simulate(int argc, char **argv) {
  const char *engine_name = NULL, *out_path = "-", *forces_path = NULL;
  double timeout = 0.0;
  const dv_cli_option options[] = {
      {"engine", DV_CLI_TEXT, &engine_name, 0, 0},
      {"out", DV_CLI_TEXT, &out_path, 0, 0},
      {"forces", DV_CLI_TEXT, &forces_path, 0, 0},
      {"timeout", DV_CLI_REAL, &timeout, 0, 1e9},
  };
  const dv_cli_command cmd = {"simulate", HELP, options, 4, 1, 1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_run_progress_start("simulate", a.quiet, !strcmp(out_path, "-"));
  /* the whole run, its settings probes and forecast too, ends at the limit */
  dv_run_within_deadline(timeout);
  const int code = simulate(a.args.items[0], &a.sets, engine_name, out_path, forces_path, timeout);
  dv_cli_args_free(&cmd, &a);
  return code;
}
