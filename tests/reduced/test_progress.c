/* test_progress: every reference integrator ends a run that cannot make
 * progress with an error that says so, never a hang (red_solver.h's guard).
 *
 * y' = -sign(y) - 1e-3 y from y = 1 reaches 0 at t ~ 1 and then sticks there,
 * the right-hand side jumping across it: each adaptive method shrinks its
 * step until the state cannot move. Each stepper must stop there with
 * status < 0 and the guard's reason (or its library's own failure), long
 * before t = 100 s. Measured (this program prints it): the GSL and CVODE
 * steppers stop on the guard at t = 0.9995 s, ARKODE on its own error test at
 * t = 1.001 s, each within 0.002 s of CPU; the limits (t < 2 s, 10 s CPU)
 * only tell a stop from a hang. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "dv_test.h"
#include "red_solver.h"

static int sticky(double t, const double *y, double *f, void *p) {
  (void)t;
  (void)p;
  f[0] = -(y[0] > 0.0 ? 1.0 : y[0] < 0.0 ? -1.0 : 0.0) - 1e-3 * y[0];
  return 0;
}

static double unit_frequency(const double *y, void *p) {
  (void)y;
  (void)p;
  return 1.0;
}

static int ignore(double t, const double *y, void *ctx) {
  (void)t;
  (void)y;
  (void)ctx;
  return 0;
}

int main(void) {
  const red_system sys = {1, sticky, NULL, unit_frequency, 0, {0}, {0}};
  for (const red_stepper_type *const *st = red_steppers; *st; st++) {
    double y[1] = {1.0};
    red_run run = {*st, 1e-12, 1e-14, 0.0, 100.0, 0.5, ignore, NULL};
    red_result res;
    dv_error err = {{0}};
    const clock_t c0 = clock();
    const int status = red_solve(&sys, &run, y, &res, &err);
    const double cpu = (double)(clock() - c0) / CLOCKS_PER_SEC;
    printf("%-20s status %d at t = %.4g s, %ld steps, %.3f s CPU: %s\n", (*st)->name, status,
           res.t_final, res.stats.steps, cpu, err.msg);
    CHECK(status < 0 && err.msg[0], "%s: a stuck run did not end with an error (status %d)",
          (*st)->name, status);
    CHECK(res.t_final < 2.0 && cpu < 10.0, "%s: ran on to t = %g s (%.1f s CPU)", (*st)->name,
          res.t_final, cpu);
  }
  return TEST_RESULT();
}
