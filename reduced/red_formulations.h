/* red_formulations: two independent formulations of the same motion, used
 * to cross-check the reduced equations (tests/reduced/test_formulations).
 *
 * Momentum form (thesis 3.58 / 3.67), state (theta, rho_theta, rho_phi,
 * rho_psi, phi, psi, x, y):
 *   rho_theta = (A + m r^2) v_th
 *   rho_phi   = (C + m r^2)(v_ps + v_ph c) c + A v_ph s^2
 *   rho_psi   = (C + m r^2)(v_ps + v_ph c)
 *
 * Lagrange-multiplier form (Pars): Lagrange's equations on the whole
 * configuration q = (x, y, theta, phi, psi) with the two rolling constraints
 *   cos(phi) x' + sin(phi) y' - r s theta' = 0
 *  -sin(phi) x' + cos(phi) y' + r c phi' + r psi' = 0
 * enforced by multipliers that a linear solve eliminates at every
 * evaluation; state (q, q'), 10 components.
 */
#ifndef RED_FORMULATIONS_H
#define RED_FORMULATIONS_H

#include "red_disk.h"

#define RED_LAGRANGE_DIM 10

/* momentum state from a reduced state, and back */
void red_momentum_from_state(const red_disk *disk, const double y[RED_NSTATE],
                             double p[RED_NSTATE]);
void red_state_from_momentum(const red_disk *disk, const double p[RED_NSTATE],
                             double y[RED_NSTATE]);

/* right-hand side of the momentum form (3.67); params is a red_disk */
int red_momentum_rhs(double t, const double *p, double *f, void *params);

/* Lagrange state (x, y, theta, phi, psi and their rates) from a reduced state, and back */
void red_lagrange_from_state(const red_disk *disk, const double y[RED_NSTATE],
                             double q[RED_LAGRANGE_DIM]);
void red_state_from_lagrange(const double q[RED_LAGRANGE_DIM], double y[RED_NSTATE]);

/* right-hand side of the multiplier form; params is a red_disk */
int red_lagrange_rhs(double t, const double *q, double *f, void *params);

/* residuals of the two velocity constraints (m/s) */
void red_lagrange_constraints(const red_disk *disk, const double q[RED_LAGRANGE_DIM],
                              double res[2]);

#endif
