/* test_shadow: the shadow's spreads (run_shadow.h) on runs moved off a
 * reference by known amounts. The reference nutates, theta = 0.9 + 0.5
 * cos(2 pi t / T0), while its contact point rolls along x at 1 m/s:
 *   - theta + 1e-3 t and the contact 2e-3 t off the path sideways: spreads of
 *     1e-3 t rad and 2e-3 t m, the phase (along the path) none;
 *   - the contact 0.05 m ahead along the path: 0.05 m of path and of phase;
 *   - a period 0.02 s longer, ending at 4 s: its k-th turn lags 0.01 k s, the
 *     lag spread their running maximum, and every spread infinite past its end.
 * The spreads are running maxima; directions' spreads add up. */
#include <math.h>
#include <string.h>

#include "dv_test.h"
#include "run_shadow.h"

#define DT 0.005
#define DURATION 8.0
#define T0 1.7413 /* off the sample grid */

/* the nutation of period T to t_end, theta offset by slope t, the contact at
 * (t + ahead, side t) */
static void run(dv_traj *tr, double T, double t_end, double slope, double ahead, double side) {
  const double k = 2 * M_PI / T;
  for (int i = 0; i * DT <= t_end + 1e-9; i++) {
    const double t = i * DT;
    dv_sample s;
    memset(&s, 0, sizeof s);
    s.t = t;
    s.y[RED_TH] = 0.9 + 0.5 * cos(k * t) + slope * t;
    s.y[RED_VTH] = -0.5 * k * sin(k * t) + slope;
    s.contact[0] = t + ahead;
    s.contact[1] = side * t;
    dv_run_traj_push(tr, &s);
  }
}

int main(void) {
  dv_traj ref = {0}, off = {0}, ahead = {0}, slow = {0};
  run(&ref, T0, DURATION, 0.0, 0.0, 0.0);
  run(&off, T0, DURATION, 1e-3, 0.0, 2e-3);
  run(&ahead, T0, DURATION, 0.0, 0.05, 0.0);
  run(&slow, T0 + 0.02, 4.0, 0.0, 0.0, 0.0);
  dv_shadow a, b, c, all;
  CHECK(!dv_shadow_alloc(&a, ref.n) && !dv_shadow_alloc(&b, ref.n) &&
            !dv_shadow_alloc(&c, ref.n) && !dv_shadow_alloc(&all, ref.n),
        "alloc");
  CHECK(!dv_shadow_add_run(&a, &off, &ref) && !dv_shadow_add_run(&b, &ahead, &ref) &&
            !dv_shadow_add_run(&c, &slow, &ref),
        "add");
  double worst[4] = {0, 0, 0, 0};
  for (size_t i = 0; i < ref.n; i++) {
    const double t = ref.s[i].t;
    worst[0] = fmax(worst[0], fabs(a.env[DV_SHADOW_THETA][i] - 1e-3 * t));
    worst[1] = fmax(worst[1], fabs(a.env[DV_SHADOW_PATH][i] - 2e-3 * t));
    /* sideways off a straight path: on it, at the same arc (1e-15 m, rounding) */
    worst[2] = fmax(worst[2], a.env[DV_SHADOW_PHASE][i]);
    if (i) /* ahead along the path: 0.05 m of both (the first sample: the phase starts at 0) */
      worst[3] = fmax(worst[3], fmax(fabs(b.env[DV_SHADOW_PATH][i] - 0.05),
                                     fabs(b.env[DV_SHADOW_PHASE][i] - 0.05)));
  }
  CHECK(worst[0] < 1e-12 && worst[1] < 1e-12, "theta, path spreads off by %g, %g", worst[0],
        worst[1]);
  CHECK(worst[2] < 1e-9, "a sideways offset moved the phase by %g m", worst[2]);
  CHECK(worst[3] < 1e-9, "0.05 m ahead: off by %g", worst[3]);
  CHECK(b.env[DV_SHADOW_LAG][ref.n - 1] < 1e-7 && a.env[DV_SHADOW_THETA][0] == 0.0,
        "no lag ahead on the path (%g), no theta spread at the start",
        b.env[DV_SHADOW_LAG][ref.n - 1]);
  /* the slow run: its k-th turn lags 0.01 k s (the reference's turns every T0 / 2,
   * 1.25e-8 s off, the Hermite interpolant); past 4 s every spread is infinite */
  for (size_t i = 0; i < ref.n; i++) {
    const double t = ref.s[i].t;
    if (t <= 4.0 + 1e-9) {
      /* turns of both runs by 4 s: the reference's 4th at 3.48 s, its own at 3.52 s */
      const double turns = t < 3.4826 ? floor(t / (T0 / 2) + 1e-9) : 4.0;
      CHECK(fabs(c.env[DV_SHADOW_LAG][i] - 0.01 * turns) < 1e-7, "lag at %g s: %g, want %g", t,
            c.env[DV_SHADOW_LAG][i], 0.01 * turns);
    } else {
      CHECK(isinf(c.env[DV_SHADOW_THETA][i]) && isinf(c.env[DV_SHADOW_PATH][i]) &&
                isinf(c.env[DV_SHADOW_PHASE][i]) && isinf(c.env[DV_SHADOW_LAG][i]),
            "past the run's end at %g s: %g %g %g %g", t, c.env[0][i], c.env[1][i], c.env[2][i],
            c.env[3][i]);
    }
    if (t > 4.0 + 1e-9) break;
  }
  /* two directions' spreads together: their sum, sample by sample (b moves no theta) */
  dv_shadow_sum(&all, &a);
  dv_shadow_sum(&all, &b);
  const size_t at = (size_t)(2.0 / DT);
  CHECK(all.env[DV_SHADOW_PATH][at] == a.env[DV_SHADOW_PATH][at] + b.env[DV_SHADOW_PATH][at] &&
            all.env[DV_SHADOW_THETA][at] == a.env[DV_SHADOW_THETA][at],
        "sum at 2 s: %g %g", all.env[DV_SHADOW_PATH][at], all.env[DV_SHADOW_THETA][at]);
  dv_shadow_clear(&all);
  CHECK(all.env[DV_SHADOW_PATH][at] == 0.0 && all.env[DV_SHADOW_LAG][ref.n - 1] == 0.0,
        "cleared: %g", all.env[DV_SHADOW_PATH][at]);
  /* the spread at a time: the reference's first sample at or after it */
  CHECK(dv_shadow_at(&a, &ref, DV_SHADOW_THETA, 2.0012) == a.env[DV_SHADOW_THETA][at + 1],
        "at 2.0012 s: %g", dv_shadow_at(&a, &ref, DV_SHADOW_THETA, 2.0012));
  CHECK(dv_shadow_at(&a, &ref, DV_SHADOW_THETA, 99.0) == a.env[DV_SHADOW_THETA][ref.n - 1],
        "past the end: the last");
  /* the errors past t_end are not measured */
  double e0[1700], e1[1700], e2[1700], *err[3] = {e0, e1, e2};
  CHECK(ref.n <= 1700 && !dv_shadow_errors(&off, &ref, 1.0, err), "errors");
  CHECK(fabs(e0[at / 2] - 1e-3) < 1e-12 && isnan(e0[at / 2 + 1]) && isnan(e1[at]),
        "to 1 s: %g, then %g", e0[at / 2], e0[at / 2 + 1]);
  dv_shadow_free(&a), dv_shadow_free(&b), dv_shadow_free(&c), dv_shadow_free(&all);
  dv_run_traj_free(&ref), dv_run_traj_free(&off), dv_run_traj_free(&ahead),
      dv_run_traj_free(&slow);
  return TEST_RESULT();
}
