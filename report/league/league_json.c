/* league_json: a cell as JSON and back (the cache and league.json's cells),
 * and league.json. Numbers read back exactly (io_json.h); NaN is null. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_file.h"
#include "io_json.h"
#include "league.h"

static void add_number(cJSON *o, const char *name, double v) {
  cJSON_AddItemToObject(o, name, dv_io_json_double(v));
}

static cJSON *settings_of(const dv_league_cell *c) {
  cJSON *s = cJSON_CreateObject();
  if (c->choice_key[0] && strcmp(c->choice, "default"))
    cJSON_AddStringToObject(s, c->choice_key, c->choice);
  if (c->step_key[0] && isfinite(c->step)) add_number(s, c->step_key, c->step);
  return s;
}

cJSON *dv_league_cell_to_json(const dv_league_cell *c) {
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "object", c->object);
  cJSON_AddStringToObject(o, "scenario_file", c->scenario_file);
  cJSON_AddStringToObject(o, "engine", c->engine);
  cJSON_AddStringToObject(o, "engine_version", c->engine_version);
  add_number(o, "target", c->target);
  add_number(o, "path_target", c->path_target);
  cJSON_AddStringToObject(o, "outcome", dv_league_outcome_name(c->outcome));
  cJSON_AddBoolToObject(o, "reached", c->outcome == DV_LEAGUE_REACHED);
  cJSON_AddItemToObject(o, "settings", settings_of(c));
  cJSON_AddStringToObject(o, "choice_key", c->choice_key);
  cJSON_AddStringToObject(o, "choice", c->choice);
  cJSON_AddStringToObject(o, "step_key", c->step_key);
  add_number(o, "step", c->step);
  add_number(o, "theta_max_err", c->theta_max_err);
  add_number(o, "path_max_err", c->path_max_err);
  add_number(o, "wall_per_sim_s", c->wall_per_sim_s);
  cJSON_AddItemToObject(o, "steps", c->steps >= 0 ? dv_io_json_double((double)c->steps)
                                                  : cJSON_CreateNull());
  add_number(o, "sim_s", c->sim_s);
  add_number(o, "order", c->order);
  cJSON_AddStringToObject(o, "verdict", c->verdict);
  cJSON_AddStringToObject(o, "why", c->why);
  cJSON_AddStringToObject(o, "cause", c->cause);
  cJSON_AddStringToObject(o, "report", c->report);
  cJSON_AddStringToObject(o, "key", c->key);
  add_number(o, "wall_s", c->wall_s);
  cJSON *pts = cJSON_AddArrayToObject(o, "points");
  for (size_t i = 0; i < c->npoints; i++) {
    const dv_league_point *p = &c->points[i];
    cJSON *q = cJSON_CreateObject();
    cJSON_AddStringToObject(q, "choice", p->choice);
    add_number(q, "step", p->step);
    add_number(q, "theta_err", p->theta_err);
    add_number(q, "path_err", p->path_err);
    add_number(q, "cost", p->cost);
    cJSON_AddBoolToObject(q, "ok", p->ok);
    cJSON_AddItemToArray(pts, q);
  }
  return o;
}

/* a field of j: a number (null: NaN), a string into buf, a bool; a missing or
 * mistyped field is an error naming it */
static int get_number(const cJSON *j, const char *name, double *v, dv_error *err) {
  const cJSON *f = cJSON_GetObjectItemCaseSensitive(j, name);
  if (cJSON_IsNumber(f)) return *v = f->valuedouble, DV_OK;
  if (cJSON_IsNull(f)) return *v = NAN, DV_OK;
  return dv_fail(err, DV_EINPUT, "field '%s' is no number", name);
}

static int get_text(const cJSON *j, const char *name, char *buf, size_t size, dv_error *err) {
  const cJSON *f = cJSON_GetObjectItemCaseSensitive(j, name);
  if (!cJSON_IsString(f) || strlen(f->valuestring) >= size)
    return dv_fail(err, DV_EINPUT, "field '%s' is no string of fewer than %zu bytes", name, size);
  memcpy(buf, f->valuestring, strlen(f->valuestring) + 1);
  return DV_OK;
}

