/* dv_engine: the registry of engines and what they share. */
#include "dv_engine.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "dv_format.h"
#include "dv_pose.h"
#include "adapter.h"

#define DV_ENGINE(name) &dv_engine_##name,
const dv_engine_type *const dv_engines_linked[] = {
#include "dv_engines.def"
    NULL};
#undef DV_ENGINE

static const dv_engine_type *registry[DV_MAX_REGISTERED + 1];
static pthread_once_t once = PTHREAD_ONCE_INIT;

/* the linked engines, then the adapters found (adapter.h) */
static void build(void) {
  size_t n = 0;
  const dv_adapter *const *a;
  for (const dv_engine_type *const *e = dv_engines_linked; *e; e++) registry[n++] = *e;
  const size_t na = dv_adapters(&a);
  for (size_t i = 0; i < na; i++) registry[n++] = &a[i]->type;
  registry[n] = NULL;
}

const dv_engine_type *const *dv_engine_list(void) {
  pthread_once(&once, build);
  return registry;
}

const dv_engine_type *dv_engine_find(const char *name) {
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++)
    if (strcmp((*e)->name, name) == 0) return *e;
  return NULL;
}

const dv_engine_type *dv_engine_of_role(dv_engine_role role) {
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++)
    if ((*e)->role == role) return *e;
  return NULL;
}

double dv_engine_half_thickness(const dv_engine_type *engine, const dv_scenario *sc) {
  return engine->half_thickness ? engine->half_thickness(sc) : 0.0;
}

void dv_engine_limit_detail(int lower, double theta_limit, double t, char *buf, size_t size) {
  char limit[DV_FORMAT_SIZE];
  dv_format_double(lower ? theta_limit : M_PI - theta_limit, limit, sizeof limit);
  const int n =
      snprintf(buf, size, "theta reached the %s limit %s rad", lower ? "lower" : "upper", limit);
  if (isfinite(t) && n >= 0 && (size_t)n < size)
    snprintf(buf + n, size - (size_t)n, " at t = %g s", t);
}

void dv_engine_lay_down(dv_engine_stats *stats, int lower, double theta_limit, double t) {
  dv_engine_limit_detail(lower, theta_limit, t, stats->detail, sizeof stats->detail);
  stats->outcome = DV_OUTCOME_EVENT;
  stats->lay_down = lower ? -1 : 1;
}

int dv_engine_stand_in(const dv_engine_type *engine, const dv_scenario *sc) {
  const dv_engine_contact *k = engine->contact;
  if (!k) return 0;
  if (!k->geom_key) return 1; /* an engine with no thin disk: a cylinder always */
  const dv_setting_spec *geom = dv_settings_find(engine->settings, k->geom_key);
  const char *shape =
      dv_setting_choice(geom, (size_t)dv_scenario_get(sc, engine->name, k->geom_key));
  return shape && strcmp(shape, k->thin_choice) != 0;
}

int dv_engine_own_body(const dv_engine_type *engine, const dv_scenario *sc) {
  if (!engine->contact) return 1;
  if (!(sc->thickness > 0.0)) return !dv_engine_stand_in(engine, sc);
  const double h = dv_engine_half_thickness(engine, sc);
  return fabs(h - 0.5 * sc->thickness) <= 1e-12 * sc->thickness;
}

void dv_engine_knobs_text(const dv_engine_type *engine, const dv_scenario *sc, char *buf,
                          size_t size) {
  const dv_engine_search *se = engine->search;
  const dv_engine_contact *k = engine->contact;
  const char *keys[] = {se ? se->choice_key : NULL, se ? se->step_key : NULL,
                        k ? k->softness_key : NULL, k ? k->geom_key : NULL};
  size_t n = 0;
  buf[0] = '\0';
  for (size_t i = 0; i < sizeof keys / sizeof keys[0] && n < size; i++) {
    const dv_setting_spec *sp = keys[i] ? dv_settings_find(engine->settings, keys[i]) : NULL;
    if (!sp) continue;
    const double v = dv_scenario_get(sc, engine->name, sp->key);
    const char *name = sp->type == DV_SETTING_CHOICE ? dv_setting_choice(sp, (size_t)v) : NULL;
    const int w = name ? snprintf(buf + n, size - n, "%s%s %s", n ? ", " : "", sp->key, name)
                       : snprintf(buf + n, size - n, "%s%s %.3g%s%s", n ? ", " : "", sp->key, v,
                                  sp->unit[0] ? " " : "", sp->unit);
    if (w < 0) return;
    n += (size_t)w;
  }
}

