/* dv_search: the cheapest settings that meet a tolerance, and stability
 * limits, by bracketing and bisection over probe runs. */
#include "search_best.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "scenario.h"

/* what a search varies: the engine's declared keys, and the names of its choices */
typedef struct space {
  const char *engine;
  const dv_engine_search *search;
  const dv_setting_spec *choice;     /* the choice key's spec */
  char choice_key[96], step_key[96]; /* engines.SECTION.KEY */
  double lo, hi;                     /* range of the step */
} space;
typedef struct ctx {
  const dv_scenario *sc; /* loaded once: every probe varies it in memory */
  space sp;
  dv_search *out;
} ctx;

/* one probe: choice (NULL: the scenario's) and step */
static int probe(ctx *c, const char *choice, double step, dv_error *err) {
  dv_search *s = c->out;
  if (s->nprobes == DV_SEARCH_MAX_PROBES) /* not with at most DV_SEARCH_MAX_CHOICES */
    return dv_fail(err, DV_ESYSTEM, "%s: more than %d probes", c->sp.engine, DV_SEARCH_MAX_PROBES),
           -1;
  dv_probe *p = &s->probes[s->nprobes++];
  char over[2][160];
  const char *ptrs[2];
  size_t n = 0;
  snprintf(over[n], sizeof over[n], "%s=%.9g", c->sp.step_key, step);
  ptrs[n] = over[n];
  n++;
  if (choice) {
    snprintf(over[n], sizeof over[n], "%s=%s", c->sp.choice_key, choice);
    ptrs[n] = over[n];
    n++;
  }
  snprintf(p->choice, sizeof p->choice, "%s", choice ? choice : "default");
  p->step = step;
  if (dv_search_sweep_probe(c->sc, c->sp.engine, ptrs, n, &p->point, err)) return -1;
  const double e = p->point.metric[DV_THETA_MAX_ERR];
  /* a run that lay down before the reference's end compared too short a window */
  const int fell = p->point.verdict == DV_VERDICT_ENDED_BY_EVENT;
  p->state = !p->point.ok || fell            ? DV_PROBE_FAILED
             : e <= s->margin * s->tolerance ? DV_PROBE_MEETS
             : e <= s->tolerance             ? DV_PROBE_MARGINAL
                                             : DV_PROBE_EXCEEDS;
  p->pass = p->state == DV_PROBE_MEETS || (s->margin >= 1.0 && p->state == DV_PROBE_MARGINAL);
  p->steps_per_sim_s = p->point.sim_s > 0.0 ? (double)p->point.steps / p->point.sim_s : NAN;
  p->cost = NAN;
  return p->pass;
}

/* largest passing step for choice: bracket from start by factors of 2, then
 * bisect on a log scale; returns the passing step or NAN, sets *fail_probe */
static double largest(ctx *c, const char *choice, double start, int *fail_probe, dv_error *err) {
  double pass = NAN, fail = NAN, h = start;
  *fail_probe = -1;
  for (int i = 0; i < DV_SEARCH_BRACKET; i++) {
    const int ok = probe(c, choice, h, err);
    if (ok < 0) return pass;
    if (ok) {
      pass = h;
      if (!isnan(fail) || h * 2.0 > c->sp.hi) break;
      h *= 2.0;
    } else {
      fail = h;
      *fail_probe = (int)c->out->nprobes - 1;
      if (!isnan(pass) || h / 2.0 < c->sp.lo) break;
      h /= 2.0;
    }
  }
  for (int i = 0; i < DV_SEARCH_BISECTIONS && !isnan(pass) && !isnan(fail) &&
                  fmax(pass, fail) / fmin(pass, fail) > DV_SEARCH_RESOLUTION;
       i++) {
    const double mid = sqrt(pass * fail);
    const int ok = probe(c, choice, mid, err);
    if (ok < 0) break;
    if (ok)
      pass = mid;
    else {
      fail = mid;
      *fail_probe = (int)c->out->nprobes - 1;
    }
  }
  return pass;
}

static int setup(const dv_scenario *sc, const char *engine, double tol, dv_search *out, ctx *c,
                 double *start, dv_error *err) {
  memset(out, 0, sizeof *out);
  const dv_engine_type *type = dv_engine_find(engine);
  const dv_engine_search *search = type ? type->search : NULL;
  const dv_engine_type *owner = search ? dv_engine_find(search->section) : NULL;
  if (!search || !owner || !owner->settings)
    return dv_fail(err, DV_EINPUT, "no search space for engine '%s'", engine);
  if (!(tol > 0.0)) return dv_fail(err, DV_EINPUT, "the tolerance must be > 0");
  *start = dv_scenario_get(sc, search->section, search->step_key);
  *c = (ctx){.sc = sc, .out = out};
  c->sp.engine = engine;
  c->sp.search = search;
  c->sp.choice = dv_settings_find(owner->settings, search->choice_key);
  size_t nchoices = 0;
  while (c->sp.choice && dv_setting_choice(c->sp.choice, nchoices)) nchoices++;
  if (nchoices > DV_SEARCH_MAX_CHOICES)
    return dv_fail(err, DV_EINPUT, "%s: %zu choices of %s, a search takes at most %d", engine,
                   nchoices, search->choice_key, DV_SEARCH_MAX_CHOICES);
  snprintf(c->sp.choice_key, sizeof c->sp.choice_key, "engines.%s.%s", search->section,
           search->choice_key);
  snprintf(c->sp.step_key, sizeof c->sp.step_key, "engines.%s.%s", search->section,
           search->step_key);
  c->sp.lo = search->lo;
  c->sp.hi = search->hi;
  snprintf(out->engine, sizeof out->engine, "%s", engine);
  snprintf(out->choice_key, sizeof out->choice_key, "%s", c->sp.choice_key);
  snprintf(out->step_key, sizeof out->step_key, "%s", c->sp.step_key);
  out->tolerance = tol;
  out->margin = 1.0;
  out->best = out->first_failure = -1;
  out->limit = NAN;
  return DV_OK;
}

