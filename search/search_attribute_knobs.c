/* search_attribute_knobs: causes over every knob a contact engine declares
 * (search_attribute.h). Each knob is changed alone, the rest as the scene
 * derives it: the choice key (MuJoCo's integrator, ODE's stepper) to each other
 * value, the step to a quarter, the contact 'stiffer' times stiffer (at a step
 * that resolves it), the friction 10x, a stand-in shape to the thin disk. The
 * error judged is every metric over its limit in the scenario's run, removed
 * where each comes within its limit or loses 90 % of its excess; where none is
 * over (a floor, a discrepancy that does not converge), theta against the thin
 * disk, removed when halved. A cause is named only where its change
 * removes the error (DESIGN section 6).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_phase.h"
#include "run_verdict.h"
#include "search_attribute.h"
#include "search_sweep.h"

#define HALVED 0.5  /* with nothing over its limit, a change removes theta's error at half */
#define RESIDUE 0.1 /* a change removes an excess over a limit that it cuts to a tenth */

/* run sc with over[0..n) and keep what attribution compares; 0, or < 0 (err) */
static int run_knob(const dv_prober *pr, const char *const *over, size_t n, int own,
                    dv_knob_probe *k, dv_error *err) {
  dv_sweep_point p;
  if (dv_search_sweep_probe_in(pr->refs, pr->sc, pr->engine->name, over, n, &p, err))
    return DV_EINPUT;
  memcpy(k->metric, p.metric, sizeof k->metric);
  k->theta_thin = own ? p.metric[DV_THETA_MAX_ERR] : p.theta_thin;
  k->ok = p.ok;
  return DV_OK;
}

/* does k bring metric m of a's excess within its limit, or cut its excess to RESIDUE */
static int removes_metric(const dv_attribution *a, const dv_knob_probe *k, int m) {
  const double excess = isfinite(a->base[m])
                            ? (k->metric[m] - a->limit[m]) / (a->base[m] - a->limit[m])
                        : k->metric[m] <= a->limit[m] ? 0.0
                                                      : INFINITY;
  return excess <= RESIDUE;
}

/* how far k leaves the error: the worst value / limit over the judged metrics;
 * it removes the error where each judged metric is within its limit or has lost
 * at least 1 - RESIDUE of its excess over it (a regression limit of 3x a
 * measurement can sit just under what the right change gives) */
static void judge(const dv_attribution *a, dv_knob_probe *k) {
  k->worst = 0.0;
  k->removes = k->ok;
  if (!a->judged) {
    k->worst = a->base_theta_thin > 0.0 ? k->theta_thin / a->base_theta_thin : INFINITY;
    k->removes = k->ok && k->worst <= HALVED;
  }
  for (int m = 0; m < DV_NMETRICS; m++)
    if (a->judged >> m & 1u) {
      /* an infinite base (a nutation the engine lost) is removed only within the limit */
      const double excess = isfinite(a->base[m])
                                ? (k->metric[m] - a->limit[m]) / (a->base[m] - a->limit[m])
                            : k->metric[m] <= a->limit[m] ? 0.0
                                                          : INFINITY;
      k->worst = fmax(k->worst, k->metric[m] / a->limit[m]);
      if (!(excess <= RESIDUE)) k->removes = 0;
    }
  if (!k->ok || isnan(k->worst)) k->worst = INFINITY, k->removes = 0;
}

/* one knob: its name, its change in words and the overrides that make it */
typedef struct knob {
  const char *name;
  char change[64];
  char over[3][128];
  size_t n;
  double cost; /* its run's cost as a share of the scene's run (steps) */
} knob;

