/* test_turning: turning points and nutation periods (run_turning.h) on
 * synthetic nutations whose answers are known in closed form:
 * theta = c + a(t) cos(2 pi t / T), phi = w t. A longer period moves no
 * turning point and shows as the period and heading differences; a decaying
 * amplitude shows as the turning points; a run that stops nutating has
 * lost its periods; steady runs and contact-sized noise have no turns. */
#include <math.h>
#include <string.h>

#include "dv_test.h"
#include "run_turning.h"

#define DT 0.005
#define DURATION 8.0

/* theta = c + (a - decay t) cos(2 pi t / T) + noise sin(900 t), phi = w t, sampled every DT */
static void nutation(dv_traj *tr, double T, double a, double decay, double w, double noise) {
  const double c = 0.9, k = 2 * M_PI / T;
  for (double t = 0.0; t <= DURATION + 1e-9; t += DT) {
    dv_sample s;
    memset(&s, 0, sizeof s);
    s.t = t;
    const double amp = a - decay * t;
    s.y[RED_TH] = c + amp * cos(k * t) + noise * sin(900 * t);
    s.y[RED_VTH] = -decay * cos(k * t) - amp * k * sin(k * t) + 900 * noise * cos(900 * t);
    s.y[RED_PH] = w * t;
    s.y[RED_VPH] = w;
    dv_run_traj_push(tr, &s);
  }
}

int main(void) {
  dv_traj ref = {0}, slow = {0}, decaying = {0}, steady = {0}, noisy = {0};
  double v[3];
  nutation(&ref, 1.74, 0.5, 0.0, 0.7, 0.0);
  nutation(&slow, 1.76, 0.5, 0.0, 0.7, 0.0);      /* 0.02 s longer */
  nutation(&decaying, 1.74, 0.5, 0.001, 0.7, 0.0); /* loses 0.00174 rad a period */
  nutation(&steady, 1.74, 0.0, 0.0, 0.7, 0.0);
  nutation(&noisy, 1.74, 0.0, 0.0, 0.7, 1e-5); /* contact-sized wiggles, 1e-5 rad */

  dv_run_turning_compare(&ref, &ref, INFINITY, v);
  CHECK(v[0] < 1e-9 && v[1] < 1e-9 && v[2] < 1e-9, "itself: %g %g %g", v[0], v[1], v[2]);

  /* the turning points are found by Hermite interpolation: within 1e-7 rad of
   * c +- a although the samples miss them by up to a k^2 (DT/2)^2 / 2 = 2e-5 */
  dv_run_turning_compare(&slow, &ref, INFINITY, v);
  CHECK(v[0] < 1e-6, "a longer period moves no turning point: %g", v[0]);
  CHECK_NEAR(v[1], 0.02, 1e-5, "the period is 0.02 s longer");
  CHECK_NEAR(v[2], 0.7 * 0.02, 1e-5, "the heading advances 0.7 rad/s x 0.02 s more");

  /* turning points are paired by count: the k-th minimum at (k - 1/2) T
   * has amplitude a - 0.001 t; the largest difference is the last one inside 8 s */
  dv_run_turning_compare(&decaying, &ref, INFINITY, v);
  const double last = 0.001 * 1.74 * 4.0; /* the fourth maximum, t = 4 T = 6.96 s */
  const double last_min = 0.001 * 1.74 * 4.5; /* the fifth minimum, t = 4.5 T = 7.83 s */
  CHECK_NEAR(v[0], fmax(last, last_min), 2e-5, "decaying amplitude: turning error");
  CHECK(v[1] < 1e-4, "the decay barely moves the period: %g", v[1]);

  /* an engine that stops nutating has lost every period, and its missing turns
   * compare with its own extremes (0.9): the amplitude */
  dv_run_turning_compare(&steady, &ref, INFINITY, v);
  CHECK_NEAR(v[0], 0.5, 1e-9, "no turns where the reference turns");
  CHECK(isinf(v[1]) && isinf(v[2]), "lost periods: %g %g", v[1], v[2]);

  /* nothing turns: nothing to compare (not judged), whatever the noise */
  dv_run_turning_compare(&noisy, &steady, INFINITY, v);
  CHECK(isnan(v[0]) && isnan(v[1]) && isnan(v[2]), "steady: %g %g %g", v[0], v[1], v[2]);

  /* the window bounds the turns compared: to 2 s no period completes, to 4 s one */
  dv_run_turning_compare(&slow, &ref, 2.0, v);
  CHECK(isnan(v[1]) && v[0] < 1e-6, "no period in 2 s: %g", v[1]);
  dv_run_turning_compare(&slow, &ref, 4.0, v);
  CHECK_NEAR(v[1], 0.02, 1e-5, "one period in 4 s");
  CHECK_NEAR(dv_run_theta_rate_max(&ref, INFINITY), 0.5 * 2 * M_PI / 1.74, 1e-4, "fastest rate");

  /* a turn just inside the window, where the reference's comes just after
   * it: timing, not a turning point off (upright_unstable's MuJoCo: a minimum
   * at 1.94 s, the reference's past 2 s, was compared with its start, 0.024
   * rad away). Starting at a minimum whose swing shrinks 0.05 rad/s, the
   * start lies 0.085 rad below the faster run's first minimum at 1.70 s */
  dv_traj rising = {0}, rising_fast = {0};
  nutation(&rising, 1.74, -0.5, -0.05, 0.7, 0.0);
  nutation(&rising_fast, 1.70, -0.5, -0.05, 0.7, 0.0);
  dv_run_turning_compare(&rising_fast, &rising, 1.72, v);
  CHECK(v[0] < 2e-3, "a minimum the reference makes just past the window: %g", v[0]);
  dv_run_turning_compare(&rising_fast, &rising, 2.5, v);
  CHECK(v[0] < 2e-3, "both minima inside: %g", v[0]);

  dv_traj *all[] = {&ref, &slow, &decaying, &steady, &noisy, &rising, &rising_fast};
  for (size_t i = 0; i < 7; i++) dv_run_traj_free(all[i]);
  return TEST_RESULT();
}