/* the calibration of choice, or NULL */
static const dv_step_cost *step_cost_of(const dv_search *s, const char *choice) {
  for (size_t k = 0; k < s->nchoices; k++)
    if (!strcmp(s->step_cost[k].choice, choice)) return &s->step_cost[k];
  return NULL;
}

/* seconds per step of every choice probed: the median of wall / steps over
 * its probes that ran; then every probe's cost */
static void calibrate(dv_search *s) {
  double per_step[DV_SEARCH_MAX_PROBES];
  for (size_t i = 0; i < s->nprobes; i++) {
    const char *choice = s->probes[i].choice;
    if (step_cost_of(s, choice) || s->nchoices == DV_SEARCH_MAX_CHOICES) continue;
    size_t n = 0;
    for (size_t j = i; j < s->nprobes; j++) {
      const dv_sweep_point *q = &s->probes[j].point;
      if (!strcmp(s->probes[j].choice, choice) && q->steps > 0 && q->wall_s > 0.0)
        per_step[n++] = q->wall_s / (double)q->steps;
    }
    dv_step_cost *k = &s->step_cost[s->nchoices++];
    snprintf(k->choice, sizeof k->choice, "%s", choice);
    k->runs = (int)n;
    k->median = k->min = k->max = NAN;
    if (!n) continue;
    gsl_stats_minmax(&k->min, &k->max, per_step, 1, n);
    k->median = gsl_stats_median(per_step, 1, n);
  }
  for (size_t i = 0; i < s->nprobes; i++) {
    const dv_step_cost *k = step_cost_of(s, s->probes[i].choice);
    s->probes[i].cost = k ? s->probes[i].steps_per_sim_s * k->median : NAN;
  }
}

/* whether probe a beats probe b: fewer steps within a choice; across choices
 * the lower cost, unless the costs lie within the calibrations' spread (a tie
 * that timing noise could turn), where fewer steps win */
static int cheaper(const dv_search *s, size_t a, size_t b) {
  const dv_probe *pa = &s->probes[a], *pb = &s->probes[b];
  if (!(pa->cost >= 0.0)) return 0;
  if (!(pb->cost >= 0.0)) return 1;
  if (strcmp(pa->choice, pb->choice)) {
    const dv_step_cost *ka = step_cost_of(s, pa->choice), *kb = step_cost_of(s, pb->choice);
    const double spread = fmax(ka->max / ka->min, kb->max / kb->min);
    const double ratio = fmax(pa->cost, pb->cost) / fmin(pa->cost, pb->cost);
    if (!(ratio <= spread)) return pa->cost < pb->cost;
  }
  return pa->steps_per_sim_s < pb->steps_per_sim_s;
}

/* probe every choice (best), or only the scenario's (stability) */
static int search(const dv_scenario *sc, const char *engine, double tol, int every_choice,
                  dv_search *out, dv_error *err) {
  ctx c;
  double start = NAN;
  const int status = setup(sc, engine, tol, out, &c, &start, err);
  if (status) return status;
  if (!every_choice) {
    out->limit = largest(&c, NULL, start, &out->first_failure, err);
    return DV_OK;
  }
  out->margin = DV_SEARCH_MARGIN;
  const char *choice;
  for (size_t i = 0; c.sp.choice && (choice = dv_setting_choice(c.sp.choice, i)); i++) {
    int fail;
    largest(&c, choice, start, &fail, err);
  }
  calibrate(out);
  for (size_t i = 0; i < out->nprobes; i++)
    if (out->probes[i].pass && (out->best < 0 || cheaper(out, i, (size_t)out->best)))
      out->best = (int)i;
  return DV_OK;
}

int dv_search_best(const dv_scenario *sc, const char *engine, double tol, dv_search *out,
                   dv_error *err) {
  return search(sc, engine, tol, 1, out, err);
}

int dv_search_stability(const dv_scenario *sc, const char *engine, double tol, dv_search *out,
                        dv_error *err) {
  return search(sc, engine, tol, 0, out, err);
}

const char *dv_search_failure_mode(const dv_probe *p) {
  const dv_sweep_point *q = &p->point;
  if (p->pass) return "none";
  if (q->failure != DV_FAILURE_NONE) return dv_failure_name(q->failure);
  switch (q->verdict) {
    case DV_VERDICT_ENDED_BY_EVENT:
      return "falls";
    case DV_VERDICT_AGREES:
    case DV_VERDICT_EXCEEDS:
      return "drifts";
    default:
      return "error";
  }
}

const char *dv_probe_state_name(dv_probe_state state) {
  static const char *const NAMES[] = {"meets", "marginal", "exceeds", "failed"};
  return state >= DV_PROBE_MEETS && state <= DV_PROBE_FAILED ? NAMES[state] : "failed";
}