/* the knobs engine declares, changed from sc's values */
static size_t declare(const dv_scenario *sc, const dv_engine_type *engine, knob *kn) {
  const dv_engine_contact *k = engine->contact;
  const dv_engine_search *se = engine->search;
  const char *name = engine->name;
  size_t n = 0;
  const dv_setting_spec *ck = dv_settings_find(engine->settings, se->choice_key);
  const int now = (int)dv_scenario_get(sc, name, se->choice_key);
  for (size_t v = 0; ck && dv_setting_choice(ck, v) && n < DV_MAX_KNOBS - 4; v++) {
    if ((int)v == now) continue;
    kn[n] = (knob){se->choice_key, "", {""}, 1, 1.0};
    snprintf(kn[n].change, sizeof kn[n].change, "%s -> %s", dv_setting_choice(ck, (size_t)now),
             dv_setting_choice(ck, v));
    snprintf(kn[n].over[0], sizeof kn[n].over[0], "engines.%s.%s=%s", name, se->choice_key,
             dv_setting_choice(ck, v));
    n++;
  }
  const double dt = dv_scenario_get(sc, name, se->step_key);
  const double soft = k->softness_key ? dv_scenario_get(sc, name, k->softness_key) : NAN;
  const double friction = dv_scenario_get(sc, name, k->friction_key);
  kn[n] = (knob){se->step_key, "", {""}, k->softness_min_steps > 0.0 ? 2 : 1, 4.0};
  snprintf(kn[n].change, sizeof kn[n].change, "%.3g -> %.3g s", dt, dt / 4);
  snprintf(kn[n].over[0], sizeof kn[n].over[0], "engines.%s.%s=%.9g", name, se->step_key, dt / 4);
  snprintf(kn[n].over[1], sizeof kn[n].over[1], "engines.%s.%s=%.9g", name, k->softness_key,
           fmax(soft, k->softness_min_steps * dt / 4));
  n++;
  for (size_t x = 0; x < k->nextra && n < DV_MAX_KNOBS - 3; x++) { /* an adapter's own knobs */
    const dv_setting_spec *sp = dv_settings_find(engine->settings, k->extra[x].key);
    const double v = dv_scenario_get(sc, name, k->extra[x].key);
    const char *now_text =
        sp && sp->type == DV_SETTING_CHOICE ? dv_setting_choice(sp, (size_t)v) : NULL;
    if (now_text && strcmp(now_text, k->extra[x].value) == 0) continue;           /* already so */
    if (se->choice_key && strcmp(k->extra[x].key, se->choice_key) == 0) continue; /* turned above */
    kn[n] = (knob){k->extra[x].what, "", {""}, 1, 1.0};
    if (now_text)
      snprintf(kn[n].change, sizeof kn[n].change, "%s %s -> %s", k->extra[x].key, now_text,
               k->extra[x].value);
    else
      snprintf(kn[n].change, sizeof kn[n].change, "%s %.3g -> %s", k->extra[x].key, v,
               k->extra[x].value);
    snprintf(kn[n].over[0], sizeof kn[n].over[0], "engines.%s.%s=%s", name, k->extra[x].key,
             k->extra[x].value);
    n++;
  }
  /* a stiffer contact, at a step that resolves it where the library ties them */
  const double stiff = fmax(soft, k->softness_min_steps * dt) * k->stiffer;
  if (!k->softness_key) goto friction; /* an engine with no softness to turn */
  const double step = k->softness_min_steps > 0.0 ? fmin(dt, stiff / k->softness_min_steps) : dt;
  kn[n] = (knob){"contact softness", "", {""}, 2, dt / step};
  snprintf(kn[n].change, sizeof kn[n].change, "%s %.3g -> %.3g", k->softness_key,
           fmax(soft, k->softness_min_steps * dt), stiff);
  snprintf(kn[n].over[0], sizeof kn[n].over[0], "engines.%s.%s=%.9g", name, k->softness_key, stiff);
  snprintf(kn[n].over[1], sizeof kn[n].over[1], "engines.%s.%s=%.9g", name, se->step_key, step);
  n++;
friction:
  kn[n] = (knob){"friction", "", {""}, 1, 1.0};
  snprintf(kn[n].change, sizeof kn[n].change, "%.3g -> %.3g", friction, 10 * friction);
  snprintf(kn[n].over[0], sizeof kn[n].over[0], "engines.%s.%s=%.9g", name, k->friction_key,
           10 * friction);
  n++;
  /* the scene's own body (the cylinder of [disk] thickness) is no stand-in to remove */
  if (k->thin_choice && dv_engine_stand_in(engine, sc) && !dv_engine_own_body(engine, sc)) {
    kn[n] = (knob){"geometry", "", {""}, 1, 1.0};
    snprintf(kn[n].change, sizeof kn[n].change, "stand-in -> %s", k->thin_choice);
    snprintf(kn[n].over[0], sizeof kn[n].over[0], "engines.%s.%s=%s", name, k->geom_key,
             k->thin_choice);
    n++;
  }
  return n;
}

