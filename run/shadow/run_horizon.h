/* run_horizon: how the reference of the scene's body amplifies a nudge of
 * its start, and the shadow of an engine's early error.
 *
 * The reference of the scene's body (the thin disk, or the matched one of
 * the scene's thickness: dv_run_body) is run again from its initial state
 * nudged in each reduced direction j (theta, theta_dot, phi_dot, psi_dot)
 * by +- d_j: DV_HORIZON_NUDGE rad for theta, DV_HORIZON_NUDGE times the
 * scene's rate scale (its largest initial spin or roll rate, at least
 * sqrt(g / r)) for the rates. Its amplification A_j(t) is the largest
 * |theta_nudged - theta_ref| up to t over d_j; G(t), the largest
 * A_j(t) d_j / DV_HORIZON_NUDGE, is the amplification of a relative nudge.
 * The growth comes from the measurement, whatever its shape: linear in t in
 * integrable motion (a wobble's period depends on its amplitude),
 * exponential near a separatrix or a fall from upright. G is information
 * (the reference block, the settings choice); it judges nothing.
 *
 * What judges is the shadow (run_shadow.h) of an engine's own early error
 * (its largest error over the scene's shortest time scale in theta, and in
 * each rate: dv_run_engine_shadow). The reference is run again from +- that
 * error in each direction, the directions' spreads summed (at least the nudge: an engine below it shares
 * the amplification's runs; at most the theta limit, or the limit over the
 * rate scale for a rate: a larger early error is the engine's own failure,
 * judged pointwise from the start, and buys no larger excuse). Their
 * spread at each time is what the scene does to an error the engine could
 * not avoid (its representation of the start); every error it makes along
 * the way is its own. The same nudged runs bound its lying down
 * (run_event.h) and move each timing-insensitive metric (spread).
 *
 * A theta nudge that would start at or past the lying-down limit
 * (theta_limit, pi - theta_limit) is not made: the other side alone gives
 * the measurement; if neither fits, one run is nudged toward upright by half
 * the room left.
 */
#ifndef DV_RUN_HORIZON_H
#define DV_RUN_HORIZON_H

#include "run_compare.h"
#include "run_event.h"
#include "run_shadow.h"
#include "scenario.h"

/* rad: near or below the engines' early errors (measured 7.2e-10 to 5.5e-5
 * rad at the derived settings: `diskval suite scenarios scenarios/hard`,
 * report.json "decided_why"; a smaller one is taken as the nudge), far above the
 * reference's own error (1e-10 rad over 200 s: README "The reference") */
#define DV_HORIZON_NUDGE 1e-6
#define DV_HORIZON_SPREAD 1e-2 /* rad: the default theta limit */

/* the nudged directions: the reduced state's RED_TH, RED_VTH, RED_VPH, RED_VPS */
#define DV_NUDGE_DIRS 4
extern const char *const dv_nudge_dir_names[DV_NUDGE_DIRS]; /* "theta", "theta_dot", ... */

/* the reference's amplification of nudges of its initial state */
typedef struct dv_amplification {
  double nudge;                   /* rad: the theta nudge made (the larger of the two) */
  double size[DV_NUDGE_DIRS];     /* each direction's nudge: rad, then rad/s */
  double rate_scale;              /* rad/s: the rates' nudge over DV_HORIZON_NUDGE */
  size_t n;                       /* samples: the reference's */
  double *t;                      /* s: the reference's sample times */
  double *gain_of[DV_NUDGE_DIRS]; /* A_j(t_i): running max |theta_nudged - theta_ref| / size[j] */
  double *gain; /* G(t_i): max over j of A_j size[j] / DV_HORIZON_NUDGE (a relative nudge) */
  double spread_of[DV_NUDGE_DIRS][DV_NMETRICS]; /* each metric between a nudged run and ref */
  double measured_to; /* s: G is measured to here (where a nudged run ended first, or ref's end) */
  double horizon;     /* s: the horizon of an engine with no early error (INFINITY: never) */
  char growth[16];    /* "linear", "power", "exponential", "bounded" (from the fits below) */
  double exponent;    /* G ~ t^exponent, least squares over where G >= 2 */
  double efold;       /* s: G ~ exp(t / efold), the same samples */
  double factor;      /* G at the end of the samples fitted (at measured_to when bounded) */
  double factor_t;    /* s: where */
  dv_run_end ends[2]; /* how the theta-nudged runs ended (ends[k].ran 0: not made) */
  double half_thickness;                 /* m: of the body nudged (0: the thin disk) */
  dv_shadow shadow_of[DV_NUDGE_DIRS];    /* each direction's runs' spread (run_shadow.h) */
} dv_amplification;

/* the reference engine of sc's body into body_sc (sc, with the matched
 * reference's half-thickness set to the scene's on a thick scene) */
const dv_engine_type *dv_run_body(const dv_scenario *sc, dv_scenario *body_sc);

/* measure a's amplification of the reference ref of sc's body; spread (may be
 * NULL): each metric's largest value between a nudged run and ref. < 0 when
 * a nudged run fails, err naming it */
int dv_run_amplification(const dv_scenario *sc, const dv_traj *ref, dv_amplification *a,
                         double spread[DV_NMETRICS], dv_error *err);

void dv_run_amplification_free(dv_amplification *a); /* NULL-safe */

/* the shadow of an engine whose early errors are early[j] (rad, rad/s):
 * the reference ref of sc's body run again from each direction j nudged by
 * +- early[j] (floored at a's nudge, where a's own runs serve, and capped
 * at the limit); at each of ref's samples the sum over the directions of
 * each direction's spread (a running maximum over its two runs) into
 * shadow (allocated here; free it with dv_shadow_free): in the linear
 * regime an early error in every direction at once moves the reference by
 * at most that sum. The largest value of each metric between a nudged run
 * and ref over the compared window (to t_end) into spread, and how the
 * theta-nudged runs ended into ends. a is the amplification of the same
 * body. < 0 when a run fails */
int dv_run_engine_shadow(const dv_scenario *sc, const dv_traj *ref, const dv_amplification *a,
                         const double early[DV_NUDGE_DIRS], double t_end, dv_shadow *shadow,
                         double spread[DV_NMETRICS], dv_run_end ends[2], dv_error *err);

/* the relative early error e of an engine whose early errors are early[j] */
double dv_run_relative_error(const dv_amplification *a, const double early[DV_NUDGE_DIRS]);

/* the horizon (s) of an engine whose early errors, to t_early (s), are
 * early[j]: where e (G(t) - 1) reaches limit, and no earlier than t_early;
 * INFINITY when it never does. gain: G there (or at the end) */
double dv_run_horizon_of(const dv_amplification *a, const double early[DV_NUDGE_DIRS],
                         double t_early, double limit, double *gain);

/* s/rad: how far the reference's nutation period moves per radian its
 * turning points move, the largest over the nudged directions (their
 * nutation_period_err over their theta_turning_err); 0 where no nudge moves
 * the turns by 1% of the theta nudge */
double dv_run_period_per_turn(const dv_amplification *a);

/* the amplification in words: "linear (G ~ t^1.02), x99 by t = 8 s" */
void dv_run_amplification_words(const dv_amplification *a, char *out, size_t size);

#endif
