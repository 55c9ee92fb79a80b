/* scenario_core: the sections every scenario has ([scenario], [disk],
 * [initial]), their checks, and the metric names a tolerance may limit. */
#include "scenario_core.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "dv_format.h"
#include "red_steady.h"
#include "red_steady_thick.h"

const char *const dv_metric_names[DV_NMETRICS] = {
    "theta_max_err", "theta_rms_err", "path_max_err",      "path_rms_err",   "path_hausdorff",
    "energy_drift",  "slip_max",      "theta_extrema_err", "invariant_drift", "theta_turning_err",
    "nutation_period_err", "heading_period_err", "phase_err", "turning_lag"};

const char *const dv_metric_units[DV_NMETRICS] = {
    "rad", "rad", "m", "m", "m", "of E(0)", "m/s", "rad", "of the momentum scale", "rad",
    "s",   "rad", "m", "s"};

#define AT(field) offsetof(dv_scenario, field)
#define STATE(k) (offsetof(dv_scenario, initial) + (k) * sizeof(double))
#define OPEN (DV_SETTING_OPEN_LO | DV_SETTING_OPEN_HI)
#define REQ DV_SETTING_REQUIRED

int dv_scenario_check_name(const char *name, char *what, size_t size) {
  const size_t n = strlen(name);
  if (n == 0) return snprintf(what, size, "empty"), -1;
  if (strspn(name, DV_SCENARIO_NAME_CHARS) != n || !strcmp(name, ".") || !strcmp(name, ".."))
    return snprintf(what, size,
                    "'%.80s' is not a file name: use letters, digits, '.', '-', '_', '+' "
                    "(not '.' or '..')",
                    name),
           -1;
  if (name[0] == '.')
    return snprintf(what, size, "'%.80s' starts with '.': such names are diskval's own", name), -1;
  /* a suite writes its own files into OUT beside the scenarios' directories */
  static const char *const own[] = {".html", ".json", ".xml", ".md"};
  for (size_t k = 0; k < sizeof own / sizeof *own; k++)
    if (n > strlen(own[k]) && !strcmp(name + n - strlen(own[k]), own[k]))
      return snprintf(what, size,
                      "'%.80s' ends in '%s', as the suite's own files (index.html, "
                      "summary.json, junit.xml, verify.md) do: choose another name",
                      name, own[k]),
             -1;
  return 0;
}

static int issue(dv_setting_issue *is, const char *section, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static int issue(dv_setting_issue *is, const char *section, const char *key, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(is->what, sizeof is->what, fmt, ap);
  va_end(ap);
  is->section = section;
  is->key = key;
  return -1;
}

/* v as the shortest text that reads back to it, in buf (DV_FORMAT_SIZE bytes) */
static const char *num(double v, char *buf) {
  dv_format_double(v, buf, DV_FORMAT_SIZE);
  return buf;
}

static int find_engine(const dv_scenario *sc, const char *name) {
  for (size_t i = 0; i < sc->nsections; i++)
    if (!strcmp(sc->sections[i]->name, name)) return (int)i;
  return -1;
}

double dv_scenario_memory_gib(const dv_scenario *sc, double *samples) {
  *samples = floor(sc->duration / sc->output_dt) + 1.0;
  return (DV_MEMORY_BASE_MIB * 1048576.0 + *samples * DV_MEMORY_PER_SAMPLE) / 1073741824.0;
}

/* [scenario]: a name that is one path component, known engines, sample count */
static int check_scenario(dv_scenario *sc, void *block, dv_setting_issue *is) {
  char list[64], names[128] = "", what[200], a[DV_FORMAT_SIZE], b[DV_FORMAT_SIZE];
  if (dv_scenario_check_name(sc->name, what, sizeof what))
    return issue(is, "scenario", "name", "%s", what);
  snprintf(list, sizeof list, "%s", sc->engines);
  for (size_t i = 0; i < sc->nsections; i++)
    snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", i ? ", " : "",
             sc->sections[i]->name);
  size_t count = 0;
  unsigned listed = 0; /* bit i: engine i named already */
  for (char *save = NULL, *tok = strtok_r(list, ", ", &save); tok;
       tok = strtok_r(NULL, ", ", &save), count++) {
    const int e = find_engine(sc, tok);
    if (e < 0 || count == sc->nsections)
      return issue(is, "scenario", "engines", "'%s': at most %zu of %s", tok, sc->nsections, names);
    if (listed & 1u << e) return issue(is, "scenario", "engines", "'%s' listed twice", tok);
    listed |= 1u << e;
  }
  if (sc->output_dt > sc->duration)
    return issue(is, "scenario", "output_dt", "%s s is longer than the duration %s s",
                 num(sc->output_dt, a), num(sc->duration, b));
  if (sc->duration / sc->output_dt > 1e7)
    return issue(is, "scenario", "output_dt", "more than 1e7 samples (duration / output_dt)");
  /* refused before any work: a run keeps every sample in memory */
  double samples;
  const double need_gib = dv_scenario_memory_gib(sc, &samples);
  if (need_gib > sc->memory_budget)
    return issue(is, "scenario", "output_dt",
                 "%.0f samples need about %.3g GiB of memory (%d bytes a sample plus %d MiB), "
                 "more than memory_budget = %g GiB",
                 samples, need_gib, DV_MEMORY_PER_SAMPLE, DV_MEMORY_BASE_MIB, sc->memory_budget);
  return 0;
}

