/* thick_coin_model SCENARIO OUTPUT_DT OUT.csv: an exact trajectory of a thick
 * coin computed independently of diskval's models, written in judge's pose
 * form (t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz) every OUTPUT_DT s.
 *
 * The model is not reduced/red_rolling.c's (world frame, the angles theta,
 * phi, psi as coordinates, the contact force eliminated by hand) nor
 * red_disk.c's (Pars's reduced equations). Here the body is a free rigid body
 * in the full 13-dimensional state: the centre G and its velocity (world
 * frame), the body-to-world quaternion q and the angular velocity w in the
 * body frame (principal moments A, A, C about the axis e3). The contact
 * point is parametrised in the body frame by u = R^T ez, the vertical seen
 * from the body: the rim corner nearest the ground is
 *
 *   rho_b(u) = -r (u_x, u_y, 0) / |(u_x, u_y)| - h sign(u_z) e3,
 *
 * and it slides over the body at rho_b' = d rho_b/du u', u' = u x w. Each
 * step solves the Newton-Euler equations with the contact force F (world) as
 * the multiplier of the rolling constraint v_G + R (w x rho_b) = 0,
 * differentiated once, a 9 x 9 linear system in (a_G, w', F), by GSL's LU:
 *
 *   m a_G - F                    = -m g ez
 *   I w' - rho_b x (R^T F)       = -w x I w
 *   a_G - R (rho_b x w')         = -R (w x (w x rho_b) + w x rho_b')
 *
 * q' = q (0, w) / 2; G' = v_G. Nothing holds the position constraint (the
 * corner's height 0) or the velocity constraint but the integration, so their
 * residuals, with the energy, check the model (gsl_odeiv2's rk8pd at 1e-13).
 * The start is the scenario's initial state (diskval's C API reads the
 * scenario: its disk and initial state, nothing else) turned into a pose by
 * the formulas of docs/judge.md: q = qz(phi) qy(theta)
 * qz(psi - pi/2), omega = phi' ez - theta' t + psi' n, v_G = -omega x rho.
 *
 * Prints the largest relative energy drift, no-slip residual (m/s), corner
 * height (m) and quaternion norm error; exit 0, or 1 when the energy drifts
 * more than 1e-10 relative or the residuals exceed 1e-10 m/s and 1e-10 m
 * (measured on tests/data/quarter_spun.ini: see check_judge_thick_model.sh). */
#include <diskval/diskval.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct coin {
  double r, h, m, A, C, g;
} coin;

static void cross(const double a[3], const double b[3], double o[3]) {
  o[0] = a[1] * b[2] - a[2] * b[1];
  o[1] = a[2] * b[0] - a[0] * b[2];
  o[2] = a[0] * b[1] - a[1] * b[0];
}

/* R (row-major, world = R body) of the unit quaternion of q (w, x, y, z) */
static void rotation(const double *q4, double R[9]) {
  const double n = sqrt(q4[0] * q4[0] + q4[1] * q4[1] + q4[2] * q4[2] + q4[3] * q4[3]);
  const double w = q4[0] / n, x = q4[1] / n, y = q4[2] / n, z = q4[3] / n;
  R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
  R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
  R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
}

static void mul(const double R[9], const double v[3], double o[3]) {
  for (int i = 0; i < 3; i++) o[i] = R[3 * i] * v[0] + R[3 * i + 1] * v[1] + R[3 * i + 2] * v[2];
}

static void mul_t(const double R[9], const double v[3], double o[3]) {
  for (int i = 0; i < 3; i++) o[i] = R[i] * v[0] + R[3 + i] * v[1] + R[6 + i] * v[2];
}

/* the contact vector in the body frame and its rate over the body, from u = R^T ez */
static void contact(const coin *k, const double u[3], const double w[3], double rho[3],
                    double rho_rate[3]) {
  const double s = hypot(u[0], u[1]);
  rho[0] = -k->r * u[0] / s, rho[1] = -k->r * u[1] / s;
  rho[2] = -k->h * ((u[2] > 0) - (u[2] < 0));
  double du[3];
  cross(u, w, du);
  const double pdp = u[0] * du[0] + u[1] * du[1];
  for (int i = 0; i < 2; i++) rho_rate[i] = -k->r * (du[i] / s - u[i] * pdp / (s * s * s));
  rho_rate[2] = 0.0;
}

