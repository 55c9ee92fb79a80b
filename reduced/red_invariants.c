/* red_invariants: f1, f2 from hypergeometric functions (GSL), checked by
 * tests/reduced/test_invariants (conservation along CVODE and GSL trajectories). */
#include "red_invariants.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sf_hyperg.h>
#include <math.h>

/* within this of lying flat the basis comes from its equation, not from 2F1 (rad) */
#define BASIS_EDGE 0.06
/* the tame equation in s needs a few hundred steps even at theta = 1e-300 */
#define BASIS_MAX_STEPS 100000

double red_legendre_k(const red_disk *dk) {
  const double mr2 = dk->m * dk->r * dk->r;
  return dk->C * mr2 / (dk->A * (dk->C + mr2));
}

/* F(a + shift, b + shift; c; z) with a, b = (1 +- gamma)/4 */
static int hyp(double k, double shift, double c, double z, double *out) {
  gsl_sf_result r;
  const double disc = 1.0 - 4.0 * k;
  int status;
  if (disc >= 0.0) {
    const double g = sqrt(disc);
    status = gsl_sf_hyperg_2F1_e(0.25 * (1.0 + g) + shift, 0.25 * (1.0 - g) + shift, c, z, &r);
  } else {
    status = gsl_sf_hyperg_2F1_conj_e(0.25 + shift, 0.25 * sqrt(-disc), c, z, &r);
  }
  *out = r.val;
  return status == GSL_SUCCESS && isfinite(r.val) ? 0 : -1;
}

/* the basis from GSL's hypergeometric functions, where they converge */
static int basis_hypergeometric(const red_disk *dk, double th, double u[2], double du[2]) {
  const double s = sin(th), x = cos(th), z = x * x, q = dk->m * dk->r * dk->r / dk->A;
  const double k = red_legendre_k(dk);
  if (!(s > 0.0)) return -1;
  if (k == 0.0) { /* C = 0: the closed forms of thesis (4.8) */
    u[0] = 1.0;
    du[0] = 0.0;
    u[1] = q * log(tan(0.5 * th));
    du[1] = q / s;
    return 0;
  }
  double F0, F1, G0, G1;
  if (hyp(k, 0.0, 0.5, z, &F0) || hyp(k, 1.0, 1.5, z, &F1) || hyp(k, 0.5, 1.5, z, &G0) ||
      hyp(k, 1.5, 2.5, z, &G1))
    return -1;
  /* dF/dz = (a b / c) F(a+1, b+1; c+1; z), a b = k/4, dz/dtheta = -2 s x */
  u[0] = F0;
  du[0] = -k * s * x * F1;
  /* (a+1/2)(b+1/2) = k/4 + 1/2 */
  u[1] = -q * x * G0;
  du[1] = q * s * (G0 + 2.0 * z * (2.0 / 3.0) * (0.25 * k + 0.5) * G1);
  return 0;
}

/* in s = log tan(theta/2) the equation rho'' = k rho - cot(theta) rho' reads
 * d2rho/ds2 = k sech^2(s) rho, tame up to lying flat (s -> +-inf) where theta
 * steps would shrink with the distance to it: y = (u1, du1/ds, u2, du2/ds) */
static int legendre_s(double s, const double y[], double dy[], void *params) {
  const double k = *(const double *)params, sech = 1.0 / cosh(s), ks2 = k * sech * sech;
  dy[0] = y[1];
  dy[1] = ks2 * y[0];
  dy[2] = y[3];
  dy[3] = ks2 * y[2];
  return GSL_SUCCESS;
}

/* near lying flat, where F(a, b; c; z) at z = cos^2 -> 1 has logarithmic terms
 * (c - a - b = 0 or -1) that GSL's 2F1 refuses: the basis at the edge of
 * BASIS_EDGE carried to th by the equation it solves (rk8pd, GSL) */
static int basis_near_flat(const red_disk *dk, double th, double u[2], double du[2]) {
  const double th0 = th < M_PI_2 ? BASIS_EDGE : M_PI - BASIS_EDGE;
  const double s0 = log(tan(0.5 * th0)), s1 = log(tan(0.5 * th));
  double y[4], k = red_legendre_k(dk);
  if (basis_hypergeometric(dk, th0, u, du)) return -1;
  /* d/ds = sin(theta) d/dtheta */
  y[0] = u[0], y[1] = sin(th0) * du[0], y[2] = u[1], y[3] = sin(th0) * du[1];
  gsl_odeiv2_system sys = {legendre_s, NULL, 4, &k};
  gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd,
                                                       s1 < s0 ? -1e-3 : 1e-3, 1e-14, 1e-14);
  if (!d) return -1;
  gsl_odeiv2_driver_set_nmax(d, BASIS_MAX_STEPS);
  double s = s0;
  const int status = gsl_odeiv2_driver_apply(d, &s, s1, y);
  gsl_odeiv2_driver_free(d);
  const double sn = sin(th);
  u[0] = y[0], du[0] = y[1] / sn, u[1] = y[2], du[1] = y[3] / sn;
  return status == GSL_SUCCESS && isfinite(du[0] + du[1] + u[0] + u[1]) ? 0 : -1;
}

int red_rho_basis(const red_disk *dk, double th, double u[2], double du[2]) {
  if (!(sin(th) > 0.0)) return -1;
  if (red_legendre_k(dk) != 0.0 && (th < BASIS_EDGE || th > M_PI - BASIS_EDGE))
    return basis_near_flat(dk, th, u, du);
  return basis_hypergeometric(dk, th, u, du);
}

int red_invariants(const red_disk *dk, const double y[RED_NSTATE], double *f1, double *f2) {
  const double mr2 = dk->m * dk->r * dk->r, th = y[RED_TH], s = sin(th);
  double u[2], du[2];
  if (red_rho_basis(dk, th, u, du)) return -1;
  const double rho = (dk->C + mr2) * (y[RED_VPS] + y[RED_VPH] * cos(th));
  const double drho = mr2 * y[RED_VPH] * s;
  /* Wronskian u1 u2' - u2 u1' = (m r^2 / A) / sin(theta) (Abel; value at pi/2) */
  const double w = mr2 / (dk->A * s);
  *f1 = (rho * du[1] - drho * u[1]) / w;
  *f2 = (u[0] * drho - du[0] * rho) / w;
  return 0;
}

int red_rates_from_invariants(const red_disk *dk, double th, double f1, double f2, double *v_phi,
                              double *v_psi) {
  const double mr2 = dk->m * dk->r * dk->r, s = sin(th);
  double u[2], du[2];
  if (red_rho_basis(dk, th, u, du)) return -1;
  *v_phi = (f1 * du[0] + f2 * du[1]) / (mr2 * s);
  *v_psi = (f1 * u[0] + f2 * u[1]) / (dk->C + mr2) - *v_phi * cos(th);
  return 0;
}