double dv_search_attribute_knobs_cost(const dv_scenario *sc, const dv_engine_type *engine) {
  knob kn[DV_MAX_KNOBS];
  if (!engine->contact || !engine->search) return 0.0;
  const size_t n = declare(sc, engine, kn);
  double cost = 1.0; /* the scene's own run, then each knob's */
  for (size_t i = 0; i < n; i++) cost += fmax(kn[i].cost, 1.0);
  return cost;
}

size_t dv_search_attribute_knobs_count(const dv_scenario *sc, const dv_engine_type *engine) {
  knob kn[DV_MAX_KNOBS];
  return engine->contact && engine->search ? declare(sc, engine, kn) : 0;
}

int dv_search_attribute_knobs(const dv_prober *pr, dv_attribution *out, dv_error *err) {
  const dv_scenario *sc = pr->sc;
  const dv_engine_type *engine = pr->engine;
  if (!engine->contact || !engine->search)
    return dv_fail(err, DV_EINPUT, "%s is not a contact engine: nothing to attribute",
                   engine->name);
  dv_sweep_point p;
  if (dv_search_sweep_probe_in(pr->refs, sc, engine->name, NULL, 0, &p, err)) return DV_EINPUT;
  dv_search_attribute_base(out, p.metric, p.limit,
                           out->own_reference ? p.metric[DV_THETA_MAX_ERR] : p.theta_thin);
  return dv_search_attribute_knobs_try(pr, NULL, 0, NULL, NULL, NULL, out, err);
}

void dv_search_attribute_base(dv_attribution *out, const double *metric, const double *limit,
                              double theta) {
  memcpy(out->base, metric, sizeof out->base);
  memcpy(out->limit, limit, sizeof out->limit);
  out->base_theta_thin = theta;
  out->judged = 0;
  for (int m = 0; m < DV_NMETRICS; m++)
    if (dv_run_limit_check(metric[m], limit[m]) == DV_LIMIT_OVER) out->judged |= 1u << m;
}

/* the position in first[] of a knob's name (nfirst where it is not there) */
static size_t rank(const char *name, const char *const *first, size_t nfirst) {
  for (size_t i = 0; i < nfirst; i++)
    if (first[i] && strcmp(first[i], name) == 0) return i;
  return nfirst;
}

/* "cause trace: mujoco: integrator (rk4 -> implicit): worst 0.3, removes it" (DV_CAUSE_TRACE) */
static void trace(const dv_engine_type *engine, const dv_knob_probe *k, const char *extra) {
  const char *on = getenv("DV_CAUSE_TRACE");
  if (!on || !*on) return;
  fprintf(stderr, "cause trace: %s: %s (%s)%s%s: worst %.3g, %s\n", engine->name, k->knob,
          k->change, extra ? " with " : "", extra ? extra : "", k->worst,
          k->removes ? "removes it" : "keeps it");
}

