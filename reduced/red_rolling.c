/* red_rolling: the thick rolling disk in Newton-Euler form. */
#include "red_rolling.h"
#include "red_vec3.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_roots.h>
#include <math.h>
#include <string.h>

const char *const red_rolling_event_names[] = {"theta_low", "theta_high", "normal_force",
                                               "friction", "upright"};

/* the upright line: |cos theta| and |theta'| / sqrt(g / r) below this */
#define UPRIGHT_LINE 1e-9

typedef struct frame {
  double s, c, sign;               /* sin, cos of theta; the side in [-1, 1] (see header) */
  double n[3], t[3], d[3], rho[3]; /* unit vectors and contact vector */
} frame;

/* the frame with rho = r d - h side n */
static void frame_on_side(const red_rolling *rr, const double *st, double side, frame *f) {
  const double sp = sin(st[RR_PH]), cp = cos(st[RR_PH]);
  f->s = sin(st[RR_TH]);
  f->c = cos(st[RR_TH]);
  f->sign = side;
  const double n[3] = {f->s * cp, f->s * sp, f->c}, t[3] = {sp, -cp, 0.0};
  const double d[3] = {f->c * cp, f->c * sp, -f->s};
  for (int i = 0; i < 3; i++) {
    f->n[i] = n[i];
    f->t[i] = t[i];
    f->d[i] = d[i];
    f->rho[i] = rr->disk.r * d[i] - rr->h * f->sign * n[i];
  }
}

/* how the disk touches the ground */
enum { ON_CORNER = 0, ON_LINE_BALANCED, ON_LINE_TIPPING };

static double contact_side(const red_rolling *rr, const double *st, int *how);

static void make_frame(const red_rolling *rr, const double *st, frame *f) {
  frame_on_side(rr, st, contact_side(rr, st, NULL), f);
}

/* theta', phi', psi' from omega */
static void angle_rates(const frame *f, const double w[3], double rates[3]) {
  const double wn = red_dot(w, f->n), s2 = f->s * f->s;
  rates[0] = -red_dot(w, f->t);
  rates[1] = (w[2] - wn * f->c) / s2;
  rates[2] = (wn - w[2] * f->c) / s2;
}

