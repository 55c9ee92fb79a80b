/* test_compare: the comparison metrics on synthetic trajectories whose
 * answers are known: a shifted circle, a time-delayed path (Hausdorff ~ 0
 * while the pointwise error is large), a constant theta offset, an energy
 * ripple, and a window cut short by the reference's end. */
#include <math.h>
#include <string.h>

#include "run_compare.h"
#include "dv_test.h"

#define N 2001

/* a contact point running on a circle of radius R about (cx, cy), phase lag */
static void circle(dv_traj *tr, double R, double cx, double cy, double lag, double theta,
                   size_t n) {
  for (size_t i = 0; i < n; i++) {
    dv_sample s;
    memset(&s, 0, sizeof s);
    s.t = 0.01 * (double)i;
    const double a = s.t - lag;
    s.contact[0] = cx + R * cos(a);
    s.contact[1] = cy + R * sin(a);
    s.y[RED_TH] = theta;
    s.energy = 2.0 * (1.0 + 1e-3 * sin(3.0 * s.t));
    s.slip = 0.25 * s.t;
    dv_run_traj_push(tr, &s);
  }
}

int main(void) {
  dv_traj ref = {0}, shifted = {0}, late = {0}, short_ref = {0};
  dv_metrics m;
  circle(&ref, 0.5, 0.0, 0.0, 0.0, 1.0, N);
  circle(&shifted, 0.5, 0.03, 0.04, 0.0, 1.0 + 1e-3, N); /* shift 0.05 m */
  circle(&late, 0.5, 0.0, 0.0, 0.3, 1.0, N);             /* 0.3 rad behind */

  dv_run_compare(&shifted, &ref, INFINITY, &m);
  CHECK_NEAR(m.value[DV_PATH_MAX_ERR], 0.05, 1e-12, "shifted: path max");
  CHECK_NEAR(m.value[DV_PATH_RMS_ERR], 0.05, 1e-12, "shifted: path rms");
  /* two circles of equal radius, centres 0.05 apart: Hausdorff 0.05 (sampled: within 1e-5) */
  CHECK_NEAR(m.value[DV_PATH_HAUSDORFF], 0.05, 1e-5, "shifted: Hausdorff");
  CHECK_NEAR(m.value[DV_THETA_MAX_ERR], 1e-3, 1e-15, "offset: theta max");
  CHECK_NEAR(m.value[DV_THETA_RMS_ERR], 1e-3, 1e-15, "offset: theta rms");
  /* E = 2 (1 + 1e-3 sin 3t): drift max |E - E0| / E0 = 1e-3 */
  CHECK_NEAR(m.value[DV_ENERGY_DRIFT], 1e-3, 1e-8, "energy drift");
  CHECK_NEAR(m.value[DV_SLIP_MAX], 0.25 * 20.0, 1e-12, "slip max");
  CHECK(m.n_window == N && m.t_window == 20.0, "window %zu %g", m.n_window, m.t_window);

  dv_run_compare(&late, &ref, INFINITY, &m);
  const double chord = 2.0 * 0.5 * sin(0.15); /* pointwise error of a 0.3 rad lag */
  CHECK_NEAR(m.value[DV_PATH_MAX_ERR], chord, 1e-12, "late: path max");
  /* the same curve: only the polyline's sagitta, R (1 - cos(0.005)) ~ 6e-6 */
  CHECK(m.value[DV_PATH_HAUSDORFF] < 1e-5, "late: Hausdorff %g", m.value[DV_PATH_HAUSDORFF]);
  CHECK(m.value[DV_PATH_HAUSDORFF] < 1e-3 * m.value[DV_PATH_MAX_ERR], "late: not timing-blind");

  /* the reference ends at t = 5 s: the window ends there too */
  circle(&short_ref, 0.5, 0.0, 0.0, 0.0, 1.0, 501);
  dv_run_compare(&shifted, &short_ref, INFINITY, &m);
  CHECK(m.n_window == 501 && m.t_window == 5.0, "short window %zu %g", m.n_window, m.t_window);
  dv_run_compare(&shifted, &ref, 2.0, &m);
  CHECK(m.n_window == 201, "t_end window %zu", m.n_window);

  /* polyline Hausdorff, directly: a segment against a point beside its middle */
  const double seg[2][2] = {{0, 0}, {1, 0}}, pt[1][2] = {{0.5, 0.2}};
  CHECK_NEAR(dv_run_hausdorff(seg, 2, pt, 1), hypot(0.5, 0.2), 1e-15, "segment vs point");
  CHECK_NEAR(dv_run_hausdorff(pt, 1, seg, 2), hypot(0.5, 0.2), 1e-15, "symmetric");

  dv_run_traj_free(&ref);
  dv_run_traj_free(&shifted);
  dv_run_traj_free(&late);
  dv_run_traj_free(&short_ref);
  return TEST_RESULT();
}
