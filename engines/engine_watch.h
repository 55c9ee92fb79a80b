/* engine_watch: the faults that end a contact engine's run (never the process).
 *
 * A run diverges where its state is not finite, where its energy runs away
 * (over E0 + |E0| / 2 + m g r), or where the body's lowest point sinks deeper
 * than DV_WATCH_SUNK r into the ground; it loses contact where that point stays
 * higher than DV_WATCH_AIR r above the ground for longer than DV_WATCH_AIR_TIME.
 * The engines check every few steps (the time off the ground adds up the steps
 * between checks) and before every sample.
 */
#ifndef DV_ENGINE_WATCH_H
#define DV_ENGINE_WATCH_H

#include <stddef.h>

#include "dv_engine.h"
#include "dv_pose.h"

#define DV_WATCH_AIR 0.01      /* lost contact: height above the ground, in radii */
#define DV_WATCH_AIR_TIME 0.05 /* and for longer than this, s */
#define DV_WATCH_SUNK 0.05     /* diverged: lowest point this deep below the ground, in radii */

typedef struct dv_engine_watch {
  double e0, e_max; /* energy at the start, runaway above, J */
  double airborne;  /* s the lowest point has been off the ground */
  long checked;     /* the step of the last check */
} dv_engine_watch;

/* all 18 numbers of the pose are finite */
int dv_pose_finite(const dv_pose *p);

/* start watching a run at its first pose: DV_FAILURE_NONE, or DV_FAILURE_SETUP
 * where the pose or its energy is not finite (msg says so) */
dv_failure dv_engine_watch_start(dv_engine_watch *w, const red_disk *disk, const dv_pose *pose,
                                 char *msg, size_t size);

/* the pose at step k of step dt: DV_FAILURE_NONE, or the fault, msg saying what
 * and when ("runaway energy at t = 0.2 s: ...") */
dv_failure dv_engine_watch_check(dv_engine_watch *w, const red_disk *disk, const dv_geometry *geom,
                                 const dv_pose *p, long k, double dt, char *msg, size_t size);

/* A run's rows against each other (docs/judge.md; the limits are measured in
 * run/file/run_trajcheck.h): each of theta, phi and psi's step from row to
 * row against the trapezoid of its rate, and the centre's step against the
 * trapezoid of its velocity. The same checks serve a trajectory file and an
 * adapter's rows. */
#define DV_ROWS_RATE_TOL 0.3 /* of the step times the rate scale or the rate */
#define DV_ROWS_DRIFT 0.08   /* of the angle's travel: the misses summed */
#define DV_ROWS_ROUND 1e-5   /* of the angles: 6 printed digits round at 5e-7 */
#define DV_ROWS_FLAT_TURN 0.2   /* sin theta of a turn too near flat to resolve phi, psi */
#define DV_ROWS_CENTRE_TOL 0.3  /* of the step times the speed scale */
#define DV_ROWS_CENTRE_TURN 0.25
#define DV_ROWS_START_TOL 1e-6 /* the start against the state given: rad, radii, rate scales */

/* the scene's rate scale: sqrt(g/r), or a larger initial rate */
double dv_rows_rate_scale(const red_disk *disk, const double y0[RED_NSTATE]);

/* theta turns between rows a and s with sin theta below DV_ROWS_FLAT_TURN:
 * phi, psi and the centre whirl there, unresolved by the rows */
int dv_rows_turn_near_flat(const dv_sample *a, const dv_sample *s);

/* an angle's misses of the trapezoid of its rate, summed from the first row
 * checked (zeroed: none yet) */
typedef struct dv_rows_drift {
  double miss, travel; /* rad: the misses summed, and the steps' trapezoids' own sizes */
  double first;        /* rad: the angle where the sum began */
  int begun;
} dv_rows_drift;

/* angle k (0 theta, 1 phi, 2 psi) from row a to row s against the trapezoid
 * of its rate: the miss over its allowance (above 1: the rows disagree), 0
 * where the rows do not resolve the rate. Two allowances: the step's,
 * DV_ROWS_RATE_TOL of the step times the larger of the rate scale and the
 * rate; and the sum's (*drift, kept), DV_ROWS_DRIFT of the travel plus the
 * step's: a jittery engine's misses cancel, a rate scaled off its angle's
 * steps adds up. *miss the step's miss, *summed 1 where the sum decided */
double dv_rows_angle(const dv_sample *a, const dv_sample *s, int k, double rate_scale,
                     dv_rows_drift *drift, double *miss, int *summed);

/* theta, phi and psi from row a to s (dv_rows_angle, drift[3] theirs); phi
 * and psi not where theta turns near flat, nor, in a pose (pose: 1), where
 * it is under 1e-3 (they whirl there, or are undefined). The first over its
 * allowance: its index (0 theta, 1 phi, 2 psi), *d, *miss and *summed as
 * dv_rows_angle's; -1 when none is */
int dv_rows_angles(const dv_sample *a, const dv_sample *s, int pose, double rate_scale,
                   dv_rows_drift drift[3], double *d, double *miss, int *summed);

/* the first of the state's eight numbers off the state given by more than
 * DV_ROWS_START_TOL (angles mod 2 pi; x, y over the radius r; rates over the
 * rate scale): its index, or -1 */
int dv_rows_start_off(const double y[RED_NSTATE], const double y0[RED_NSTATE], double r,
                      double rate_scale);

/* the centre's step against its velocity, row by row (dv_rows_centre) */
typedef struct dv_rows_centre_track {
  size_t n; /* rows seen */
  double t, pos[2], vel[2], miss[2];
} dv_rows_centre_track;

/* the row s (a: the row before, NULL for the first), its centre x, y (pos)
 * and velocity vx, vy (vel): the share of the step times the speed scale
 * (floor: at least) by which the centre's step misses the trapezoid of its
 * velocity, and that miss's change from the step before's, each over its
 * limit: the larger (above 1: the rows disagree), of x or y into *k */
double dv_rows_centre(dv_rows_centre_track *c, const dv_sample *a, const dv_sample *s,
                      const double pos[2], const double vel[2], double speed_floor, int *k);

#endif
