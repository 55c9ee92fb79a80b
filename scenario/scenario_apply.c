/* scenario_apply: a loaded scenario with more overrides, checked again as a
 * load checks a file, so that a search loads its file once and varies the
 * struct (a file that changes, or a pipe, is read once). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scenario.h"
#include "scenario_core.h"

/* one key back at its default, as before a load reads the file */
static void reset_key(const dv_setting_spec *sp, void *block) {
  char *field = (char *)block + sp->offset;
  if (sp->type == DV_SETTING_TEXT)
    memset(field, 0, sp->size);
  else if (sp->type == DV_SETTING_REAL)
    *(double *)field = sp->def;
  else /* as dv_settings_defaults: a whole number derived from the scene is 0 until derived */
    *(int *)field = isnan(sp->def) ? 0 : (int)sp->def;
}

/* every key of section that was not given back at its default: what the
 * checks derived from the old values is derived again from the new ones */
static void reset_not_given(const dv_settings_section *sec, void *block, unsigned given) {
  for (size_t k = 0; k < sec->nspecs && k < 32; k++)
    if (!(given & (1u << k)) && !(sec->specs[k].flags & DV_SETTING_REQUIRED))
      reset_key(&sec->specs[k], block);
}

/* [tolerance] or [tolerance.ENGINE] metric = text, replacing an earlier limit */
static int set_tolerance(dv_scenario *sc, const char *section, const char *key, const char *text,
                         dv_error *err) {
  const char *engine = section[9] == '.' ? section + 10 : "";
  int metric = -1, known = !*engine;
  for (size_t i = 0; i < sc->nsections; i++) known |= !strcmp(sc->sections[i]->name, engine);
  for (int m = 0; m < DV_NMETRICS; m++)
    if (!strcmp(dv_metric_names[m], key)) metric = m;
  if (!known) return dv_fail(err, DV_EINPUT, "%s: unknown engine '%s'", section, engine);
  if (metric < 0) return dv_fail(err, DV_EINPUT, "%s.%s: unknown tolerance metric", section, key);
  const dv_setting_spec spec = {.key = key, .type = DV_SETTING_REAL, .hi = INFINITY};
  double limit;
  char what[320];
  if (dv_setting_parse(&spec, text, &limit, what, sizeof what))
    return dv_fail(err, DV_EINPUT, "%s.%s: %s", section, key, what);
  size_t i = 0;
  while (i < sc->ntolerances &&
         (strcmp(sc->tolerances[i].engine, engine) || (int)sc->tolerances[i].metric != metric))
    i++;
  if (i == DV_MAX_TOLERANCES)
    return dv_fail(err, DV_EINPUT, "%s.%s: too many tolerances", section, key);
  if (i == sc->ntolerances) sc->ntolerances++;
  snprintf(sc->tolerances[i].engine, sizeof sc->tolerances[i].engine, "%.31s", engine);
  sc->tolerances[i].metric = (dv_metric_id)metric;
  sc->tolerances[i].limit = limit;
  return DV_OK;
}

/* one "section.key=value" */
static int apply(dv_scenario *sc, const char *text, dv_error *err) {
  char buf[512], *eq, *dot, what[320];
  snprintf(buf, sizeof buf, "%s", text);
  if (!(eq = strchr(buf, '=')) || (*eq = '\0', !(dot = strrchr(buf, '.'))))
    return dv_fail(err, DV_EINPUT, "%s: expected section.key=value", text);
  *dot = '\0';
  const char *section = buf, *key = dot + 1, *value = eq + 1;
  if (!strncmp(section, "tolerance", 9) && (section[9] == '\0' || section[9] == '.'))
    return set_tolerance(sc, section, key, value, err);
  if (!strncmp(section, "engines.", 8)) { /* the loader's words for what it does not know */
    for (size_t i = 0; i < sc->nsections; i++)
      if (!strcmp(sc->sections[i]->name, section + 8))
        return dv_settings_find(sc->sections[i], key)
                   ? dv_scenario_set(sc, section + 8, key, value, err)
                   : dv_fail(err, DV_EINPUT, "%s.%s: unknown key in [%s]", section, key, section);
  }
  for (size_t s = 0; s < DV_NCORE_SECTIONS; s++) {
    if (strcmp(dv_scenario_core[s].name, section)) continue;
    const dv_setting_spec *sp = dv_settings_find(&dv_scenario_core[s], key);
    if (!sp) return dv_fail(err, DV_EINPUT, "%s.%s: unknown key in [%s]", section, key, section);
    if (dv_setting_parse(sp, value, sc, what, sizeof what))
      return dv_fail(err, DV_EINPUT, "%s.%s: %s", section, key, what);
    if (sp - dv_scenario_core[s].specs < 32)
      sc->core_given[s] |= 1u << (sp - dv_scenario_core[s].specs);
    return DV_OK;
  }
  return dv_fail(err, DV_EINPUT, "%s: unknown section [%s]", text, section);
}

int dv_scenario_with(const dv_scenario *base, const char *const *overrides, size_t noverrides,
                     dv_scenario *out, dv_error *err) {
  *out = *base;
  for (size_t s = 0; s < DV_NCORE_SECTIONS; s++)
    reset_not_given(&dv_scenario_core[s], out, out->core_given[s]);
  for (size_t i = 0; i < out->nsections; i++) {
    reset_not_given(out->sections[i], &out->settings[i], out->given_keys[i]);
    memset(out->derived[i], 0, sizeof out->derived[i]);
    out->derived_keys[i] = 0;
  }
  for (size_t i = 0; i < noverrides; i++)
    if (apply(out, overrides[i], err)) return DV_EINPUT;
  /* the checks in a load's order: the core sections, then every engine's */
  if (dv_scenario_check_core(out, err)) return DV_EINPUT;
  for (size_t i = 0; i < out->nsections; i++) {
    dv_setting_issue is = {0};
    const dv_settings_section *sec = out->sections[i];
    if (dv_scenario_check_engine(out, i, &is))
      return dv_fail(err, DV_EINPUT, "%s%s.%s: %s", strcmp(is.section, sec->name) ? "" : "engines.",
                     is.section, is.key, is.what);
  }
  return DV_OK;
}
