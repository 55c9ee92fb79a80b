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

/* what a cell's backing report says of its engine's run (its report.json) */
typedef struct dv_league_backing {
  double theta_max_err, path_max_err; /* rad, m; NAN when nothing was compared */
  double theta_limit, path_limit;     /* the limits it was given (the cell's targets), before
                                         the shadow's spread */
  double wall_per_sim_s, sim_s;       /* s of wall a simulated s; simulated s */
  long steps;                         /* -1: none */
  int slips;                          /* slip_max over its limit */
  double step;                        /* the step it ran at, when asked for (NAN: not read) */
  char choice[32];                    /* the choice it ran with, when asked for */
  char verdict[24];                   /* pass, fail, not judged */
  char cause[320], version[96];
  char failure[240]; /* its first failure line, without "SCENARIO: ENGINE: " and the cause */
} dv_league_backing;

/* a cell is reached only when its backing compare passed, judged, with theta
 * and path within the cell's targets and a disk that does not slide: c's
 * verdict and errors (taken from the report), slips from it */
int dv_league_backed(const dv_league_cell *c, int slips);

/* the backing report's folder of c (its object, engine, target), relative to the league's */
void dv_league_backing_dir(const dv_league_cell *c, char *out, size_t size);

/* a cached cell c may be reused: 0 when what it claims is what its backing
 * report (in out_dir/compare/, resolved) says (errors, cost, steps, verdict,
 * cause, version, limits, settings and whether it is reached), or, a cell
 * that cannot model sc, when compare's rule still says so; else -1 and why */
int dv_league_cell_check(const char *out_dir, const dv_league_cell *c, const dv_scenario *sc,
                         char *why, size_t size);

/* cell k of pair: best's search within the targets and the cost cap, then
 * the compare at its settings that backs it (its report written); the
 * cell's key and file fields are the caller's */
void dv_league_cell_run(const dv_league_pair *pair, size_t k, dv_league_cell *cell);

#endif
