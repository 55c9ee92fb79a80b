/* test_period_quadrature: the period the reference folds with, against the
 * effective potential.
 *
 * The fold (red_period.h) takes its period T, and the heading and spin
 * advances dphi, dpsi over it, from a time integration. On the level set of
 * E, f1, f2 the same numbers are quadratures over theta between the turning
 * points lo, hi (red_nutation, red_potential.h; U and the rates from the
 * hypergeometric closed form, red_invariants.h):
 *
 *   T    = 2 int dtheta / |theta'|,   |theta'| = sqrt(2 (E - U) / (A + m r^2))
 *   dphi = 2 int v_phi(theta) dtheta / |theta'|,   dpsi likewise with v_psi
 *
 * With theta = (lo + hi)/2 - (hi - lo)/2 cos(s) the inverse square roots at
 * both ends cancel and the integrand is smooth in s over [0, pi]: GSL's
 * fixed Gauss-Legendre rule of 256 points; the rule's own error is taken as
 * what 128 points change (2.6e-10 to 9.6e-10 here, 6e-12 for C = 0, where U
 * is elementary). Four disks and starts (uniform spinning, non-uniform,
 * C = 0, nearer upright); the two formulations agree within 1e-9 relative
 * plus twice the rule's error. Measured (this test's output): the period to
 * 1.0e-11 .. 1.6e-10, the advances to 4e-12 .. 1.2e-9.
 */
#include <gsl/gsl_errno.h>
#include <math.h>

#include "dv_test.h"
#include "dv_testlib.h"
#include "red_period.h"
#include "red_potential.h"
#include "red_reference.h"

/* the fold's period from y0, as the reference records it at its defaults */
static int fold(const red_disk *disk, const double y0[RED_NSTATE], double out[3]) {
  red_reference ref;
  red_reference_init(&ref, disk, 0.01);
  red_integrator *in = red_integrator_alloc(&ref.sys, red_stepper_default(), 1e-12, 1e-13, NULL);
  red_period *p = red_period_alloc(disk, 1e-12, 1e-13, NULL);
  double t_a = NAN;
  int status = in && p ? DV_OK : DV_ESYSTEM;
  if (!status) {
    red_integrator_observe(in, red_period_record, p);
    status = red_period_reset(p, 0.0, y0, NULL);
  }
  if (!status) status = red_integrator_reset(in, 0.0, 1000.0, y0, NULL);
  if (!status) status = red_integrator_step_to(in, 1000.0, NULL);
  if (!status) status = red_period_orbit(p, &t_a, &out[0], &out[1], &out[2]);
  CHECK(status == DV_OK, "no period: %s", p ? red_period_note(p) : "out of memory");
  red_period_free(p);
  red_integrator_free(in);
  return status;
}

static void check(const char *what, double a_ratio, double c_ratio, const double y0[RED_NSTATE]) {
  const red_disk disk = tl_disk(a_ratio, c_ratio);
  double range[2], got[3], want[3];
  int falls = 0;
  CHECK(red_theta_range(&disk, y0, 0.01, range, &falls, NULL) == DV_OK && !falls,
        "%s: turning points", what);
  if (fold(&disk, y0, got)) return;
  double rule = NAN; /* how far half the nodes move the numbers */
  CHECK(red_nutation(&disk, y0, range, want, &rule, NULL) == DV_OK, "%s: quadrature failed", what);
  /* near the turning points E - U is the difference of two close numbers, each
   * carrying the special functions' rounding: that limits the rule */
  CHECK(rule <= 1e-8, "%s: the quadrature rule moves the numbers by %.2g", what, rule);
  printf(
      "%s: theta %.6f..%.6f; T %.15g vs %.15g (%.1e), dphi %.15g vs %.15g (%.1e), dpsi %.15g "
      "vs %.15g (%.1e); rule %.1e\n",
      what, range[0], range[1], got[0], want[0], fabs(got[0] / want[0] - 1.0), got[1], want[1],
      fabs(got[1] - want[1]) / fmax(1.0, fabs(want[1])), got[2], want[2],
      fabs(got[2] - want[2]) / fmax(1.0, fabs(want[2])), rule);
  for (int k = 0; k < 3; k++) /* relative to the period, to 1 rad for the advances */
    CHECK(fabs(got[k] - want[k]) <= (1e-9 + 2.0 * rule) * fmax(k ? 1.0 : 0.0, fabs(want[k])),
          "%s: %s %.17g vs %.17g", what, k ? "advance" : "period", got[k], want[k]);
}

int main(void) {
  gsl_set_error_handler_off();
  const double spin[RED_NSTATE] = {1.0, 0.0, 0.0, -12.0, 0.0, 0.0, 0.0, 0.0};
  const double odd[RED_NSTATE] = {0.8, 0.5, 2.0, 10.0, 0.0, 0.0, 0.0, 0.0};
  const double c_zero[RED_NSTATE] = {1.1, 0.2, 3.0, -6.0, 0.0, 0.0, 0.0, 0.0};
  const double upright[RED_NSTATE] = {1.3, 0.0, 0.0, 15.0, 0.0, 0.0, 0.0, 0.0};
  check("uniform, spinning", 0.25, 0.5, spin);
  check("A = 0.3, C = 0.4 (m r^2)", 0.3, 0.4, odd);
  check("C = 0", 0.25, 0.0, c_zero);
  check("nearer upright", 0.25, 0.5, upright);
  return TEST_RESULT();
}
