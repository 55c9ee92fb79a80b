/* test_deciding: the metric that decides a verdict (run_decided.h), on results made by
 * hand. A fail is decided by the metric furthest over its limit, and a value not
 * measured (NaN) under a limit is furthest of all; a pass by the one nearest its limit;
 * a metric without a limit (NaN) never decides; a failed run, one not judged and an
 * engine lying down where it should not are decided by no metric. */
#include <math.h>
#include <string.h>

#include "dv_test.h"
#include "run_decided.h"

static dv_engine_result r;

/* r with no limit and nothing measured, then the given metrics */
static void reset(dv_verdict verdict, int pass) {
  memset(&r, 0, sizeof r);
  r.verdict = verdict, r.pass = pass;
  r.event.agrees = 1;
  for (int m = 0; m < DV_NMETRICS; m++) r.tolerance[m] = NAN, r.vs_ref.value[m] = NAN;
}

static void metric(int m, double value, double limit) {
  r.vs_ref.value[m] = value, r.tolerance[m] = limit;
}

int main(void) {
  reset(DV_VERDICT_EXCEEDS, 0);
  metric(DV_THETA_MAX_ERR, 0.5, 0.01); /* 50 times over */
  metric(DV_ENERGY_DRIFT, 0.02, 0.01); /* twice */
  CHECK(dv_run_deciding_metric(&r) == DV_THETA_MAX_ERR, "fail: %d, not the furthest over",
        dv_run_deciding_metric(&r));
  metric(DV_PATH_MAX_ERR, NAN, 0.01); /* not measured */
  CHECK(dv_run_deciding_metric(&r) == DV_PATH_MAX_ERR, "fail: %d, not the metric not measured",
        dv_run_deciding_metric(&r));

  reset(DV_VERDICT_AGREES, 1);
  metric(DV_THETA_MAX_ERR, 0.001, 0.01); /* 0.1 of its limit */
  metric(DV_PATH_MAX_ERR, 0.004, 0.005); /* 0.8 */
  metric(DV_ENERGY_DRIFT, 0.0, 0.01);
  metric(DV_SLIP_MAX, 5.0, NAN); /* no limit: never decides */
  CHECK(dv_run_deciding_metric(&r) == DV_PATH_MAX_ERR, "pass: %d, not the nearest its limit",
        dv_run_deciding_metric(&r));

  const dv_verdict none[] = {DV_VERDICT_DIVERGED, DV_VERDICT_NOT_JUDGED,
                             DV_VERDICT_OUTSIDE_VALIDITY};
  for (int i = 0; i < 3; i++) {
    reset(none[i], 0);
    metric(DV_THETA_MAX_ERR, 0.5, 0.01);
    CHECK(dv_run_deciding_metric(&r) == -1, "%s decided by metric %d",
          dv_run_verdict_name(none[i]), dv_run_deciding_metric(&r));
  }
  reset(DV_VERDICT_EXCEEDS, 0);
  metric(DV_THETA_MAX_ERR, 0.5, 0.01);
  r.event.judged = 1, r.event.agrees = 0;
  CHECK(dv_run_deciding_metric(&r) == -1, "lying down early: decided by metric %d",
        dv_run_deciding_metric(&r));
  return TEST_RESULT();
}
