/* red_rolling: the thick rolling disk in Newton-Euler form. */
#include "red_rolling.h"
#include "red_vec3.h"

#include <gsl/gsl_linalg.h>
#include <math.h>
#include <string.h>

const char *const red_rolling_event_names[] = {"theta_low", "theta_high", "normal_force",
                                               "friction", "upright"};

typedef struct frame {
  double s, c, sign;               /* sin, cos of theta; sign(cos theta) */
  double n[3], t[3], d[3], rho[3]; /* unit vectors and contact vector */
} frame;

static void make_frame(const red_rolling *rr, const double *st, frame *f) {
  const double sp = sin(st[RR_PH]), cp = cos(st[RR_PH]);
  f->s = sin(st[RR_TH]);
  f->c = cos(st[RR_TH]);
  f->sign = f->c >= 0.0 ? 1.0 : -1.0;
  const double n[3] = {f->s * cp, f->s * sp, f->c}, t[3] = {sp, -cp, 0.0};
  const double d[3] = {f->c * cp, f->c * sp, -f->s};
  for (int i = 0; i < 3; i++) {
    f->n[i] = n[i];
    f->t[i] = t[i];
    f->d[i] = d[i];
    f->rho[i] = rr->disk.r * d[i] - rr->h * f->sign * n[i];
  }
}

/* theta', phi', psi' from omega */
static void angle_rates(const frame *f, const double w[3], double rates[3]) {
  const double wn = red_dot(w, f->n), s2 = f->s * f->s;
  rates[0] = -red_dot(w, f->t);
  rates[1] = (w[2] - wn * f->c) / s2;
  rates[2] = (wn - w[2] * f->c) / s2;
}

int red_rolling_dynamics(const red_rolling *rr, const double *st, double wdot[3], double force[3]) {
  const red_disk *dk = &rr->disk;
  const double *w = st + RR_WX, m = dk->m;
  frame f;
  make_frame(rr, st, &f);
  if (!(f.s > 0.0)) return -1;
  double rates[3], ndot[3], rdot[3];
  angle_rates(&f, w, rates);
  red_cross(w, f.n, ndot);
  for (int i = 0; i < 3; i++) {
    const double ddot = -rates[0] * f.n[i] - f.c * rates[1] * f.t[i];
    rdot[i] = dk->r * ddot - rr->h * f.sign * ndot[i];
  }
  /* I omega, and the right-hand side -omega x I omega + m rho x (g ez - omega x rho') */
  const double wn = red_dot(w, f.n), rr2 = red_dot(f.rho, f.rho);
  double Iw[3], wIw[3], w_rdot[3], q[3], rq[3], rhs[3], M[9];
  for (int i = 0; i < 3; i++) Iw[i] = dk->A * w[i] + (dk->C - dk->A) * wn * f.n[i];
  red_cross(w, Iw, wIw);
  red_cross(w, rdot, w_rdot);
  for (int i = 0; i < 3; i++) q[i] = (i == 2 ? dk->g : 0.0) - w_rdot[i];
  red_cross(f.rho, q, rq);
  for (int i = 0; i < 3; i++) {
    rhs[i] = -wIw[i] + m * rq[i];
    for (int j = 0; j < 3; j++)
      M[3 * i + j] = (dk->C - dk->A) * f.n[i] * f.n[j] + m * (-f.rho[i] * f.rho[j]) +
                     (i == j ? dk->A + m * rr2 : 0.0);
  }
  gsl_matrix_view Mv = gsl_matrix_view_array(M, 3, 3);
  gsl_vector_view b = gsl_vector_view_array(rhs, 3), x = gsl_vector_view_array(wdot, 3);
  /* M is symmetric positive definite: A > 0 and the rest is semi-definite */
  if (gsl_linalg_cholesky_decomp1(&Mv.matrix) ||
      gsl_linalg_cholesky_solve(&Mv.matrix, &b.vector, &x.vector))
    return -1;
  if (force) {
    /* F = m (a_G + g ez), a_G = -omega' x rho - omega x rho' */
    double wd_rho[3];
    red_cross(wdot, f.rho, wd_rho);
    for (int i = 0; i < 3; i++) force[i] = m * (-wd_rho[i] - w_rdot[i] + (i == 2 ? dk->g : 0.0));
  }
  return isfinite(wdot[0] + wdot[1] + wdot[2]) ? 0 : -1;
}

