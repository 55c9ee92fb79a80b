/* test_pose: the state <-> pose mapping of DESIGN section 1: round trip,
 * the rim point at rest, the lowest point on the ground, equal energies. */
#include <math.h>

#include "dv_pose.h"
#include "dv_test.h"
#include "red_rolling.h"

static const double STATES[][RED_NSTATE] = {
    {1.2, 0.3, 2.0, -8.0, 0.1, 0.4, 0.5, -0.2},
    {M_PI / 2 + 0.3, -0.5, -3.0, 12.0, -2.0, 3.0, 0.2, -0.1},
    {0.2, 1.0, 0.5, 3.0, 3.1, -3.1, 0.0, 0.0},
    {2.9, 0.0, -4.0, 0.0, 1.0, 2.0, 0.0, 0.0},
    {M_PI / 2 - 1e-3, 0.0, 0.0, 20.0, 0.0, 0.0, 0.0, 0.0},
};

/* elementary rotations about z and y, and a product, row-major */
static void rot_z(double a, double *m) {
  const double c = cos(a), s = sin(a), r[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
  for (int i = 0; i < 9; i++) m[i] = r[i];
}

static void rot_y(double a, double *m) {
  const double c = cos(a), s = sin(a), r[9] = {c, 0, s, 0, 1, 0, -s, 0, c};
  for (int i = 0; i < 9; i++) m[i] = r[i];
}

static void mat_mul(const double *a, const double *b, double *out) {
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      out[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
}

/* Every bound here is rounding. The largest |diff| over the states of main,
 * measured with DV_TEST_MEASURE=1 ./tests/test_pose: the round trip 5.7e-15
 * (0.04 of 1e-13 (1 + |y|)), det R 2.2e-16, the lowest point's z and slip 0,
 * Rz Ry Rz 5.1e-16, the reduced contact point 3.9e-17 m, the contact height
 * 2.8e-17 m, the energy 8.9e-16 J (0.02 of 1e-14 |E|), the ellipsoid 0. */
static void check_state(const double y[RED_NSTATE], const dv_geometry *g, const char *label) {
  const red_disk dk = red_disk_uniform(0.1, 1.0, 9.81);
  dv_pose p;
  double back[RED_NSTATE], pt[3], slip;
  dv_pose_from_state(g, y, &p);
  dv_state_from_pose(&p, y, back);
  for (int i = 0; i < RED_NSTATE; i++)
    CHECK_NEAR(back[i], y[i], 1e-13 * (1.0 + fabs(y[i])), label);
  /* the body frame is a rotation: orthonormal, right-handed */
  double det = p.R[0] * (p.R[4] * p.R[8] - p.R[5] * p.R[7]) -
               p.R[1] * (p.R[3] * p.R[8] - p.R[5] * p.R[6]) +
               p.R[2] * (p.R[3] * p.R[7] - p.R[4] * p.R[6]);
  CHECK_NEAR(det, 1.0, 1e-14, label);
  dv_pose_lowest_point(g, &p, pt, &slip);
  CHECK_NEAR(pt[2], 0.0, 1e-15, label);
  CHECK_NEAR(slip, 0.0, 1e-13, label);
  /* independent of the mapping's own code: DESIGN's R = Rz(phi) Ry(theta)
   * Rz(psi - pi/2) from elementary rotations, and the pose's lowest point is the
   * reduced model's contact point */
  double Rz1[9], Ry[9], Rz2[9], T[9], R[9];
  rot_z(y[RED_PH], Rz1), rot_y(y[RED_TH], Ry), rot_z(y[RED_PS] - M_PI / 2, Rz2);
  mat_mul(Rz1, Ry, T), mat_mul(T, Rz2, R);
  for (int i = 0; i < 9; i++)
    CHECK_NEAR(p.R[i], R[i], 1e-14, label);
  if (g->shape == DV_SHAPE_CYLINDER && g->half_thickness == 0.0) {
    double pc[2];
    red_contact_point(&dk, y, pc);
    CHECK_NEAR(hypot(pt[0] - pc[0], pt[1] - pc[1]), 0.0, 1e-15, label);
  }
  /* the height the engines check every step is the contact vector's z */
  double rho[3];
  dv_geometry_contact_vector(g, p.R, rho);
  const double height = dv_geometry_contact_height(g, p.R);
  CHECK_NEAR(height, rho[2], 1e-15, label);
  if (g->shape == DV_SHAPE_CYLINDER) {
    red_rolling rr;
    double s[RR_NSTATE];
    red_rolling_init(&rr, &dk, g->half_thickness, 1.0, 0.01);
    red_rolling_from_state(&rr, y, s);
    const double e_ref = g->half_thickness == 0.0 ? red_energy(&dk, y) : red_rolling_energy(&rr, s);
    const double e = dv_pose_energy(&dk, &p);
    CHECK_NEAR(e, e_ref, 1e-14 * fabs(e_ref), label);
  } else {
    /* no point of the ellipsoid's surface lies below the support point */
    double lowest = INFINITY;
    for (int i = 0; i < 200; i++)
      for (int j = 0; j < 100; j++) {
        const double u = 2 * M_PI * i / 200, v = M_PI * (j + 0.5) / 100;
        const double b[3] = {g->radius * cos(u) * sin(v), g->radius * sin(u) * sin(v),
                             g->half_thickness * cos(v)};
        const double z = p.pos[2] + p.R[6] * b[0] + p.R[7] * b[1] + p.R[8] * b[2];
        lowest = fmin(lowest, z);
      }
    CHECK_NEAR(fmin(lowest, 0.0), 0.0, 1e-12, label);
  }
}

int main(void) {
  const dv_geometry geoms[] = {{DV_SHAPE_CYLINDER, 0.1, 0.0},
                               {DV_SHAPE_CYLINDER, 0.1, 0.002},
                               {DV_SHAPE_ELLIPSOID, 0.1, 0.002}};
  const char *names[] = {"thin", "cylinder h 2 mm", "ellipsoid e 2 mm"};
  for (size_t g = 0; g < 3; g++)
    for (size_t k = 0; k < sizeof STATES / sizeof STATES[0]; k++) {
      char label[64];
      snprintf(label, sizeof label, "%s, state %zu", names[g], k);
      check_state(STATES[k], &geoms[g], label);
    }
  return TEST_RESULT();
}