/* [disk]: a disk thinner than its diameter; A and C of a uniform disk of that
 * thickness unless given (a solid cylinder: A = m (r^2 / 4 + t^2 / 12)); no
 * rigid body has C > 2A */
static int check_disk(dv_scenario *sc, void *block, dv_setting_issue *is) {
  red_disk *d = &sc->disk;
  const double mr2 = d->m * d->r * d->r, t = sc->thickness;
  const int given_c = !isnan(d->C);
  const int given_a = !isnan(d->A);
  char a[DV_FORMAT_SIZE], b[DV_FORMAT_SIZE];
  if (!(t < 2.0 * d->r))
    return issue(is, "disk", "thickness", "%s m is not less than the diameter %s m: not a disk",
                 num(t, a), num(2.0 * d->r, b));
  if (!given_a) d->A = 0.25 * mr2 + d->m * t * t / 12.0;
  if (!given_c) d->C = 0.5 * mr2;
  /* a tiny radius or mass can make the derived moments underflow to zero */
  if (!(d->A > 0.0) || !isfinite(d->A))
    return issue(is, "disk", given_a ? "A" : "radius",
                 given_a ? "A = %s must be a positive finite number"
                         : "A = m (r^2 / 4 + thickness^2 / 12) = %s (derived from the radius, "
                           "mass and thickness) is not a positive finite number",
                 num(d->A, a));
  if (d->C > 2.0 * d->A * (1.0 + 1e-15))
    return issue(is, "disk", given_c ? "C" : "A",
                 "C = %s exceeds 2A = %s: no rigid body has these moments", num(d->C, a),
                 num(2.0 * d->A, b));
  return 0;
}

/* the rates of the steady motion of the cylinder the engines simulate */
static int steady_thick(dv_scenario *sc, int has_radius, dv_error *e) {
  double *y = sc->initial;
  red_rolling rr;
  red_rolling_init(&rr, &sc->disk, 0.5 * sc->thickness, 1.0, 0.0);
  return has_radius ? red_steady_thick_from_radius(&rr, y[RED_TH], sc->steady_circle_radius,
                                                   &y[RED_VPH], &y[RED_VPS], e)
                    : red_steady_thick_from_phi_dot(&rr, y[RED_TH], y[RED_VPH], &y[RED_VPS], e);
}

