/* run_horizon: how long the reference is predictable at an engine's accuracy.
 *
 * The thin-disk reference is run again from its initial state nudged in
 * each reduced direction j (theta, theta_dot, phi_dot, psi_dot) by +- d_j:
 * DV_HORIZON_NUDGE rad for theta, DV_HORIZON_NUDGE times the scene's rate
 * scale (its largest initial spin or roll rate, at least sqrt(g / r)) for
 * the rates. Its amplification A_j(t) is the largest
 * |theta_nudged - theta_ref| up to t over d_j. The directions respond alike
 * (within 0.3-1x of theta's on the hoop, long_horizon, upright_stable,
 * critical_below and the separatrix), but an engine's early error often
 * lies in its rates (MuJoCo on steady_circle: 2.5e-5 of the rate scale
 * against 1.1e-5 rad in theta), which only these nudges put in scale. The
 * growth comes from the measurement, whatever its shape: linear in t in
 * integrable motion (a wobble's period depends on its amplitude),
 * exponential near a separatrix or a fall from upright.
 *
 * G(t), the largest A_j(t) d_j / DV_HORIZON_NUDGE, is the amplification of
 * a relative nudge. An engine's pointwise comparison ends at its horizon:
 * where its own early error e (its largest error over the scene's shortest
 * time scale in theta, and in each rate over the rate scale; at least the
 * nudge, at most DV_HORIZON_SPREAD: a larger one is the engine's own
 * failure, not the scene's sensitivity) grows by
 * e (G(t) - 1) >= DV_HORIZON_SPREAD rad, what the dynamics add to it (an
 * engine's own large early error on a scene that amplifies little does not
 * end its pointwise judging), and never before the early window itself. Up to there a pointwise
 * error measures the engine; past it, it measures the scene's sensitivity, and only
 * timing-insensitive measures mean something: turning points, period, the path's Hausdorff
 * distance, the drift of E, f1, f2 along the engine's own states, when the
 * disk lies down (run_event.h).
 * Where both runs nutate, pointwise judging also ends at the turn before
 * the engine's turning points first lag or lead the reference's by the time
 * in which the reference's fastest theta rate moves theta by the limit
 * (run_turning.h, dv_run_turning_lag): past it a pointwise error measures
 * when, not what (errors made at a turn, not at the start, and amplified by
 * a pass near upright); the turning values and the period judge there.
 * Those are judged unless the reference nudged by +- the engine's early
 * error in some direction moves them by half their limit (the well a
 * separatrix start falls into): their spread.
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
} dv_amplification;

/* measure a's amplification of sc's thin reference ref; spread (may be
 * NULL): each metric's largest value between a nudged run and ref. < 0 when
 * a nudged run fails, err naming it */
int dv_run_amplification(const dv_scenario *sc, const dv_traj *ref, dv_amplification *a,
                         double spread[DV_NMETRICS], dv_error *err);

void dv_run_amplification_free(dv_amplification *a); /* NULL-safe */

/* the reference run again from each direction j nudged by +- early[j] (a
 * theta nudge kept inside the lying-down limits), where early[j] exceeds
 * a's own nudge (a's spread_of[j] elsewhere): spread, the largest value of
 * each metric between a nudged run and ref, and how the theta-nudged runs
 * ended (ends: a's when theta is not nudged again). < 0 when a run fails */
int dv_run_nudged_spread(const dv_scenario *sc, const dv_traj *ref, const dv_amplification *a,
                         const double early[DV_NUDGE_DIRS], double spread[DV_NMETRICS],
                         dv_run_end ends[2], dv_error *err);

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
