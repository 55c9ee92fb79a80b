/* dv_scenario: reading (inih), then validating, a scenario file. */
#include "scenario.h"

#include <errno.h>
#include <ini.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "red_reference.h"
#include "red_solver.h"
#include "red_steady.h"

enum { REQUIRED = 1, TEXT = 2 };

typedef struct key_spec {
  const char *section;
  const char *key;
  int flags;
} key_spec;

static const key_spec KEYS[] = {
    {"scenario", "name", REQUIRED | TEXT},
    {"scenario", "description", TEXT},
    {"scenario", "engines", TEXT},
    {"scenario", "duration", REQUIRED},
    {"scenario", "output_dt", REQUIRED},
    {"disk", "radius", REQUIRED},
    {"disk", "mass", REQUIRED},
    {"disk", "A", 0},
    {"disk", "C", 0},
    {"disk", "gravity", 0},
    {"initial", "theta", REQUIRED},
    {"initial", "phi", 0},
    {"initial", "psi", 0},
    {"initial", "x", 0},
    {"initial", "y", 0},
    {"initial", "theta_dot", 0},
    {"initial", "phi_dot", 0},
    {"initial", "psi_dot", 0},
    {"initial", "steady_circle_radius", 0},
    {"initial", "steady_phi_dot", 0},
    {"engines.reduced", "integrator", TEXT},
    {"engines.reduced", "rtol", 0},
    {"engines.reduced", "atol", 0},
    {"engines.reduced", "theta_limit", 0},
};
#define NKEYS (sizeof KEYS / sizeof KEYS[0])

static const char *const METRICS[] = {"theta_max_err", "theta_rms_err",  "path_max_err",
                                      "path_rms_err",  "path_hausdorff", "energy_drift",
                                      "slip_max"};
static const char *const ENGINES[] = {"reduced", "matched", "ode", "mujoco"};
#define NMETRICS (sizeof METRICS / sizeof METRICS[0])
#define NENGINES (sizeof ENGINES / sizeof ENGINES[0])

#define MAX_SECTIONS 16
#define MAX_SPECS 64

typedef struct parse_ctx {
  const char *path; /* for messages */
  int line;         /* current line, counted by the reader */
  FILE *file;
  int failed; /* first error kept */
  dv_error *err;
  char value[NKEYS][256];
  int value_line[NKEYS]; /* 0: not given */
  char spec_value[MAX_SPECS][128];
  int spec_line[MAX_SPECS];
  char sections[MAX_SECTIONS][64];
  int section_line[MAX_SECTIONS];
  int nsections;
  dv_scenario *sc;
} parse_ctx;

