/* run_horizon: how long the reference itself is predictable.
 *
 * The thin-disk reference is run again from theta(0) +- DV_HORIZON_NUDGE
 * rad. While both stay within DV_HORIZON_SPREAD rad of the reference, a
 * pointwise comparison of theta(t) and the contact path measures an
 * engine's accuracy; past that time it measures the scene's sensitivity
 * (an unstable equilibrium, a separatrix), and only timing-insensitive
 * measures mean something: extrema of theta, the path's Hausdorff distance,
 * the drift of E, f1, f2 along the engine's own states, when the disk lies
 * down (run_event.h). Where the nudged runs move a timing-insensitive
 * measure too (the well a separatrix start falls into), that measure is not
 * predictable either: its spread is what the nudge alone changes it by.
 * A nudge that would start at or past the lying-down limit (theta_limit,
 * pi - theta_limit) is not made: the other side alone gives the horizon; if
 * neither fits, one run is nudged toward upright by half the room left.
 */
#ifndef DV_RUN_HORIZON_H
#define DV_RUN_HORIZON_H

#include "run_compare.h"
#include "run_event.h"
#include "scenario.h"

#define DV_HORIZON_NUDGE 1e-3  /* rad: the default accuracy of the engines */
#define DV_HORIZON_SPREAD 1e-2 /* rad: the default theta limit */

/* the predictability horizon (s) of sc's reference ref, INFINITY when the
 * nudged runs stay within DV_HORIZON_SPREAD to their ends; spread, the
 * largest value of each metric between a nudged run and ref; and how each
 * nudged run ended (nudged[k].ran 0: not made). < 0 when a nudged run fails,
 * err naming it */
int dv_run_horizon(const dv_scenario *sc, const dv_traj *ref, double *horizon,
                   double spread[DV_NMETRICS], dv_run_end nudged[2], dv_error *err);

#endif
