/* red_steady: steady motions of the disk and their linear stability.
 *
 * Steady circle: theta constant, v_theta = 0, v_phi and v_psi constant with
 * v_theta' = 0, i.e.  A v_phi^2 c s - m g r c = (C + m r^2)(v_psi + v_phi c) v_phi s.
 * The contact point runs on a circle of radius R = |r v_psi / v_phi|; a disk
 * leaning toward the circle's centre has v_psi = -sign(c) (R / r) v_phi.
 *
 * Upright rolling (theta = pi/2, v_phi = 0, v_psi = Omega) is linearly stable
 * iff Omega^2 > m g r A / (C (C + m r^2)); never at C = 0.
 */
#ifndef RED_STEADY_H
#define RED_STEADY_H

#include "dv_error.h"
#include "red_disk.h"

/* v_psi of the steady motion with tilt theta and heading rate v_phi != 0 */
int red_steady_from_phi_dot(const red_disk *disk, double theta, double v_phi, double *v_psi,
                            dv_error *err);

/* v_phi > 0 and v_psi of the steady circle of contact radius R (m) at tilt
 * theta, leaning toward its centre; DV_EINPUT when no such circle exists */
int red_steady_from_radius(const red_disk *disk, double theta, double radius, double *v_phi,
                           double *v_psi, dv_error *err);

/* critical spin rate of upright rolling, rad/s (INFINITY when C = 0) */
double red_upright_critical_spin(const red_disk *disk);

/* is y a steady motion: |v_theta| and |v_theta'| below tol (relative to g/r) */
int red_is_steady(const red_disk *disk, const double y[RED_NSTATE], double tol);

/* eigenvalues of the linearised 4-D reduced system at y (re, im pairs).
 * Two are always 0 (the family of steady motions, f1 and f2); the motion is
 * called stable when no real part exceeds 1e-6 of the largest modulus. */
int red_linear_stability(const red_disk *disk, const double y[RED_NSTATE],
                         double eig[RED_NREDUCED][2], int *stable, dv_error *err);

/* how far the eigenvalues eig (from red_linear_stability) move when the
 * finite-difference step of the Jacobian doubles: their uncertainty, which
 * near a double eigenvalue (exactly at the critical spin) is the square root
 * of the Jacobian's error (NAN where they cannot be computed) */
double red_eigen_uncertainty(const red_disk *disk, const double y[RED_NSTATE],
                             const double eig[RED_NREDUCED][2]);

#endif