/* state: G (0-2), v_G (3-5), q (6-9), w body (10-12) */
static int rhs(double t, const double y[], double f[], void *params) {
  (void)t;
  const coin *k = params;
  double R[9], u[3], rho[3], rr[3];
  const double *w = y + 10, ez[3] = {0, 0, 1};
  rotation(y + 6, R);
  mul_t(R, ez, u);
  contact(k, u, w, rho, rr);
  const double I[3] = {k->A, k->A, k->C};
  double Iw[3], wIw[3], wr[3], wwr[3], wrr[3], b[9], Mm[81] = {0};
  for (int i = 0; i < 3; i++) Iw[i] = I[i] * w[i];
  cross(w, Iw, wIw);
  cross(w, rho, wr);
  cross(w, wr, wwr);
  cross(w, rr, wrr);
  double c[3], Rc[3];
  for (int i = 0; i < 3; i++) c[i] = wwr[i] + wrr[i];
  mul(R, c, Rc);
  /* [rho]x: rho x v = X v */
  const double X[9] = {0, -rho[2], rho[1], rho[2], 0, -rho[0], -rho[1], rho[0], 0};
  for (int i = 0; i < 3; i++) {
    /* m a - F = -m g ez */
    Mm[9 * i + i] = k->m;
    Mm[9 * i + 6 + i] = -1.0;
    b[i] = -k->m * k->g * (i == 2);
    /* I w' - X R^T F = -w x I w */
    Mm[9 * (3 + i) + 3 + i] = I[i];
    for (int j = 0; j < 3; j++) { /* (X R^T)_ij = sum_l X_il R_jl */
      double xr = 0.0;
      for (int l = 0; l < 3; l++) xr += X[3 * i + l] * R[3 * j + l];
      Mm[9 * (3 + i) + 6 + j] = -xr;
    }
    b[3 + i] = -wIw[i];
    /* a - R X w' = -R (w x (w x rho) + w x rho') */
    Mm[9 * (6 + i) + i] = 1.0;
    for (int j = 0; j < 3; j++) {
      double rx = 0.0;
      for (int l = 0; l < 3; l++) rx += R[3 * i + l] * X[3 * l + j];
      Mm[9 * (6 + i) + 3 + j] = -rx;
    }
    b[6 + i] = -Rc[i];
  }
  gsl_matrix_view M = gsl_matrix_view_array(Mm, 9, 9);
  gsl_vector_view B = gsl_vector_view_array(b, 9);
  double z[9];
  gsl_vector_view Z = gsl_vector_view_array(z, 9);
  gsl_permutation *perm = gsl_permutation_alloc(9);
  int sign;
  gsl_linalg_LU_decomp(&M.matrix, perm, &sign);
  gsl_linalg_LU_solve(&M.matrix, perm, &B.vector, &Z.vector);
  gsl_permutation_free(perm);
  for (int i = 0; i < 3; i++) f[i] = y[3 + i], f[3 + i] = z[i], f[10 + i] = z[3 + i];
  const double *q = y + 6; /* q' = q (0, w) / 2 */
  f[6] = 0.5 * (-q[1] * w[0] - q[2] * w[1] - q[3] * w[2]);
  f[7] = 0.5 * (q[0] * w[0] + q[2] * w[2] - q[3] * w[1]);
  f[8] = 0.5 * (q[0] * w[1] + q[3] * w[0] - q[1] * w[2]);
  f[9] = 0.5 * (q[0] * w[2] + q[1] * w[1] - q[2] * w[0]);
  return GSL_SUCCESS;
}

