/* bench_reduced: cost against accuracy of the reference integrators.
 *
 * For each case and output spacing: the theta error (max over the samples,
 * against a GSL rk8pd run at 1e-14 stepping onto the samples) and the wall
 * time per simulated second of every stepper over a range of rtol, and of
 * the baseline: a plain GSL rk8pd driver at eps 1e-10 stepping onto every
 * output point. Prints, per stepper, the cheapest rtol with theta error
 * <= 1e-10 and its cost as a ratio to the baseline measured in the same run.
 */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "red_reference.h"
#include "dv_clock.h"

#define TARGET 1e-10
#define REPEAT 3

typedef struct samples {
  long n, cap;
  double *theta;
} samples;

static int keep(double t, const double *y, void *ctx) {
  samples *s = ctx;
  if (s->n < s->cap) s->theta[s->n++] = y[RED_TH];
  return 0;
}


/* best-of-REPEAT wall time of one reference run; theta samples left in out */
static double time_run(red_reference *ref, const red_stepper_type *T, double rtol, const double *y0,
                       double duration, double dt, samples *out) {
  double best = INFINITY;
  for (int r = 0; r < REPEAT; r++) {
    double y[RED_NSTATE];
    memcpy(y, y0, sizeof y);
    out->n = 0;
    red_run run = {T, rtol, rtol * 1e-2, 0.0, duration, dt, keep, out};
    red_result res;
    const double t0 = dv_clock_now();
    red_solve(&ref->sys, &run, y, &res, NULL);
    best = fmin(best, dv_clock_now() - t0);
  }
  return best;
}

static int plain_rhs(double t, const double y[], double f[], void *p) {
  return red_rhs(p, y, f) ? GSL_EBADFUNC : GSL_SUCCESS;
}

/* the baseline: gsl_odeiv2_driver, rk8pd, eps 1e-10, onto every output */
static double time_baseline(red_disk *dk, const double *y0, double duration, double dt,
                            samples *out) {
  double best = INFINITY;
  for (int r = 0; r < REPEAT; r++) {
    gsl_odeiv2_system sys = {plain_rhs, NULL, RED_NSTATE, dk};
    gsl_odeiv2_driver *d =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3, 1e-10, 1e-10);
    double y[RED_NSTATE], t = 0.0;
    memcpy(y, y0, sizeof y);
    out->n = 0;
    const double t0 = dv_clock_now();
    keep(0.0, y, out);
    const long n = lround(duration / dt);
    for (long k = 1; k <= n; k++) {
      if (gsl_odeiv2_driver_apply(d, &t, k * dt, y) != GSL_SUCCESS) break;
      keep(t, y, out);
    }
    best = fmin(best, dv_clock_now() - t0);
    gsl_odeiv2_driver_free(d);
  }
  return best;
}

static double max_err(const samples *a, const samples *b) {
  double e = 0.0;
  const long n = a->n < b->n ? a->n : b->n;
  for (long i = 0; i < n; i++) e = fmax(e, fabs(a->theta[i] - b->theta[i]));
  return a->n == b->n ? e : INFINITY;
}

static void bench_case(const char *name, red_disk dk, const double *y0, double duration, double dt,
                       double *ratio_default) {
  red_reference ref;
  red_reference_init(&ref, &dk, 0.01);
  const long cap = lround(duration / dt) + 2;
  samples exact = {0, cap, malloc(cap * sizeof(double))};
  samples s = {0, cap, malloc(cap * sizeof(double))};
  time_run(&ref, &red_gsl_rk8pd_stepped, 1e-14, y0, duration, dt, &exact);
  const double base = time_baseline(&dk, y0, duration, dt, &s);
  printf("\n%s, %g s, output every %g ms\n", name, duration, dt * 1e3);
  printf(
      "  baseline (GSL rk8pd driver, eps 1e-10, onto outputs): %.3f ms/sim-s, theta error %.1e\n",
      1e3 * base / duration, max_err(&s, &exact));
  printf("  %-20s %-7s %12s %12s %10s\n", "integrator", "rtol", "theta error", "ms/sim-s",
         "/baseline");
  for (const red_stepper_type *const *T = red_steppers; *T; T++) {
    double best_ratio = INFINITY, best_tol = 0.0;
    for (int k = 8; k <= 13; k++) {
      const double rtol = pow(10.0, -k);
      const double w = time_run(&ref, *T, rtol, y0, duration, dt, &s);
      const double e = max_err(&s, &exact);
      printf("  %-20s %-7.0e %12.2e %12.3f %10.2f\n", (*T)->name, rtol, e, 1e3 * w / duration,
             w / base);
      if (e <= TARGET && w / base < best_ratio) {
        best_ratio = w / base;
        best_tol = rtol;
      }
    }
    printf("  -> %-17s cheapest at theta error <= %.0e: rtol %.0e, %.2fx baseline\n", (*T)->name,
           TARGET, best_tol, best_ratio);
    if (*T == red_stepper_default()) *ratio_default = best_ratio;
  }
  free(exact.theta);
  free(s.theta);
}

int main(void) {
  gsl_set_error_handler_off();
  const red_disk uniform = red_disk_uniform(0.1, 1.0, 9.81);
  const double general[RED_NSTATE] = {1.1, 0.2, 3.0, -6.0, 0.0, 0.0, 0.0, 0.0};
  const double wobble[RED_NSTATE] = {M_PI / 2, 0.3, 0.0, 8.0, 0.0, 0.0, 0.0, 0.0};
  double r10[2], r1[2];
  bench_case("uniform disk, rolling and turning", uniform, general, 20.0, 0.01, &r10[0]);
  bench_case("uniform disk, rolling and turning", uniform, general, 20.0, 0.001, &r1[0]);
  bench_case("uniform disk, upright wobble", uniform, wobble, 20.0, 0.01, &r10[1]);
  bench_case("uniform disk, upright wobble", uniform, wobble, 20.0, 0.001, &r1[1]);
  printf("\ndefault (%s) at theta error <= 1e-10, cost / baseline:\n", red_stepper_default()->name);
  printf("  output 10 ms: %.2f, %.2f   (target <= 1)\n", r10[0], r10[1]);
  printf("  output  1 ms: %.2f, %.2f   (target <= 0.25)\n", r1[0], r1[1]);
  return 0;
}
