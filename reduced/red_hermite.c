/* red_hermite: Hermite interpolation through step ends (GSL divided differences). */
#include "red_hermite.h"

#include <gsl/gsl_poly.h>
#include <string.h>

void red_hermite_init(red_hermite *h, size_t dim, const red_node *const *nodes, size_t n) {
  double t[RED_HERMITE_NODES], y[RED_HERMITE_NODES], f[RED_HERMITE_NODES];
  h->dim = dim;
  h->n = n;
  for (size_t k = 0; k < n; k++) t[k] = nodes[k]->t;
  for (size_t i = 0; i < dim; i++) {
    for (size_t k = 0; k < n; k++) {
      y[k] = nodes[k]->y[i];
      f[k] = nodes[k]->f[i];
    }
    gsl_poly_dd_hermite_init(h->dd[i], h->z, t, y, f, n);
  }
}

double red_hermite_eval_one(const red_hermite *h, size_t i, double t) {
  return gsl_poly_dd_eval(h->dd[i], h->z, 2 * h->n, t);
}

void red_hermite_eval(const red_hermite *h, double t, double *y) {
  for (size_t i = 0; i < h->dim; i++) y[i] = red_hermite_eval_one(h, i, t);
}

int red_node_step(gsl_odeiv2_step *method, const gsl_odeiv2_system *sys, const red_node *start,
                  double t, double *y) {
  double yerr[RED_MAX_DIM], f[RED_MAX_DIM];
  memcpy(y, start->y, sys->dimension * sizeof(double));
  memcpy(f, start->f, sys->dimension * sizeof(double));
  gsl_odeiv2_step_reset(method);
  return gsl_odeiv2_step_apply(method, start->t, t - start->t, y, yerr, f, NULL, sys);
}
