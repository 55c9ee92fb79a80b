/* adapter_settings: an adapter's settings for a scene, and the scene's lines
 * it is sent (adapter.h; docs/adapters.md). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "adapter.h"
#include "dv_format.h"
#include "dv_pose.h"
#include "engine_friction.h"

/* where key's value lives in a's settings block (every key a manifest's roles name exists) */
static void *field(const dv_adapter *a, void *block, const char *key) {
  return (char *)block + dv_settings_find(&a->section, key)->offset;
}

/* append "; text" to why and key to keys (n of them so far) */
static void add_reason(char *why, size_t size, const char **keys, size_t *n, const char *key,
                       const char *text) {
  const size_t used = strlen(why);
  snprintf(why + used, size - used, "%s%s", used ? "; " : "", text);
  keys[(*n)++] = key;
  keys[*n] = NULL;
}

int dv_adapter_check(const dv_adapter *a, dv_scenario *sc, void *block, dv_setting_issue *issue) {
  char why[DV_DERIVED_BYTES] = "", number[DV_FORMAT_SIZE];
  const char *keys[10] = {NULL};
  (void)issue;
  double no_softness = NAN;
  double *dt = field(a, block, a->step_key);
  double *soft = a->softness_key[0] ? field(a, block, a->softness_key) : &no_softness;
  int *choice = field(a, block, a->choice_key);
  /* the body first: the probe judges the cylinder against its matched reference */
  char body[160] = "";
  double *half = field(a, block, DV_ADAPTER_HALF_KEY);
  const int half_derived = !dv_scenario_is_given(sc, a->name, DV_ADAPTER_HALF_KEY);
  if (half_derived) {
    *half = sc->thickness > 0.0 ? 0.5 * sc->thickness : a->stand_in;
    dv_format_double(*half, number, sizeof number);
    snprintf(body, sizeof body, "%s %s m: %s", DV_ADAPTER_HALF_KEY, number,
             sc->thickness > 0.0 ? "[disk] thickness / 2"
                                 : "a stand-in for the thin disk, which the engine has not");
  }
  char rough[160] = "";
  const char *friction_key[2] = {NULL, NULL};
  dv_engine_derive_friction(sc, a->name, a->friction_key, 1.0, "", field(a, block, a->friction_key),
                            rough, sizeof rough, friction_key);
  const int friction_derived = friction_key[0] != NULL;
  const int given = dv_scenario_is_given(sc, a->name, a->choice_key);
  const dv_knob_choice in = {given ? *choice : -1, *dt, *soft};
  dv_knob_choice out;
  dv_engine_choose(sc, &a->type, &a->knobs, *choice, &in, &out, why, sizeof why, keys);
  *choice = out.choice;
  *dt = out.timestep;
  if (a->softness_key[0] && !isnan(out.softness)) *soft = out.softness;
  size_t n = 0;
  while (keys[n]) n++;
  if (half_derived) add_reason(why, sizeof why, keys, &n, DV_ADAPTER_HALF_KEY, body);
  if (friction_derived) add_reason(why, sizeof why, keys, &n, a->friction_key, rough);
  dv_scenario_set_derived(sc, a->name, keys, why);
  return 0;
}

/* append to buf; -1 where it no longer fits */
static int put(char *buf, size_t size, size_t *used, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static int put(char *buf, size_t size, size_t *used, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  const int n = vsnprintf(buf + *used, size - *used, fmt, ap);
  va_end(ap);
  if (n < 0 || (size_t)n >= size - *used) return -1;
  *used += (size_t)n;
  return 0;
}

int dv_adapter_scene_text(const dv_adapter *a, const dv_scenario *sc, const double *state,
                          char *buf, size_t size, dv_error *err) {
  const void *block = dv_scenario_settings(sc, a->name);
  const double h = dv_scenario_get(sc, a->name, DV_ADAPTER_HALF_KEY);
  const dv_geometry geom = {DV_SHAPE_CYLINDER, sc->disk.r, h};
  const red_disk *d = &sc->disk;
  dv_pose p;
  double q[4];
  size_t used = 0;
  if (!block) return dv_fail(err, DV_EINPUT, "the scenario has no [engines.%s]", a->name);
  dv_pose_from_state(&geom, state ? state : sc->initial, &p);
  dv_matrix_to_quat(p.R, q);
  const double v[] = {d->r,
                      d->m,
                      d->A,
                      d->C,
                      h,
                      d->g,
                      dv_scenario_get(sc, a->name, a->friction_key),
                      p.pos[0],
                      p.pos[1],
                      p.pos[2],
                      q[0],
                      q[1],
                      q[2],
                      q[3],
                      p.vel[0],
                      p.vel[1],
                      p.vel[2],
                      p.omega[0],
                      p.omega[1],
                      p.omega[2]};
  /* each line's name and how many of v it takes: shortest round-trip numbers */
  static const struct {
    const char *name;
    int n;
  } LINES[] = {{"radius", 1},          {"mass", 1},       {"inertia", 2},
               {"half_thickness", 1},  {"gravity", 1},    {"friction", 1},
               {"position", 3},        {"quaternion", 4}, {"velocity", 3},
               {"angular_velocity", 3}};
  int bad = put(buf, size, &used, "diskval-adapter %d\n", DV_ADAPTER_PROTOCOL);
  for (size_t l = 0, k = 0; l < sizeof LINES / sizeof LINES[0]; l++) {
    bad |= put(buf, size, &used, "%s", LINES[l].name);
    for (int j = 0; j < LINES[l].n; j++, k++) {
      char number[DV_FORMAT_SIZE];
      dv_format_double(v[k] == 0.0 ? 0.0 : v[k], number, sizeof number); /* no "-0" */
      bad |= put(buf, size, &used, " %s", number);
    }
    bad |= put(buf, size, &used, "\n");
  }
  for (size_t i = 0; i < a->nsettings && !bad; i++) {
    const dv_setting_spec *s = &a->specs[i];
    const double x = dv_setting_value(s, block);
    if (strcmp(s->key, DV_ADAPTER_HALF_KEY) == 0) continue;
    if (!isfinite(x)) return dv_fail(err, DV_EINPUT, "engines.%s.%s: no value", a->name, s->key);
    if (s->type == DV_SETTING_CHOICE)
      bad |= put(buf, size, &used, "set %s %s\n", s->key, dv_setting_choice(s, (size_t)x));
    else if (s->type == DV_SETTING_INT)
      bad |= put(buf, size, &used, "set %s %d\n", s->key, (int)x);
    else {
      char number[DV_FORMAT_SIZE];
      dv_format_double(x, number, sizeof number);
      bad |= put(buf, size, &used, "set %s %s\n", s->key, number);
    }
  }
  if (bad || put(buf, size, &used, "start\n"))
    return dv_fail(err, DV_EINPUT, "the scene for %s is longer than %zu bytes", a->name, size);
  return 0;
}