/* omega' and F in the frame f of the contact */
static int dynamics_in_frame(const red_rolling *rr, const double *st, const frame *frame_of_contact,
                             double wdot[3], double force[3]) {
  const red_disk *dk = &rr->disk;
  const double *w = st + RR_WX, m = dk->m;
  const frame f = *frame_of_contact;
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

/* omega' and F with the contact on the given side */
static int dynamics_on_side(const red_rolling *rr, const double *st, double side, double wdot[3],
                            double force[3]) {
  frame f;
  frame_on_side(rr, st, side, &f);
  return dynamics_in_frame(rr, st, &f, wdot, force);
}

typedef struct side_probe {
  const red_rolling *rr;
  const double *st;
  int status;
} side_probe;

/* theta'' = -(omega'.t + omega.t'), t' = phi' (cos phi, sin phi, 0), with the contact on side */
static double tilt_acceleration(double side, void *p) {
  side_probe *q = p;
  const double *st = q->st, *w = st + RR_WX;
  double wdot[3], rates[3];
  frame f;
  frame_on_side(q->rr, st, side, &f);
  if (dynamics_on_side(q->rr, st, side, wdot, NULL)) {
    q->status = -1;
    return 0.0;
  }
  angle_rates(&f, w, rates);
  const double tdot[3] = {rates[1] * cos(st[RR_PH]), rates[1] * sin(st[RR_PH]), 0.0};
  return -(red_dot(wdot, f.t) + red_dot(w, tdot));
}

/* the side where theta'' = 0, between the corners' a (side 1) and b (side -1) */
static double balancing_side(side_probe *q, double a, double b) {
  if (a == 0.0) return 1.0;
  if (b == 0.0) return -1.0;
  gsl_function fn = {tilt_acceleration, q};
  gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  double side = 0.0;
  if (!s || gsl_root_fsolver_set(s, &fn, -1.0, 1.0)) {
    if (s) gsl_root_fsolver_free(s);
    return 0.0; /* the straight-rolling balance, by symmetry */
  }
  for (int iter = 0; iter < 100 && !q->status; iter++) {
    if (gsl_root_fsolver_iterate(s)) break;
    side = gsl_root_fsolver_root(s);
    const double lo = gsl_root_fsolver_x_lower(s), hi = gsl_root_fsolver_x_upper(s);
    if (gsl_root_test_interval(lo, hi, 1e-16, 0.0) == GSL_SUCCESS) break;
  }
  gsl_root_fsolver_free(s);
  return side;
}

/* Where the disk rests on a rim corner: sign(cos theta). Exactly upright
 * (theta = pi/2 and theta' = 0 to UPRIGHT_LINE) a thick disk stands on the
 * line across its rim: the contact force acts at rho = r d - h side n, side
 * in [-1, 1], wherever keeps theta'' = 0; where no point of the line can,
 * the disk tips onto the corner that way, smoothly (no impact). *how (may
 * be NULL) is one of ON_*. */
static double contact_side(const red_rolling *rr, const double *st, int *how) {
  const double c = cos(st[RR_TH]), sign = c >= 0.0 ? 1.0 : -1.0;
  int ignored;
  if (!how) how = &ignored;
  *how = ON_CORNER;
  if (!(rr->h > 0.0) || fabs(c) > UPRIGHT_LINE) return sign;
  const double *w = st + RR_WX, t[3] = {sin(st[RR_PH]), -cos(st[RR_PH]), 0.0};
  if (fabs(red_dot(w, t)) > UPRIGHT_LINE * sqrt(rr->disk.g / rr->disk.r)) return sign;
  side_probe q = {rr, st, 0};
  const double a = tilt_acceleration(1.0, &q), b = tilt_acceleration(-1.0, &q);
  if (q.status) return sign;
  *how = ON_LINE_TIPPING;
  if (a < 0.0 && b < 0.0) return 1.0; /* tips towards cos theta > 0 */
  if (a > 0.0 && b > 0.0) return -1.0;
  *how = ON_LINE_BALANCED;
  if (a >= 0.0 && b <= 0.0) return balancing_side(&q, a, b);
  *how = ON_CORNER;
  return sign;
}

int red_rolling_tilt_acceleration(const red_rolling *rr, const double y[RED_NSTATE], double *thdd) {
  double st[RR_NSTATE];
  red_rolling_from_state(rr, y, st);
  side_probe q = {rr, st, 0};
  *thdd = tilt_acceleration(contact_side(rr, st, NULL), &q);
  return q.status;
}

int red_rolling_dynamics(const red_rolling *rr, const double *st, double wdot[3], double force[3]) {
  return dynamics_on_side(rr, st, contact_side(rr, st, NULL), wdot, force);
}

static int rolling_rhs(double t, const double *st, double *out, void *p) {
  const red_rolling *rr = p;
  frame f;
  double rates[3], v[3];
  int how;
  const double side = contact_side(rr, st, &how);
  if (dynamics_on_side(rr, st, side, out + RR_WX, NULL)) return -1;
  frame_on_side(rr, st, side, &f);
  angle_rates(&f, st + RR_WX, rates);
  red_cross(st + RR_WX, f.rho, v); /* v_G = -omega x rho */
  /* on the upright line theta stays pi/2: a theta' within UPRIGHT_LINE is rounding */
  out[RR_TH] = how == ON_LINE_BALANCED ? 0.0 : rates[0];
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
  frame_on_side(rr, st, 1.0, &f); /* rates need no contact */
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

/* cos theta; tipping off the upright line its sign is the corner's, which
 * it has where it leaves the line: leaving the line is no impact */
static double upright(double t, const double *st, void *p) {
  int how;
  const double side = contact_side(p, st, &how);
  return how == ON_LINE_TIPPING ? side * UPRIGHT_LINE : cos(st[RR_TH]);
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
  frame_on_side(rr, st, 1.0, &f); /* omega is not set yet: n and t need no contact */
  for (int i = 0; i < 3; i++)
    st[RR_WX + i] = y[RED_VPH] * (i == 2) - y[RED_VTH] * f.t[i] + y[RED_VPS] * f.n[i];
}

void red_rolling_to_state(const double *st, double y[RED_NSTATE]) {
  const red_rolling dummy = {{1.0, 1.0, 1.0, 1.0, 0.0}, 0.0, 0.0, 0.0, {0}};
  frame f;
  double rates[3];
  frame_on_side(&dummy, st, 1.0, &f);
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

static double energy_in_frame(const red_rolling *rr, const double *st, const frame *fp) {
  const red_disk *dk = &rr->disk;
  const double *w = st + RR_WX;
  const frame f = *fp;
  double v[3];
  red_cross(w, f.rho, v);
  const double wn = red_dot(w, f.n);
  const double rot = dk->A * red_dot(w, w) + (dk->C - dk->A) * wn * wn;
  return 0.5 * dk->m * red_dot(v, v) + 0.5 * rot - dk->m * dk->g * f.rho[2];
}

double red_rolling_energy(const red_rolling *rr, const double *st) {
  frame f;
  make_frame(rr, st, &f);
  return energy_in_frame(rr, st, &f);
}

static void contact_in_frame(const double *st, const frame *f, double p[2]) {
  p[0] = st[RR_X] + f->rho[0];
  p[1] = st[RR_Y] + f->rho[1];
}

void red_rolling_contact_point(const red_rolling *rr, const double *st, double p[2]) {
  frame f;
  make_frame(rr, st, &f);
  contact_in_frame(st, &f, p);
}

int red_rolling_observe(const red_rolling *rr, const double *st, double p[2], double *energy,
                        double omega_dot[3], double force[3]) {
  frame f;
  make_frame(rr, st, &f);
  contact_in_frame(st, &f, p);
  *energy = energy_in_frame(rr, st, &f);
  return dynamics_in_frame(rr, st, &f, omega_dot, force);
}
