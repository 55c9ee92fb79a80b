/* engine_choose: settings chosen from a probe against the reference (engine_choose.h). */
#include "engine_choose.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_phase.h"
#include "dv_reference.h"

#define MAX_CANDIDATES 16
#define MEMO 32 /* scenes remembered per process */

typedef struct candidate {
  dv_knob_choice k;
  double cost;        /* counted: steps over the duration times the cost of a step (s) */
  int model_step;     /* the model's own step (always allowed, whatever the cap) */
  int probed;         /* 1 ran, -1 failed to run */
  double theta, path; /* projected over the duration (rad, m) */
  double margin;      /* the larger of theta / target and path / target */
} candidate;

/* the probe's reference samples and the target they set */
typedef struct probe {
  double window;               /* s */
  int ns;                      /* sample times: multiples of output_dt, on every step */
  double t[DV_CHOOSE_SAMPLES]; /* s */
  int n;                       /* samples the reference reached */
  double horizon;              /* s: the duration, or where the reference ended (an event) */
  double theta[DV_CHOOSE_SAMPLES];
  double xy[DV_CHOOSE_SAMPLES][2];
  double valid;  /* s: where the reference leaves the friction cone (INFINITY: never) */
  double rolled; /* m, projected over the horizon */
  double theta_target, path_target;
} probe;

typedef struct memo_entry {
  uint64_t key;
  dv_knob_choice out;
  char why[DV_DERIVED_BYTES];
  int chose; /* the choice key was chosen (more than one candidate) */
} memo_entry;
static memo_entry memo[MEMO];
static int nmemo, next_slot; /* entries filled; the next to (re)use */

static uint64_t mix(uint64_t h, const void *p, size_t n) {
  const unsigned char *b = p;
  for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ull;
  return h;
}

/* what the choice depends on: the disk, the start, the times, every setting of
 * the engine and of the reference, and what was given */
static uint64_t scene_key(const dv_scenario *sc, const dv_engine_type *engine,
                          const dv_knob_choice *given) {
  uint64_t h = 1469598103934665603ull;
  const double times[] = {sc->duration, sc->output_dt, sc->disk.r, sc->disk.m,
                          sc->disk.A,   sc->disk.C,    sc->disk.g};
  h = mix(h, times, sizeof times);
  h = mix(h, sc->initial, sizeof sc->initial);
  h = mix(h, engine->name, strlen(engine->name));
  const dv_knob_choice g = {given->choice, given->timestep, given->softness};
  h = mix(h, &g.choice, sizeof g.choice);
  h = mix(h, &g.timestep, sizeof g.timestep);
  h = mix(h, &g.softness, sizeof g.softness);
  const dv_settings_section *secs[3] = {engine->settings,
                                        dv_engine_of_role(DV_ENGINE_THIN_REFERENCE)->settings,
                                        dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE)->settings};
  h = mix(h, &sc->thickness, sizeof sc->thickness);
  /* a shape given picks the probe's reference, even at its default value */
  const int shape_given[2] = {engine->contact && engine->contact->geom_key &&
                                  dv_scenario_is_given(sc, engine->name, engine->contact->geom_key),
                              dv_scenario_is_given(sc, engine->name, "half_thickness")};
  h = mix(h, shape_given, sizeof shape_given);
  for (int s = 0; s < 3; s++) {
    const void *block = dv_scenario_settings(sc, secs[s]->name);
    for (size_t i = 0; block && i < secs[s]->nspecs; i++) {
      const double v = dv_setting_value(&secs[s]->specs[i], block);
      h = mix(h, &v, sizeof v);
    }
  }
  return h;
}