/* the product a b of quaternions (w, x, y, z) */
static void qmul(const double a[4], const double b[4], double o[4]) {
  o[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  o[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  o[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  o[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* energy, no-slip residual |v_G + R (w x rho_b)| and corner height z_G + (R rho_b)_z */
static void measure(const coin *k, const double y[13], double *energy, double *slip,
                    double *height) {
  double R[9], u[3], rho[3], rr[3], wr[3], Rwr[3], Rrho[3];
  const double ez[3] = {0, 0, 1}, *w = y + 10;
  rotation(y + 6, R);
  mul_t(R, ez, u);
  contact(k, u, w, rho, rr);
  cross(w, rho, wr);
  mul(R, wr, Rwr);
  mul(R, rho, Rrho);
  const double v2 = y[3] * y[3] + y[4] * y[4] + y[5] * y[5];
  *energy = 0.5 * k->m * v2 + 0.5 * (k->A * (w[0] * w[0] + w[1] * w[1]) + k->C * w[2] * w[2]) +
            k->m * k->g * y[2];
  *slip = sqrt(pow(y[3] + Rwr[0], 2) + pow(y[4] + Rwr[1], 2) + pow(y[5] + Rwr[2], 2));
  *height = fabs(y[2] + Rrho[2]);
}

int main(int argc, char **argv) {
  if (argc < 4) return fprintf(stderr, "usage: thick_coin_model SCENARIO OUTPUT_DT OUT.csv\n"), 2;
  diskval_error err;
  diskval_scenario *sc;
  if (diskval_scenario_load(argv[1], NULL, 0, &sc, &err) < 0)
    return fprintf(stderr, "%s\n", err.msg), 2;
  diskval_disk d;
  diskval_state s0;
  diskval_scenario_disk(sc, &d);
  diskval_scenario_initial(sc, &s0);
  const double dt = atof(argv[2]), duration = diskval_scenario_duration(sc);
  diskval_scenario_free(sc);
  coin k = {d.radius, 0.5 * d.thickness, d.mass, d.A, d.C, d.gravity};
  /* the start: q = qz(phi) qy(theta) qz(psi - pi/2) */
  double y[13], qa[4], qb[4];
  const double a = 0.5 * s0.phi, b = 0.5 * s0.theta, c = 0.5 * (s0.psi - M_PI / 2);
  const double qz1[4] = {cos(a), 0, 0, sin(a)}, qy[4] = {cos(b), 0, sin(b), 0},
               qz2[4] = {cos(c), 0, 0, sin(c)};
  qmul(qz1, qy, qa);
  qmul(qa, qz2, qb);
  for (int i = 0; i < 4; i++) y[6 + i] = qb[i];
  double R[9], u[3], rho[3], rr[3], Rrho[3], omega[3], v[3];
  rotation(y + 6, R);
  const double ez[3] = {0, 0, 1}, n[3] = {R[2], R[5], R[8]};
  const double t_dir[3] = {sin(s0.phi), -cos(s0.phi), 0};
  for (int i = 0; i < 3; i++)
    omega[i] = s0.phi_dot * ez[i] - s0.theta_dot * t_dir[i] + s0.psi_dot * n[i];
  mul_t(R, omega, y + 10);
  mul_t(R, ez, u);
  contact(&k, u, y + 10, rho, rr);
  mul(R, rho, Rrho);
  cross(omega, Rrho, v);
  y[0] = s0.x, y[1] = s0.y, y[2] = -Rrho[2];
  for (int i = 0; i < 3; i++) y[3 + i] = -v[i];
  gsl_odeiv2_system sys = {rhs, NULL, 13, &k};
  gsl_odeiv2_driver *drv =
      gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-6, 1e-13, 1e-13);
  FILE *out = fopen(argv[3], "w");
  if (!out || !drv) return fprintf(stderr, "cannot write %s\n", argv[3]), 2;
  fprintf(out,
          "# the rolling cylinder, Newton-Euler in the body frame with the contact force as "
          "multiplier (tests/run/thick_coin_model.c)\n");
  fprintf(out, "t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n");
  double e0, slip, height, e_drift = 0, slip_max = 0, height_max = 0, qnorm_max = 0, t = 0;
  measure(&k, y, &e0, &slip, &height);
  int status = GSL_SUCCESS;
  for (long i = 0; status == GSL_SUCCESS; i++) {
    double ti = i * dt; /* the reference's sample times (the last one the duration) */
    if (fabs(ti - duration) <= 1e-9 * dt || ti > duration) ti = duration;
    if (ti > t) status = gsl_odeiv2_driver_apply(drv, &t, ti, y);
    if (status != GSL_SUCCESS) break;
    double e, w_world[3], q[4];
    measure(&k, y, &e, &slip, &height);
    e_drift = fmax(e_drift, fabs(e - e0) / e0);
    slip_max = fmax(slip_max, slip), height_max = fmax(height_max, height);
    const double qn = sqrt(y[6] * y[6] + y[7] * y[7] + y[8] * y[8] + y[9] * y[9]);
    qnorm_max = fmax(qnorm_max, fabs(qn - 1.0));
    for (int j = 0; j < 4; j++) q[j] = y[6 + j] / qn;
    rotation(q, R);
    mul(R, y + 10, w_world);
    fprintf(out,
            "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
            ti, y[0], y[1], y[2], q[0], q[1], q[2], q[3], y[3], y[4], y[5], w_world[0], w_world[1],
            w_world[2]);
    if (ti >= duration) break;
  }
  gsl_odeiv2_driver_free(drv);
  if (fclose(out) || status != GSL_SUCCESS)
    return fprintf(stderr, "integration failed at t = %g s\n", t), 2;
  printf(
      "energy drift %.3g (relative), no-slip residual %.3g m/s, corner height %.3g m, "
      "quaternion norm %.3g\n",
      e_drift, slip_max, height_max, qnorm_max);
  return e_drift <= 1e-10 && slip_max <= 1e-10 && height_max <= 1e-10 ? 0 : 1;
}
