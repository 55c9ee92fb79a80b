/* test_collider_bullet: Bullet's collider on the engine's shape, pose by pose.
 *
 * Over a grid of poses (theta on both sides of upright, every heading and
 * spin), the thin disk (h = 0) and two cylinders (h 2 mm, 20 mm) are placed
 * 1e-6 m into the plane z = 0. Bullet's narrow phase must find the body's
 * lowest point of the closed form (dv_pose.h: the rim point P = G + r d, or
 * the rim corner G + r d - h sign(n.z) n) at that depth, and placed 1e-6 m
 * above it, no point inside the ground. The margin is 0: with Bullet's
 * default 0.04 m the rim would be rounded and the disk would sink. */
#include <math.h>
#include <stdio.h>

#include "bullet_contact.h"
#include "dv_pose.h"
#include "dv_test.h"

#define DEPTH 1e-6 /* m */

/* Measured with DV_TEST_MEASURE=1 over the grid (864 poses): the point 2.8e-16 m
 * from the closed form, the distance 2.9e-17 m from -DEPTH (double precision);
 * a grid of 2760 poses gave 3.2e-16 and 3.2e-17 at 3x the time (59 s under ASan) */
#define POINT_TOL 1e-12
#define DEPTH_TOL 1e-12

static void check_pose(double r, double h, const double y[RED_NSTATE], double shift) {
  const dv_geometry g = {DV_SHAPE_CYLINDER, r, h};
  dv_pose pose;
  dv_pose_from_state(&g, y, &pose);
  double lowest[3], slip;
  dv_pose_lowest_point(&g, &pose, lowest, &slip);
  pose.pos[2] += shift;
  lowest[2] += shift;
  double p[3], distance;
  const int n = dv_bullet_contact(r, h, pose.R, pose.pos, p, &distance);
  if (shift < 0.0) {
    CHECK(n >= 1, "h %g theta %g phi %g psi %g: %d points", h, y[RED_TH], y[RED_PH], y[RED_PS], n);
    if (n < 1) return;
    CHECK_NEAR(hypot(hypot(p[0] - lowest[0], p[1] - lowest[1]), p[2] - lowest[2]), 0.0, POINT_TOL,
               "the deepest point from the closed form's");
    CHECK_NEAR(distance, shift, DEPTH_TOL, "its depth");
  } else {
    CHECK(n >= 0 && (n == 0 || distance > 0.0), "h %g theta %g: %d points above, %g m", h,
          y[RED_TH], n, distance);
  }
}

int main(void) {
  const double r = 0.1, halves[] = {0.0, 0.002, 0.02};
  int poses = 0;
  for (size_t k = 0; k < sizeof halves / sizeof halves[0]; k++)
    for (int i = 1; i < 24; i += 2) {
      const double theta = M_PI * i / 24.0 + 0.013; /* never exactly upright */
      for (int j = 0; j < 8; j++)
        for (int l = 0; l < 3; l++) {
          const double y[RED_NSTATE] = {theta,     0, 0, 0, 2 * M_PI * j / 8 + 0.1,
                                        1.3 * l, 0.2 * j - 0.7, 0.3 * l - 0.5};
          check_pose(r, halves[k], y, -DEPTH);
          check_pose(r, halves[k], y, +DEPTH);
          poses++;
        }
    }
  printf("%d poses, each below and above the plane\n", poses);
  return TEST_RESULT();
}
