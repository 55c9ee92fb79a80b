/* props: the verdict checked by its properties over generated scenes
 * (props_gen.c over engine_generate.h): the exact reference of the scene's
 * body judged as an engine passes (a); a known error added fails exactly the
 * metric it targets past its limit plus the shadow of its early error, that
 * boundary computed here apart from run/ (b); a rigid motion or a similarity
 * scaling of the scene changes no verdict (c); no metric reads past the
 * compared window, no pointwise verdict past the pointwise end, and no empty
 * window is judged (d); a thickness going to 0 gives the thin verdict and
 * numbers (e); the reference on a clock slowed by 1 - eps fails theta (and
 * the path) once its deviation passes the limit plus the spread, and passes
 * below (t); the reference with its energy bled at a constant rate k fails
 * energy_drift once its drift passes its limit, and passes below (k); the
 * reference started from a nudge of engine size (1e-6 to 1e-4) passes (n).
 * The library runs in-process: references and the judge path (run/file/),
 * as diskval judge runs them. */
#ifndef DV_PROPS_H
#define DV_PROPS_H

#include <stdio.h>

#include "engine_generate.h"
#include "run_scenario.h"

enum { PROP_GEN = 0, PROP_A, PROP_B, PROP_C, PROP_D, PROP_E, PROP_T, PROP_K, PROP_N, PROP_COUNT };
/* each property's letter, by the enum above */
#define PROPS_LETTERS "gabcdetkn"
/* a failure named by no metric (a refusal, a whole verdict) */
#define PROPS_NO_METRIC DV_NMETRICS

/* the gaps the summary prints: a shadowed limit less its excuse against the
 * documented one (of it), the early window's end and the pointwise end (s),
 * an unexcused value by the judge against the one computed here (of its limit) */
enum { PROPS_GAP_LIMIT = 0, PROPS_GAP_EARLY, PROPS_GAP_END, PROPS_GAP_AGREE };

/* how a props scene was made (props_gen.c): the generator's own kinds, or
 * one it drew again because the generator's compared nothing */
typedef enum props_kind {
  PROPS_KIND_PERIODIC = 4, /* a stable steady circle set nutating, over >= 9 wobble periods */
  PROPS_KIND_UNSTABLE,     /* released near an unstable steady circle or upright rolling */
  PROPS_NKINDS
} props_kind;
extern const char *const props_kind_names[PROPS_NKINDS]; /* dv_gen_kind_names, then these */

/* what one scene gave each property: checks run, failures, skips (not judged) */
typedef struct props_tally {
  long checks[PROP_COUNT], failures[PROP_COUNT], skipped[PROP_COUNT];
  /* each property's failures by the metric they name (PROPS_NO_METRIC: none) */
  long failed_by[PROP_COUNT][DV_NMETRICS + 1];
  /* the bracketing properties (b, t, k): per metric targeted, brackets run and those wrong */
  long runs[PROP_COUNT][DV_NMETRICS], wrong[PROP_COUNT][DV_NMETRICS];
  long known[PROP_COUNT]; /* failures of a scene the known list names for that property */
  /* the scenes: by kind, judged, periodic over >= 8 nutation periods in the
   * window, released near an unstable state (exponential amplification) */
  long kinds[PROPS_NKINDS], judged, periodic8, unstable;
  long d_pointwise; /* d: trajectories bent past a pointwise end before the window's */
  /* the largest gaps between the judge and the rule computed here (PROPS_GAP_*),
   * which the tolerances on them are measured by */
  double gap[4];
  /* the known failures (--known FILE): "P NAME" a line, P one of PROPS_LETTERS */
  size_t nknown;
  char (*known_list)[80];
} props_tally;

/* 1 when t's known list names scene for property p */
int props_known(const props_tally *t, char p, const char *scene);

/* what is done to a trajectory's samples, in this order: theta offset and
 * phase shift growing from 0 at t_from to their size at t_full, and on at that rate;
 * rates times 1 + bleed[i] at sample i (NULL: none); past tail_after, every
 * sample bent away; a rigid motion (rotation by dphi about origin, then a
 * shift); a similarity scaling (lengths lambda, times tau) */
typedef struct props_error {
  double theta, phase;        /* rad; m along the contact path */
  double t_from, t_full;      /* s */
  const double *bleed;        /* one a sample of the trajectory, or NULL */
  double tail_after;          /* s (INFINITY: none) */
  double origin[2], shift[3]; /* m, m, m, rad */
  double lambda, tau;
} props_error;

/* no error at all */
props_error props_none(void);

/* the share of e's ramp reached at time t (0 to t_from, 1 at t_full, and on) */
double props_ramp(const props_error *e, double t);

/* the unit tangent of tr's contact path at sample i (0, 0 where it stands still) */
void props_tangent(const dv_traj *tr, size_t i, double u[2]);

/* the reference of sc's body solved again, at rtol 1e-13 and atol 1e-14 (not
 * the default 1e-12, 1e-13: other steps, so not the reference's own samples)
 * and without the fold (the thin disk stepped to the end), from sc's start
 * moved by nudge (rad, rad/s by RED_TH .. RED_VPS; NULL: none), over sc's
 * duration and output_dt times clock (1: as sc): DV_OK or < 0 */
int props_solve_from(const dv_scenario *sc, const double *nudge, double clock, dv_traj *out,
                     dv_error *err);
/* the same from sc's own start on its own clock */
int props_solve(const dv_scenario *sc, dv_traj *out, dv_error *err);

/* judge the samples of tr, with err added, against sc as diskval judge
 * does (pose: in the pose form) into c: DV_OK, or < 0 (a refusal: err) */
int props_judge(const dv_scenario *sc, const dv_traj *tr, const props_error *e, int pose,
                dv_comparison *c, dv_error *err);

/* sc with overrides ("section.key=value") into out: DV_OK or DV_EINPUT */
int props_with(const dv_scenario *sc, const char *const *sets, size_t n, dv_scenario *out,
               dv_error *err);

/* scene index of seed as props checks it (props_gen.c): the generator's, or,
 * where the generator's compares nothing (its reference ends within 5
 * samples or leaves the friction cone in the first tenth: plain 0), one
 * drawn again as periodic or unstable; its kind (props_kind, or the
 * generator's). DV_OK, or < 0 */
int props_generate(uint64_t seed, size_t index, int plain, dv_gen_scene *g, dv_scenario *sc,
                   int *kind, dv_error *err);

/* one scene and where its failures go */
typedef struct props_scene_ctx {
  uint64_t seed;
  size_t index;
  int kind; /* props_kind, or the generator's dv_gen_kind */
  dv_gen_scene g;
  dv_scenario sc;
  FILE *fp;
  props_tally *t;
} props_scene_ctx;

/* a failure of property prop naming metric (PROPS_NO_METRIC: none) of s, one line */
void props_fail(props_scene_ctx *s, int prop, int metric, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* the failure lines of r, joined */
const char *props_failures(const dv_engine_result *r);

/* metric m failed in r (its name in a failure line) */
int props_names(const dv_engine_result *r, dv_metric_id m);

/* the properties over scene index of seed (which: bit i for property i;
 * plain: the generator's scenes only), each failure one line on fp */
void props_scene(uint64_t seed, size_t index, unsigned which, int plain, props_tally *t, FILE *fp);

#endif