static int rolling_rhs(double t, const double *st, double *out, void *p) {
  const red_rolling *rr = p;
  frame f;
  double rates[3], v[3];
  if (red_rolling_dynamics(rr, st, out + RR_WX, NULL)) return -1;
  make_frame(rr, st, &f);
  angle_rates(&f, st + RR_WX, rates);
  red_cross(st + RR_WX, f.rho, v); /* v_G = -omega x rho */
  out[RR_TH] = rates[0];
  out[RR_PH] = rates[1];
  out[RR_PS] = rates[2];
  out[RR_X] = -v[0];
  out[RR_Y] = -v[1];
  return 0;
}

static double frequency(const double *st, void *p) {
  const red_rolling *rr = p;
  frame f;
  double rates[3];
  make_frame(rr, st, &f);
  angle_rates(&f, st + RR_WX, rates);
  return sqrt(rr->disk.g / rr->disk.r) + fabs(rates[0]) + fabs(rates[1]) + fabs(rates[2]);
}

static double theta_low(double t, const double *st, void *p) {
  return st[RR_TH] - ((const red_rolling *)p)->theta_limit;
}

static double theta_high(double t, const double *st, void *p) {
  return (M_PI - ((const red_rolling *)p)->theta_limit) - st[RR_TH];
}

static double normal_force(double t, const double *st, void *p) {
  double wd[3], F[3];
  return red_rolling_dynamics(p, st, wd, F) ? NAN : F[2];
}

static double friction_margin(double t, const double *st, void *p) {
  const red_rolling *rr = p;
  double wd[3], F[3];
  if (red_rolling_dynamics(rr, st, wd, F)) return NAN;
  return rr->mu * F[2] - hypot(F[0], F[1]);
}

static double upright(double t, const double *st, void *p) {
  return cos(st[RR_TH]);
}

void red_rolling_init(red_rolling *rr, const red_disk *disk, double h, double mu,
                      double theta_limit) {
  rr->disk = *disk;
  rr->h = h;
  rr->mu = mu;
  rr->theta_limit = theta_limit;
  rr->sys = (red_system){RR_NSTATE,
                         rolling_rhs,
                         rr,
                         frequency,
                         h > 0.0 ? 5 : 4,
                         {theta_low, theta_high, normal_force, friction_margin, upright},
                         {"theta_low", "theta_high", "normal_force", "friction", "upright"}};
}

void red_rolling_from_state(const red_rolling *rr, const double y[RED_NSTATE], double *st) {
  frame f;
  st[RR_TH] = y[RED_TH];
  st[RR_PH] = y[RED_PH];
  st[RR_PS] = y[RED_PS];
  st[RR_X] = y[RED_X];
  st[RR_Y] = y[RED_Y];
  make_frame(rr, st, &f);
  for (int i = 0; i < 3; i++)
    st[RR_WX + i] = y[RED_VPH] * (i == 2) - y[RED_VTH] * f.t[i] + y[RED_VPS] * f.n[i];
}

void red_rolling_to_state(const double *st, double y[RED_NSTATE]) {
  const red_rolling dummy = {{1.0, 1.0, 1.0, 1.0, 0.0}, 0.0, 0.0, 0.0, {0}};
  frame f;
  double rates[3];
  make_frame(&dummy, st, &f);
  angle_rates(&f, st + RR_WX, rates);
  y[RED_TH] = st[RR_TH];
  y[RED_VTH] = rates[0];
  y[RED_VPH] = rates[1];
  y[RED_VPS] = rates[2];
  y[RED_PH] = st[RR_PH];
  y[RED_PS] = st[RR_PS];
  y[RED_X] = st[RR_X];
  y[RED_Y] = st[RR_Y];
}

double red_rolling_energy(const red_rolling *rr, const double *st) {
  const red_disk *dk = &rr->disk;
  const double *w = st + RR_WX;
  frame f;
  double v[3];
  make_frame(rr, st, &f);
  red_cross(w, f.rho, v);
  const double wn = red_dot(w, f.n);
  const double rot = dk->A * red_dot(w, w) + (dk->C - dk->A) * wn * wn;
  return 0.5 * dk->m * red_dot(v, v) + 0.5 * rot - dk->m * dk->g * f.rho[2];
}

void red_rolling_contact_point(const red_rolling *rr, const double *st, double p[2]) {
  frame f;
  make_frame(rr, st, &f);
  p[0] = st[RR_X] + f.rho[0];
  p[1] = st[RR_Y] + f.rho[1];
}