/* sample type's run of sc at the probe's times; the samples reached */
static int run_samples(const dv_engine_type *type, const dv_scenario *sc, const probe *pr,
                       double theta[], double xy[][2], dv_sample *keep) {
  dv_error err = {{0}};
  void *e = type->alloc_self ? type->alloc_self(type, sc, &err) : type->alloc(sc, &err);
  int got = 0;
  if (e && type->reset(e, sc->initial, &err) == DV_OK) {
    for (int i = 0; i < pr->ns; i++) {
      dv_sample s;
      const int status = type->advance(e, pr->t[i], &s, &err);
      if (status < 0 || !isfinite(s.y[RED_TH])) break;
      if (keep) keep[got] = s;
      theta[got] = s.y[RED_TH];
      xy[got][0] = s.contact[0];
      xy[got][1] = s.contact[1];
      got++;
      if (status != DV_OK) break;
    }
  }
  if (type->free) type->free(e);
  return got;
}

/* e(D) = D^p max e(t) / t^p over the samples' second half, e the running max */
static double project(const double *e, const probe *pr, double p) {
  double rate = 0.0;
  for (int i = pr->n / 2; i < pr->n; i++) rate = fmax(rate, e[i] / pow(pr->t[i], p));
  return rate * pow(pr->horizon, p);
}

/* run candidate c over the probe window and project its errors */
static void probe_candidate(const dv_scenario *sc, const dv_engine_type *engine, const probe *pr,
                            const dv_engine_knobs *kn, candidate *c) {
  dv_scenario *copy = malloc(sizeof *copy);
  double theta[DV_CHOOSE_SAMPLES], xy[DV_CHOOSE_SAMPLES][2];
  c->probed = -1;
  c->margin = INFINITY;
  if (!copy) return;
  *copy = *sc;
  copy->duration = pr->window;
  void *block = (void *)dv_scenario_settings(copy, kn->engine);
  char what[160];
  const dv_setting_spec *ck = dv_settings_find(engine->settings, kn->choice_key);
  const dv_setting_spec *dt = dv_settings_find(engine->settings, "timestep");
  const dv_setting_spec *soft =
      kn->models[c->k.choice].soft_key
          ? dv_settings_find(engine->settings, kn->models[c->k.choice].soft_key)
          : NULL;
  int bad = !block || !ck || !dt || dv_setting_store(ck, c->k.choice, block, what, sizeof what) ||
            dv_setting_store(dt, c->k.timestep, block, what, sizeof what) ||
            (soft && dv_setting_store(soft, c->k.softness, block, what, sizeof what));
  const int n = bad ? 0 : run_samples(engine, copy, pr, theta, xy, NULL);
  free(copy);
  if (n < pr->n) return;
  double th[DV_CHOOSE_SAMPLES], pa[DV_CHOOSE_SAMPLES];
  for (int i = 0; i < pr->n; i++) {
    const double et = fabs(theta[i] - pr->theta[i]);
    const double ep = hypot(xy[i][0] - pr->xy[i][0], xy[i][1] - pr->xy[i][1]);
    th[i] = i ? fmax(th[i - 1], et) : et;
    pa[i] = i ? fmax(pa[i - 1], ep) : ep;
  }
  c->theta = project(th, pr, DV_CHOOSE_THETA_GROWTH);
  c->path = project(pa, pr, DV_CHOOSE_PATH_GROWTH);
  c->probed = 1;
  c->margin = fmax(c->theta / pr->theta_target, c->path / pr->path_target);
}