/* every engine's settings table, NULL-terminated */
static void tables(const dv_settings_section **out) {
  _Static_assert(DV_MAX_REGISTERED <= DV_MAX_ENGINE_SECTIONS,
                 "every engine's settings section fits");
  size_t n = 0;
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++)
    if ((*e)->settings) out[n++] = (*e)->settings;
  out[n] = NULL;
}

int dv_engine_load_scenario(const char *path, const char *const *overrides, size_t noverrides,
                            dv_scenario *sc, dv_error *err) {
  const dv_settings_section *t[DV_MAX_ENGINE_SECTIONS + 1];
  tables(t);
  return dv_scenario_load(t, path, overrides, noverrides, sc, err);
}

void dv_engine_init_scenario(dv_scenario *sc) {
  const dv_settings_section *t[DV_MAX_ENGINE_SECTIONS + 1];
  tables(t);
  dv_scenario_init(sc, t);
}

int dv_engine_derive_settings(dv_scenario *sc, dv_error *err) {
  for (size_t i = 0; i < sc->nsections; i++) {
    dv_setting_issue issue = {0};
    if (dv_scenario_check_engine(sc, i, &issue)) /* "initial.theta" is no engine's */
      return dv_fail(err, DV_EINPUT, "%s%s.%s: %s", dv_engine_find(issue.section) ? "engines." : "",
                     issue.section, issue.key, issue.what);
  }
  return DV_OK;
}

int dv_engine_parse_list(const char *list, const dv_engine_type **engines, size_t max,
                         dv_error *err) {
  char buf[256];
  size_t n = 0;
  snprintf(buf, sizeof buf, "%s", list);
  for (char *save = NULL, *tok = strtok_r(buf, ", ", &save); tok;
       tok = strtok_r(NULL, ", ", &save)) {
    const dv_engine_type *e = dv_engine_find(tok);
    if (!e) {
      char names[256] = "";
      for (const dv_engine_type *const *k = dv_engine_list(); *k; k++)
        snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s",
                 k == dv_engine_list() ? "" : ", ", (*k)->name);
      return dv_fail(err, DV_EINPUT, "unknown engine '%s' (one of: %s)", tok, names);
    }
    for (size_t k = 0; k < n; k++) /* a report holds one result per engine */
      if (engines[k] == e) return dv_fail(err, DV_EINPUT, "engine '%s' listed twice", tok);
    if (n + 1 >= max) return dv_fail(err, DV_EINPUT, "too many engines");
    engines[n++] = e;
  }
  if (!n) return dv_fail(err, DV_EINPUT, "no engine in '%s'", list);
  engines[n] = NULL;
  return DV_OK;
}

const char *dv_failure_name(dv_failure failure) {
  static const char *const names[] = {"none",  "NaN",          "silent reset", "energy blow-up",
                                      "sinks", "lost contact", "error",        "error"};
  _Static_assert(sizeof names / sizeof names[0] == DV_NFAILURES, "a name per failure");
  return (unsigned)failure < DV_NFAILURES ? names[failure] : "unknown";
}

dv_outcome dv_failure_outcome(dv_failure failure) {
  switch (failure) {
    case DV_FAILURE_NONE:
      return DV_OUTCOME_COMPLETED;
    case DV_FAILURE_LOST_CONTACT:
      return DV_OUTCOME_LOST_CONTACT;
    case DV_FAILURE_LIBRARY:
    case DV_FAILURE_SETUP:
      return DV_OUTCOME_ERROR;
    default:
      return DV_OUTCOME_DIVERGED;
  }
}

const char *dv_outcome_name(dv_outcome outcome) {
  static const char *const names[] = {"completed", "event", "diverged", "lost_contact", "error"};
  return (unsigned)outcome < sizeof names / sizeof names[0] ? names[outcome] : "unknown";
}

void dv_sample_from_pose(const red_disk *disk, const dv_geometry *geom, const dv_pose *pose,
                         double t, const double *prev_y, dv_sample *out) {
  double p[3];
  out->t = t;
  dv_state_from_pose(pose, prev_y, out->y);
  dv_pose_lowest_point(geom, pose, p, &out->slip);
  out->contact[0] = p[0];
  out->contact[1] = p[1];
  out->penetration = fmax(0.0, -p[2]);
  out->energy = dv_pose_energy(disk, pose);
  out->force[0] = out->force[1] = out->force[2] = NAN;
}

void dv_stats_add_sample(dv_engine_stats *st, const dv_sample *s) {
  st->slip_max = fmax(st->slip_max, s->slip);
  st->penetration_max = fmax(st->penetration_max, s->penetration);
  if (s->contacts > st->contacts_max) st->contacts_max = s->contacts;
}
