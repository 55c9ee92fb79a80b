/* red_potential: effective potential and turning points of theta. Checked by
 * tests/reduced/test_limits against the extremes of integrated trajectories. */
#include "red_potential.h"
#include "red_gsl_words.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include "red_root.h"
#include <math.h>

#include "red_invariants.h"

int red_effective_potential(const red_disk *dk, double f1, double f2, double th, double *U) {
  const double mr2 = dk->m * dk->r * dk->r;
  double u[2], du[2];
  if (red_rho_basis(dk, th, u, du)) return -1;
  const double rho = f1 * u[0] + f2 * u[1], drho = f1 * du[0] + f2 * du[1];
  *U = rho * rho / (2.0 * (dk->C + mr2)) + dk->A * drho * drho / (2.0 * mr2 * mr2) +
       dk->m * dk->g * dk->r * sin(th);
  return isfinite(*U) ? 0 : -1;
}

typedef struct level_ctx {
  const red_disk *disk;
  double f1, f2, E;
} level_ctx;

static double excess(double th, void *p) {
  const level_ctx *c = p;
  double U;
  return red_effective_potential(c->disk, c->f1, c->f2, th, &U) ? NAN : U - c->E;
}

/* walk from th0 toward limit until U > E, then refine; *hit when never */
static int turning_point(gsl_function *fn, double th0, double limit, double *out, int *hit) {
  const int n = 2000;
  const double step = (limit - th0) / n;
  double a = th0;
  /* at rest in theta to rounding: th0 is its own turning point */
  if (!(GSL_FN_EVAL(fn, th0) < 0.0)) {
    *out = th0;
    return GSL_SUCCESS;
  }
  for (int i = 1; i <= n; i++) {
    const double b = (i == n) ? limit : th0 + i * step;
    const double gb = GSL_FN_EVAL(fn, b);
    if (!isfinite(gb)) return GSL_EDOM;
    if (gb > 0.0) return red_brent(fn, fmin(a, b), fmax(a, b), 1e-15, 1e-14, out);
    a = b;
  }
  *out = limit;
  *hit = 1;
  return GSL_SUCCESS;
}

int red_theta_range(const red_disk *dk, const double y[RED_NSTATE], double theta_limit,
                    double range[2], int *falls, dv_error *err) {
  level_ctx c = {dk, 0.0, 0.0, red_energy(dk, y)};
  const double th = y[RED_TH], mr2 = dk->m * dk->r * dk->r;
  if (red_invariants(dk, y, &c.f1, &c.f2))
    return dv_fail(err, DV_ENUMERIC, "invariants undefined at theta = %g", th);
  gsl_function fn = {excess, &c};
  *falls = 0;
  /* a state at rest in theta is its own turning point on the side where U rises */
  const double kin = 0.5 * (dk->A + mr2) * y[RED_VTH] * y[RED_VTH];
  const double scale = fabs(c.E) + dk->m * dk->g * dk->r;
  double dU = 0.0;
  const double h = 1e-6;
  dU = (excess(th + h, &c) - excess(th - h, &c)) / (2.0 * h);
  int lo_hit = 0, hi_hit = 0, status = GSL_SUCCESS;
  range[0] = range[1] = th;
  if (kin > 1e-13 * scale || dU > 1e-9 * scale)
    status = turning_point(&fn, th - ((kin > 1e-13 * scale) ? 0.0 : 1e-9), theta_limit, &range[0],
                           &lo_hit);
  if (status == GSL_SUCCESS && (kin > 1e-13 * scale || dU < -1e-9 * scale))
    status = turning_point(&fn, th + ((kin > 1e-13 * scale) ? 0.0 : 1e-9), M_PI - theta_limit,
                           &range[1], &hi_hit);
  if (status) return dv_fail(err, DV_ENUMERIC, "turning points: %s", red_gsl_words(status));
  *falls = lo_hit || hi_hit;
  return DV_OK;
}

typedef struct nutation_ctx {
  const red_disk *disk;
  double f1, f2, E, lo, hi;
  int rate; /* 0: 1 (the period), 1: v_phi, 2: v_psi */
  int failed;
} nutation_ctx;

/* 2 / |theta'| times the rate, times dtheta / ds = sqrt((theta - lo)(hi - theta)) */
static double nutation_integrand(double s, void *p) {
  nutation_ctx *c = p;
  const double th = 0.5 * (c->lo + c->hi) - 0.5 * (c->hi - c->lo) * cos(s);
  const double mr2 = c->disk->m * c->disk->r * c->disk->r;
  double U, v[2] = {1.0, 1.0};
  if (red_effective_potential(c->disk, c->f1, c->f2, th, &U) ||
      (c->rate && red_rates_from_invariants(c->disk, th, c->f1, c->f2, &v[0], &v[1]))) {
    c->failed = 1;
    return 0.0;
  }
  const double rate = c->rate ? v[c->rate - 1] : 1.0;
  if (!(c->E - U > 0.0)) c->failed = 1; /* rounding has crossed the turning point */
  return 2.0 * rate * sqrt((c->disk->A + mr2) * (th - c->lo) * (c->hi - th) / (2.0 * (c->E - U)));
}

/* the three quadratures with an n-point rule */
static int nutation_rule(nutation_ctx *c, size_t n, double out[3]) {
  gsl_integration_glfixed_table *t = gsl_integration_glfixed_table_alloc(n);
  if (!t) return DV_ESYSTEM;
  gsl_function fn = {nutation_integrand, c};
  for (c->rate = 0; c->rate < 3; c->rate++)
    out[c->rate] = gsl_integration_glfixed(&fn, 0.0, M_PI, t);
  gsl_integration_glfixed_table_free(t);
  return DV_OK;
}

int red_nutation(const red_disk *dk, const double y[RED_NSTATE], const double range[2],
                 double out[3], double *resolution, dv_error *err) {
  nutation_ctx c = {dk, 0.0, 0.0, red_energy(dk, y), range[0], range[1], 0, 0};
  double half[3];
  if (!(range[0] < range[1])) return dv_fail(err, DV_EINPUT, "no nutation: theta is steady");
  if (red_invariants(dk, y, &c.f1, &c.f2))
    return dv_fail(err, DV_ENUMERIC, "invariants undefined at theta = %g", y[RED_TH]);
  if (nutation_rule(&c, 256, out) || nutation_rule(&c, 128, half))
    return dv_fail(err, DV_ESYSTEM, "out of memory: the nutation quadrature's points");
  if (c.failed || !isfinite(out[0] + out[1] + out[2] + half[0] + half[1] + half[2]))
    return dv_fail(
        err, DV_ENUMERIC,
        "E - U(theta) is within the special functions' rounding near the turning points");
  *resolution = fabs(half[0] / out[0] - 1.0);
  for (int k = 1; k < 3; k++)
    *resolution = fmax(*resolution, fabs(half[k] - out[k]) / fmax(1.0, fabs(out[k])));
  return DV_OK;
}