int dv_league_cell_from_json(const cJSON *j, dv_league_cell *c, dv_error *err) {
  memset(c, 0, sizeof *c);
  char outcome[32];
  double steps;
  const struct {
    const char *name;
    char *buf;
    size_t size;
  } texts[] = {{"object", c->object, sizeof c->object},
               {"scenario_file", c->scenario_file, sizeof c->scenario_file},
               {"engine", c->engine, sizeof c->engine},
               {"engine_version", c->engine_version, sizeof c->engine_version},
               {"outcome", outcome, sizeof outcome},
               {"choice_key", c->choice_key, sizeof c->choice_key},
               {"choice", c->choice, sizeof c->choice},
               {"step_key", c->step_key, sizeof c->step_key},
               {"verdict", c->verdict, sizeof c->verdict},
               {"why", c->why, sizeof c->why},
               {"cause", c->cause, sizeof c->cause},
               {"report", c->report, sizeof c->report},
               {"key", c->key, sizeof c->key}};
  const struct {
    const char *name;
    double *v;
  } numbers[] = {{"target", &c->target},         {"path_target", &c->path_target},
                 {"step", &c->step},             {"theta_max_err", &c->theta_max_err},
                 {"path_max_err", &c->path_max_err}, {"wall_per_sim_s", &c->wall_per_sim_s},
                 {"steps", &steps},              {"sim_s", &c->sim_s},
                 {"order", &c->order},           {"wall_s", &c->wall_s}};
  for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++)
    if (get_text(j, texts[i].name, texts[i].buf, texts[i].size, err)) return DV_EINPUT;
  for (size_t i = 0; i < sizeof numbers / sizeof numbers[0]; i++)
    if (get_number(j, numbers[i].name, numbers[i].v, err)) return DV_EINPUT;
  c->steps = isfinite(steps) ? (long)steps : -1;
  c->outcome = DV_LEAGUE_NOT_RUN + 1;
  for (int o = DV_LEAGUE_REACHED; o <= DV_LEAGUE_NOT_RUN; o++)
    if (!strcmp(outcome, dv_league_outcome_name((dv_league_outcome)o))) c->outcome = o;
  if (c->outcome > DV_LEAGUE_NOT_RUN)
    return dv_fail(err, DV_EINPUT, "field 'outcome': unknown '%s'", outcome);
  const cJSON *reached = cJSON_GetObjectItemCaseSensitive(j, "reached");
  if (!cJSON_IsBool(reached) || cJSON_IsTrue(reached) != (c->outcome == DV_LEAGUE_REACHED))
    return dv_fail(err, DV_EINPUT, "field 'reached' is not what 'outcome' says (%s)", outcome);
  const cJSON *pts = cJSON_GetObjectItemCaseSensitive(j, "points"), *q;
  if (!cJSON_IsArray(pts) || cJSON_GetArraySize(pts) > DV_LEAGUE_MAX_POINTS)
    return dv_fail(err, DV_EINPUT, "field 'points' is no array of at most %d", DV_LEAGUE_MAX_POINTS);
  cJSON_ArrayForEach(q, pts) {
    dv_league_point *p = &c->points[c->npoints++];
    const cJSON *ok = cJSON_GetObjectItemCaseSensitive(q, "ok");
    if (get_text(q, "choice", p->choice, sizeof p->choice, err) ||
        get_number(q, "step", &p->step, err) || get_number(q, "theta_err", &p->theta_err, err) ||
        get_number(q, "path_err", &p->path_err, err) || get_number(q, "cost", &p->cost, err) ||
        !cJSON_IsBool(ok))
      return dv_fail(err, DV_EINPUT, "a point: %s", err->msg[0] ? err->msg : "field 'ok'");
    p->ok = cJSON_IsTrue(ok);
  }
  return DV_OK;
}

