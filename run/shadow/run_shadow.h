/* run_shadow: what the scene does to an engine's early error, at each time.
 *
 * Shadowing is the one excuse for an engine's error. The reference of the
 * scene's body is run again from its start nudged by +- the engine's early
 * error in each reduced direction (run_horizon.h); at each of the
 * reference's samples the shadow is how far those runs have spread from it
 * so far (a running maximum over time and over the runs):
 *   DV_SHADOW_THETA   |theta - theta_ref| (rad)
 *   DV_SHADOW_PATH    |contact - contact_ref| (m)
 *   DV_SHADOW_PHASE   the phase error along the reference's path (m, run_phase.h)
 *   DV_SHADOW_LAG     |t_k - t_k,ref| of the turns made so far (s, run_turning.h)
 * INFINITY past a nudged run's end (it lay down sooner: nothing past it is
 * predictable). An engine's pointwise error e(t) is judged against its limit
 * plus the shadow s(t): the part of it s excuses is max(0, e - s) short of e.
 */
#ifndef DV_RUN_SHADOW_H
#define DV_RUN_SHADOW_H

#include "run_compare.h"

typedef enum dv_shadow_kind {
  DV_SHADOW_THETA = 0,
  DV_SHADOW_PATH,
  DV_SHADOW_PHASE,
  DV_SHADOW_LAG,
  DV_SHADOW_N
} dv_shadow_kind;

typedef struct dv_shadow {
  size_t n;                  /* the reference's samples */
  double *env[DV_SHADOW_N];  /* each measure's spread up to the reference's sample i */
} dv_shadow;

/* n samples, every spread 0: 0, or -1 out of memory */
int dv_shadow_alloc(dv_shadow *s, size_t n);
void dv_shadow_free(dv_shadow *s); /* NULL-safe */
/* from's spreads added to into's (the same n): directions' spreads together */
void dv_shadow_sum(dv_shadow *into, const dv_shadow *from);
/* every spread 0 again */
void dv_shadow_clear(dv_shadow *s);

/* one nudged run's spread from ref added to into: its running maximum of
 * each measure, INFINITY past its last sample shared with ref */
int dv_shadow_add_run(dv_shadow *into, const dv_traj *run, const dv_traj *ref);

/* e's error series against ref at ref's samples up to t_end: theta, path
 * and phase (NAN where e has no sample at that time, or past t_end) into
 * err[DV_SHADOW_THETA .. DV_SHADOW_PHASE] (ref->n each); 0, or -1 out of memory */
int dv_shadow_errors(const dv_traj *e, const dv_traj *ref, double t_end, double *err[3]);

/* room for an error series against a reference of nref samples (err[3],
 * dv_shadow_errors) and for the turning lags of a run of ne samples against
 * it (t, lag: dv_run_turning_lags) */
typedef struct dv_shadow_scratch {
  double *err[3], *t, *lag;
} dv_shadow_scratch;
int dv_shadow_scratch_alloc(dv_shadow_scratch *s, size_t nref, size_t ne); /* 0, or -1 */
void dv_shadow_scratch_free(dv_shadow_scratch *s);

/* the spread of kind at time t (the reference's first sample at or after t;
 * its last past the end) */
double dv_shadow_at(const dv_shadow *s, const dv_traj *ref, dv_shadow_kind kind, double t);

#endif
