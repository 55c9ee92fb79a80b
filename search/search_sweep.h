/* dv_sweep: speed against error over a grid of engine settings.
 *
 * A sweep varies settings of one engine ("key=v1,v2,..." or, on a log scale,
 * "key=a..b:n"; a key without a section means [engines.ENGINE]) over the
 * cartesian product of the lists. Every point is the scenario, loaded once,
 * with the point's settings (dv_scenario_with: every value is validated like
 * a scenario key, and what the scene derives is derived anew), runs
 * the engine against its reference (dv_run.h) and records the metrics and
 * the cost: wall-clock seconds per simulated second, the median of five runs
 * where one run is shorter than 0.2 s. When the engine is a reference itself
 * (reduced, matched), its reference is the reduced solver stepping onto every
 * sample at rtol 1e-14. Points run in up to jobs processes, each taking the
 * next point as it finishes one.
 */
#ifndef DV_SWEEP_H
#define DV_SWEEP_H

#include <stddef.h>

#include "run_compare.h"
#include "run_verdict.h"
#include "scenario.h"
#include "dv_error.h"

#define DV_SWEEP_MAX_VARY 4
#define DV_SWEEP_MAX_VALUES 64
#define DV_SWEEP_MAX_POINTS 4096
#define DV_SWEEP_MAX_FLOORS 16 /* curves whose floor's cause is attributed */

typedef struct dv_vary {
  char key[96]; /* section.key */
  size_t n;
  char values[DV_SWEEP_MAX_VALUES][32];
} dv_vary;

typedef struct dv_sweep_point {
  char values[DV_SWEEP_MAX_VARY][32]; /* this point's value of each varied key */
  double metric[DV_NMETRICS];         /* against the engine's reference */
  double limit[DV_NMETRICS];          /* the verdict's limits on them */
  double theta_thin;                  /* theta_max_err against the thin disk */
  int thinner; /* not judged only for a body thinner than the scene's: theta_thin measures it */
  double wall_per_sim_s; /* s per simulated s (median where repeated) */
  int timed_runs;        /* engine runs timed: 1, or 5 for a short run */
  long steps;
  double sim_s;  /* simulated seconds the engine ran */
  double wall_s; /* wall seconds of its first run alone */
  int ok;        /* ran through its compared window */
  int pareto;    /* no other ok point is both cheaper and more accurate */
  dv_verdict verdict;
  dv_failure failure; /* why the run failed, as the engine saw it */
  char detail[192];
} dv_sweep_point;

typedef struct dv_sweep {
  char scenario[64]; /* scenario name */
  char engine[32];
  size_t nvary;
  dv_vary vary[DV_SWEEP_MAX_VARY];
  size_t n;
  dv_sweep_point *p; /* n points, the first key varying slowest */
  int interrupted;   /* stopped by SIGINT or SIGTERM: points not run "missing", NaN */
  size_t nfloors;    /* curves with an accuracy floor, and its cause */
  struct {
    char curve[96];
    char cause[200];
  } floors[DV_SWEEP_MAX_FLOORS];
  const char *checkpoint_dir; /* under MPI: tables rewritten after every result */
} dv_sweep;

/* parse "v1,v2" or "a..b:n" (a log range) into out's values; errors begin
 * with as_typed, the option as the user wrote it ("--c 0.05..0.5:8") */
int dv_search_values_parse(const char *list, const char *as_typed, dv_vary *out, dv_error *err);

/* parse "key=v1,v2" or "key=a..b:n" for engine into out */
int dv_search_vary_parse(const char *spec, const char *engine, dv_vary *out, dv_error *err);

/* run the sweep over sc (loaded once, with the common --set overrides).
 * Under mpirun the ranks share the points: rank 0 gets the results, the
 * other ranks return DV_EVENT. */
int dv_search_sweep_run(const dv_scenario *sc, const char *engine, const dv_vary *vary,
                        size_t nvary, int jobs, dv_sweep *out, dv_error *err);

void dv_search_sweep_free(dv_sweep *s); /* NULL-safe */

/* one run of sc in this process with the given key=value overrides
 * (section.key), timed once (no repeats: its cost is steps, see search_best.h) */
