/* dv_cli_compare: diskval compare SCENARIO: the engines against the
 * references on one scenario, with its report. */
#include <stdio.h>

#include "cli.h"
#include "cli_args.h"
#include "io_lock.h"
#include "report_suite_dir.h"
#include "report_suite_run.h"
#include "report_within.h"
#include "run_progress.h"
#include "run_scenario.h"
#include "run_within.h"

static const char HELP[] =
    "usage: diskval compare SCENARIO [--engines LIST] [--out DIR] [--timeout S] [--jobs N]\n"
    "                       [--cause quick|full|none] [--set section.key=value]...\n"
    "\n"
    "Run SCENARIO in the engines (default: every contact engine) and in the references, compare\n"
    "theta(t) and the contact path, check the scenario's tolerances, and write\n"
    "DIR/<scenario>/ (default DIR: report): every trajectory as CSV, the plots,\n"
    "report.json, report.md and index.html (its page). Prints one line per engine.\n"
    "--timeout S: stop the comparison after S s of wall time, its settings probes included\n"
    "(an error report); one whose probed cost is more than twice S is not started.\n"
    "Default 0: no limit.\n"
    "--jobs N: run the engines (each with its settings probes), the references, then the\n"
    "failing engines' causes in up to N processes (default: the cores); the report is the\n"
    "same whatever N.\n"
    "--cause quick (default): each failing engine's cause, the knob whose change alone\n"
    "removes its error: the knob its failure points to first (energy: a time integrator;\n"
    "penetration: the contact; slip: the friction; else the integrator or the step), over\n"
    "the window where the error appears, stopping at the first that removes it;\n"
    "full: every knob over the whole scene (diskval attribute); none: no cause searched.\n"
    "--quiet: no progress line on a terminal, no warning before a run longer than a minute.\n"
    "Exit status: 0 all pass, 1 a tolerance or outcome failed, 2 bad input or error.\n";

/* the up-front estimate of the comparison of sc by the engines (ctx) that
 * dv_report_compare_within checks against the limit: sc's own [scenario]
 * engines where it names them */
static double forecast(const dv_scenario *sc, void *ctx) {
  const dv_engine_type *own[DV_MAX_ENGINES + 1], *const *run = ctx;
  size_t n = 0;
  dv_error ignored; /* a bad list is the comparison's to report */
  if (sc->engines[0] && !dv_engine_parse_list(sc->engines, own, DV_MAX_ENGINES + 1, &ignored))
    run = own;
  while (run[n]) n++;
  return dv_run_progress_estimate(sc, NULL, run, n);
}

/* after the limit ended the load (its settings probes): sc, as loaded with
 * nothing probed, gets the error report a killed comparison leaves; 0, or -1 */
static int report_timed_out(const dv_scenario *sc, const char *out, const char *cause, int *lock) {
  dv_error ignored;
  if (dv_report_dir_check(out, sc, 1, NULL, 0, &ignored) || dv_io_make_dirs(out, &ignored) ||
      dv_io_lock_dir(out, lock, &ignored) || dv_report_dir_check(out, sc, 1, NULL, 0, &ignored))
    return -1;
  return dv_report_dir_write_error(out, sc, cause, &ignored) ? -1 : 0;
}

int dv_cli_compare(int argc, char **argv) {
  const char *out = "report", *list = NULL, *cause = NULL;
  double timeout = 0.0;
  int jobs = dv_cli_default_jobs();
  const dv_cli_option options[] = {
      {"out", DV_CLI_TEXT, &out, 0, 0},
      {"engines", DV_CLI_TEXT, &list, 0, 0},
      {"timeout", DV_CLI_REAL, &timeout, 0, 1e9},
      {"cause", DV_CLI_TEXT, &cause, 0, 0},
      {"jobs", DV_CLI_INT, &jobs, 1, 1024},
  };
  const dv_cli_command cmd = {"compare", HELP, options, 5, 1, 1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_run_progress_start("compare", a.quiet, 0);
  /* the whole comparison, its settings probes and forecast too, ends at the limit */
  dv_run_within_deadline(timeout);
  const dv_engine_type *engines[DV_MAX_ENGINES + 1];
  dv_scenario sc;
  dv_error err = {{0}};
  dv_report_explain explain;
  int code, lock = -1, timed_out = 0;
  if ((code = dv_cli_explainer("compare", cause, &a.sets, &explain)) != DV_OK)
    ;
  else if (dv_cli_engine_list(list, engines, &err))
    code = dv_cli_error("compare", "%s", err.msg);
  else if (dv_cli_load_scenario_within("compare", a.args.items[0], &a.sets, timeout, forecast,
                                       engines, &sc, &timed_out, &err)) {
    if (timed_out) report_timed_out(&sc, out, err.msg, &lock);
    code = timed_out ? dv_cli_error("compare", "%s: %s", a.args.items[0], err.msg)
                     : (fprintf(stderr, "%s\n", err.msg), DV_EXIT_ERROR);
  } else if (dv_report_dir_check(out, &sc, 1, NULL, 0, &err) || dv_io_make_dirs(out, &err) ||
             dv_io_lock_dir(out, &lock, &err) || dv_report_dir_check(out, &sc, 1, NULL, 0, &err))
    code = dv_cli_error("compare", "%s", err.msg);
  else if ((code = dv_report_compare_within(&sc, engines, out, &explain, jobs, timeout, &err)) ==
           DV_EXIT_ERROR)
    dv_cli_error("compare", "%s: %s", sc.path, err.msg);
  else
    printf("report: %s/%s/report.md\npage: %s/%s/index.html\n", out, sc.name, out, sc.name);
  dv_io_unlock_dir(out, lock);
  dv_cli_args_free(&cmd, &a);
  return code;
}
