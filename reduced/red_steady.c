/* red_steady: steady circles, upright critical spin, linear stability.
 * Checked by tests/reduced/test_steady (steady circles stay steady, upright above
 * and below the critical spin). */
#include "red_steady.h"
#include "red_gsl_words.h"

#include <gsl/gsl_deriv.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

int red_steady_from_phi_dot(const red_disk *dk, double th, double vph, double *vps, dv_error *err) {
  const double s = sin(th), c = cos(th), mr2 = dk->m * dk->r * dk->r;
  if (!(vph != 0.0) || !isfinite(vph))
    return dv_fail(err, DV_EINPUT, "a steady motion needs phi_dot != 0");
  *vps =
      (dk->A * vph * vph * c * s - dk->m * dk->g * dk->r * c) / ((dk->C + mr2) * vph * s) - vph * c;
  return isfinite(*vps) ? DV_OK : dv_fail(err, DV_EINPUT, "no steady motion at this tilt");
}

int red_steady_from_radius(const red_disk *dk, double th, double R, double *vph, double *vps,
                           dv_error *err) {
  const double s = sin(th), c = cos(th), mr2 = dk->m * dk->r * dk->r;
  if (!(R > 0.0) || !isfinite(R)) return dv_fail(err, DV_EINPUT, "radius must be > 0");
  if (fabs(c) < 1e-12)
    return dv_fail(err, DV_EINPUT, "an upright disk rolls straight: no circle of finite radius");
  const double ratio = -copysign(R / dk->r, c); /* v_psi / v_phi */
  const double denom = s * (dk->A * c - (dk->C + mr2) * (ratio + c));
  const double vph2 = dk->m * dk->g * dk->r * c / denom;
  if (!(vph2 > 0.0) || !isfinite(vph2))
    return dv_fail(err, DV_EINPUT,
                   "no steady circle of radius %g m at theta %g rad: v_phi^2 would be %g", R, th,
                   vph2);
  *vph = sqrt(vph2);
  *vps = ratio * *vph;
  return DV_OK;
}

double red_upright_critical_spin(const red_disk *dk) {
  const double mr2 = dk->m * dk->r * dk->r;
  if (dk->C <= 0.0) return INFINITY;
  return sqrt(dk->m * dk->g * dk->r * dk->A / (dk->C * (dk->C + mr2)));
}

int red_is_steady(const red_disk *dk, const double y[RED_NSTATE], double tol) {
  double f[RED_NSTATE];
  const double w = sqrt(dk->g / dk->r) + fabs(y[RED_VPH]) + fabs(y[RED_VPS]);
  if (red_rhs(dk, y, f)) return 0;
  return fabs(y[RED_VTH]) <= tol * w && fabs(f[RED_VTH]) <= tol * w * w;
}

typedef struct column_ctx {
  const red_disk *disk;
  double y[RED_NSTATE];
  int col, row;
} column_ctx;

static double component(double v, void *p) {
  column_ctx *c = p;
  double y[RED_NSTATE], f[RED_NSTATE];
  memcpy(y, c->y, sizeof y);
  y[c->col] = v;
  if (red_rhs(c->disk, y, f)) return NAN;
  return f[c->row];
}

/* eigenvalues of the Jacobian by central differences of relative step hrel */
static int eigenvalues(const red_disk *dk, const double y[RED_NSTATE], double hrel,
                       double eig[RED_NREDUCED][2], dv_error *err) {
  enum { N = RED_NREDUCED };
  double jac[N * N];
  column_ctx ctx = {dk, {0}, 0, 0};
  memcpy(ctx.y, y, sizeof ctx.y);
  gsl_function fn = {component, &ctx};
  for (ctx.row = 0; ctx.row < N; ctx.row++) {
    for (ctx.col = 0; ctx.col < N; ctx.col++) {
      double d, abserr;
      const double h = hrel * fmax(1.0, fabs(y[ctx.col]));
      gsl_deriv_central(&fn, y[ctx.col], h, &d, &abserr);
      if (!isfinite(d)) return dv_fail(err, DV_ENUMERIC, "Jacobian is not finite");
      jac[ctx.row * N + ctx.col] = d;
    }
  }
  gsl_matrix_view J = gsl_matrix_view_array(jac, N, N);
  gsl_vector_complex *ev = gsl_vector_complex_alloc(N);
  gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc(N);
  int status = (ev && w) ? gsl_eigen_nonsymm(&J.matrix, ev, w) : GSL_ENOMEM;
  for (int i = 0; status == GSL_SUCCESS && i < N; i++) {
    gsl_complex z = gsl_vector_complex_get(ev, (size_t)i);
    eig[i][0] = GSL_REAL(z);
    eig[i][1] = GSL_IMAG(z);
  }
  if (w) gsl_eigen_nonsymm_free(w);
  if (ev) gsl_vector_complex_free(ev);
  return status ? dv_fail(err, DV_ENUMERIC, "eigenvalues: %s", red_gsl_words(status)) : DV_OK;
}

int red_linear_stability(const red_disk *dk, const double y[RED_NSTATE],
                         double eig[RED_NREDUCED][2], int *stable, dv_error *err) {
  const int status = eigenvalues(dk, y, 1e-4, eig, err);
  if (status) return status;
  double big = 0.0, re_max = -INFINITY;
  for (int i = 0; i < RED_NREDUCED; i++) {
    big = fmax(big, hypot(eig[i][0], eig[i][1]));
    re_max = fmax(re_max, eig[i][0]);
  }
  *stable = re_max <= 1e-6 * fmax(big, 1e-300);
  return DV_OK;
}

double red_eigen_uncertainty(const red_disk *dk, const double y[RED_NSTATE],
                             const double eig[RED_NREDUCED][2]) {
  double other[RED_NREDUCED][2], u = 0.0;
  if (eigenvalues(dk, y, 2e-4, other, NULL)) return NAN;
  for (int i = 0; i < RED_NREDUCED; i++) { /* each to its nearest at the other step */
    double near = INFINITY;
    for (int k = 0; k < RED_NREDUCED; k++)
      near = fmin(near, hypot(eig[i][0] - other[k][0], eig[i][1] - other[k][1]));
    u = fmax(u, near);
  }
  return u;
}