/* the summary of every engine at every target */
static cJSON *summary_of(const dv_league *lg) {
  cJSON *a = cJSON_CreateArray();
  for (size_t e = 0; e < lg->nengines; e++)
    for (size_t t = 0; lg->engines[e].available && t < lg->ntargets; t++) {
      dv_league_summary s;
      dv_league_summarize(lg, lg->engines[e].name, lg->targets[t], &s);
      cJSON *o = cJSON_CreateObject();
      cJSON_AddStringToObject(o, "engine", lg->engines[e].name);
      add_number(o, "target", lg->targets[t]);
      add_number(o, "reached", (double)s.reached);
      add_number(o, "not_reached", (double)s.not_reached);
      add_number(o, "cannot_model", (double)s.cannot_model);
      add_number(o, "not_run", (double)s.not_run);
      add_number(o, "geomean_wall_per_sim_s", s.geomean_wall_per_sim_s);
      add_number(o, "geomean_steps_per_sim_s", s.geomean_steps_per_sim_s);
      cJSON *missed = cJSON_AddArrayToObject(o, "objects_not_reached");
      for (size_t k = 0; k < lg->ncells; k++) {
        const dv_league_cell *c = &lg->cells[k];
        if (!strcmp(c->engine, lg->engines[e].name) && c->target == lg->targets[t] &&
            c->outcome != DV_LEAGUE_REACHED)
          cJSON_AddItemToArray(missed, cJSON_CreateString(c->object));
      }
      cJSON_AddItemToArray(a, o);
    }
  return a;
}

int dv_league_write_json(const char *dir, const dv_league *lg, dv_error *err) {
  cJSON *root = cJSON_CreateObject();
  cJSON_AddStringToObject(root, "format", DV_LEAGUE_FORMAT);
  cJSON_AddStringToObject(root, "date", lg->date);
  cJSON_AddStringToObject(root, "machine", lg->machine);
  cJSON_AddStringToObject(root, "diskval_version", lg->diskval_version);
  add_number(root, "cost_cap", lg->cost_cap);
  cJSON_AddBoolToObject(root, "interrupted", lg->interrupted);
  cJSON *sets = cJSON_AddArrayToObject(root, "overrides");
  for (size_t i = 0; i < lg->noverrides; i++)
    cJSON_AddItemToArray(sets, cJSON_CreateString(lg->overrides[i]));
  cJSON *targets = cJSON_AddArrayToObject(root, "targets");
  for (size_t t = 0; t < lg->ntargets; t++) cJSON_AddItemToArray(targets, dv_io_json_double(lg->targets[t]));
  cJSON *objects = cJSON_AddArrayToObject(root, "objects");
  for (size_t i = 0; i < lg->nobjects; i++) {
    const dv_league_object *b = &lg->objects[i];
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "name", b->name);
    cJSON_AddStringToObject(o, "file", b->file);
    cJSON_AddStringToObject(o, "description", b->description);
    add_number(o, "radius", b->radius);
    add_number(o, "thickness", b->thickness);
    add_number(o, "duration", b->duration);
    cJSON_AddItemToArray(objects, o);
  }
  cJSON *engines = cJSON_AddArrayToObject(root, "engines");
  for (size_t i = 0; i < lg->nengines; i++) {
    const dv_league_engine *e = &lg->engines[i];
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "name", e->name);
    cJSON_AddStringToObject(o, "version", e->version);
    cJSON_AddBoolToObject(o, "available", e->available);
    cJSON_AddStringToObject(o, "why", e->why);
    cJSON_AddItemToArray(engines, o);
  }
  cJSON *cells = cJSON_AddArrayToObject(root, "cells");
  for (size_t k = 0; k < lg->ncells; k++) cJSON_AddItemToArray(cells, dv_league_cell_to_json(&lg->cells[k]));
  cJSON_AddItemToObject(root, "summary", summary_of(lg));
  char *text = cJSON_Print(root);
  cJSON_Delete(root);
  if (!text) return dv_fail(err, DV_ESYSTEM, "league.json: out of memory");
  const size_t len = strlen(text);
  char *with_newline = realloc(text, len + 2);
  if (!with_newline) return free(text), dv_fail(err, DV_ESYSTEM, "league.json: out of memory");
  memcpy(with_newline + len, "\n", 2);
  const int status = dv_io_write_text(dir, "league.json", with_newline, err);
  free(with_newline);
  return status;
}
