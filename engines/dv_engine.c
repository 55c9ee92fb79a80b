/* dv_engine: what every engine shares (the registry is engine_registry.c). */
#include "dv_engine.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dv_format.h"
#include "dv_pose.h"

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
