/* dv_run: one scenario through the references and the engines, compared.
 *
 * Every engine is compared with the reference for the body it simulates:
 * the geometry-matched disk (engine "matched", same half-thickness) for a
 * cylinder, the thin disk for a thin or ellipsoid stand-in; and, in any
 * case, with the thin disk. The compared window ends where the reference
 * ends (its event or validity limit). Tolerances ([tolerance] and
 * [tolerance.ENGINE], the engine's own first) apply to the metrics against
 * the engine's own reference.
 */
#ifndef DV_RUN_H
#define DV_RUN_H

#include "run_compare.h"
#include "run_verdict.h"
#include "dv_engine.h"
#include "scenario.h"

#define DV_MAX_ENGINES 4
#define DV_MAX_FAILURES (DV_NMETRICS + 1)

typedef struct dv_engine_result {
  const dv_engine_type *engine;
  int status; /* of the engine's run */
  dv_engine_stats stats;
  dv_traj traj;          /* the engine's samples (up to a failure) */
  double wall_s;         /* wall-clock time of the engine's run, s */
  double half_thickness; /* of its reference: 0 for the thin disk */
  dv_traj matched;       /* that reference's samples when half_thickness > 0 */
  dv_engine_stats matched_stats;
  dv_metrics vs_ref, vs_thin;    /* against its own reference, and the thin disk */
  double tolerance[DV_NMETRICS]; /* limits, INFINITY where none */
  int pass;
  dv_verdict verdict;
  size_t nfailures;
  char failures[DV_MAX_FAILURES][256];
} dv_engine_result;

typedef struct dv_comparison {
  const dv_scenario *sc;
  dv_traj thin; /* the thin-disk reference */
  dv_engine_stats thin_stats;
  double thin_valid_end; /* where rolling stops describing the physics, s */
  size_t n;
  dv_engine_result r[DV_MAX_ENGINES];
  int pass; /* every engine passed */
} dv_comparison;

/* run the engines on sc and compare; the references run on ref_sc (NULL:
 * sc; a tighter reference for sweeps of the reference's own settings).
 * DV_OK (see out->pass), or < 0 when a reference fails */
int dv_run_scenario(const dv_scenario *sc, const dv_scenario *ref_sc,
                    const dv_engine_type *const *engines, size_t n, dv_comparison *out,
                    dv_error *err);

void dv_run_comparison_free(dv_comparison *c);

#endif