/* the reference's samples over the window, and the target over the duration */
static int probe_reference(const dv_scenario *sc, const dv_engine_type *ref_type, double half,
                           probe *pr) {
  dv_scene_scales s;
  dv_engine_scene_scales(sc, &s);
  double t = s.t[DV_SCALE_FALL];
  for (int i = 0; i < DV_SCALE_DURATION; i++) t = fmin(t, s.t[i]);
  pr->window = fmin(sc->duration, fmax(DV_CHOOSE_SCALES * t,
                                       fmin(sc->duration / DV_CHOOSE_SHARE, DV_CHOOSE_MAX_WINDOW)));
  if (!(pr->window > 0.0)) return -1;
  if (pr->window < sc->duration / DV_CHOOSE_SHARE * (1.0 - 1e-12)) return -2;
  /* at least 8 samples of output_dt (where the scene is that long) */
  pr->window = fmin(sc->duration, fmax(pr->window, 8.0 * sc->output_dt));
  const double step = fmax(sc->output_dt, pr->window / DV_CHOOSE_SAMPLES);
  pr->ns = 0;
  for (int i = 1; i <= DV_CHOOSE_SAMPLES;
       i++) { /* on output_dt's grid: on every candidate's step */
    const double at = sc->output_dt * ceil(step * i / sc->output_dt * (1.0 - 1e-12));
    if (at > pr->window * (1.0 + 1e-12)) break;
    if (!pr->ns || at > pr->t[pr->ns - 1]) pr->t[pr->ns++] = at;
  }
  dv_scenario *copy = malloc(sizeof *copy);
  if (!copy) return -1;
  *copy = *sc;
  copy->duration = pr->window;
  dv_sample ref[DV_CHOOSE_SAMPLES];
  /* the matched reference of the engine's half-thickness, as compare runs it */
  if (half > 0.0 && dv_scenario_set_number(copy, ref_type->name, "half_thickness", half, NULL))
    return free(copy), -1;
  pr->n = run_samples(ref_type, copy, pr, pr->theta, pr->xy, ref);
  free(copy);
  /* a reference that ends inside the window (an event), or stops describing
   * the physics (its validity window), ends what is compared there */
  const double valid = pr->n ? dv_reference_valid_until(sc, ref, (size_t)pr->n) : 0.0;
  const int reached = pr->n;
  pr->valid = valid;
  int ended = pr->n < pr->ns;
  /* an event's sample (the matched reference at its friction limit) is off
   * the grid: the engine's sample at the grid time is not comparable with it */
  while (pr->n > 0 && (pr->t[pr->n - 1] > valid ||
                       fabs(ref[pr->n - 1].t - pr->t[pr->n - 1]) > 1e-9 * pr->t[pr->n - 1]))
    pr->n--, ended = 1;
  if (pr->n < 8) return reached >= 8 ? -3 : -1; /* nothing to measure against */
  pr->horizon = ended ? pr->t[pr->n - 1] : sc->duration;
  double rolled = 0.0;
  for (int i = 1; i < pr->n; i++)
    rolled += hypot(pr->xy[i][0] - pr->xy[i - 1][0], pr->xy[i][1] - pr->xy[i - 1][1]);
  pr->rolled = rolled * pr->horizon / pr->t[pr->n - 1];
  pr->theta_target = DV_SCENE_ACCURACY;
  pr->path_target = DV_SCENE_ACCURACY * fmax(pr->rolled, sc->disk.r);
  return 0;
}

/* the candidates: every free value at its model's step and the halvings, by cost */
static int candidates(const dv_scenario *sc, const dv_engine_knobs *kn, const dv_knob_choice *given,
                      candidate *c) {
  int n = 0;
  const double cap = fmin(DV_SCENE_WALL_PER_SIM * sc->duration, DV_SCENE_WALL_PER_RUN);
  for (int v = 0; v < kn->nchoices; v++) {
    if (given->choice >= 0 ? v != given->choice : !(kn->choosable >> v & 1u)) continue;
    const dv_step_model *m = &kn->models[v];
    double dt = given->timestep, soft = given->softness;
    dv_engine_derive_step(sc, m, &dt, m->soft_steps > 0.0 ? &soft : NULL, NULL, 0, NULL);
    const int nh = isnan(given->timestep) ? kn->halvings : 0;
    for (int k = 0; k <= nh && n < MAX_CANDIDATES; k++) {
      candidate *x = &c[n];
      memset(x, 0, sizeof *x);
      x->k.choice = v;
      x->k.timestep = fmax(dt / (1 << k), 1e-7);
      x->k.softness = m->soft_steps <= 0.0                ? NAN
                      : k == 0 || !isnan(given->softness) ? soft
                                                          : m->soft_steps * x->k.timestep;
      x->cost = ceil(sc->duration / x->k.timestep) * m->step_cost;
      x->model_step = k == 0;
      if (x->model_step || x->cost <= cap) n++;
    }
  }
  for (int i = 1; i < n; i++) /* by cost; a tie keeps the declared order */
    for (int j = i; j > 0 && c[j].cost < c[j - 1].cost; j--) {
      const candidate t = c[j];
      c[j] = c[j - 1];
      c[j - 1] = t;
    }
  return n;
}

