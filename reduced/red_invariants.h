/* red_invariants: the two integrals f1, f2 of the reduced system.
 *
 * rho_psi = (C + m r^2)(v_psi + v_phi cos(theta)) obeys, as a function of
 * theta (thesis 3.72),
 *
 *   rho'' + cot(theta) rho' - k rho = 0,   k = C m r^2 / (A (C + m r^2)),
 *
 * with rho' = d rho / d theta = m r^2 v_phi sin(theta). With x = cos(theta) it
 * is Legendre's equation with nu (nu + 1) = -k; with z = x^2 it is the
 * hypergeometric equation with a + b = 1/2, a b = k/4, c = 1/2:
 *
 *   a, b = (1 +- gamma)/4,   gamma = sqrt(1 - 4 k)
 *
 * (the thesis's 3.74 drops the 4, and its 3.77 raises a, b by 1 where the
 * second solution needs 1/2). The basis used here is
 *
 *   u1 = F(a, b; 1/2; x^2),   u2 = -(m r^2 / A) x F(a + 1/2, b + 1/2; 3/2; x^2)
 *
 * and rho_psi(theta) = f1 u1 + f2 u2. gamma is real for k <= 1/4 (small C)
 * and imaginary otherwise (every ordinary disk: k = 4/3 for a uniform one),
 * where a, b are a complex-conjugate pair (gsl_sf_hyperg_2F1_conj). At C = 0,
 * u1 = 1 and u2 = (m r^2/A) ln tan(theta/2): f1 and f2 are then the thesis's
 * (4.9), f2 = rho_phi - rho_psi cos(theta) = A v_phi sin^2(theta).
 * Both f1 and f2 have units of angular momentum (kg m^2 / s).
 */
#ifndef RED_INVARIANTS_H
#define RED_INVARIANTS_H

#include "red_disk.h"

/* k = C m r^2 / (A (C + m r^2)) */
double red_legendre_k(const red_disk *disk);

/* the basis u1, u2 and their theta-derivatives at theta; returns 0 or < 0 */
int red_rho_basis(const red_disk *disk, double theta, double u[2], double du[2]);

/* f1, f2 of a state; returns 0, or < 0 where the special functions fail */
int red_invariants(const red_disk *disk, const double y[RED_NSTATE], double *f1, double *f2);

/* the rates (v_phi, v_psi) that the integrals f1, f2 give at theta */
int red_rates_from_invariants(const red_disk *disk, double theta, double f1, double f2,
                              double *v_phi, double *v_psi);

#endif