int dv_search_attribute_knobs_try(const dv_prober *pr, const char *const *first, size_t nfirst,
                                  const double *budget, const char *extra,
                                  const dv_attribution *whole, dv_attribution *out,
                                  dv_error *err) {
  const dv_scenario *sc = pr->sc;
  const dv_engine_type *engine = pr->engine;
  knob kn[DV_MAX_KNOBS];
  const size_t n = declare(sc, engine, kn);
  size_t order[DV_MAX_KNOBS], m = 0;
  for (size_t r = 0; r <= nfirst; r++) /* the signature's knobs first, then the rest as declared */
    for (size_t i = 0; i < n; i++)
      if (rank(kn[i].name, first, nfirst) == r) order[m++] = i;
  out->nknobs = 0;
  out->cause = -1;
  out->untried[0] = '\0';
  double spent = 0.0, after_first = 0.0;
  /* each knob an item of the attribution phase, after the runs its caller counted there */
  const dv_phase *ph;
  const size_t depth = dv_phase_stack(&ph);
  const size_t before = depth && !strcmp(ph[depth - 1].name, "attribution") ? ph[depth - 1].k : 0;
  dv_attribution w; /* the window's base, where knobs run over one */
  if (whole) w = *out;
  for (size_t j = 0; j < n; j++) {
    const knob *kj = &kn[order[j]];
    /* quick: the first knob always, the next ones while the budget lasts */
    const int over_budget = budget && j > 0 && after_first + fmax(kj->cost, 1.0) > *budget;
    if (over_budget || (budget && out->cause >= 0)) {
      const size_t len = strlen(out->untried);
      if (!strstr(out->untried, kj->name) && len < sizeof out->untried)
        snprintf(out->untried + len, sizeof out->untried - len, "%s%s", len ? ", " : "", kj->name);
      continue;
    }
    spent += fmax(kj->cost, 1.0);
    if (j > 0) after_first += fmax(kj->cost, 1.0);
    char subject[64];
    snprintf(subject, sizeof subject, "%s %s", engine->name, kj->name);
    dv_phase_item("attribution", before + j + 1, before + n, subject);
    dv_knob_probe *k = &out->knobs[out->nknobs];
    const char *over[4] = {kj->over[0], kj->over[1], kj->over[2], NULL};
    size_t nover = kj->n;
    if (extra) over[nover++] = extra;
    memset(k, 0, sizeof *k);
    k->knob = kj->name;
    snprintf(k->change, sizeof k->change, "%s", kj->change);
    if (run_knob(pr, over, nover, out->own_reference, k, err)) return DV_EINPUT;
    judge(out, k);
    trace(engine, k, extra);
    /* removed over a short window: it names the cause only if it removes the whole run's error */
    if (k->removes && whole) {
      out->base_theta_thin = whole->base_theta_thin, out->judged = whole->judged;
      memcpy(out->base, whole->base, sizeof out->base);
      memcpy(out->limit, whole->limit, sizeof out->limit);
      if (run_knob(pr, over, kj->n, out->own_reference, k, err)) return DV_EINPUT;
      judge(out, k);
      trace(engine, k, NULL);
      /* the whole run counts against the budget: one that keeps the error ends quick */
      if (budget) after_first += fmax(kj->cost, 1.0) * *budget / DV_CAUSE_QUICK_BUDGET;
      if (!k->removes) { /* back to the window's base for the next knob */
        out->base_theta_thin = w.base_theta_thin, out->judged = w.judged;
        memcpy(out->base, w.base, sizeof out->base);
        memcpy(out->limit, w.limit, sizeof out->limit);
      } else
        out->window = 0.0; /* the numbers named are the whole run's */
    }
    if (k->removes && (out->cause < 0 || k->worst < out->knobs[out->cause].worst))
      out->cause = (int)out->nknobs;
    out->nknobs++;
  }
  out->runs_spent = spent;
  return DV_OK;
}

/* "path 1.98e-02 -> 1.98e-03 m" for metric m from a to b */
static int metric_change(int m, double a, double b, char *buf, size_t size) {
  static const struct {
    int m;
    const char *name, *unit;
    double scale;
  } names[] = {{DV_THETA_MAX_ERR, "theta", "rad", 1},
               {DV_PATH_MAX_ERR, "path", "m", 1},
               {DV_ENERGY_DRIFT, "energy", "%", 100},
               {DV_INVARIANT_DRIFT, "invariants", "%", 100},
               {DV_SLIP_MAX, "slip", "m/s", 1},
               {DV_PATH_HAUSDORFF, "path (as curves)", "m", 1},
               {DV_THETA_RMS_ERR, "theta rms", "rad", 1},
               {DV_PATH_RMS_ERR, "path rms", "m", 1},
               {DV_THETA_EXTREMA_ERR, "theta extrema", "rad", 1}};
  for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
    if (names[i].m == m)
      return snprintf(buf, size, "%s %.3g -> %.3g %s", names[i].name, names[i].scale * a,
                      names[i].scale * b, names[i].unit);
  return snprintf(buf, size, "%s %.3g -> %.3g", dv_metric_names[m], a, b);
}

/* is knob i's name among knobs[0..before) (an integrator tried to each value) */
static int tried_before(const dv_attribution *a, size_t i, size_t before) {
  for (size_t j = 0; j < before; j++)
    if (strcmp(a->knobs[j].knob, a->knobs[i].knob) == 0) return 1;
  return 0;
}

/* quick's found cause: which of the knobs tried it was (its numbers are the whole run's) */
static void quick_tried(const dv_attribution *a, char *out, size_t size) {
  int n = a->cause == 0 ? snprintf(out, size, ", the first of the knobs tried")
                        : snprintf(out, size, ", the knob tried after ");
  for (int i = 0; i < a->cause && n > 0 && (size_t)n < size; i++)
    if (!tried_before(a, (size_t)i, (size_t)i))
      n += snprintf(out + n, size - (size_t)n, "%s%s", i ? ", " : "", a->knobs[i].knob);
  if (n > 0 && (size_t)n < size)
    snprintf(out + n, size - (size_t)n, " (quick; --cause full tries all)");
}