/* the error model's reason for value choice (dv_engine_derive_step) */
static void model_reason(const dv_scenario *sc, const dv_engine_knobs *kn,
                         const dv_knob_choice *given, int choice, char *buf, size_t size) {
  const dv_step_model *m = &kn->models[choice];
  double dt = given->timestep, soft = given->softness;
  buf[0] = '\0';
  dv_engine_derive_step(sc, m, &dt, m->soft_steps > 0.0 ? &soft : NULL, buf, size, NULL);
}

/* "integrator implicit, timestep 5e-06 s, solref_timeconst 1e-05 s" (the chosen keys only) */
static void describe(const dv_engine_type *engine, const dv_engine_knobs *kn,
                     const dv_knob_choice *given, const dv_knob_choice *k, char *buf, size_t size) {
  const dv_setting_spec *ck = dv_settings_find(engine->settings, kn->choice_key);
  const char *soft_key = kn->models[k->choice].soft_key;
  int n = 0;
  if (given->choice < 0)
    n += snprintf(buf + n, size - (size_t)n, "%s %s", kn->choice_key,
                  dv_setting_choice(ck, (size_t)k->choice));
  if (isnan(given->timestep))
    n += snprintf(buf + n, size - (size_t)n, "%stimestep %.3g s", n ? ", " : "", k->timestep);
  if (soft_key && isnan(given->softness) && (size_t)n < size)
    snprintf(buf + n, size - (size_t)n, "%s%s %.3g s", n ? ", " : "", soft_key, k->softness);
}

/* the short name of a candidate: "rk4 5e-05 s" */
static void name_of(const dv_engine_type *engine, const dv_engine_knobs *kn, const candidate *c,
                    char *buf, size_t size) {
  const dv_setting_spec *ck = dv_settings_find(engine->settings, kn->choice_key);
  snprintf(buf, size, "%s %.3g s", dv_setting_choice(ck, (size_t)c->k.choice), c->k.timestep);
}

