/* report_judge: a judgement of recorded trajectories and its report (report_judge.h). */
#include "report_judge.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report_scenario.h"
#include "report_suite.h"
#include "report_suite_dir.h"

/* attribution re-runs an engine with its knobs turned: a file has none */
static void say_no_cause(dv_comparison *c) {
  for (size_t i = 0; i < c->n; i++) {
    dv_engine_result *r = &c->r[i];
    if (r->verdict != DV_VERDICT_EXCEEDS) continue;
    snprintf(r->cause, sizeof r->cause,
             "not attributed: a recorded trajectory cannot be re-run with its knobs turned");
    for (size_t k = 0; k < r->nfailures; k++) {
      const size_t len = strlen(r->failures[k]);
      snprintf(r->failures[k] + len, sizeof r->failures[k] - len, "; cause: %s", r->cause);
    }
  }
}

int dv_report_judge_run(const dv_scenario *sc, dv_replay *replays, size_t n, const char *out_dir,
                        const char *junit, double *theta_err, dv_error *err) {
  char tmp[1300];
  dv_comparison *c = calloc(1, sizeof *c);
  if (!c) return dv_fail(err, DV_ESYSTEM, "out of memory"), DV_SUITE_ERROR;
  int code = DV_SUITE_ERROR, bad_input = 0;
  if (!dv_report_dir_begin(tmp, sizeof tmp, out_dir, sc->name, err)) {
    int status = dv_run_judge(sc, replays, n, c, err);
    bad_input = status == DV_EINPUT;
    if (!status) say_no_cause(c);
    if (!status) status = dv_report_scenario_write(tmp, c, err);
    bad_input = bad_input || status == DV_EINPUT; /* two outputs one file: no report */
    if (!status) dv_report_scenario_print(stdout, c);
    for (size_t i = 0; !status && theta_err && i < c->n; i++)
      theta_err[i] = c->r[i].vs_ref.value[DV_THETA_MAX_ERR];
    if (status)
      dv_report_dir_discard(tmp);
    else if (!dv_report_dir_install(tmp, out_dir, sc->name, err))
      code = c->pass ? DV_SUITE_PASS : DV_SUITE_FAIL;
  }
  dv_run_comparison_free(c);
  free(c);
  dv_error ignored;
  if (code == DV_SUITE_ERROR && !bad_input)
    dv_report_dir_write_error(out_dir, sc, err->msg, &ignored);
  if (code != DV_SUITE_ERROR && junit && dv_report_suite_write_junit(out_dir, sc->name, junit, err))
    code = DV_SUITE_ERROR;
  return code;
}
