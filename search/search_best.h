/* dv_search: searches over an engine's settings by probing runs.
 *
 * best: for every choice of the engine's discrete setting (MuJoCo's
 * integrator, ODE's stepper, the reference's integrator), the largest
 * timestep (rtol for the reference) whose theta error is at most
 * DV_SEARCH_MARGIN times the tolerance (a margin below the limit):
 * doubling or halving from the default until the answer changes, then six
 * bisections on a log scale; the cheapest passing probe wins. The error is
 * assumed to grow with the step; a probe that diverges counts as too large.
 * Cost is counted, not timed, so the same input gives the same answer: a
 * probe costs its steps per simulated second times its choice's seconds per
 * step, calibrated once per search as the median of wall / steps over that
 * choice's probes (min and max kept). Two choices whose costs lie within
 * their calibrations' spread (max / min) of each other are a tie, won by
 * fewer steps per simulated second.
 *
 * stability: the largest timestep at which a run stays finite and within a
 * theta error, by the same bracketing and bisection; every probe recorded.
 */
#ifndef DV_SEARCH_H
#define DV_SEARCH_H

#include <stddef.h>

#include "search_sweep.h"

#define DV_SEARCH_BRACKET 24    /* probes at most to bracket the limit, by factors of 2 */
#define DV_SEARCH_BISECTIONS 6  /* probes at most then to narrow it */
#define DV_SEARCH_RESOLUTION 1.1 /* narrowed until the failing step is within 10 % of the
                                    passing one: the cost, ~ 1 / step, to 10 % */
#define DV_SEARCH_MAX_CHOICES 8 /* choices of the discrete setting a search takes */
#define DV_SEARCH_MAX_PROBES (DV_SEARCH_MAX_CHOICES * (DV_SEARCH_BRACKET + DV_SEARCH_BISECTIONS))
#define DV_SEARCH_MARGIN 0.5 /* best: the error it accepts, as a share of the tolerance */
#define DV_SEARCH_TIE 0.01   /* errors within 1 % at the same step are the same error */
#define DV_SEARCH_TIE_COST 1.5 /* ... and a choice whose steps cost this much more is not searched */

/* a probe's state, one word each: meets (within the margin), marginal (within
 * the tolerance, above the margin), exceeds, failed (the run did not complete,
 * or lay down before the reference's end) */
typedef enum dv_probe_state {
  DV_PROBE_MEETS = 0,
  DV_PROBE_MARGINAL,
  DV_PROBE_EXCEEDS,
  DV_PROBE_FAILED
} dv_probe_state;

/* the seconds one step of a choice takes, from its probes' timed runs */
typedef struct dv_step_cost {
  char choice[32];
  double median, min, max; /* s per step */
  int runs;                /* timed runs it is taken from */
} dv_step_cost;

typedef struct dv_probe {
  char choice[32];      /* the discrete setting, e.g. "rk4" */
  double step;          /* the continuous setting, e.g. the timestep, as the run was given it */
  dv_sweep_point point; /* what the run gave */
  int pass;             /* ok and theta error within margin x tolerance */
  dv_probe_state state;
  double steps_per_sim_s; /* the work: steps per simulated second */
  double cost;            /* s per simulated s: steps_per_sim_s x the choice's s per step */
} dv_probe;

typedef struct dv_search {
  char engine[32];
  char choice_key[96], step_key[96]; /* e.g. engines.mujoco.integrator, engines.mujoco.timestep */
  double tolerance;                  /* theta_max_err limit, rad */
  double margin; /* a probe passes at margin x tolerance (best: DV_SEARCH_MARGIN) */
  size_t nprobes;
  dv_probe probes[DV_SEARCH_MAX_PROBES];
  int best;          /* index of the cheapest passing probe, or -1 */
  double limit;      /* stability: largest passing step, NAN when none */
  int first_failure; /* stability: the probe just above the limit, or -1 */
  size_t nchoices;   /* best: the calibration of each choice probed */
  dv_step_cost step_cost[DV_SEARCH_MAX_CHOICES];
  char skipped[512]; /* best: the choices not searched and why ("" when none) */
  double path_tolerance; /* m: a probe meets only with path_max_err within margin x it too
                            (NAN: theta alone) */
  char stopped[512]; /* bounded: the choices whose search a bound ended, and which ("" none) */
} dv_search;

/* what bounds a search besides its tolerance, and what its probes reuse
 * (dv_search_best_bounded) */
struct dv_comparison;
typedef struct dv_search_bounds {
  int with_path;   /* the path too, at the scene's path limit scaled as the default theta
                      limit (DV_LIMIT_THETA) is scaled to the tolerance (taken from the first
                      probe that compared), and the slip within its limit */
  double cost_cap; /* s of wall a simulated s: no finer step is probed whose cost, forecast
                      from the choice's last probe, is above it (<= 0: none) */
  int stop_at_floor; /* a choice whose error falls at an order below DV_FLOOR_ORDER over
                        two halvings of the step, both exceeding, is searched no further */
  const struct dv_comparison *refs; /* the references of the scene already run, reused by
                                       every probe (dv_search_sweep_probe_in); NULL: each
                                       probe runs its own */
} dv_search_bounds;

/* the cheapest settings of engine meeting theta_max_err <= DV_SEARCH_MARGIN tol */
int dv_search_best(const dv_scenario *sc, const char *engine, double tol, dv_search *out,
                   dv_error *err);

/* dv_search_best within bounds; out->stopped says which bound ended which choice */
int dv_search_best_bounded(const dv_scenario *sc, const char *engine, double tol,
                           const dv_search_bounds *bounds, dv_search *out, dv_error *err);

/* the largest timestep (engine's default discrete setting) within tol */
int dv_search_stability(const dv_scenario *sc, const char *engine, double tol, dv_search *out,
                        dv_error *err);

/* the failure mode of a probe: "NaN", "silent reset", "energy blow-up",
 * "sinks", "lost contact", "falls", "drifts" (exceeds the error), "error" */
const char *dv_search_failure_mode(const dv_probe *p);

/* the word for a state */
const char *dv_probe_state_name(dv_probe_state state);

#endif