/* the choice, why, and whether the choice key was chosen (1) or had one candidate (0) */
static int choose(const dv_scenario *sc, const dv_engine_type *engine, const dv_engine_knobs *kn,
                  int default_choice, const dv_knob_choice *given, int runs, dv_knob_choice *out,
                  char *why, size_t size) {
  candidate c[MAX_CANDIDATES];
  const int n = candidates(sc, kn, given, c);
  char what[160] = "";
  const candidate *fallback = NULL;
  for (int i = 0; i < n && !fallback; i++)
    if (c[i].model_step && c[i].k.choice == (given->choice >= 0 ? given->choice : default_choice))
      fallback = &c[i];
  if (!fallback) fallback = &c[0];
  probe pr;
  const char *no_probe = NULL;
  char left[160];
  int status;
  /* the shape may be derived after the step (a [disk] thickness): ask for it.
   * A cylinder, of [disk] thickness or given, is judged against the matched
   * reference of its half-thickness, and probed against it; an engine that
   * models the thin disk (Bullet) against the thin reference */
  const double half = dv_engine_half_thickness(engine, sc);
  const dv_engine_type *ref =
      dv_engine_of_role(half > 0.0 ? DV_ENGINE_MATCHED_REFERENCE : DV_ENGINE_THIN_REFERENCE);
  if (!runs)
    no_probe = "the engine is not among those run";
  else if (ref->role == DV_ENGINE_THIN_REFERENCE && dv_engine_stand_in(engine, sc))
    no_probe = "a stand-in shape no reference models";
  else if (n < 2 && !isnan(given->timestep))
    no_probe = "nothing left to choose";
  else if (dv_phase_item("settings probe", 1, (size_t)n + 1, engine->name),
           (status = probe_reference(sc, ref, half, &pr)) == -2)
    no_probe = "the duration is over 4 of the longest probe's 2 s: too far to project";
  else if (status == -3) {
    snprintf(left, sizeof left,
             "the reference leaves its validity window, the friction cone of mu %g, at t = %g "
             "s: too soon to measure",
             dv_matched_friction(sc), pr.valid);
    no_probe = left;
  } else if (status)
    no_probe = "the reference does not run through the probe";
  char model[DV_DERIVED_BYTES];
  if (no_probe && n < 2) { /* one candidate: the model's settings, as it gives its reason */
    *out = fallback->k;
    model_reason(sc, kn, given, out->choice, why, size);
    return 0;
  }
  if (no_probe) {
    *out = fallback->k;
    describe(engine, kn, given, out, what, sizeof what);
    model_reason(sc, kn, given, out->choice, model, sizeof model);
    snprintf(why, size, "%s: the error model, not probed (%s): %s", what, no_probe, model);
    return 1;
  }
  const candidate *best = NULL, *meets = NULL;
  int nprobed = 0;
  for (int i = 0; i < n && !meets; i++) {
    char name[64], subject[96];
    name_of(engine, kn, &c[i], name, sizeof name);
    snprintf(subject, sizeof subject, "%s %s", engine->name, name);
    dv_phase_item("settings probe", (size_t)i + 2, (size_t)n + 1, subject);
    probe_candidate(sc, engine, &pr, kn, &c[i]);
    nprobed++;
    if (c[i].probed > 0 && (!best || c[i].margin < best->margin)) best = &c[i];
    if (c[i].probed > 0 && c[i].margin <= DV_CHOOSE_MARGIN) meets = &c[i];
  }
  const candidate *run = meets ? meets : best ? best : fallback;
  *out = run->k;
  describe(engine, kn, given, out, what, sizeof what);
  /* the path target is a share of the distance rolled only where the disk rolls that far */
  char target[96];
  if (pr.rolled >= sc->disk.r)
    snprintf(target, sizeof target, "%g of the %.3g m rolled over %g s", DV_SCENE_ACCURACY,
             pr.rolled, pr.horizon);
  else
    snprintf(target, sizeof target, "%g of the %.3g m radius, more than it rolls over %g s",
             DV_SCENE_ACCURACY, sc->disk.r, pr.horizon);
  int m = snprintf(why, size,
                   "%s: %s: projected theta %.2g rad, path %.2g m (%.2f of the target: theta "
                   "%g rad, path %s) from a probe of %.3g s",
                   what,
                   meets  ? "the cheapest candidate that meets the target with margin 0.5"
                   : best ? "no candidate within the cost cap meets the target; the best runs"
                          : "no candidate ran through the probe; the error model's step",
                   run->probed > 0 ? run->theta : NAN, run->probed > 0 ? run->path : NAN,
                   run->probed > 0 ? run->margin : NAN, DV_SCENE_ACCURACY, target, pr.window);
  model_reason(sc, kn, given, run->k.choice, model, sizeof model);
  if (m > 0 && (size_t)m < size) m += snprintf(why + m, size - (size_t)m, "; the model: %s", model);
  for (int i = 0, listed = 0; i < nprobed && listed < 3 && m > 0 && (size_t)m < size; i++) {
    if (&c[i] == run) continue;
    char name[64];
    name_of(engine, kn, &c[i], name, sizeof name);
    m += snprintf(why + m, size - (size_t)m, "%s %s %.2f", listed ? "," : "; rejected:", name,
                  c[i].margin);
    listed++;
  }
  return 1;
}

