/* test_output_grid: the default integrator keeps its accuracy whatever the
 * output spacing: interpolated between bounded steps for fine output, free
 * steps and one step onto each output for coarse output (red_step_gsl.c),
 * which also costs less there. */
#include <gsl/gsl_errno.h>
#include <math.h>

#include "dv_test.h"
#include "dv_testlib.h"

/* a uniform disk from theta 1 rad spinning at -12 rad/s (bench_output.sh) */
static const double Y0[RED_NSTATE] = {1.0, 0.0, 0.0, -12.0, 0.0, 0.0, 0.0, 0.0};
#define DURATION 200.0

static double max_energy_drift(const red_disk *dk, const tl_traj *tr) {
  const double e0 = red_energy(dk, tr->y[0]);
  double drift = 0.0;
  for (long i = 0; i < tr->n; i++) drift = fmax(drift, fabs(red_energy(dk, tr->y[i]) - e0) / e0);
  return drift;
}

/* the promise of docs/reference.md at the defaults (rtol 1e-12, atol 1e-13): theta within
 * 1e-10 rad of a 1e-14 run stepped onto the outputs over 200 s, energy within
 * 1e-11 relative. Measured (this test's output): theta 7.0e-12 rad every 1 ms,
 * 1.2e-11 every 1 s (two 1e-14 references differ by 2e-11 there: rounding);
 * energy 2.1e-12 and 9e-13. Returns the right-hand side evaluations. */
static long check_grid(const red_disk *dk, double dt) {
  tl_traj ref = tl_run(dk, &red_gsl_rk8pd_stepped, 1e-14, Y0, DURATION, dt, 0.01);
  tl_traj def = tl_run_tols(dk, red_stepper_default(), 1e-12, 1e-13, Y0, DURATION, dt, 0.01);
  double theta, path;
  tl_compare(dk, &ref, &def, &theta, &path);
  const double drift = max_energy_drift(dk, &def);
  printf(
      "output every %g s over %g s: theta error %.2e rad, energy drift %.2e, %ld steps, %ld rhs\n",
      dt, DURATION, theta, drift, def.result.stats.steps, def.result.stats.rhs_evals);
  CHECK(ref.status == DV_OK && def.status == DV_OK && def.n == ref.n, "dt %g: status %d %d", dt,
        ref.status, def.status);
  CHECK(theta <= 1e-10, "dt %g: theta error %.3g > 1e-10", dt, theta);
  CHECK(drift <= 1e-11, "dt %g: energy drift %.3g > 1e-11", dt, drift);
  const long evals = def.result.stats.rhs_evals;
  tl_free(&ref);
  tl_free(&def);
  return evals;
}

/* a fall sampled every 1 s ends at its event where the 1e-14 run does: the
 * crossing is found on one step of the method, not on an interpolant the
 * free steps outgrow (falls at 1.68 s). Measured 3.1e-11 s; limit 1e-9 s */
static void check_event(const red_disk *dk) {
  const double y0[RED_NSTATE] = {M_PI / 2 - 1e-6, 0.0, 0.0, 0.1, 0.0, 0.0, 0.0, 0.0};
  tl_traj ref = tl_run(dk, &red_gsl_rk8pd_stepped, 1e-14, y0, 20.0, 1.0, 0.2);
  tl_traj def = tl_run_tols(dk, red_stepper_default(), 1e-12, 1e-13, y0, 20.0, 1.0, 0.2);
  CHECK(ref.status == DV_EVENT && def.status == DV_EVENT, "fall: status %d %d", ref.status,
        def.status);
  const double dt_event = fabs(def.result.t_final - ref.result.t_final);
  printf("fall sampled every 1 s: event at %.12f s, %.1e s from the 1e-14 run\n",
         def.result.t_final, dt_event);
  CHECK(dt_event <= 1e-9, "fall: event %.3g s off", dt_event);
  tl_free(&ref);
  tl_free(&def);
}

int main(void) {
  gsl_set_error_handler_off();
  const red_disk dk = tl_disk(0.25, 0.5);
  const long fine = check_grid(&dk, 1e-3), coarse = check_grid(&dk, 1.0);
  /* steps bounded for the interpolant cost the same on both grids; measured
   * 0.87 of the fine grid's evaluations with free steps */
  CHECK(coarse <= 0.95 * fine, "coarse output costs %ld rhs, fine %ld: steps not free", coarse,
        fine);
  check_event(&dk);
  return TEST_RESULT();
}
