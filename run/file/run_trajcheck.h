/* run_trajcheck: what a trajectory's columns say about each other and about
 * the ground (run_trajfile.h reads them; docs/judge.md).
 *
 * The pose form gives the body's height: its lowest point is watched as a
 * linked engine's is (engine_watch.h, the same limits): deeper than
 * DV_WATCH_SUNK radii below the ground the run has sunk (diverged), higher
 * than DV_WATCH_AIR radii for longer than DV_WATCH_AIR_TIME it has lost
 * contact; the replay fails there (run_replay.h). Measured on correct pose
 * files, the lowest point's height over the radius: MuJoCo's soft contact
 * (examples/plain_mujoco_judge, tests/check_judge_mujoco_pose.sh) -4.4e-6 ..
 * 4.1e-4, the thick coin model (check_judge_thick_model.sh) -1.3e-15 ..
 * 2.7e-13, a state file rewritten as poses (check_judge_perturbed.sh) 4e-16:
 * 24 times under the air limit, 10^4 under the sinking one.
 *
 * The state form with both the contact point and phi, psi, x, y gives the
 * contact point twice: given, and where theta, phi and the centre put it on
 * the scene's disk. They must agree to DV_TRAJ_CONTACT_TOL radii plus the
 * scene's half-thickness plus DV_TRAJ_ROUND of the coordinates. Measured
 * (simulate of the reference and every contact engine on every scenario of
 * scenarios/ and scenarios/hard/, league/ and tests/data/quarter_spun,
 * short_circle): at most 2.9e-14 r where the file is of the scene's disk;
 * 0.0168 r for the thin reference of a 2 mm thick scene
 * (steady_circle_cylinder), 0.0796 r = h sin theta for that of a 2-euro coin
 * (h = 0.085 r), inside the half-thickness. The reference's output with x
 * one row late (tests/check_judge_hostile.sh) is 2.1e-3 r off at its second
 * row, 0.1 r at its thirtieth (steady_circle).
 * With rates as well (given, or the pose form's angular velocity), each of
 * theta, phi and psi's step from row to row must match the trapezoid of its
 * rate (mod 2 pi: wrapped angles are fine; a pose lying flat, theta < 1e-3,
 * has no phi or psi) within DV_ROWS_RATE_TOL of the step times the larger of
 * the two rates and the scene's rate scale, and the misses summed from the
 * start within DV_ROWS_DRIFT of the trapezoids' own sizes summed (the
 * angle's travel) plus that step allowance (engine_watch.h), where the rate
 * is resolved by the samples: a step over which it changes by more than
 * DV_TRAJ_RATE_TOL of its scale is not checked (a generated fall's phi_dot
 * goes from -5.8 to -36.9 and -98.5 rad/s in two 0.016 s rows near lying
 * down: diskval_props, property a, seed 1 scene 12). The sum catches a rate
 * off its angle by a steady share, which a step's allowance, wide for
 * engines whose rows jitter (Havok's prism on a circle: theta misses 0.0056
 * rad in a 0.01 s step), lets through. Measured, each over its allowance:
 * simulate as above, as written and in the pose form: the step at most 0.066
 * (c_zero, theta), the sum 0.060 (tiny_c, psi); diskval_props --props ak,
 * seed 1, 200 scenes: the step 0.152 (phi), the sum 0.294 (theta); --props
 * a, seed 2026, 300 scenes: the step 0.313 (theta), the sum 0.273 (phi). A psi
 * scaled by 1.2 sums to 0.167 of its travel, by 1.12 to 0.107, by 1.05 to
 * 0.048 (short_circle); the reference's phi with its first step 1.9 times
 * its rate's misses by 0.6 of a step's allowance (its contact point refuses it).
 * Re-measure: print off / r and the angle's d in dv_run_trajcheck_columns and judge
 * those files (and run diskval_props --props a).
 */
#ifndef DV_RUN_TRAJCHECK_H
#define DV_RUN_TRAJCHECK_H

#include "dv_error.h"
#include "dv_pose.h"
#include "run_trajfile.h"

#define DV_TRAJ_CONTACT_TOL 1e-3 /* of the radius */
#define DV_TRAJ_ROUND 1e-5      /* of the coordinates: 6 printed digits round at 5e-7 */
#define DV_TRAJ_RATE_TOL DV_ROWS_RATE_TOL
/* phi and psi are not checked over a step in which theta turns with sin theta
 * below this: generated falls (diskval_props, property a, seed 1 scenes 25,
 * 32, 33, 53) turn at theta 0.03 to 0.11 rad with phi turning 2 to 5 rad more
 * than the rows' rates say */
#define DV_TRAJ_FLAT_TURN DV_ROWS_FLAT_TURN
/* The pose form with velocities: the centre's step from row to row against
 * the trapezoid of its velocity vx, vy, over the step times the speed scale
 * (the scene's rate scale times the radius, or the larger speed): its miss at
 * most DV_TRAJ_CENTRE_TOL, and its change from the step before's miss at most
 * DV_TRAJ_CENTRE_TURN (smooth motion misses smoothly; a centre sliding back
 * and forth under rolling velocities misses by turns). Measured on simulate
 * of the reference, ODE and MuJoCo on every scenario of scenarios/,
 * quarter_spun and short_circle, written as poses with rolling velocities
 * (tests/judge_to_pose): the miss at most 0.108 (the reference on c_zero;
 * 0.276 MuJoCo's fall, which slides as it lands while the poses say it
 * rolls), its change at most 0.144 (tiny_c, every engine). The hostile file
 * of x +3 mm on every other row of a 1.52 m/s steady circle at 10 ms: miss
 * 0.198, change 0.395. Re-measure: print fabs(e[i]) and its change in
 * dv_run_trajcheck_centre and judge those files. As for the angles, a step
 * in which theta turns near flat (DV_TRAJ_FLAT_TURN) or the velocity changes
 * by more than DV_TRAJ_CENTRE_TOL of the speed scale is not checked: the
 * centre whirls with phi between the rows (diskval_props, property a, seed 1
 * scenes 25, 27, 32: misses 1.07 to 2.89 of the limit there). */
#define DV_TRAJ_CENTRE_TOL DV_ROWS_CENTRE_TOL
#define DV_TRAJ_CENTRE_TURN DV_ROWS_CENTRE_TURN

/* the pose-form row f->s[f->n] (not yet counted), its lowest point height m
 * above the ground: the first fault into f->ground_* */
void dv_run_trajcheck_ground(dv_trajfile *f, const dv_scenario *sc, double height);

/* the pose-form row f->s[f->n] (not yet counted) with velocities: its centre
 * x, y (pos) and velocity vx, vy (vel) against the row before's: the share of
 * the step times the speed scale by which the centre's step misses the
 * trapezoid of its velocity, and that miss's change from the row before's,
 * each over its limit: the larger (above 1: the columns disagree), of x or y
 * into *k (0: x, 1: y); 0 for the first row. Either way pos, vel and the miss
 * are kept in f for the next. */
double dv_run_trajcheck_centre(dv_trajfile *f, const dv_scenario *sc, const double pos[2],
                               const double vel[2], int *k);

/* the columns against each other: the contact point given (ccol, its 1-based
 * column; 0: none) against the state's, and with rates (given, or the pose
 * form's angular velocity) each angle's step against its rate (col: the
 * 1-based columns of theta, phi, psi for the message): DV_OK, or DV_EINPUT
 * with err "PATH:LINE:COLUMN: what" */
int dv_run_trajcheck_columns(const dv_trajfile *f, const dv_scenario *sc, int ccol,
                             const int col[3], dv_error *err);

#endif