/* the engines this process runs (dv_engine_choose_only); none set: every engine */
static const dv_engine_type *running[DV_MAX_REGISTERED + 1];
static int running_set;
static int probing_off; /* dv_engine_choose_probing(0) */

void dv_engine_choose_probing(int on) {
  probing_off = !on;
}

void dv_engine_choose_only(const dv_engine_type *const *engines) {
  size_t n = 0;
  running_set = engines != NULL;
  for (; engines && engines[n] && n < DV_MAX_REGISTERED; n++) running[n] = engines[n];
  running[n] = NULL;
}

/* does engine run in sc: this process's engines, or those sc names ([scenario] engines);
 * an engine outside the build runs only where named */
static int runs_in(const dv_scenario *sc, const dv_engine_type *engine) {
  if (probing_off) return 0;
  if (!running_set && !engine->outside) return 1;
  for (size_t i = 0; running[i]; i++)
    if (running[i] == engine) return 1;
  char list[sizeof sc->engines];
  snprintf(list, sizeof list, "%s", sc->engines);
  for (char *save = NULL, *tok = strtok_r(list, ", ", &save); tok;
       tok = strtok_r(NULL, ", ", &save))
    if (strcmp(tok, engine->name) == 0) return 1;
  return 0;
}

/* the memory as saved: its entries and where the next goes */
typedef struct memo_image {
  int nmemo, next_slot;
  memo_entry memo[MEMO];
} memo_image;
_Static_assert(sizeof(memo_image) <= DV_CHOOSE_MEMO_BYTES, "DV_CHOOSE_MEMO_BYTES holds the memo");

void dv_engine_choose_memo_save(void *buf) {
  memo_image *m = buf;
  m->nmemo = nmemo;
  m->next_slot = next_slot;
  memcpy(m->memo, memo, sizeof memo);
}

void dv_engine_choose_memo_restore(const void *buf) {
  const memo_image *m = buf;
  if (m->nmemo < 0 || m->nmemo > MEMO || m->next_slot < 0 || m->next_slot >= MEMO) return;
  nmemo = m->nmemo;
  next_slot = m->next_slot;
  memcpy(memo, m->memo, sizeof memo);
}

void dv_engine_choose(const dv_scenario *sc, const dv_engine_type *engine,
                      const dv_engine_knobs *knobs, int default_choice, const dv_knob_choice *given,
                      dv_knob_choice *out, char *why, size_t size, const char **keys) {
  const int runs = runs_in(sc, engine);
  const uint64_t key =
      scene_key(sc, engine, given) ^ (uint64_t)!runs; /* an unprobed choice apart */
  const memo_entry *hit = NULL;
  for (int i = 0; i < nmemo && !hit; i++)
    if (memo[i].key == key) hit = &memo[i];
  memo_entry fresh = {key, {0}, "", 0};
  if (!hit) {
    fresh.chose = choose(sc, engine, knobs, default_choice, given, runs, &fresh.out, fresh.why,
                         sizeof fresh.why);
    dv_phase_end("settings probe"); /* its reference and candidates, one item each */
    memo[next_slot] = fresh;
    next_slot = (next_slot + 1) % MEMO; /* full: the oldest entry goes */
    nmemo = nmemo < MEMO ? nmemo + 1 : MEMO;
    hit = &fresh;
  }
  *out = hit->out;
  if (why) snprintf(why, size, "%s", hit->why);
  size_t nkeys = 0;
  if (keys) {
    if (given->choice < 0 && hit->chose) keys[nkeys++] = knobs->choice_key;
    if (isnan(given->timestep)) keys[nkeys++] = "timestep";
    if (knobs->models[out->choice].soft_key && isnan(given->softness))
      keys[nkeys++] = knobs->models[out->choice].soft_key;
    keys[nkeys] = NULL;
  }
}
