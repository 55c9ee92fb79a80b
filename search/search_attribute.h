/* search_attribute: why a contact engine disagrees with the thin disk.
 *
 * The engine's max theta error against the thin disk, e, is split into
 * shares, each a measured difference (all at the scenario's other settings):
 *   geometry  e with the engine's stand-in shape minus e with the exact thin
 *             disk (zero when the engine already models the thin disk)
 *   time      Richardson over dt, dt/2, dt/4 with the thin disk: the part
 *             that vanishes as dt -> 0, e(dt) - e(0); reported only where the
 *             errors fall with the step (an order p > 0.2, and e(dt/4) at
 *             least 10% below e(dt)); else zero, "flat"
 *   contact   at dt/4, e minus e with a stiffer contact and 10x friction
 *   rest      what the three leave (interactions, the solver's tolerance)
 * Where the library raises the contact softness to a number of steps (MuJoCo's
 * solref), the softness follows the step in every probe.
 *
 * The cause is not a share: every knob the engine declares is changed alone
 * (search_attribute_knobs.c: the integrator or stepper to each other value,
 * the step, the contact softness, the friction, a stand-in's shape) and the
 * cause is the knob whose change removes the error (every metric over its
 * limit back within it; with none over, theta against the thin disk halved),
 * named with the numbers; none is named where no change removes it.
 */
#ifndef DV_SEARCH_ATTRIBUTE_H
#define DV_SEARCH_ATTRIBUTE_H

#include <stddef.h>

#include "dv_error.h"
#include "scenario.h"

/* the measured errors attribution splits (rad) */
typedef struct dv_attribution_errors {
  double stand_in; /* against the thin disk, at the scenario's settings */
  double thin;     /* the same with the exact thin-disk geometry */
  double dt[3];    /* thin geometry at dt, dt/2, dt/4 */
  double stiff;    /* at dt/4 with a stiffer contact and more friction */
} dv_attribution_errors;

/* one knob the engine declares, changed alone (the rest as the scene derives it) */
#define DV_MAX_KNOBS 12
typedef struct dv_knob_probe {
  const char *knob; /* "integrator", "timestep", "contact softness", "friction", "geometry" */
  char change[64];  /* "rk4 -> implicit", "5e-05 -> 1.25e-05 s" */
  double metric[DV_NMETRICS]; /* against the engine's reference; NAN where the run failed */
  double theta_thin;          /* theta_max_err against the thin disk (own_reference: its own) */
  double worst;               /* over the metrics judged: value / limit (or / the base's) */
  int ok;                     /* the run ran through its window */
  int removes;                /* every metric judged is within its limit (or halved) */
} dv_knob_probe;

typedef struct dv_attribution {
  dv_attribution_errors e;
  /* causes over every knob: the base run, what is judged, each knob changed */
  double base[DV_NMETRICS];  /* the scenario's run, against the engine's reference */
  double limit[DV_NMETRICS]; /* the verdict's limits */
  double base_theta_thin;
  unsigned judged; /* bit m: metric m exceeds its limit; 0: theta against the thin disk */
  size_t nknobs;
  dv_knob_probe knobs[DV_MAX_KNOBS];
  int cause;        /* the knob whose change removes the error with the smallest worst; -1: none */
  double timestep;  /* s, the scenario's */
  int has_stand_in; /* the scenario's geometry is not the thin disk */
  double geometry, time, contact, rest; /* rad; they add up to e.stand_in */
  double order;                         /* observed order of the time error; NAN: flat */
  /* measured against the engine's own reference (the matched one: it simulates
   * the scene's cylinder), not the thin disk; the probes keep its shape */
  int own_reference;
  char not_measured[320]; /* "": measured; else why the scenario's run measured nothing */
  /* quick (dv_search_cause): knobs in the signature's order, stopped at the first
   * that removes the error or at the budget */
  int quick;
  double window;     /* s: base and knobs measured from the start to here; 0: the whole scene */
  double runs_spent; /* the knob runs made, in runs of the scene (or of its window) */
  char untried[160]; /* the knobs quick did not try, "" */
} dv_attribution;

/* a scenario and an engine to probe with overrides */
struct dv_engine_type;
typedef struct dv_prober {
  const struct dv_scenario *sc; /* loaded once: every probe varies it in memory */
  const struct dv_engine_type *engine;
  int own_reference; /* measure against the engine's own reference (the matched
                        one for a cylinder), not the thin disk */
  const struct dv_comparison *refs; /* sc's references, already run (NULL: each probe runs them) */
} dv_prober;