static int fail_at(parse_ctx *c, int line, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static int fail_at(parse_ctx *c, int line, const char *key, const char *fmt, ...) {
  if (c->failed) return 0;
  char what[300];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(what, sizeof what, fmt, ap);
  va_end(ap);
  c->failed = 1;
  if (line < 0)
    dv_fail(c->err, DV_EINPUT, "--set:%d: %s: %s", -line, key, what);
  else
    dv_fail(c->err, DV_EINPUT, "%s:%d: %s: %s", c->path, line, key, what);
  return 0;
}

/* inih reader: one line per call, counted; over-long lines are errors */
static char *read_line(char *buf, int size, void *stream) {
  parse_ctx *c = stream;
  if (!fgets(buf, size, c->file)) return NULL;
  c->line++;
  size_t n = strlen(buf);
  if (n + 1 == (size_t)size && buf[n - 1] != '\n' && !feof(c->file)) {
    fail_at(c, c->line, "syntax", "line longer than %d characters", size - 2);
    return NULL;
  }
  const char *p = buf + strspn(buf, " \t");
  if (*p == '[' && c->nsections < MAX_SECTIONS) {
    const char *end = strchr(p, ']');
    size_t len = end ? (size_t)(end - p - 1) : 0;
    if (len >= sizeof c->sections[0]) len = sizeof c->sections[0] - 1;
    memcpy(c->sections[c->nsections], p + 1, len);
    c->sections[c->nsections][len] = '\0';
    c->section_line[c->nsections++] = c->line;
  }
  return buf;
}

static int section_line(const parse_ctx *c, const char *section) {
  for (int i = 0; i < c->nsections; i++)
    if (strcmp(c->sections[i], section) == 0) return c->section_line[i];
  return 0;
}

/* index of s in list (n entries, or up to a NULL entry), or -1 */
static int find_in(const char *const *list, size_t n, const char *s) {
  for (size_t i = 0; i < n && list[i]; i++)
    if (strcmp(list[i], s) == 0) return (int)i;
  return -1;
}

static int parse_number(const char *text, double *out) {
  char *end;
  errno = 0;
  *out = strtod(text, &end);
  if (end == text || errno == ERANGE) return -1;
  end += strspn(end, " \t");
  return (*end == '\0' && isfinite(*out)) ? 0 : -1;
}

/* tolerance sections: [tolerance] and [tolerance.ENGINE] */
static int set_tolerance(parse_ctx *c, int line, const char *section, const char *key,
                         const char *value) {
  const char *engine = section[9] == '.' ? section + 10 : "";
  double limit;
  if (*engine && find_in(ENGINES, NENGINES, engine) < 0)
    return fail_at(c, line, section, "unknown engine '%s' (reduced, matched, ode, mujoco)", engine);
  if (find_in(METRICS, NMETRICS, key) < 0)
    return fail_at(c, line, key, "unknown tolerance metric in [%s]", section);
  if (parse_number(value, &limit)) return fail_at(c, line, key, "not a number: '%s'", value);
  if (!(limit >= 0.0)) return fail_at(c, line, key, "must be >= 0, got %g", limit);
  dv_scenario *sc = c->sc;
  for (size_t i = 0; i < sc->ntolerances; i++)
    if (!strcmp(sc->tolerances[i].engine, engine) && !strcmp(sc->tolerances[i].metric, key)) {
      if (line > 0) return fail_at(c, line, key, "given twice in [%s]", section);
      sc->tolerances[i].limit = limit;
      return 1;
    }
  if (sc->ntolerances == DV_MAX_TOLERANCES) return fail_at(c, line, key, "too many tolerances");
  dv_tolerance *t = &sc->tolerances[sc->ntolerances++];
  snprintf(t->engine, sizeof t->engine, "%s", engine);
  snprintf(t->metric, sizeof t->metric, "%s", key);
  t->limit = limit;
  return 1;
}

static int set_key(parse_ctx *c, int line, const char *section, const char *key,
                   const char *value) {
  if (!section[0]) return fail_at(c, line, key, "key before any [section]");
  if (strncmp(section, "tolerance", 9) == 0 && (section[9] == '\0' || section[9] == '.'))
    return set_tolerance(c, line, section, key, value);
  int known_section = 0;
  for (size_t i = 0; i < NKEYS; i++) {
    if (strcmp(KEYS[i].section, section) != 0) continue;
    known_section = 1;
    if (strcmp(KEYS[i].key, key) != 0) continue;
    if (c->value_line[i] > 0 && line > 0)
      return fail_at(c, line, key, "given twice in [%s] (first on line %d)", section,
                     c->value_line[i]);
    snprintf(c->value[i], sizeof c->value[i], "%s", value);
    c->value_line[i] = line;
    return 1;
  }
  for (size_t i = 0; i < dv_nsetting_specs && i < MAX_SPECS; i++) {
    const dv_setting_spec *sp = &dv_setting_specs[i];
    if (strcmp(sp->section, section) != 0) continue;
    known_section = 1;
    if (strcmp(sp->key, key) != 0) continue;
    if (c->spec_line[i] > 0 && line > 0)
      return fail_at(c, line, key, "given twice in [%s] (first on line %d)", section,
                     c->spec_line[i]);
    snprintf(c->spec_value[i], sizeof c->spec_value[i], "%s", value);
    c->spec_line[i] = line;
    return 1;
  }
  if (!known_section) return fail_at(c, line, section, "unknown section [%s]", section);
  return fail_at(c, line, key, "unknown key in [%s]", section);
}

static int on_key(void *user, const char *section, const char *key, const char *value) {
  parse_ctx *c = user;
  if (c->failed) return 1;
  set_key(c, c->line, section, key, value);
  return 1;
}

static int apply_override(parse_ctx *c, int index, const char *text) {
  char buf[512], *eq, *dot;
  snprintf(buf, sizeof buf, "%s", text);
  if (!(eq = strchr(buf, '='))) return fail_at(c, -index, text, "expected section.key=value");
  *eq = '\0';
  if (!(dot = strrchr(buf, '.'))) return fail_at(c, -index, buf, "expected section.key=value");
  *dot = '\0';
  return set_key(c, -index, buf, dot + 1, eq + 1);
}

/* the value of key i as a number, def when absent */
static int number(parse_ctx *c, size_t i, double def, double *out) {
  if (!c->value_line[i]) {
    *out = def;
    return 0;
  }
  if (parse_number(c->value[i], out))
    return fail_at(c, c->value_line[i], KEYS[i].key, "not a number: '%s'", c->value[i]), -1;
  return 0;
}

static size_t key_index(const char *section, const char *key) {
  for (size_t i = 0; i < NKEYS; i++)
    if (!strcmp(KEYS[i].section, section) && !strcmp(KEYS[i].key, key)) return i;
  return NKEYS; /* not reached for the names used below */
}

/* a checked number: lo < v (or lo <= v when closed), v < hi */
typedef struct range {
  const char *section, *key;
  double def;
  double lo, hi;
  int closed_lo;
  double *out;
} range;

static int read_ranges(parse_ctx *c, const range *r, size_t n) {
  for (size_t k = 0; k < n; k++) {
    const size_t i = key_index(r[k].section, r[k].key);
    if (KEYS[i].flags & REQUIRED && !c->value_line[i]) {
      const int line = section_line(c, r[k].section);
      return fail_at(c, line ? line : 1, r[k].key, "missing (required in [%s])", r[k].section), -1;
    }
    double v;
    if (number(c, i, r[k].def, &v)) return -1;
    const int ok_lo = r[k].closed_lo ? v >= r[k].lo : v > r[k].lo;
    if (!ok_lo || !(v < r[k].hi))
      return fail_at(c, c->value_line[i], r[k].key, "%g is outside %s%g, %g)", v,
                     r[k].closed_lo ? "[" : "(", r[k].lo, r[k].hi),
             -1;
    *r[k].out = v;
  }
  return 0;
}

static int line_of(const parse_ctx *c, const char *section, const char *key) {
  const int line = c->value_line[key_index(section, key)];
  if (line) return line;
  const int s = section_line(c, section);
  return s ? s : 1;
}

static int known_section(const char *name) {
  if (!strcmp(name, "tolerance")) return 1;
  for (size_t i = 0; i < dv_nsetting_specs; i++)
    if (!strcmp(dv_setting_specs[i].section, name)) return 1;
  if (!strncmp(name, "tolerance.", 10)) return find_in(ENGINES, NENGINES, name + 10) >= 0;
  for (size_t i = 0; i < NKEYS; i++)
    if (!strcmp(KEYS[i].section, name)) return 1;
  return 0;
}

/* the line of an engine setting, or of its section, or 1 */
static int setting_line(const parse_ctx *c, const char *section, const char *key) {
  for (size_t i = 0; i < dv_nsetting_specs && i < MAX_SPECS; i++)
    if (!strcmp(dv_setting_specs[i].section, section) && !strcmp(dv_setting_specs[i].key, key) &&
        c->spec_line[i])
      return c->spec_line[i];
  const int s = section_line(c, section);
  return s ? s : 1;
}

/* the engine settings: defaults, names of choices, ranges */
static int read_settings(parse_ctx *c) {
  for (size_t i = 0; i < dv_nsetting_specs && i < MAX_SPECS; i++) {
    const dv_setting_spec *sp = &dv_setting_specs[i];
    double v = sp->def;
    const char *text = c->spec_value[i];
    if (c->spec_line[i] && sp->choices) {
      int k = find_in(sp->choices, SIZE_MAX, text);
      if (k < 0) {
        char list[160] = "";
        for (size_t j = 0; sp->choices[j]; j++)
          snprintf(list + strlen(list), sizeof list - strlen(list), "%s%s", j ? ", " : "",
                   sp->choices[j]);
        return fail_at(c, c->spec_line[i], sp->key, "'%s' is not one of %s", text, list), -1;
      }
      v = k;
    } else if (c->spec_line[i] && parse_number(text, &v)) {
      return fail_at(c, c->spec_line[i], sp->key, "not a number: '%s'", text), -1;
    }
    if (sp->is_int && v != floor(v))
      return fail_at(c, c->spec_line[i], sp->key, "%g is not a whole number", v), -1;
    if (!(v >= sp->lo && v <= sp->hi))
      return fail_at(c, c->spec_line[i], sp->key, "%g is outside [%g, %g]", v, sp->lo, sp->hi), -1;
    char *field = (char *)c->sc + sp->offset;
    if (sp->is_int)
      *(int *)field = (int)v;
    else
      *(double *)field = v;
  }
  return 0;
}

static int validate(parse_ctx *c) {
  dv_scenario *sc = c->sc;
  red_disk *d = &sc->disk;
  for (int i = 0; i < c->nsections; i++) /* sections without keys never reach the handler */
    if (!known_section(c->sections[i]))
      return fail_at(c, c->section_line[i], c->sections[i], "unknown section [%s]", c->sections[i]),
             -1;
  const char *sections[] = {"scenario", "disk", "initial"};
  for (size_t i = 0; i < 3; i++)
    if (!section_line(c, sections[i]))
      return fail_at(c, 1, sections[i], "missing section [%s]", sections[i]), -1;
  const size_t iname = key_index("scenario", "name");
  if (!c->value_line[iname])
    return fail_at(c, section_line(c, "scenario"), "name", "missing (required in [scenario])"), -1;
  if (!c->value[iname][0]) return fail_at(c, c->value_line[iname], "name", "empty"), -1;
  snprintf(sc->name, sizeof sc->name, "%.63s", c->value[iname]);
  snprintf(sc->description, sizeof sc->description, "%s",
           c->value[key_index("scenario", "description")]);
  const size_t ieng = key_index("scenario", "engines");
  snprintf(sc->engines, sizeof sc->engines, "%.63s", c->value[ieng]);
  if (c->value_line[ieng]) {
    int count = 0;
    char list[64];
    snprintf(list, sizeof list, "%s", sc->engines);
    for (char *save = NULL, *tok = strtok_r(list, ", ", &save); tok;
         tok = strtok_r(NULL, ", ", &save), count++)
      if (find_in(ENGINES, NENGINES, tok) < 0 || count == 4)
        return fail_at(c, c->value_line[ieng], "engines",
                       "'%s': at most 4 of reduced, matched, ode, mujoco", tok),
               -1;
    if (!count) return fail_at(c, c->value_line[ieng], "engines", "empty list"), -1;
  }

  const range basic[] = {
      {"scenario", "duration", 0, 0.0, 1e6, 0, &sc->duration},
      {"scenario", "output_dt", 0, 0.0, 1e6, 0, &sc->output_dt},
      {"disk", "radius", 0, 0.0, 1e6, 0, &d->r},
      {"disk", "mass", 0, 0.0, 1e12, 0, &d->m},
      {"disk", "gravity", 9.81, 0.0, 1e6, 1, &d->g},
  };
  if (read_ranges(c, basic, 5)) return -1;
  if (sc->output_dt > sc->duration)
    return fail_at(c, line_of(c, "scenario", "output_dt"), "output_dt",
                   "%g s is longer than the duration %g s", sc->output_dt, sc->duration),
           -1;
  if (sc->duration / sc->output_dt > 1e7)
    return fail_at(c, line_of(c, "scenario", "output_dt"), "output_dt",
                   "more than 1e7 samples (duration / output_dt)"),
           -1;
  const double mr2 = d->m * d->r * d->r;
  const range moments[] = {
      {"disk", "A", 0.25 * mr2, 0.0, INFINITY, 0, &d->A},
      {"disk", "C", 0.5 * mr2, 0.0, INFINITY, 1, &d->C},
  };
  if (read_ranges(c, moments, 2)) return -1;
  if (d->C > 2.0 * d->A * (1.0 + 1e-15)) {
    const int given_c = c->value_line[key_index("disk", "C")] != 0;
    return fail_at(c, line_of(c, "disk", given_c ? "C" : "A"), given_c ? "C" : "A",
                   "C = %g exceeds 2A = %g: no rigid body has these moments", d->C, 2.0 * d->A),
           -1;
  }

  dv_reduced_settings *rs = &sc->reduced;
  const size_t iint = key_index("engines.reduced", "integrator");
  snprintf(rs->integrator, sizeof rs->integrator, "%s",
           c->value_line[iint] ? c->value[iint] : red_stepper_default()->name);
  if (!red_stepper_find(rs->integrator))
    return fail_at(c, c->value_line[iint], "integrator", "unknown integrator '%s'", rs->integrator),
           -1;
  const range solver[] = {
      {"engines.reduced", "rtol", 1e-12, 0.0, 1.0, 0, &rs->rtol},
      {"engines.reduced", "atol", 1e-14, 0.0, 1.0, 0, &rs->atol},
      {"engines.reduced", "theta_limit", 0.01, 0.0, M_PI / 2, 0, &rs->theta_limit},
  };
  if (read_ranges(c, solver, 3)) return -1;
  if (read_settings(c)) return -1;
  /* an engine samples on its own steps: a step longer than the spacing of the samples */
  const struct {
    const char *section;
    double dt;
  } steps[] = {{"engines.mujoco", sc->mujoco.timestep}, {"engines.ode", sc->ode.timestep}};
  for (size_t i = 0; i < 2; i++)
    if (steps[i].dt > sc->output_dt * (1.0 + 1e-12))
      return fail_at(c, setting_line(c, steps[i].section, "timestep"), "timestep",
                     "%g s is longer than output_dt %g s", steps[i].dt, sc->output_dt),
             -1;

  double *y = sc->initial;
  double radius = 0.0, steady_phi_dot = 0.0;
  const range init[] = {
      {"initial", "theta", 0, rs->theta_limit, M_PI - rs->theta_limit, 0, &y[RED_TH]},
      {"initial", "phi", 0, -1e6, 1e6, 0, &y[RED_PH]},
      {"initial", "psi", 0, -1e6, 1e6, 0, &y[RED_PS]},
      {"initial", "x", 0, -1e12, 1e12, 0, &y[RED_X]},
      {"initial", "y", 0, -1e12, 1e12, 0, &y[RED_Y]},
      {"initial", "theta_dot", 0, -1e6, 1e6, 0, &y[RED_VTH]},
      {"initial", "phi_dot", 0, -1e6, 1e6, 0, &y[RED_VPH]},
      {"initial", "psi_dot", 0, -1e6, 1e6, 0, &y[RED_VPS]},
      {"initial", "steady_circle_radius", 0, -INFINITY, INFINITY, 0, &radius},
      {"initial", "steady_phi_dot", 0, -1e6, 1e6, 0, &steady_phi_dot},
  };
  if (read_ranges(c, init, 10)) return -1;
  const int has_radius = c->value_line[key_index("initial", "steady_circle_radius")] != 0;
  const int has_rate = c->value_line[key_index("initial", "steady_phi_dot")] != 0;
  sc->init_mode = has_radius ? DV_INIT_STEADY_RADIUS
                  : has_rate ? DV_INIT_STEADY_PHI_DOT
                             : DV_INIT_STATE;
  if (sc->init_mode != DV_INIT_STATE) {
    const char *steady_key = has_radius ? "steady_circle_radius" : "steady_phi_dot";
    const char *rates[] = {"theta_dot", "phi_dot", "psi_dot", has_radius ? "steady_phi_dot" : NULL};
    for (size_t i = 0; i < 4 && rates[i]; i++)
      if (c->value_line[key_index("initial", rates[i])])
        return fail_at(c, line_of(c, "initial", rates[i]), rates[i],
                       "cannot be combined with %s (the steady motion fixes the rates)",
                       steady_key),
               -1;
    dv_error e;
    const int status =
        has_radius ? red_steady_from_radius(d, y[RED_TH], radius, &y[RED_VPH], &y[RED_VPS], &e)
                   : red_steady_from_phi_dot(d, y[RED_TH], steady_phi_dot, &y[RED_VPS], &e);
    if (has_rate) y[RED_VPH] = steady_phi_dot;
    if (status) return fail_at(c, line_of(c, "initial", steady_key), steady_key, "%s", e.msg), -1;
  }
  return 0;
}

int dv_scenario_load(const char *path, const char *const *overrides, size_t noverrides,
                     dv_scenario *sc, dv_error *err) {
  parse_ctx *c = calloc(1, sizeof *c);
  struct stat st;
  int status = DV_EINPUT;
  if (!c) return dv_fail(err, DV_ESYSTEM, "out of memory");
  memset(sc, 0, sizeof *sc);
  snprintf(sc->path, sizeof sc->path, "%s", path);
  c->path = path;
  c->err = err;
  c->sc = sc;
  if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
    fail_at(c, 1, "file", "is a directory, not a scenario file");
    goto cleanup;
  }
  if (!(c->file = fopen(path, "r"))) {
    fail_at(c, 1, "file", "cannot open: %s", strerror(errno));
    goto cleanup;
  }
  const int bad_line = ini_parse_stream(read_line, c, on_key, c);
  if (ferror(c->file)) fail_at(c, c->line, "file", "read error: %s", strerror(errno));
  if (bad_line > 0) fail_at(c, bad_line, "syntax", "expected [section] or key = value");
  for (size_t i = 0; i < noverrides && !c->failed; i++) apply_override(c, (int)i + 1, overrides[i]);
  if (!c->failed && validate(c) == 0 && !c->failed) status = DV_OK;

cleanup:
  if (c->file) fclose(c->file);
  free(c);
  return status;
}