/* [initial]: the rates given, or those of the steady motion asked for */
static int check_initial(dv_scenario *sc, void *block, dv_setting_issue *is) {
  double *y = sc->initial;
  const int has_radius = !isnan(sc->steady_circle_radius);
  const int has_rate = !isnan(sc->steady_phi_dot);
  sc->init_mode = has_radius ? DV_INIT_STEADY_RADIUS
                  : has_rate ? DV_INIT_STEADY_PHI_DOT
                             : DV_INIT_STATE;
  if (sc->init_mode == DV_INIT_STATE) {
    for (int k = RED_VTH; k <= RED_VPS; k++)
      if (isnan(y[k])) y[k] = 0.0;
    return 0;
  }
  const char *steady_key = has_radius ? "steady_circle_radius" : "steady_phi_dot";
  const char *rates[] = {"theta_dot", "phi_dot", "psi_dot", "steady_phi_dot"};
  const double given[] = {y[RED_VTH], y[RED_VPH], y[RED_VPS],
                          has_radius ? sc->steady_phi_dot : NAN};
  for (size_t i = 0; i < 4; i++)
    if (!isnan(given[i]))
      return issue(is, "initial", rates[i],
                   "cannot be combined with %s (the steady motion fixes the rates)", steady_key);
  dv_error e;
  y[RED_VTH] = 0.0;
  if (has_rate) y[RED_VPH] = sc->steady_phi_dot;
  const int status = sc->thickness > 0.0 ? steady_thick(sc, has_radius, &e)
                     : has_radius
                         ? red_steady_from_radius(&sc->disk, y[RED_TH], sc->steady_circle_radius,
                                                  &y[RED_VPH], &y[RED_VPS], &e)
                         : red_steady_from_phi_dot(&sc->disk, y[RED_TH], sc->steady_phi_dot,
                                                   &y[RED_VPS], &e);
  if (status) return issue(is, "initial", steady_key, "%s", e.msg);
  /* the rates derived meet the ranges of rates given (a tiny turning rate
   * derives a spin of 1e101 rad/s that no solver follows) */
  const size_t derived[] = {RED_VPH, RED_VPS};
  for (size_t i = 0; i < 2; i++) {
    const dv_setting_spec *sp =
        dv_settings_find(&dv_scenario_core[2], derived[i] == RED_VPH ? "phi_dot" : "psi_dot");
    char what[200], range[96], v[DV_FORMAT_SIZE];
    if (!dv_setting_store(sp, y[derived[i]], sc, what, sizeof what)) continue;
    dv_setting_range_text(sp, range, sizeof range);
    return issue(is, "initial", steady_key,
                 "derives %s = %s rad/s, outside %s (a given %s's range)", sp->key,
                 num(y[derived[i]], v), range, sp->key);
  }
  return 0;
}

static const dv_setting_spec SCENARIO_KEYS[] = {
    {"name", DV_SETTING_TEXT, AT(name), sizeof(((dv_scenario *)0)->name), REQ, 0, 0, 0, NULL, NULL,
     "", "names the report's directory"},
    {"description", DV_SETTING_TEXT, AT(description), sizeof(((dv_scenario *)0)->description), 0, 0,
     0, 0, NULL, NULL, "", "one line"},
    {"engines", DV_SETTING_TEXT, AT(engines), sizeof(((dv_scenario *)0)->engines), 0, 0, 0, 0, NULL,
     NULL, "", "engines a comparison runs (default: the contact engines)"},
    {"duration", DV_SETTING_REAL, AT(duration), 0, REQ | OPEN, 0, 0.0, 1e6, NULL, NULL, "s", ""},
    {"output_dt", DV_SETTING_REAL, AT(output_dt), 0, REQ | OPEN, 0, 0.0, 1e6, NULL, NULL, "s", ""},
    {"memory_budget", DV_SETTING_REAL, AT(memory_budget), 0, OPEN, DV_MEMORY_BUDGET_GIB, 0.0, 1e6,
     NULL, NULL, "GiB", "a run whose samples would need more memory is refused before it starts"},
};

static const dv_setting_spec DISK_KEYS[] = {
    {"radius", DV_SETTING_REAL, AT(disk.r), 0, REQ | OPEN, 0, 0.0, 1e6, NULL, NULL, "m", ""},
    {"mass", DV_SETTING_REAL, AT(disk.m), 0, REQ | OPEN, 0, 0.0, 1e12, NULL, NULL, "kg", ""},
    {"thickness", DV_SETTING_REAL, AT(thickness), 0, DV_SETTING_OPEN_HI, 0.0, 0.0, 1e6, NULL, NULL,
     "m", "full thickness, less than the diameter (0: the thin disk)"},
    {"A", DV_SETTING_REAL, AT(disk.A), 0, OPEN, NAN, 0.0, INFINITY, NULL, NULL, "kg m^2",
     "about a diameter (default m (r^2 / 4 + thickness^2 / 12))"},
    {"C", DV_SETTING_REAL, AT(disk.C), 0, DV_SETTING_OPEN_HI, NAN, 0.0, INFINITY, NULL, NULL,
     "kg m^2", "about the axis (default m r^2 / 2)"},
    {"gravity", DV_SETTING_REAL, AT(disk.g), 0, DV_SETTING_OPEN_HI, 9.81, 0.0, 1e6, NULL, NULL,
     "m/s^2", ""},
    {"friction", DV_SETTING_REAL, AT(friction), 0, 0, DV_FRICTION_DEFAULT, 0.0, 1e6, NULL, NULL,
     "", "coefficient against the ground: every engine's and the validity window's"},
};

