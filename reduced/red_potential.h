/* red_potential: the one-degree-of-freedom picture of the reduced motion.
 *
 * On a level set of f1, f2 the rates are functions of theta, and
 *
 *   E = 1/2 (A + m r^2) v_theta^2 + U(theta),
 *   U = rho_psi^2 / (2 (C + m r^2)) + A rho_psi'^2 / (2 (m r^2)^2) + m g r sin(theta)
 *
 * (thesis 3.82 with rho_phi - rho_psi cos = (A / m r^2) sin rho_psi').
 * theta oscillates between the turning points where U(theta) = E.
 */
#ifndef RED_POTENTIAL_H
#define RED_POTENTIAL_H

#include "dv_error.h"
#include "red_disk.h"

/* U(theta) for the integrals f1, f2 (J) */
int red_effective_potential(const red_disk *disk, double f1, double f2, double theta, double *U);

/* the interval [lo, hi] of theta reachable from y at its energy: turning points
 * found by Brent's method; an end that reaches theta_limit (the disk lies down
 * before turning) is reported as theta_limit or pi - theta_limit, with
 * *falls set. Returns DV_OK or < 0. */
int red_theta_range(const red_disk *disk, const double y[RED_NSTATE], double theta_limit,
                    double range[2], int *falls, dv_error *err);

/* the nutation between the turning points range (red_theta_range, not
 * falling) on the level set of y: its period T (s) and the advances of phi
 * and psi over it (rad), out = {T, dphi, dpsi}, as quadratures
 *
 *   T = 2 int dtheta / |theta'|,  dphi = 2 int v_phi dtheta / |theta'|, ...
 *   |theta'| = sqrt(2 (E - U(theta)) / (A + m r^2))
 *
 * with theta = mid - half cos(s), which removes the inverse square roots at
 * the ends, by a 256-point Gauss-Legendre rule (GSL). Near the turning points
 * E - U is the difference of two close numbers, so *resolution says how far
 * 128 points move the results (relative to T, and to 1 rad for the
 * advances): about 1e-9 for the hypergeometric U, 1e-11 at C = 0. Returns
 * DV_OK, or < 0 where the special functions fail or E - U falls to rounding
 * (a nutation too small to resolve). Near a separatrix E - U also nearly
 * vanishes inside the range, which the fixed rule does not resolve either:
 * *resolution then says so. */
int red_nutation(const red_disk *disk, const double y[RED_NSTATE], const double range[2],
                 double out[3], double *resolution, dv_error *err);

#endif
