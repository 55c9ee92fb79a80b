/* run_turning: theta's turning points and the nutation period, cycle by cycle.
 *
 * The reduced motion nutates: theta swings between two turning points of the
 * effective potential, every period the same (docs/reference.md, "Periodic motion").
 * These measures stay meaningful where a pointwise error measures timing:
 *   theta_turning_err    the largest |theta at the engine's k-th maximum -
 *                        theta at the reference's k-th maximum|, and the same
 *                        for minima (rad); a turning point one run has and
 *                        the other has not is compared with that other run's
 *                        extreme of its kind over the window, unless it is
 *                        the last and the other run, at the window's end, is
 *                        still on its way to it
 *   nutation_period_err  the largest |engine's k-th period - reference's k-th
 *                        period| (s), a period being the time from one maximum
 *                        (or minimum) to the next; INFINITY where the reference
 *                        completes a period and the engine none
 *   heading_period_err   the same for the heading advance over each period,
 *                        phi(t_{k+1}) - phi(t_k) (rad)
 * A turning point is where theta_dot changes sign between two samples, placed
 * by the cubic Hermite interpolant of theta and theta_dot (of phi and phi_dot
 * for the heading); a swing smaller than DV_TURNING_MIN_SWING is not one.
 * NAN (not judged, run_scenario.c says why) where there is nothing to
 * compare: neither run turns, or the reference completes no period.
 */
#ifndef DV_RUN_TURNING_H
#define DV_RUN_TURNING_H

#include "run_compare.h"

/* rad: a tenth of the default theta limit; smaller swings (contact noise on
 * a steady circle: measured up to 2.4e-5 rad, the early errors) are not turns */
#define DV_TURNING_MIN_SWING 1e-3
/* the heading advance between two turns is not compared where a turn of
 * either run has sin theta below this: near flat phi whirls between the
 * samples, and its value at the turn is the interpolant's guess (the column
 * check's DV_TRAJ_FLAT_TURN: diskval_props, property a, seed 1 scenes 27, 33
 * gave 0.84 and 1.84 rad for the reference against itself as poses) */
#define DV_TURNING_FLAT 0.2

/* the three measures of e against ref over samples up to t_end into out:
 * theta_turning_err, nutation_period_err, heading_period_err */
void dv_run_turning_compare(const dv_traj *e, const dv_traj *ref, double t_end, double out[3]);

/* the lag of each of e's turning points behind ref's (s; negative: a lead),
 * the k-th maximum paired with the k-th maximum and minimum with minimum,
 * over samples up to t_end: into t (the reference's turn's time) and lag,
 * room for e->n + ref->n each; their count. A turn one run makes in the
 * window and the other does not lies past the window's end in that other
 * run: its lag is at least the time from it to the end (that bound is
 * given, at the unpaired turn's time). turning_lag, cumulative: a drift of
 * any size a period adds up turn by turn. id (may be NULL): which turn each is */
typedef struct dv_turn_id {
  int kind;       /* +1 a maximum, -1 a minimum */
  size_t ordinal; /* the ordinal-th of its kind (1: the first) */
  int only;       /* 1 the engine's alone in the window, -1 the reference's, 0 both */
} dv_turn_id;
size_t dv_run_turning_lags(const dv_traj *e, const dv_traj *ref, double t_end, double *t,
                           double *lag, dv_turn_id *id);

/* turning_lag: the largest |lag| of those (s; NAN: no turn), which turn it
 * is into worst and its signed lag into lag (each may be NULL) */
double dv_run_turning_lag_worst(const dv_traj *e, const dv_traj *ref, double t_end,
                                dv_turn_id *worst, double *lag);

/* the turning points theta_turning_err compares: those of tr up to t_end,
 * in time order, into t, theta and kind (+1 maximum, -1 minimum), tr->n of
 * room each; their count (0 also when out of memory) */
size_t dv_run_turning_points(const dv_traj *tr, double t_end, double *t, double *theta, int *kind);

/* the turning point that made theta_turning_err: kind +1 a maximum, -1 a
 * minimum (0: none), the ordinal-th of its kind (1: the first), lag the
 * engine's time minus the reference's (s; NAN where one run alone makes it),
 * only which run that is (1 the engine, -1 the reference, 0 both) */
typedef struct dv_turning_worst {
  int kind;
  size_t ordinal;
  double lag;
  int only;
} dv_turning_worst;

/* that turning point of e against ref over samples up to t_end */
void dv_run_turning_worst(const dv_traj *e, const dv_traj *ref, double t_end,
                          dv_turning_worst *out);

/* the largest |theta_dot| of tr up to t_end (rad/s) */
double dv_run_theta_rate_max(const dv_traj *tr, double t_end);

#endif
