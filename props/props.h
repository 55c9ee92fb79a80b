/* props: the verdict checked by its properties over generated scenes
 * (engine_generate.h): the exact reference of the scene's body judged as an
 * engine passes (a); a known error added fails exactly the metric it targets
 * past its limit (b); a rigid motion or a similarity scaling of the scene
 * changes no verdict (c); no metric reads past the compared window, and no
 * empty window is judged (d); a thickness going to 0 gives the thin verdict
 * and numbers (e). The library runs in-process: references and the judge
 * path (run/file/), as diskval judge runs them. */
#ifndef DV_PROPS_H
#define DV_PROPS_H

#include <stdio.h>

#include "engine_generate.h"
#include "run_scenario.h"

enum { PROP_GEN = 0, PROP_A, PROP_B, PROP_C, PROP_D, PROP_E, PROP_N };

/* what one scene gave each property: checks run, failures, skips (not judged) */
typedef struct props_tally {
  long checks[PROP_N], failures[PROP_N], skipped[PROP_N];
  /* property b: per metric targeted, the brackets run and those wrong */
  long b_runs[DV_NMETRICS], b_wrong[DV_NMETRICS];
  long known[PROP_N]; /* failures of a scene the known list names for that property */
  /* the known failures (--known FILE): "P NAME" a line, P one of gabcde */
  size_t nknown;
  char (*known_list)[80];
} props_tally;

/* 1 when t's known list names scene for property p */
int props_known(const props_tally *t, char p, const char *scene);

/* what is done to a trajectory's samples, in this order: theta offset and
 * phase shift growing from 0 at t_from to their size at t_full, and on;
 * past tail_after, every sample bent away; a rigid motion (rotation by dphi
 * about origin, then a shift); a similarity scaling (lengths lambda, times tau) */
typedef struct props_error {
  double theta, phase;        /* rad; m along the contact path */
  double t_from, t_full;      /* s */
  double tail_after;          /* s (INFINITY: none) */
  double origin[2], shift[3]; /* m, m, m, rad */
  double lambda, tau;
} props_error;

/* no error at all */
props_error props_none(void);

/* the reference of sc's body solved again, at rtol 1e-13 and atol 1e-14 (not
 * the default 1e-12, 1e-13: other steps, so not the reference's own samples)
 * and without the fold (the thin disk stepped to the end): DV_OK or < 0 */
int props_solve(const dv_scenario *sc, dv_traj *out, dv_error *err);

/* judge the samples of tr, with err added, against sc as diskval judge
 * does (pose: in the pose form) into c: DV_OK, or < 0 (a refusal: err) */
int props_judge(const dv_scenario *sc, const dv_traj *tr, const props_error *e, int pose,
                dv_comparison *c, dv_error *err);

/* sc with overrides ("section.key=value") into out: DV_OK or DV_EINPUT */
int props_with(const dv_scenario *sc, const char *const *sets, size_t n, dv_scenario *out,
               dv_error *err);

/* the properties over scene index of seed (which: bit i for property i),
 * each failure one line on fp */
void props_scene(uint64_t seed, size_t index, unsigned which, props_tally *t, FILE *fp);

#endif