static const dv_setting_spec INITIAL_KEYS[] = {
    {"theta", DV_SETTING_REAL, STATE(RED_TH), 0, REQ | OPEN, 0, 0.0, M_PI, NULL, NULL, "rad",
     "tilt: pi/2 upright"},
    {"phi", DV_SETTING_REAL, STATE(RED_PH), 0, OPEN, 0, -1e6, 1e6, NULL, NULL, "rad", ""},
    {"psi", DV_SETTING_REAL, STATE(RED_PS), 0, OPEN, 0, -1e6, 1e6, NULL, NULL, "rad", ""},
    {"x", DV_SETTING_REAL, STATE(RED_X), 0, OPEN, 0, -1e12, 1e12, NULL, NULL, "m", ""},
    {"y", DV_SETTING_REAL, STATE(RED_Y), 0, OPEN, 0, -1e12, 1e12, NULL, NULL, "m", ""},
    {"theta_dot", DV_SETTING_REAL, STATE(RED_VTH), 0, OPEN, NAN, -1e6, 1e6, NULL, NULL, "rad/s",
     ""},
    {"phi_dot", DV_SETTING_REAL, STATE(RED_VPH), 0, OPEN, NAN, -1e6, 1e6, NULL, NULL, "rad/s", ""},
    {"psi_dot", DV_SETTING_REAL, STATE(RED_VPS), 0, OPEN, NAN, -1e6, 1e6, NULL, NULL, "rad/s", ""},
    {"steady_circle_radius", DV_SETTING_REAL, AT(steady_circle_radius), 0, OPEN, NAN, -INFINITY,
     INFINITY, NULL, NULL, "m", "start on this steady circle"},
    {"steady_phi_dot", DV_SETTING_REAL, AT(steady_phi_dot), 0, OPEN, NAN, -1e6, 1e6, NULL, NULL,
     "rad/s", "start in the steady motion of this turning rate"},
};

#define SECTION(name, keys, check) \
  { name, keys, sizeof keys / sizeof keys[0], 0, check }

const dv_settings_section dv_scenario_core[DV_NCORE_SECTIONS] = {
    SECTION("scenario", SCENARIO_KEYS, check_scenario),
    SECTION("disk", DISK_KEYS, check_disk),
    SECTION("initial", INITIAL_KEYS, check_initial),
};

void dv_scenario_core_defaults(dv_scenario *sc) {
  for (size_t s = 0; s < DV_NCORE_SECTIONS; s++) dv_settings_defaults(&dv_scenario_core[s], sc);
}

int dv_scenario_set_core(dv_scenario *sc, const char *section, const char *key, double v,
                         dv_error *err) {
  for (size_t s = 0; s < DV_NCORE_SECTIONS; s++) {
    const dv_setting_spec *sp = strcmp(dv_scenario_core[s].name, section)
                                    ? NULL
                                    : dv_settings_find(&dv_scenario_core[s], key);
    char what[320];
    if (!sp) continue;
    if (dv_setting_store(sp, v, sc, what, sizeof what))
      return dv_fail(err, DV_EINPUT, "%s.%s: %s", section, key, what);
    if (sp - dv_scenario_core[s].specs < 32)
      sc->core_given[s] |= 1u << (sp - dv_scenario_core[s].specs);
    return DV_OK;
  }
  return dv_fail(err, DV_EINPUT, "%s.%s: no such setting", section, key);
}

int dv_scenario_check_core(dv_scenario *sc, dv_error *err) {
  for (size_t s = 0; s < DV_NCORE_SECTIONS; s++) {
    dv_setting_issue is = {0};
    if (dv_scenario_core[s].check(sc, sc, &is))
      return dv_fail(err, DV_EINPUT, "%s.%s: %s", is.section, is.key, is.what);
  }
  return DV_OK;
}
