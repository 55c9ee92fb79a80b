/* league_run: the league's cells, from its cache or run in the exec pool. */
#ifndef DV_LEAGUE_RUN_H
#define DV_LEAGUE_RUN_H

#include "dv_engine.h"
#include "league.h"
#include "report_suite_run.h"
#include "scenario.h"

typedef struct dv_league_request {
  const dv_scenario *objects; /* loaded, with the --set overrides */
  size_t nobjects;
  const dv_engine_type *const *engines; /* NULL-ended */
  const double *targets;
  size_t ntargets;
  double cost_cap;
  const char *const *overrides; /* the --set overrides, part of every cell's key */
  size_t noverrides;
  const char *out_dir; /* owned by the caller, made */
  int jobs;
  const dv_report_explain *explain;
  double timeout; /* s of wall time a pair of object and engine may take (<= 0: no limit;
                     none under MPI): its cells not ended then are errors */
} dv_league_request;

/* no input (inputs[0..n), the objects' files) lies in out_dir's cells/ or
 * compare/, which the league writes (a cached cell, a backing report's
 * file); else DV_EINPUT naming it. With dv_io_check_inputs for the league's
 * fixed-name files, before anything is written. */
int dv_league_check_inputs(const char *out_dir, const char *const *inputs, size_t n,
                           dv_error *err);

/* none of the --set overrides sets a key the league gives every cell itself:
 * an engine's step or choice (engines[]'s search varies them) or the theta
 * limit (--targets); else DV_EINPUT naming the key and what sets it */
int dv_league_check_overrides(const dv_engine_type *const *engines, const char *const *overrides,
                              size_t n, dv_error *err);

/* the cell's file in the cache, relative to the league's folder */
void dv_league_cache_name(const dv_league_cell *c, char *out, size_t size);

/* fill lg (its cells allocated: dv_league_free) and run what the cache in
 * out_dir/cells/ does not hold. DV_OK; DV_EVENT when a stop signal ended it
 * (the cells not run say so); an error otherwise. Under MPI a worker rank
 * returns DV_EVENT + 1 (rank 0 has the results). */
#define DV_LEAGUE_WORKER (DV_EVENT + 1)
int dv_league_run(const dv_league_request *rq, dv_league *lg, dv_error *err);

void dv_league_free(dv_league *lg); /* NULL-safe */

#endif
