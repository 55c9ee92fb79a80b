/* dv_pose: the DESIGN section 1 mapping, both ways; checked by
 * tests/engines/test_pose (round trip, rim point at rest, equal energies). */
#include "dv_pose.h"
#include "red_vec3.h"

#include <math.h>
#include <string.h>

/* body axis k (column k of R) */
static void axis(const double R[9], int k, double v[3]) {
  v[0] = R[k];
  v[1] = R[3 + k];
  v[2] = R[6 + k];
}

void dv_geometry_contact_vector(const dv_geometry *g, const double R[9], double rho[3]) {
  double n[3];
  axis(R, 2, n);
  const double c = n[2], s = sqrt(fmax(0.0, 1.0 - c * c));
  if (g->shape == DV_SHAPE_ELLIPSOID) {
    /* support point in -ez of the ellipsoid diag(r, r, e): -E^2 u / |E u|, u = R^T ez */
    const double u[3] = {R[6], R[7], R[8]};
    const double E2[3] = {g->radius * g->radius, g->radius * g->radius,
                          g->half_thickness * g->half_thickness};
    const double norm = sqrt(E2[0] * u[0] * u[0] + E2[1] * u[1] * u[1] + E2[2] * u[2] * u[2]);
    double b[3];
    for (int i = 0; i < 3; i++) b[i] = -E2[i] * u[i] / norm;
    for (int i = 0; i < 3; i++)
      rho[i] = R[3 * i] * b[0] + R[3 * i + 1] * b[1] + R[3 * i + 2] * b[2];
    return;
  }
  /* d = (cos(theta) n - ez) / sin(theta) */
  const double sg = (c > 0.0) - (c < 0.0);
  for (int i = 0; i < 3; i++) {
    const double d = (s > 0.0) ? (c * n[i] - (i == 2)) / s : 0.0;
    rho[i] = g->radius * d - g->half_thickness * sg * n[i];
  }
}

/* rho.z: -|E u| for the ellipsoid, -(r sin(theta) + h |cos(theta)|) for the cylinder */
double dv_geometry_contact_height(const dv_geometry *g, const double R[9]) {
  const double c = R[8];
  if (g->shape == DV_SHAPE_ELLIPSOID)
    return -sqrt(g->radius * g->radius * (R[6] * R[6] + R[7] * R[7]) +
                 g->half_thickness * g->half_thickness * c * c);
  return -g->radius * sqrt(fmax(0.0, 1.0 - c * c)) - g->half_thickness * fabs(c);
}

void dv_pose_from_state(const dv_geometry *g, const double y[RED_NSTATE], dv_pose *p) {
  const double th = y[RED_TH], ph = y[RED_PH], ps = y[RED_PS];
  const double s = sin(th), c = cos(th), sp = sin(ph), cp = cos(ph);
  const double a[3] = {cp, sp, 0.0}, t[3] = {sp, -cp, 0.0};
  const double d[3] = {c * a[0], c * a[1], -s}, n[3] = {s * a[0], s * a[1], c};
  const double cs = cos(ps), ss = sin(ps);
  for (int i = 0; i < 3; i++) {
    p->R[3 * i + 0] = cs * t[i] + ss * d[i];
    p->R[3 * i + 1] = -ss * t[i] + cs * d[i];
    p->R[3 * i + 2] = n[i];
  }
  for (int i = 0; i < 3; i++)
    p->omega[i] = y[RED_VPH] * (i == 2) - y[RED_VTH] * t[i] + y[RED_VPS] * n[i];
  double rho[3], w_rho[3];
  dv_geometry_contact_vector(g, p->R, rho);
  red_cross(p->omega, rho, w_rho);
  for (int i = 0; i < 3; i++) p->vel[i] = -w_rho[i];
  p->pos[0] = y[RED_X];
  p->pos[1] = y[RED_Y];
  p->pos[2] = -rho[2];
}

/* the value of angle nearest prev, modulo 2 pi */
static double unwrap(double angle, double prev) {
  return angle + 2.0 * M_PI * round((prev - angle) / (2.0 * M_PI));
}

void dv_state_from_pose(const dv_pose *p, const double *prev, double y[RED_NSTATE]) {
  double n[3], x1[3];
  axis(p->R, 2, n);
  axis(p->R, 0, x1);
  const double c = fmax(-1.0, fmin(1.0, n[2])), th = acos(c), s = sin(th);
  const double ph = atan2(n[1], n[0]);
  const double a[3] = {cos(ph), sin(ph), 0.0}, t[3] = {a[1], -a[0], 0.0};
  const double d[3] = {c * a[0], c * a[1], -s};
  const double ps = atan2(red_dot(x1, d), red_dot(x1, t));
  const double wz = p->omega[2], wn = red_dot(p->omega, n), s2 = s * s;
  y[RED_TH] = th;
  y[RED_VTH] = -red_dot(p->omega, t);
  y[RED_VPH] = (wz - wn * c) / s2;
  y[RED_VPS] = (wn - wz * c) / s2;
  y[RED_PH] = prev ? unwrap(ph, prev[RED_PH]) : ph;
  y[RED_PS] = prev ? unwrap(ps, prev[RED_PS]) : ps;
  y[RED_X] = p->pos[0];
  y[RED_Y] = p->pos[1];
}

double dv_pose_energy(const red_disk *dk, const dv_pose *p) {
  double n[3];
  axis(p->R, 2, n);
  /* I = A 1 + (C - A) n n^T */
  const double wn = red_dot(p->omega, n);
  const double rot = dk->A * red_dot(p->omega, p->omega) + (dk->C - dk->A) * wn * wn;
  return 0.5 * dk->m * red_dot(p->vel, p->vel) + 0.5 * rot + dk->m * dk->g * p->pos[2];
}

void dv_pose_lowest_point(const dv_geometry *g, const dv_pose *p, double pt[3], double *slip) {
  double rho[3], w_rho[3], v[3];
  dv_geometry_contact_vector(g, p->R, rho);
  red_cross(p->omega, rho, w_rho);
  for (int i = 0; i < 3; i++) {
    pt[i] = p->pos[i] + rho[i];
    v[i] = p->vel[i] + w_rho[i];
  }
  *slip = sqrt(red_dot(v, v));
}

void dv_quat_to_matrix(const double q[4], double R[9]) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
  R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
  R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
}

void dv_matrix_to_quat(const double R[9], double q[4]) {
  const double tr = R[0] + R[4] + R[8];
  const double c[4] = {1 + tr, 1 + R[0] - R[4] - R[8], 1 - R[0] + R[4] - R[8],
                       1 - R[0] - R[4] + R[8]}; /* 4 w^2, 4 x^2, 4 y^2, 4 z^2 */
  int k = 0;
  for (int i = 1; i < 4; i++)
    if (c[i] > c[k]) k = i;
  const double s = 0.5 / sqrt(c[k]);
  const double wx = (R[7] - R[5]) * s, wy = (R[2] - R[6]) * s, wz = (R[3] - R[1]) * s;
  const double xy = (R[1] + R[3]) * s, xz = (R[2] + R[6]) * s, yz = (R[5] + R[7]) * s;
  const double big = 0.5 * sqrt(c[k]);
  const double out[4][4] = {
      {big, wx, wy, wz}, {wx, big, xy, xz}, {wy, xy, big, yz}, {wz, xz, yz, big}};
  const double sign = out[k][0] < 0 ? -1.0 : 1.0;
  for (int i = 0; i < 4; i++) q[i] = sign * out[k][i];
}
