/* test_run_within: a run under a time limit, without timing anything.
 *
 * The refusal is a pure comparison of a probe's estimate with
 * DV_RUN_WITHIN_REFUSE times the limit, checked at limits other than 1 s (where
 * REFUSE * limit and REFUSE / limit agree). How the work ends is checked with
 * work whose end does not depend on the machine's load: it returns at once
 * (limit 600 s), sleeps for 600 s (limit 0.2 s: killed however slow the
 * machine), or dies. */
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_error.h"
#include "dv_test.h"
#include "run_within.h"

static void answer(void *ctx, void *result) {
  (void)ctx;
  *(int *)result = 42;
}

static void sleep_long(void *ctx, void *result) {
  (void)ctx;
  (void)result;
  sleep(600);
}

static void die(void *ctx, void *result) {
  (void)ctx;
  (void)result;
  raise(SIGKILL);
}

static int refused(double estimate, double timeout) {
  dv_error err = {{0}};
  const int status = dv_run_within_refuse(estimate, timeout, "its", &err);
  CHECK(status == 0 || strstr(err.msg, "not started"), "refused without saying so: '%s'",
        err.msg);
  return status != 0;
}

int main(void) {
  const double limits[] = {0.25, 0.5, 3.0, 40.0};
  for (int i = 0; i < 4; i++) {
    const double T = limits[i], edge = DV_RUN_WITHIN_REFUSE * T;
    CHECK(!refused(0.99 * edge, T), "%g s under a limit of %g s refused", 0.99 * edge, T);
    CHECK(!refused(edge, T), "the edge %g s under a limit of %g s refused", edge, T);
    CHECK(refused(1.01 * edge, T), "%g s under a limit of %g s started", 1.01 * edge, T);
  }
  CHECK(!refused(1e9, 0.0), "no limit (0 s) refused a long run");
  CHECK(!refused(1e9, -1.0), "no limit (-1 s) refused a long run");
  CHECK(!refused(NAN, 1.0), "an unknown estimate (NaN) refused");

  int result = 0;
  CHECK(dv_run_within(600.0, answer, NULL, &result, sizeof result) == DV_RUN_WITHIN_DONE,
        "work that returns at once did not end DONE");
  CHECK(result == 42, "its result %d did not come back", result);
  result = 7;
  CHECK(dv_run_within(0.2, sleep_long, NULL, &result, sizeof result) == DV_RUN_WITHIN_TIMED_OUT,
        "work sleeping 600 s under a 0.2 s limit did not end TIMED_OUT");
  CHECK(result == 7, "a killed run's result changed to %d", result);
  CHECK(dv_run_within(600.0, die, NULL, &result, sizeof result) == DV_RUN_WITHIN_LOST,
        "work killed by a signal did not end LOST");
  CHECK(result == 7, "a lost run's result changed to %d", result);
  result = 0;
  dv_run_within(0.0, answer, NULL, &result, sizeof result);
  CHECK(result == 42, "without a limit the work did not run here");
  return TEST_RESULT();
}
