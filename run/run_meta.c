/* dv_meta: run metadata as JSON (cJSON). */
#include "run_meta.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "io_file.h"
#include "io_json.h"

/* every key of engine's table in sc, by name */
static void add_settings(cJSON *o, const dv_scenario *sc, const char *engine) {
  const void *block = dv_scenario_settings(sc, engine);
  const dv_engine_type *type = dv_engine_find(engine);
  if (!block || !type || !type->settings) return;
  for (size_t i = 0; i < type->settings->nspecs; i++) {
    const dv_setting_spec *sp = &type->settings->specs[i];
    const double v = dv_setting_value(sp, block);
    if (sp->type == DV_SETTING_CHOICE)
      cJSON_AddStringToObject(o, sp->key, dv_setting_choice(sp, (size_t)v));
    else
      cJSON_AddNumberToObject(o, sp->key, v);
  }
}

void *dv_run_meta_settings(const dv_engine_type *engine, const dv_scenario *sc) {
  cJSON *o = cJSON_CreateObject();
  /* a reference integrates with another engine's solver settings: those first */
  if (engine->search && strcmp(engine->search->section, engine->name) != 0)
    add_settings(o, sc, engine->search->section);
  add_settings(o, sc, engine->name);
  return o;
}

/* the settings of engine sc derived from the scene, and why: {"keys": [...],
 * "reason": "..."}; null when the scenario gave them all */
static cJSON *derived(const dv_engine_type *engine, const dv_scenario *sc) {
  const char *why = dv_scenario_derived(sc, engine->name);
  if (!why[0] || !engine->settings) return cJSON_CreateNull();
  cJSON *o = cJSON_CreateObject(), *keys = cJSON_AddArrayToObject(o, "keys");
  for (size_t i = 0; i < engine->settings->nspecs; i++)
    if (dv_scenario_is_derived(sc, engine->name, engine->settings->specs[i].key))
      cJSON_AddItemToArray(keys, cJSON_CreateString(engine->settings->specs[i].key));
  cJSON_AddStringToObject(o, "reason", why);
  return o;
}

void *dv_io_json_number(double v) {
  return dv_io_json_double(v); /* cJSON's own 15-digit text does not always read back */
}

int dv_io_json_write(const char *dir, const char *name, void *json, dv_error *err) {
  char *text = cJSON_Print(json);
  cJSON_Delete(json);
  if (!text) return dv_fail(err, DV_ESYSTEM, "out of memory: the text of %s", name);
  char path[1200];
  dv_io_file out;
  snprintf(path, sizeof path, "%s%s%s", dir, name ? "/" : "", name ? name : "");
  int status = dv_io_open(&out, path, err);
  if (!status) {
    fprintf(out.fp, "%s\n", text);
    status = dv_io_commit(&out, err);
  }
  free(text);
  return status;
}

int dv_run_meta_write(const char *path, const dv_engine_type *engine, const dv_scenario *sc,
                      const dv_engine_stats *st, dv_error *err) {
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "scenario", sc->name);
  cJSON_AddStringToObject(o, "engine", engine->name);
  cJSON_AddStringToObject(o, "version", engine->version());
  cJSON_AddItemToObject(o, "settings", dv_run_meta_settings(engine, sc));
  cJSON_AddItemToObject(o, "derived", derived(engine, sc));
  cJSON *s = cJSON_AddObjectToObject(o, "run");
  cJSON_AddStringToObject(s, "outcome", dv_outcome_name(st->outcome));
  cJSON_AddStringToObject(s, "detail", st->detail);
  cJSON_AddStringToObject(s, "method", st->method);
  cJSON_AddNumberToObject(s, "steps", (double)st->steps);
  cJSON_AddNumberToObject(s, "rhs_evals", (double)st->rhs_evals);
  cJSON_AddNumberToObject(s, "slip_max", st->slip_max);
  cJSON_AddNumberToObject(s, "penetration_max", st->penetration_max);
  cJSON_AddNumberToObject(s, "contacts_max", st->contacts_max);
  cJSON_AddNumberToObject(s, "warnings", (double)st->warnings);
  return dv_io_json_write(path, NULL, o, err);
}

int dv_run_meta_check_replaceable(const char *path, dv_error *err) {
  struct stat st;
  if (dv_io_check_output(path, err)) return DV_EINPUT;
  if (stat(path, &st) || !S_ISREG(st.st_mode))
    return DV_OK; /* new, or a device: written in place */
  cJSON *o = dv_io_json_read(path, 1L << 20, NULL, 0);
  const int ours = cJSON_IsString(cJSON_GetObjectItem(o, "scenario")) &&
                   cJSON_IsString(cJSON_GetObjectItem(o, "engine")) &&
                   cJSON_IsObject(cJSON_GetObjectItem(o, "settings")) &&
                   cJSON_IsObject(cJSON_GetObjectItem(o, "run"));
  cJSON_Delete(o);
  return ours ? DV_OK
              : dv_fail(err, DV_EINPUT,
                        "%s: a file that is not simulate's metadata is in the way of the one "
                        "--out writes beside it; nothing was written: move it, or choose "
                        "another --out",
                        path);
}
