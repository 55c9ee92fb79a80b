/* report_within: a comparison and its report under a wall-time limit (report_within.h). */
#include "report_within.h"

#include "io_temp.h"
#include "report_suite_dir.h"
#include "run_progress.h"
#include "run_scenario.h"
#include "run_within.h"

/* what the comparison's process is given, and hands back */
typedef struct compare_job {
  const dv_scenario *sc;
  const dv_engine_type *const *engines;
  const char *out_dir;
  const dv_report_explain *explain;
  int jobs;
} compare_job;

typedef struct compare_result {
  int code; /* a dv_suite_result */
  dv_error err;
} compare_result;

static void compare_task(void *ctx, void *result) {
  const compare_job *j = ctx;
  compare_result *r = result;
  r->code = dv_report_suite_run_one(j->sc, j->engines, j->out_dir, 1, j->explain, j->jobs, &r->err);
}

/* the comparison's probed cost against timeout: 0, or -1 with err */
static int refuse(const dv_scenario *sc, const dv_engine_type *const *engines, double timeout,
                  dv_error *err) {
  const dv_engine_type *own[DV_MAX_ENGINES + 1], *const *run = engines;
  size_t n = 0;
  dv_error ignored; /* a bad list is run_one's to report */
  if (sc->engines[0] && !dv_engine_parse_list(sc->engines, own, DV_MAX_ENGINES + 1, &ignored))
    run = own; /* the engines run_one will run */
  while (run[n]) n++;
  return dv_run_within_refuse(dv_run_progress_estimate(sc, NULL, run, n), timeout, "each engine's",
                              err);
}

int dv_report_compare_within(const dv_scenario *sc, const dv_engine_type *const *engines,
                             const char *out_dir, const dv_report_explain *explain, int jobs,
                             double timeout, dv_error *err) {
  if (timeout > 0.0 && refuse(sc, engines, timeout, err)) return DV_SUITE_ERROR;
  compare_job job = {sc, engines, out_dir, explain, jobs};
  compare_result r = {DV_SUITE_ERROR, {{0}}};
  dv_fail(&r.err, DV_ESYSTEM, "its process ended without a result (crashed or killed)");
  const dv_run_within_end end = dv_run_within(timeout, compare_task, &job, &r, sizeof r);
  if (end == DV_RUN_WITHIN_DONE) {
    *err = r.err;
    return r.code;
  }
  dv_io_temp_remove_stale(out_dir); /* the report the killed process was building */
  if (end == DV_RUN_WITHIN_STOPPED) return dv_run_within_stop(err), DV_SUITE_ERROR;
  if (end == DV_RUN_WITHIN_TIMED_OUT) dv_fail(&r.err, DV_ESYSTEM, "timed out after %g s", timeout);
  dv_error ignored;
  dv_report_dir_write_error(out_dir, sc, r.err.msg, &ignored);
  *err = r.err;
  return DV_SUITE_ERROR;
}