void dv_search_attribute_cause(const dv_attribution *a, char *out, size_t size) {
  if (a->not_measured[0]) {
    snprintf(out, size, "none: nothing measured (%s)", a->not_measured);
    return;
  }
  if (a->cause < 0 && a->untried[0]) { /* quick stopped short of every knob */
    int n = snprintf(out, size, "not found among ");
    for (size_t i = 0; i < a->nknobs && n > 0 && (size_t)n < size; i++)
      if (!tried_before(a, i, i))
        n += snprintf(out + n, size - (size_t)n, "%s%s", i ? ", " : "", a->knobs[i].knob);
    if (n > 0 && (size_t)n < size) n += snprintf(out + n, size - (size_t)n, " (quick");
    if (a->window > 0.0 && n > 0 && (size_t)n < size)
      n += snprintf(out + n, size - (size_t)n, ", each over the first %.3g s", a->window);
    if (n > 0 && (size_t)n < size)
      snprintf(out + n, size - (size_t)n, "; --cause full tries %s)", a->untried);
    return;
  }
  if (a->cause < 0) {
    int n = snprintf(out, size, "none of the knobs removes it (");
    for (size_t i = 0; i < a->nknobs && n > 0 && (size_t)n < size; i++)
      if (i == 0 || strcmp(a->knobs[i].knob, a->knobs[i - 1].knob))
        n += snprintf(out + n, size - (size_t)n, "%s%s", i ? ", " : "", a->knobs[i].knob);
    if (n > 0 && (size_t)n < size) n += snprintf(out + n, size - (size_t)n, " tried)");
    /* a knob that removes part of the excess is the cause of that part, named with it */
    for (size_t i = 0; i < a->nknobs && n > 0 && (size_t)n < size; i++) {
      const dv_knob_probe *k = &a->knobs[i];
      int named = 0;
      for (int m = 0; m < DV_NMETRICS && k->ok && n > 0 && (size_t)n < size; m++) {
        if (!(a->judged >> m & 1u) || !removes_metric(a, k, m)) continue;
        n += snprintf(out + n, size - (size_t)n, named ? ", " : "; %s (%s) removes ", k->knob,
                      k->change);
        if (n > 0 && (size_t)n < size)
          n += metric_change(m, a->base[m], k->metric[m], out + n, size - (size_t)n);
        named = 1;
      }
      if (named && n > 0 && (size_t)n < size)
        n += snprintf(out + n, size - (size_t)n, ", not the rest");
    }
    return;
  }
  const dv_knob_probe *k = &a->knobs[a->cause];
  int n = snprintf(out, size, "%s (%s: ", k->knob, k->change);
  int first = 1;
  for (int m = 0; m < DV_NMETRICS && n > 0 && (size_t)n < size; m++)
    if (a->judged >> m & 1u) {
      n += snprintf(out + n, size - (size_t)n, "%s", first ? "" : ", ");
      if ((size_t)n < size)
        n += metric_change(m, a->base[m], k->metric[m], out + n, size - (size_t)n);
      first = 0;
    }
  if (!a->judged && n > 0 && (size_t)n < size) {
    n += snprintf(out + n, size - (size_t)n, "theta against %s %.3g -> %.3g rad",
                  a->own_reference ? "its own reference" : "the thin disk", a->base_theta_thin,
                  k->theta_thin);
    first = 0;
  }
  if (!(a->judged >> DV_ENERGY_DRIFT & 1u) && n > 0 && (size_t)n < size) {
    n += snprintf(out + n, size - (size_t)n, ", ");
    if ((size_t)n < size)
      n += metric_change(DV_ENERGY_DRIFT, a->base[DV_ENERGY_DRIFT], k->metric[DV_ENERGY_DRIFT],
                         out + n, size - (size_t)n);
  }
  if (n > 0 && (size_t)n < size) n += snprintf(out + n, size - (size_t)n, ")");
  if (a->quick && n > 0 && (size_t)n < size) quick_tried(a, out + n, size - (size_t)n);
}
