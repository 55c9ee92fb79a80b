/* league_cell: the cells of one object and one engine, one per target. */
#ifndef DV_LEAGUE_CELL_H
#define DV_LEAGUE_CELL_H

#include "league.h"
#include "report_suite_run.h"
#include "scenario.h"

/* what a pair of object and engine is run with */
typedef struct dv_league_pair {
  const dv_scenario *sc;        /* the object, loaded once with the --set overrides */
  const dv_league_object *object;
  const dv_league_engine *engine;
  const double *targets;
  size_t ntargets;
  double cost_cap;
  const char *out_dir;          /* the league's: reports go to compare/OBJECT/ENGINE-TARGET/ */
  const dv_report_explain *explain; /* the cause of a backing compare that fails */
  const struct dv_comparison *refs; /* the object's references, run once for the pair's
                                       searches (dv_league_pair_references); may be NULL */
} dv_league_pair;

/* the references of pair's object for its engine: the thin disk, its
 * amplification and the matched reference of the engine's body; NULL when
 * one fails (each probe then runs its own). Free with dv_league_pair_references_free */
struct dv_comparison *dv_league_pair_references(const dv_league_pair *pair);
void dv_league_pair_references_free(struct dv_comparison *refs);

/* the backing report's folder of a cell, relative to the league's */
void dv_league_report_dir(const char *object, const char *engine, double target, char *out,
                          size_t size);

/* cell k of pair: best's search within the targets and the cost cap, then
 * the compare at its settings that backs it (its report written); the
 * cell's key and file fields are the caller's */
void dv_league_cell_run(const dv_league_pair *pair, size_t k, dv_league_cell *cell);

#endif
