/* scenario_settings: an engine's settings in a scenario, by name. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scenario.h"

void dv_scenario_init(dv_scenario *sc, const dv_settings_section *const *engines) {
  memset(sc, 0, sizeof *sc);
  sc->steady_circle_radius = sc->steady_phi_dot = NAN;
  sc->friction = DV_FRICTION_DEFAULT;
  for (size_t i = 0; engines && engines[i] && i < DV_MAX_ENGINE_SECTIONS; i++) {
    sc->sections[sc->nsections] = engines[i];
    dv_settings_defaults(engines[i], &sc->settings[sc->nsections++]);
  }
}

static int find(const dv_scenario *sc, const char *engine) {
  for (size_t i = 0; i < sc->nsections; i++)
    if (!strcmp(sc->sections[i]->name, engine)) return (int)i;
  return -1;
}

const void *dv_scenario_settings(const dv_scenario *sc, const char *engine) {
  const int i = find(sc, engine);
  return i < 0 ? NULL : &sc->settings[i];
}

double dv_scenario_get(const dv_scenario *sc, const char *engine, const char *key) {
  const int i = find(sc, engine);
  const dv_setting_spec *sp = i < 0 ? NULL : dv_settings_find(sc->sections[i], key);
  return sp ? dv_setting_value(sp, &sc->settings[i]) : NAN;
}

static unsigned key_bit(const dv_scenario *sc, int i, const char *key);

/* set [engines.ENGINE] key from text, or (text NULL) to v */
static int set(dv_scenario *sc, const char *engine, const char *key, const char *text, double v,
               dv_error *err) {
  const int i = find(sc, engine);
  const dv_setting_spec *sp = i < 0 ? NULL : dv_settings_find(sc->sections[i], key);
  char what[320];
  if (!sp) return dv_fail(err, DV_EINPUT, "engines.%s.%s: no such setting", engine, key);
  const int bad = text ? dv_setting_parse(sp, text, &sc->settings[i], what, sizeof what)
                       : dv_setting_store(sp, v, &sc->settings[i], what, sizeof what);
  if (bad) return dv_fail(err, DV_EINPUT, "engines.%s.%s: %s", engine, key, what);
  sc->given_keys[i] |= key_bit(sc, i, key);
  if (dv_scenario_is_derived(sc, engine, key)) { /* the reason no longer holds */
    sc->derived[i][0] = '\0';
    sc->derived_keys[i] = 0;
  }
  return DV_OK;
}

int dv_scenario_set(dv_scenario *sc, const char *engine, const char *key, const char *text,
                    dv_error *err) {
  return set(sc, engine, key, text, 0.0, err);
}

int dv_scenario_set_number(dv_scenario *sc, const char *engine, const char *key, double v,
                           dv_error *err) {
  return set(sc, engine, key, NULL, v, err);
}

const char *dv_scenario_derived(const dv_scenario *sc, const char *engine) {
  const int i = find(sc, engine);
  return i < 0 ? "" : sc->derived[i];
}

/* bit of key in engine's table section i (0 when it has none) */
static unsigned key_bit(const dv_scenario *sc, int i, const char *key) {
  const dv_setting_spec *sp = dv_settings_find(sc->sections[i], key);
  const size_t k = sp ? (size_t)(sp - sc->sections[i]->specs) : 32;
  return k < 32 ? 1u << k : 0u;
}

int dv_scenario_is_derived(const dv_scenario *sc, const char *engine, const char *key) {
  const int i = find(sc, engine);
  return i >= 0 && (sc->derived_keys[i] & key_bit(sc, i, key)) != 0;
}

int dv_scenario_is_given(const dv_scenario *sc, const char *engine, const char *key) {
  const int i = find(sc, engine);
  return i >= 0 && (sc->given_keys[i] & key_bit(sc, i, key)) != 0;
}

void dv_scenario_set_derived(dv_scenario *sc, const char *engine, const char *const *keys,
                             const char *why) {
  const int i = find(sc, engine);
  if (i < 0) return;
  sc->derived_keys[i] = 0;
  for (size_t k = 0; keys && keys[k]; k++) sc->derived_keys[i] |= key_bit(sc, i, keys[k]);
  char *text = sc->derived[i];
  const size_t size = sizeof sc->derived[i];
  if (snprintf(text, size, "%s", why ? why : "") < (int)size) return;
  /* too long: cut before a whole character and end with an ellipsis, so a reader sees the cut */
  size_t end = size - 4;
  while (end > 0 && ((unsigned char)text[end] & 0xC0) == 0x80) end--;
  memcpy(text + end, "\xe2\x80\xa6", 4);
}

/* value v of sp as a scenario file writes it */
static void value_text(const dv_setting_spec *sp, double v, char *buf, size_t size) {
  const char *name = sp->type == DV_SETTING_CHOICE ? dv_setting_choice(sp, (size_t)v) : NULL;
  if (name)
    snprintf(buf, size, "%s", name);
  else
    snprintf(buf, size, "%.6g", v);
}

int dv_scenario_check_engine(dv_scenario *sc, size_t i, dv_setting_issue *issue) {
  const dv_settings_section *sec = sc->sections[i];
  const size_t n = sec->nspecs < 32 ? sec->nspecs : 32;
  double before[32];
  for (size_t k = 0; k < n; k++) before[k] = dv_setting_value(&sec->specs[k], &sc->settings[i]);
  sc->replaced[i][0] = '\0';
  if (!sec->check) return 0;
  if (sec->check(sc, &sc->settings[i], issue)) return -1;
  for (size_t k = 0; k < n; k++) {
    const double after = dv_setting_value(&sec->specs[k], &sc->settings[i]);
    if (!(sc->given_keys[i] >> k & 1u) || after == before[k] || (isnan(after) && isnan(before[k])))
      continue;
    char was[48], now[48];
    value_text(&sec->specs[k], before[k], was, sizeof was);
    value_text(&sec->specs[k], after, now, sizeof now);
    const size_t used = strlen(sc->replaced[i]);
    snprintf(sc->replaced[i] + used, sizeof sc->replaced[i] - used, "%s%s %s -> %s",
             used ? "; " : "", sec->specs[k].key, was, now);
  }
  return 0;
}

const char *dv_scenario_replaced(const dv_scenario *sc, const char *engine) {
  const int i = find(sc, engine);
  return i < 0 ? "" : sc->replaced[i];
}

double dv_scenario_tolerance(const dv_scenario *sc, const char *engine, dv_metric_id metric,
                             int *own) {
  double limit = INFINITY;
  if (own) *own = -1;
  for (int pass = 0; pass < 2; pass++) /* the scenario's, then the engine's own */
    for (size_t i = 0; i < sc->ntolerances; i++) {
      const dv_tolerance *t = &sc->tolerances[i];
      if (t->metric != metric || strcmp(t->engine, pass ? engine : "")) continue;
      limit = t->limit;
      if (own) *own = pass;
    }
  return limit;
}
