/* test_formulations: the reduced equations, the momentum form (3.67) and
 * Pars's Lagrange-multiplier equations give the same motion, and so do the
 * GSL, CVODE and ARKODE integrators. theta and the contact point must agree
 * to 1e-8 over 10 s from several non-symmetric initial conditions. Both
 * contact points come from red_contact_point; test_pose holds it to the lowest
 * point of DESIGN's pose built from elementary rotations. */
#include <gsl/gsl_errno.h>
#include <math.h>

#include "dv_test.h"
#include "dv_testlib.h"
#include "red_formulations.h"

/* Measured with this test's output (rtol 1e-14): largest differences 1.2e-9 rad
 * and 6e-9 m (CVODE Adams, state 1); the limit 1e-8 is the issue's. */
#define LIMIT 1e-8

static void compare(const red_disk *dk, const tl_traj *ref, const tl_traj *other, const char *what,
                    int state) {
  double th, path;
  CHECK(other->status == DV_OK && other->n == ref->n, "%s: state %d: status %d, %ld samples", what,
        state, other->status, other->n);
  tl_compare(dk, ref, other, &th, &path);
  printf("state %d %-28s theta %.2e rad  contact %.2e m\n", state, what, th, path);
  CHECK(th <= LIMIT && path <= LIMIT, "%s: state %d: theta %.3g, contact point %.3g", what, state,
        th, path);
}

int main(void) {
  gsl_set_error_handler_off();
  const double states[][RED_NSTATE] = {
      {1.2, 0.3, 2.0, -8.0, 0.1, 0.0, 0.0, 0.0},
      {M_PI / 2 + 0.3, -0.5, -3.0, 12.0, 0.0, 0.7, 0.2, -0.1},
      {0.9, 0.0, 4.0, 3.0, 1.0, 0.5, 0.0, 0.0},
      {1.5, 0.8, 0.5, 20.0, -2.0, 0.0, 1.0, 1.0},
  };
  const double disks[][2] = {{0.25, 0.5}, {0.3, 0.05}};
  for (size_t d = 0; d < 2; d++) {
    red_disk dk = tl_disk(disks[d][0], disks[d][1]);
    for (int s = 0; s < 4; s++) {
      const double *y0 = states[s];
      tl_traj ref = tl_run_form(&dk, 0, &red_gsl_rk8pd, 1e-13, y0, 10.0, 0.01);
      CHECK(ref.status == DV_OK && ref.n == 1001, "reference run: status %d", ref.status);
      const struct {
        int form;
        const red_stepper_type *T;
        const char *what;
      } others[] = {
          {0, &red_cvode_adams, "reduced, CVODE Adams"},
          {0, &red_arkode_fehlberg13, "reduced, ARKODE Fehlberg13"},
          {0, &red_gsl_rk8pd_stepped, "reduced, GSL rk8pd stepped"},
          {1, &red_gsl_rk8pd, "momentum (3.67), GSL"},
          {2, &red_gsl_rk8pd_stepped, "Lagrange multipliers, GSL"},
          {2, &red_gsl_rk8pd, "Lagrange multipliers, GSL dense"},
      };
      for (size_t k = 0; k < sizeof others / sizeof others[0]; k++) {
        /* the global error is up to ~1e5 rtol on these runs: rtol 1e-14 for 1e-8 */
        tl_traj tr = tl_run_form(&dk, others[k].form, others[k].T, 1e-14, y0, 10.0, 0.01);
        compare(&dk, &ref, &tr, others[k].what, s);
        tl_free(&tr);
      }
      tl_free(&ref);
    }
  }
  /* the constraints hold along the multiplier form (index-reduced: drift only) */
  red_disk dk = tl_disk(0.25, 0.5);
  double q[RED_LAGRANGE_DIM], res[2];
  red_lagrange_from_state(&dk, states[0], q);
  red_lagrange_constraints(&dk, q, res);
  CHECK(fabs(res[0]) < 1e-15 && fabs(res[1]) < 1e-15, "initial constraint residual %g %g", res[0],
        res[1]);
  return TEST_RESULT();
}
