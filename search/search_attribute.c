/* search_attribute: the shares of a contact engine's error (search_attribute.h). */
#include "search_attribute.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dv_clock.h"
#include "dv_engine.h"
#include "dv_phase.h"
#include "run_progress.h"
#include "search_sweep.h"

/* a plateau, where the errors do not fall with the step: an order below
 * MIN_ORDER, or less than MIN_FALL of e(dt) gone at dt/4 */
#define MIN_ORDER 0.2
#define MIN_FALL 0.1

void dv_search_attribute_split(const dv_attribution_errors *e, int has_stand_in,
                               dv_attribution *out) {
  out->e = *e;
  out->has_stand_in = has_stand_in;
  out->geometry = has_stand_in ? e->stand_in - e->thin : 0.0;
  const double d1 = e->dt[0] - e->dt[1], d2 = e->dt[1] - e->dt[2];
  const double p = d1 > 0.0 && d2 > 0.0 ? log2(d1 / d2) : NAN;
  out->order = p > MIN_ORDER && e->dt[0] - e->dt[2] > MIN_FALL * e->dt[0] ? p : NAN;
  /* e(dt) - e(0) = d1 / (1 - 2^-p) for e(h) = e(0) + c h^p */
  out->time = isnan(out->order) ? 0.0 : d1 / (1.0 - pow(2.0, -out->order));
  out->contact = e->dt[2] - e->stiff;
  out->rest = e->stand_in - out->geometry - out->time - out->contact;
}

/* p's theta error against pr's reference (the thin disk where pr measures
 * against it) into *e; 1 where it measures something: a run judged, or a
 * stand-in's (the thin disk's of a thick scene, a cylinder's of a thin one),
 * which is not judged yet measured, all the geometry step and a
 * convergence read */
static int measured(const dv_prober *pr, const dv_sweep_point *p, double *e, int *stand_in) {
  *e = pr->own_reference ? p->metric[DV_THETA_MAX_ERR] : p->theta_thin;
  *stand_in = p->thinner && isfinite(*e);
  return p->ok || *stand_in;
}

int dv_search_probe_theta(const dv_prober *pr, double *e, dv_error *err, const char *o1,
                          const char *o2, const char *o3, const char *o4) {
  const char *given[4] = {o1, o2, o3, o4}, *over[4];
  size_t n = 0;
  for (int i = 0; i < 4; i++)
    if (given[i]) over[n++] = given[i];
  dv_sweep_point p;
  if (dv_search_sweep_probe_in(pr->refs, pr->sc, pr->engine->name, over, n, &p, err))
    return DV_EINPUT;
  int stand_in;
  if (!measured(pr, &p, e, &stand_in)) {
    char with[400] = "";
    for (size_t i = 0; i < n; i++)
      snprintf(with + strlen(with), sizeof with - strlen(with), " %s", over[i]);
    return dv_fail(err, DV_ENUMERIC, "%s cannot be attributed: the run%s%s failed: %s: %s",
                   pr->engine->name, n ? " with" : "", with, dv_run_verdict_name(p.verdict),
                   p.detail);
  }
  return DV_OK;
}

/* the scenario's own run: its error e against pr's reference (NAN where it
 * failed: dv_search_probe_theta says how), or why it measures nothing */
static int measures_nothing(const dv_prober *pr, double *e, char *why, size_t size, dv_error *err) {
  dv_sweep_point p;
  why[0] = '\0';
  if (dv_search_sweep_probe_in(pr->refs, pr->sc, pr->engine->name, NULL, 0, &p, err))
    return DV_EINPUT;
  int stand_in;
  if (!measured(pr, &p, e, &stand_in)) *e = NAN;
  if (!stand_in && p.ok && isnan(*e))
    snprintf(why, size, "%s against %s: %.270s", dv_run_verdict_name(p.verdict),
             pr->own_reference ? "its own reference" : "the thin disk",
             p.detail[0] ? p.detail : "its compared window is too short to measure");
  else if (!stand_in && !p.ok && p.verdict == DV_VERDICT_NOT_JUDGED)
    snprintf(why, size, "%.300s", p.detail);
  return DV_OK;
}

/* the attribution's runs, each an item of its phase: the scene's own, the
 * thin disk's, three steps, the stiff contact, the knobs' base, each knob */
#define SPLIT_RUNS 7

