/* test_ode_seed: ODE runs are bit-reproducible. dWorldQuickStep permutes its
 * constraint rows with ODE's random generator, whose state lives on in the
 * process: without a seed per run, the same settings gave theta errors
 * 2.0506187484725658e-4 and then 2.0506187490931804e-4 in one process. Usage:
 * test_ode_seed SCENARIO (a steady circle; run 1 s with QuickStep, twice in
 * this process, after a run with the other stepper between them). */
#include <string.h>

#include "dv_engine.h"
#include "dv_test.h"
#include "dv_test_traj.h"

int main(int argc, char **argv) {
  if (argc != 2) return fprintf(stderr, "usage: test_ode_seed SCENARIO\n"), 2;
  static dv_scenario quick, plain;
  static traj a, b, between;
  dv_error err = {{0}};
  const char *quick_sets[] = {"engines.ode.stepper=quickstep", "scenario.duration=1"};
  const char *plain_sets[] = {"scenario.duration=1"};
  CHECK(dv_engine_load_scenario(argv[1], quick_sets, 2, &quick, &err) == DV_OK, "%s", err.msg);
  CHECK(dv_engine_load_scenario(argv[1], plain_sets, 1, &plain, &err) == DV_OK, "%s", err.msg);
  dv_test_run(&dv_engine_ode, &quick, &a);
  dv_test_run(&dv_engine_ode, &plain, &between);
  dv_test_run(&dv_engine_ode, &quick, &b);
  CHECK(a.status == DV_OK && b.status == DV_OK && a.n == b.n && a.n > 50, "runs: %d %d, %ld %ld",
        a.status, b.status, a.n, b.n);
  long differ = 0;
  for (long i = 0; i < a.n && i < b.n; i++)
    differ += memcmp(a.s[i].y, b.s[i].y, sizeof a.s[i].y) != 0;
  printf("QuickStep twice in one process: %ld of %ld samples differ\n", differ, a.n);
  CHECK(differ == 0, "%ld samples differ between two identical runs", differ);
  return TEST_RESULT();
}
