/* props_shadow: the shadow of an early error computed here, apart from run/,
 * from the rule as DESIGN.md section 6 and run_shadow.h state it, so that
 * the properties' boundaries do not come from the code they check.
 *
 * The reference of the scene's body (the thin disk, or the matched one at
 * half the scene's thickness) at its default settings, and the same run
 * from its start nudged by +- nudge[j] in each reduced direction j (theta,
 * theta_dot, phi_dot, psi_dot: the state's first four; a theta nudge that
 * would start past the lying-down limits left out). The shadow at each of
 * the reference's samples is, summed over the directions, the running
 * maximum over each direction's two runs of |theta - theta_ref| and
 * |contact - contact_ref|, INFINITY past a run's end. An error series e is judged against the limit
 * plus the shadow: its unexcused part is max over the samples of e, over the early window (t <=
 * t_early), and of e - s past it, up to where s reaches the motion's size (the pointwise end) or
 * the window ends. */
#ifndef DV_PROPS_SHADOW_H
#define DV_PROPS_SHADOW_H

#include "props.h"

#define PROPS_DIRS 4 /* the nudged directions: RED_TH, RED_VTH, RED_VPH, RED_VPS */

/* the rule's numbers, restated (DESIGN.md 6; run_horizon.h, run_limits.h) */
#define PROPS_NUDGE 1e-6       /* rad: the floor of a nudge (times the rate scale for a rate) */
#define PROPS_THETA_LIMIT 1e-2 /* rad: the documented theta limit, and a nudge's cap */
#define PROPS_SIZE_FLOOR 10.0  /* the motion's size is at least this many limits */
/* b, t, k: the bracket around a boundary (0.8x passes the metric targeted,
 * 1.25x fails it, named) */
#define PROPS_BELOW 0.8
#define PROPS_ABOVE 1.25

/* what every shadowed check of a scene shares: its early window, its
 * compared window's end and the documented limits */
typedef struct props_frame {
  double t_early; /* s: the early window's end (props_early_until) */
  double t_end;   /* s: the compared window's end (the judged reference's) */
  double lim[2];  /* rad, m: the theta and path limits (props_limits) */
} props_frame;

typedef struct props_shadow {
  dv_traj ref;              /* the body's reference at its default settings */
  double nudge[PROPS_DIRS]; /* the nudges made (rad, rad/s) */
  double *theta;            /* rad: the spread in theta at each of ref's samples */
  double *path;             /* m: in the contact point */
} props_shadow;

/* rad/s: sc's rate scale, its largest initial spin or heading rate, at least sqrt(g / r) */
double props_rate_scale(const dv_scenario *sc);

/* an early error early[j] (NULL: none) as the nudges the rule makes:
 * at least PROPS_NUDGE (times the rate scale for a rate), at most the
 * theta limit (times the rate scale) */
void props_nudges(const dv_scenario *sc, const double *early, double nudge[PROPS_DIRS]);

/* sc's body into body (sc; the matched reference's half-thickness set to
 * half the scene's on a thick scene) and the reference engine that runs it */
const dv_engine_type *props_body_of(const dv_scenario *sc, dv_scenario *body);

/* the reference of sc's body and its runs nudged by nudge into s (free it
 * with props_shadow_free): DV_OK, or < 0 when a run fails (err) */
int props_shadow_run(const dv_scenario *sc, const double nudge[PROPS_DIRS], props_shadow *s,
                     dv_error *err);
void props_shadow_free(props_shadow *s); /* NULL-safe */

/* the largest |y_j - y_ref,j| of tr against ref over their shared samples to t_early */
void props_early_errors(const dv_traj *tr, const dv_traj *ref, double t_early,
                        double early[PROPS_DIRS]);

/* s: the end of sc's early window, its shortest time scale (at least
 * output_dt) past the reference's first sample */
double props_early_until(const dv_scenario *sc, const dv_traj *ref);

/* the motion's size over ref to t_end (rad; m): half its theta swing, and
 * twice the largest distance of its contact point from their mean, each at
 * least PROPS_SIZE_FLOOR limits (lim: theta's, then the path's) */
void props_motion_size(const dv_traj *ref, double t_end, const double lim[2], double size[2]);

/* s: where s's spread reaches size past t_early, to t_end (INFINITY: never) */
double props_pointwise_stop(const props_shadow *s, double t_early, double t_end,
                            const double size[2]);

/* the unexcused part of err (one value a sample of s->ref, NAN: none) by
 * the spread (0 theta, 1 path): 0 at least */
double props_unexcused(const props_shadow *s, const double *err, int path, double t_early,
                       double stop, double t_end);

/* the pointwise end of s in frame f (props_motion_size, props_pointwise_stop) */
double props_frame_stop(const props_shadow *s, const props_frame *f);

/* the bracketing of metric m, metric m's planted size: 0.8x its boundary
 * passes, 1.25x fails named; what the judge made of it in r (verdict, its
 * unexcused value against want, the unexcused value computed here, both
 * in the metric's units) checked, each wrong one a failure of prop. lim:
 * its limit; what: the planted error in words */
void props_check_bracket(props_scene_ctx *s, int prop, dv_metric_id m, int above, double lim,
                         double want, const dv_engine_result *r, const char *what);

/* the properties b, t, k and n (props_rule.c) on s: tr the reference solved
 * again, base its judged result (it agrees), f its frame, least the floor's
 * shadow (its reference: the judged one's run) */
void props_rules(props_scene_ctx *s, const dv_traj *tr, const dv_engine_result *base,
                 const props_frame *f, const props_shadow *least, unsigned which);

/* the documented limits (DESIGN.md 6, run_limits.h as stated): theta
 * 0.01 rad; the path 1% of the distance ref's contact point rolls to
 * t_end, at most 10% of the motion's extent, at least 1% of the radius */
void props_limits(const dv_scenario *sc, const dv_traj *ref, double t_end, double lim[2]);

#endif
