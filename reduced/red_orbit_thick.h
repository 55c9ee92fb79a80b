/* red_orbit_thick: the thick disk's motion in theta, from its own equations.
 *
 * The thin disk's range of theta, its nutation period and what phi and psi
 * advance over it come from the effective potential of its integrals f1, f2
 * (red_potential.h). A cylinder rolling on its rim corner (red_rolling.h)
 * has other integrals; here they come from its equations themselves: the
 * matched system is integrated from y, sampled every 1/SAMPLES of the
 * motion's shortest time scale, and each turning point of theta (a sign
 * change of theta') is the zero of the parabola of theta' through the three
 * samples around it, theta, phi and psi there by cubic Hermite on their
 * rates (tests/check_analyze_thick.sh measures it against a finer run). The run stops after one
 * period (three turning points), at an event of the matched system (lying
 * down: *falls; the normal force or friction: the validity window ends) or
 * at t_max.
 */
#ifndef RED_ORBIT_THICK_H
#define RED_ORBIT_THICK_H

#include "dv_error.h"
#include "red_rolling.h"
#include "red_solver.h"

typedef struct red_orbit_thick {
  int steady;         /* theta' and theta'' zero at the start (within 1e-9 of g/r) */
  double range[2];    /* theta's lowest and highest, rad */
  int falls;          /* the run lay down (theta_limit) before turning */
  int event;          /* the matched system's event that ended the run, or -1 */
  double t_event;     /* s, where it did */
  int nutates;        /* a whole period was seen */
  double nutation[3]; /* its period (s), the advances of phi and psi over it (rad) */
  double t_end;       /* s, how far the run went */
} red_orbit_thick;

/* the motion of rr from y (canonical state) as above; DV_OK or < 0 */
int red_orbit_thick_run(const red_rolling *rr, const red_stepper_type *stepper, double rtol,
                        double atol, const double y[RED_NSTATE], double t_max, red_orbit_thick *out,
                        dv_error *err);

#endif
