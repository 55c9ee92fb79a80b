/* red_steady_thick: steady circles of the thick disk (red_rolling.h).
 *
 * A cylinder rolling on its rim corner has steady motions like the thin
 * disk's: theta constant, theta' = 0, phi' and psi' constant. Its rim
 * corner is a circle of radius r, so the contact point runs on a circle of
 * radius R = |r psi' / phi'| as for the thin disk. The balance theta'' = 0
 * differs: with psi' = k phi' it is a phi'^2 + b = 0 (gyroscopic terms are
 * quadratic in the rates, gravity is not), and at a given phi' it is linear
 * in psi'; both are read off red_rolling's own theta'' at two rates and
 * checked at the solution. At h = 0 they are red_steady's closed forms.
 */
#ifndef RED_STEADY_THICK_H
#define RED_STEADY_THICK_H

#include "dv_error.h"
#include "red_rolling.h"

/* v_phi > 0 and v_psi of the thick disk's steady circle of contact radius R
 * at tilt theta, leaning toward its centre; DV_EINPUT when none exists */
int red_steady_thick_from_radius(const red_rolling *rr, double theta, double radius,
                                 double *v_phi, double *v_psi, dv_error *err);

/* v_psi of the thick disk's steady motion with tilt theta and heading rate v_phi */
int red_steady_thick_from_phi_dot(const red_rolling *rr, double theta, double v_phi,
                                  double *v_psi, dv_error *err);

#endif
