/* test_phase: the phase error along the reference's contact path
 * (run_phase.h) on paths whose answer is known: a circle run round 30 times
 * with the engine falling behind by 1.5 rad and by 3.1 rad (past half a round:
 * the walk keeps to the round it is on), an engine off the circle by a
 * radial offset (no phase), a straight roll with the engine ahead past the
 * reference's end, and the same value under a rigid motion and a scaling. */
#include <math.h>

#include "run_phase.h"
#include "dv_test.h"

#define N 20001
#define R 0.5
#define DA 0.01 /* rad between samples: the polyline's arc is short by DA^2/24 */

static double e[N][2], ref[N][2];

/* ref round a circle of radius R, 200 rad; e behind it by lag * i / (N - 1),
 * on a circle of radius R + dr */
static void circles(double lag, double dr) {
  for (int i = 0; i < N; i++) {
    const double a = DA * i, b = a - lag * i / (N - 1.0);
    ref[i][0] = R * cos(a), ref[i][1] = R * sin(a);
    e[i][0] = (R + dr) * cos(b), e[i][1] = (R + dr) * sin(b);
  }
}

/* x -> k (rotation by c x + shift) of both paths */
static void move(double c, double k, double sx, double sy) {
  double(*p[2])[2] = {e, ref};
  for (int j = 0; j < 2; j++)
    for (int i = 0; i < N; i++) {
      const double x = p[j][i][0], y = p[j][i][1];
      p[j][i][0] = k * (cos(c) * x - sin(c) * y) + sx;
      p[j][i][1] = k * (sin(c) * x + cos(c) * y) + sy;
    }
}

int main(void) {
  const double tol = R * 200 * DA * DA / 24 + 1e-9; /* the polyline's shortening over 200 rad */
  circles(1.5, 0.0);
  CHECK_NEAR(dv_run_phase_err(e, ref, N), 1.5 * R, tol, "1.5 rad behind after 32 rounds");
  move(0.7, 3.0, -2.0, 5.0);
  CHECK_NEAR(dv_run_phase_err(e, ref, N), 3.0 * 1.5 * R, 3.0 * tol, "rotated, shifted, scaled x3");
  circles(3.1, 0.0);
  CHECK_NEAR(dv_run_phase_err(e, ref, N), 3.1 * R, tol, "3.1 rad behind: past half a round");
  circles(0.0, 0.01);
  CHECK_NEAR(dv_run_phase_err(e, ref, N), 0.0, tol, "0.01 m outside the circle, in phase");
  for (int i = 0; i < N; i++) { /* a straight roll of 2 m, the engine 2% ahead */
    ref[i][0] = 2.0 * i / (N - 1.0), ref[i][1] = 0.0;
    e[i][0] = 1.02 * ref[i][0], e[i][1] = 1e-3;
  }
  CHECK_NEAR(dv_run_phase_err(e, ref, N), 0.04, 1e-12, "2% ahead on a straight roll");
  CHECK(dv_run_phase_err(e, ref, 1) == 0.0, "one sample: nothing compared");
  e[5][0] = NAN;
  CHECK_NEAR(dv_run_phase_err(e, ref, N), 0.04, 1e-12, "a NaN point is skipped");
  return TEST_RESULT();
}