static int attribute(const dv_scenario *scenario, const char *engine_name, dv_attribution *out,
                     dv_error *err) {
  const dv_engine_type *engine = dv_engine_find(engine_name);
  if (!engine) return dv_fail(err, DV_EINPUT, "unknown engine '%s'", engine_name);
  const dv_engine_contact *k = engine->contact;
  if (!k || !engine->search)
    return dv_fail(err, DV_EINPUT, "%s is not a contact engine: nothing to attribute",
                   engine->name);
  const char *name = engine->name;
  const double dt = dv_scenario_get(scenario, name, engine->search->step_key);
  const double soft = k->softness_key ? dv_scenario_get(scenario, name, k->softness_key) : NAN;
  const double friction = dv_scenario_get(scenario, name, k->friction_key);
  /* an engine that simulates the scene's cylinder is measured against its own
   * reference, in its own shape: the thin disk is not its body */
  const int own = (scenario->thickness > 0.0 && dv_engine_own_body(engine, scenario)) ||
                  !k->thin_choice; /* an engine with no thin disk: its shape, its reference */
  const int stand_in = dv_engine_stand_in(engine, scenario) && !own;
  char thin[128], steps[4][128], softs[4][128], stiff[128], rough[128];
  snprintf(thin, sizeof thin, "engines.%s.%s=%s", name, k->geom_key, k->thin_choice);
  const char *shape = own ? NULL : thin; /* the probes' shape: the thin disk, or its own */
  for (int i = 0; i < 4; i++) {          /* dt, dt/2, dt/4, dt/8 */
    const double h = dt / (1 << i);
    snprintf(steps[i], sizeof steps[i], "engines.%s.%s=%.9g", name, engine->search->step_key, h);
    snprintf(softs[i], sizeof softs[i], "engines.%s.%s=%.9g", name, k->softness_key,
             fmax(soft, k->softness_min_steps * h));
  }
  /* a stiffer contact needs a step that resolves it, where the softness follows the step */
  const int f = k->softness_min_steps > 0.0 ? 3 : 2;
  snprintf(stiff, sizeof stiff, "engines.%s.%s=%.9g", name, k->softness_key,
           fmax(soft, k->softness_min_steps * dt) * k->stiffer);
  snprintf(rough, sizeof rough, "engines.%s.%s=%.9g", name, k->friction_key, 10.0 * friction);
  const int follows = k->softness_min_steps > 0.0;
  const dv_prober pr = {scenario, engine, own, NULL};
  dv_attribution_errors e;
  memset(out, 0, sizeof *out);
  out->own_reference = own;
  out->cause = -1;
  out->timestep = dt;
  const double began = dv_clock_now();
  const size_t items = SPLIT_RUNS + dv_search_attribute_knobs_count(scenario, engine);
  char subject[64];
  snprintf(subject, sizeof subject, "%s, its own run", name);
  dv_phase_item("attribution", 1, items, subject);
  int status = measures_nothing(&pr, &e.stand_in, out->not_measured, sizeof out->not_measured, err);
  if (status || out->not_measured[0]) { /* nothing to split, no knob to judge by */
    for (int m = 0; m < DV_NMETRICS; m++) out->base[m] = out->limit[m] = NAN;
    out->e = (dv_attribution_errors){NAN, NAN, {NAN, NAN, NAN}, NAN};
    out->geometry = out->time = out->contact = out->rest = out->order = NAN;
    out->base_theta_thin = NAN;
    return status;
  }
  if (isnan(e.stand_in)) /* its run failed: the error names it */
    status = dv_search_probe_theta(&pr, &e.stand_in, err, NULL, NULL, NULL, NULL);
  /* the split's runs (the thin disk, three steps, the stiff one), then the knobs' */
  const double runs =
      1.0 + 7.0 + (double)(1 << f) + dv_search_attribute_knobs_cost(scenario, engine);
  char what[96], basis[96];
  snprintf(what, sizeof what, "%.40s: %s: its cause (%.0f runs' worth)", scenario->name, name,
           runs);
  snprintf(basis, sizeof basis, "its own run took %.3g s", dv_clock_now() - began);
  if (!status) dv_run_progress_announce(what, runs * (dv_clock_now() - began), basis);
  e.thin = e.stand_in;
  snprintf(subject, sizeof subject, "%s, the thin disk", name);
  dv_phase_item("attribution", 2, items, subject);
  if (!status && !own) status = dv_search_probe_theta(&pr, &e.thin, err, thin, NULL, NULL, NULL);
  for (int i = 0; !status && i < 3; i++) {
    snprintf(subject, sizeof subject, "%s dt %.3g s", name, dt / (1 << i));
    dv_phase_item("attribution", 3 + (size_t)i, items, subject);
    status =
        dv_search_probe_theta(&pr, &e.dt[i], err, shape, steps[i], follows ? softs[i] : NULL, NULL);
  }
  snprintf(subject, sizeof subject, "%s, a stiffer contact", name);
  dv_phase_item("attribution", 6, items, subject);
  if (!status)
    status = dv_search_probe_theta(&pr, &e.stiff, err, shape, steps[f],
                                   k->softness_key ? stiff : NULL, rough);
  if (status) return status;
  dv_search_attribute_split(&e, stand_in, out);
  snprintf(subject, sizeof subject, "%s, the knobs' base", name);
  dv_phase_item("attribution", SPLIT_RUNS, items, subject);
  return dv_search_attribute_knobs(&pr, out, err);
}

int dv_search_attribute(const dv_scenario *scenario, const char *engine_name, dv_attribution *out,
                        dv_error *err) {
  const int status = attribute(scenario, engine_name, out, err);
  dv_phase_end("attribution");
  return status;
}