/* the max theta error against the thin disk (or the engine's own reference)
 * of one run with up to four section.key=value overrides (NULL: none); a run
 * that fails is an error */
int dv_search_probe_theta(const dv_prober *pr, double *e, dv_error *err, const char *o1,
                          const char *o2, const char *o3, const char *o4);

/* the shares from measured errors (the maths alone) */
void dv_search_attribute_split(const dv_attribution_errors *e, int has_stand_in,
                               dv_attribution *out);

/* the cause in words: the knob whose change removes the error, with the
 * numbers, "integrator (rk4 -> implicit: path 1.98e-02 -> 1.98e-03 m, energy
 * 0.99 % -> 0.07 %)"; where no knob's change removes it, "none of the knobs
 * (...) removes it" and no cause is named */
void dv_search_attribute_cause(const dv_attribution *a, char *out, size_t size);

/* what dv_search_attribute_knobs will run, in runs of the scene's own cost */
struct dv_engine_type;
double dv_search_attribute_knobs_cost(const struct dv_scenario *sc,
                                      const struct dv_engine_type *engine);

/* how many knobs dv_search_attribute_knobs changes, one run each */
size_t dv_search_attribute_knobs_count(const struct dv_scenario *sc,
                                       const struct dv_engine_type *engine);

/* causes over every knob: pr's scenario run, then each knob its engine
 * declares changed alone (search_attribute_knobs.c), every probe made by pr
 * (its references reused where it carries them); fills the knob part of out */
int dv_search_attribute_knobs(const dv_prober *pr, dv_attribution *out, dv_error *err);

/* the base the knobs are judged against: its metrics, their limits and theta
 * against the thin disk (or its own reference); sets out->judged */
void dv_search_attribute_base(dv_attribution *out, const double *metric, const double *limit,
                              double theta);

/* the knobs engine declares, changed alone against out's base: those named in
 * first[0..nfirst) in that order, then the rest as declared. With a budget
 * (runs of the scene's cost), quick: the first knob always, the next while their
 * runs fit in the budget, none after one removes the error (out->untried names the
 * rest); NULL: every knob. extra ("section.key=value", e.g. a short window) is
 * added to every knob's run (NULL: none); out's base is then the window's, and
 * a knob that removes the error there runs again without it against whole's
 * base (the whole run's), the cause only if it removes that too (that run
 * counts against the budget). With DV_CAUSE_TRACE set, each knob
 * run is a line on stderr ("cause trace: ...") */
int dv_search_attribute_knobs_try(const dv_prober *pr, const char *const *first, size_t nfirst,
                                  const double *budget, const char *extra,
                                  const dv_attribution *whole, dv_attribution *out,
                                  dv_error *err);

/* how compare and suite search an engine's cause (--cause) */
typedef enum dv_cause_mode { DV_CAUSE_NONE = 0, DV_CAUSE_QUICK, DV_CAUSE_FULL } dv_cause_mode;

/* quick's budget: the knob runs after the first knob's, in runs of the whole
 * scene (a knob over a short window costs its share of one) */
#define DV_CAUSE_QUICK_BUDGET 1.0

/* the knobs the failure's signature points to, most likely first, into
 * first[0..max): energy over its limit -> the choice where it is a time
 * integrator (MuJoCo's, Simbody's; a solver's choice never removed a measured
 * error); penetration or a contact failure -> contact softness; slip over its limit
 * -> friction; else the time integrator where the choice is one (MuJoCo's,
 * Simbody's), else (an error that should fall with the step) the step */
struct dv_comparison;
struct dv_engine_result;
size_t dv_search_cause_signature(const struct dv_comparison *c, const struct dv_engine_result *r,
                                 const char **first, size_t max);

/* compare's and suite's cause of r's excess in c: no split. The base is r
 * (the comparison's own run, not run again); full: every knob, as
 * dv_search_attribute; quick: the knobs in the signature's order, each over
 * the window where the error appears where that window is short (the base
 * then run once over it too), stopped at the first that removes the error */
int dv_search_cause(const struct dv_scenario *sc, const struct dv_comparison *c,
                    const struct dv_engine_result *r, dv_cause_mode mode, dv_attribution *out,
                    dv_error *err);

/* probe the engine on the scenario, split its error and try every knob; a probe that fails
 * (diverges, cannot run the scenario) is an error naming it. A scenario whose
 * run measures nothing (a compared window of zero length or too short to
 * judge) is DV_OK with not_measured saying why: no share, no knob, no cause */
struct dv_scenario;
int dv_search_attribute(const struct dv_scenario *sc, const char *engine, dv_attribution *out,
                        dv_error *err);

#endif
