/* red_hermite: the Hermite interpolant through y and y' at up to
 * RED_HERMITE_NODES step ends, degree 2n - 1 in every component (GSL's
 * divided differences, gsl_poly_dd_hermite_init). With four nodes it is
 * degree 7, the dense output of the 8th-order steppers (red_step_gsl.c) and
 * of a recorded period (red_period.c); and one step of the method from a
 * step end, for a time the interpolant does not cover to the method's accuracy. */
#ifndef RED_HERMITE_H
#define RED_HERMITE_H

#include <gsl/gsl_odeiv2.h>
#include <stddef.h>

#include "red_solver.h"

#define RED_HERMITE_NODES 4

/* a step end: time, y and y' */
typedef struct red_node {
  double t, y[RED_MAX_DIM], f[RED_MAX_DIM];
} red_node;

typedef struct red_hermite {
  size_t dim, n;                                 /* components, nodes */
  double dd[RED_MAX_DIM][2 * RED_HERMITE_NODES]; /* divided differences */
  double z[2 * RED_HERMITE_NODES];
} red_hermite;

/* the interpolant through nodes[0..n-1] (1 <= n <= RED_HERMITE_NODES, times increasing) */
void red_hermite_init(red_hermite *h, size_t dim, const red_node *const *nodes, size_t n);

/* y at t, every component */
void red_hermite_eval(const red_hermite *h, double t, double *y);

/* component i at t */
double red_hermite_eval_one(const red_hermite *h, size_t i, double t);

/* y at t by one step of method from the step end start (no interpolation
 * error: a step no longer than the one taken from there is within its
 * tolerance); returns GSL's status */
int red_node_step(gsl_odeiv2_step *method, const gsl_odeiv2_system *sys, const red_node *start,
                  double t, double *y);

#endif