int dv_search_sweep_probe(const dv_scenario *sc, const char *engine, const char *const *overrides,
                          size_t n, dv_sweep_point *out, dv_error *err);

/* dv_search_sweep_probe against the references refs already ran (NULL: run
 * them): the thin disk, its amplification and the matched references of refs
 * (a comparison of sc, whose overrides change the engine's settings alone)
 * are not run again. A reference engine (one that tightens its own reference)
 * runs its references all the same. */
struct dv_comparison;
int dv_search_sweep_probe_in(const struct dv_comparison *refs, const dv_scenario *sc,
                             const char *engine, const char *const *overrides, size_t n,
                             dv_sweep_point *out, dv_error *err);

/* mark the Pareto points (theta_max_err against wall_per_sim_s) among ok points */
void dv_search_pareto(dv_sweep_point *p, size_t n);

/* errors within this share of each other tie (for the Pareto front): a
 * point twice the cost for 1e-13 less error is not worth a star */
#define DV_SEARCH_ERROR_TIE 0.01

/* least-squares slope of log(err) against log(h) over the points with
 * err > 0 and h > 0: the observed order of convergence (NAN below 2 points) */
double dv_search_fit_order(const double *h, const double *err, size_t n);

/* how a curve's errors go with the step. Sorted by the step, the floor is
 * the finest steps' errors while each, going to the next coarser step, grows
 * at a local order below DV_FLOOR_ORDER (or falls): errors that have stopped
 * falling with the step (at least 2 points). The order is then fitted only
 * where the errors fall, over the points at least twice the floor, to
 * log(err - floor); without a floor, over every point. (Noise between close
 * steps can end the floor early; points under twice the floor stay out of the
 * fit all the same.) */
#define DV_FLOOR_ORDER 0.3
typedef struct dv_step_fit {
  double order;      /* NAN: fewer than 2 falling points */
  double floor;      /* the floor's median error (rad); NAN: none */
  double floor_step; /* the largest step on the floor; NAN: none */
  size_t nfalling, nfloor;
} dv_step_fit;

void dv_search_fit_convergence(const double *h, const double *err, size_t n, dv_step_fit *out);

/* the label of the curve point k lies on: the engine and its other values */
void dv_search_sweep_curve_label(const dv_sweep *s, size_t k, char *out, size_t size);

/* whether point k is the first point of its curve */
int dv_search_sweep_curve_first(const dv_sweep *s, size_t k);

/* the attributed cause of the floor of curve label (dv_search_sweep_floor_causes), or NULL */
const char *dv_search_sweep_floor_cause(const dv_sweep *s, const char *label);

/* the index of the key that orders a curve: a timestep or rtol, else the last */
size_t dv_search_sweep_curve_key(const dv_sweep *s);

/* 1 when the curve key is the step the engine declares (dv_engine_search:
 * engines.mujoco.timestep, engines.reduced.rtol): only then do the errors
 * have an order of convergence and an accuracy floor to fit, else 0 */
int dv_search_sweep_fits_order(const dv_sweep *s);

/* the fit of the curve through point k (its ok points); DV_ESYSTEM without memory */
int dv_search_sweep_curve_fit(const dv_sweep *s, size_t k, dv_step_fit *out);

/* for every curve over a timestep whose errors end at a floor, its cause from
 * attribution (search_attribute.h) at the largest step on the floor, into
 * s->floors; a probe that fails leaves the cause "unknown: " and why */
int dv_search_sweep_floor_causes(const dv_scenario *sc, dv_sweep *s, dv_error *err);

/* sweep.csv, sweep.json ("orders" empty unless dv_search_sweep_fits_order) and the plots into the
 * existing dir; reference is an optional sweep of the reference's own integrators drawn on the same
 * axes */
int dv_search_sweep_write(const char *dir, const dv_sweep *s, const dv_sweep *reference,
                          dv_error *err);

/* sweep.csv and sweep.json only (no plots): the checkpoint written under MPI */
int dv_search_sweep_write_tables(const char *dir, const dv_sweep *s, dv_error *err);

#endif
