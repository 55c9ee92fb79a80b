/* run_limits: the limit of every metric, never none.
 *
 * A limit comes from the scenario ([tolerance.ENGINE], then [tolerance]) or,
 * where it gives none, from a rule grounded in the scene (README, "Verdicts"):
 *   theta_max_err, theta_rms_err,   DV_LIMIT_THETA rad: the default accuracy
 *   theta_extrema_err,              of the engines' derived settings, 1e-3,
 *   theta_turning_err               with a margin of 10
 *   nutation_period_err             DV_LIMIT_THETA over the reference's largest
 *                                   |theta_dot|: a period off by that moves
 *                                   theta by at most the theta limit
 *   turning_lag                     the theta limit (the scene's, else
 *                                   DV_LIMIT_THETA) over the reference's
 *                                   largest |theta_dot|: the time in which
 *                                   theta moves by that limit
 *   heading_period_err              DV_LIMIT_HEADING rad: a heading off by it
 *                                   moves a point rolled L away by 1% of L,
 *                                   the path limit
 *   path_max_err, path_rms_err,     DV_LIMIT_PATH of the distance the
 *   path_hausdorff                  reference's contact point travels over
 *                                   the compared window, at most
 *                                   DV_LIMIT_EXTENT of the motion's size
 *                                   (dv_run_motion_extent: a circle's
 *                                   diameter), and at least DV_LIMIT_PATH
 *                                   of the radius
 *   phase_err                       DV_LIMIT_PHASE rad of half the motion's
 *                                   size (an angle round a circle), at most
 *                                   the path limit and at least DV_LIMIT_PATH
 *                                   of the radius
 *   energy_drift                    DV_LIMIT_ENERGY of the initial energy
 *   invariant_drift                 DV_LIMIT_INVARIANTS of the momentum scale
 *   slip_max                        DV_LIMIT_SLIP of the scene's speed scale,
 *                                   max(r |psi_dot|, r |phi_dot|, sqrt(g r))
 * Every limit carries the words that say where it came from.
 */
#ifndef DV_RUN_LIMITS_H
#define DV_RUN_LIMITS_H

#include "run_compare.h"
#include "scenario.h"

#define DV_LIMIT_THETA 1e-2      /* rad */
#define DV_LIMIT_PATH 1e-2       /* of the distance rolled */
#define DV_LIMIT_ENERGY 1e-2     /* of the initial energy */
#define DV_LIMIT_SLIP 1e-2       /* of the speed scale */
#define DV_LIMIT_INVARIANTS 1e-2 /* of the momentum scale sqrt(2 E0 (A + m r^2)) */
#define DV_LIMIT_HEADING 1e-2    /* rad a period: moves a point rolled L away by 1% of L */
/* of the motion's size, the chord of 0.2 rad round a circle: twice the phase
 * limit's, so that a phase error is named by phase_err first */
#define DV_LIMIT_EXTENT 0.1
/* rad round a circle (an arc of 0.1 of its radius). Measured on the engines
 * at their derived settings (compare --engines mujoco,ode,bullet,dart,simbody;
 * report.json limits.phase_err.margin): on every shipped scenario the largest
 * margin 0.16 (ODE and DART on steady_steep), every other under 0.09; on a
 * 1-euro coin (r 0.011625 m, mass 0.0075, thickness 0.00233, theta 1.2,
 * steady_circle_radius 0.05, 2 s) 0.26 (DART) and 0.21 (ODE); on a dinner
 * plate (r 0.13, mass 0.6, thickness 0.015, A 0.0036, C 0.0071, theta 1.3,
 * psi_dot -20, 2 s) and a hoop (r 0.4, mass 0.5, thickness 0.01, A 0.04,
 * C 0.08, theta 1.4, psi_dot -8, 4 s) under 0.002; the path margins under
 * the capped limits at most 0.33. On a steel Euler disk
 * (tests/data/euler_disk.ini) ODE is 1.48 rad behind after 2 s (margin 14.7)
 * and Bullet 3.15 rad (31), from a heading rate that drifts with theta. */
#define DV_LIMIT_PHASE 0.1

/* nutation_period_err's default is at least this times the period change
 * the engine's own theta_turning_err makes in the reference (s/rad from the
 * nudged runs, linear): near upright a turn's time grows faster than linear.
 * Measured 1.3 for Simbody on a thin quarter falling from theta 1.565 with
 * psi_dot 5 (its turns 0.0033 rad off, its period 0.061 s at 14.2 s/rad;
 * `diskval simulate` each engine, then `diskval judge`, report.md) */
#define DV_PERIOD_PER_TURN_MARGIN 2.0

typedef struct dv_limit {
  double value;  /* the metric passes when value <= this */
  char why[112]; /* "[tolerance.ode]", "1% of the 7.6 m rolled", ... */
} dv_limit;

/* the limits of engine's metrics in sc; ref is the reference compared with,
 * t_end the end of the compared window */
void dv_run_limits(const dv_scenario *sc, const char *engine, const dv_traj *ref, double t_end,
                   dv_limit out[DV_NMETRICS]);

/* m: path_max_err's default limit over ref to t_end, whatever the scenario gives */
double dv_run_default_path_limit(const dv_scenario *sc, const dv_traj *ref, double t_end);

/* rad/s: sc's rate scale, its largest initial spin or roll rate, at least
 * sqrt(g / r); r times it is the speed scale */
double dv_run_rate_scale(const dv_scenario *sc);

/* the distance (m) the contact point of tr travels up to t_end */
double dv_run_distance_rolled(const dv_traj *tr, double t_end);

/* the motion's size (m): twice the largest distance of tr's contact points
 * up to t_end from their mean (a circle's diameter, a straight roll's length);
 * unchanged by a rigid motion of the scene */
double dv_run_motion_extent(const dv_traj *tr, double t_end);

#endif
