/* adapter_manifest: an adapter's manifest.ini read into its tables
 * (adapter.h; the format in docs/adapters.md). */
#include <errno.h>
#include <ini.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "adapter.h"
#include "dv_input.h"
#include "scenario_number.h"

#define TIMEOUT_MAX 600.0 /* s: a manifest's timeout at most (the suite's default time limit) */
#define MANIFEST_MAX_BYTES (64 * 1024) /* a manifest is a few KiB; /dev/zero never ends */

/* the manifest's bytes, read whole, handed to inih a line at a time */
typedef struct reader {
  const char *data;
  size_t size, at;
  int line;
  int too_long; /* the line that was */
} reader;

typedef struct parse {
  dv_adapter *a;
  reader rd;
  const char *path;
  dv_error *err;
  int failed;
  char model_c[DV_ADAPTER_MAX_CHOICES + 1][DV_ADAPTER_NAME]; /* [model] and [model.VALUE]s */
  size_t nmodels;
  char knob_name[DV_ADAPTER_MAX_EXTRA][DV_ADAPTER_NAME]; /* [knob.NAME]'s NAME */
  unsigned given; /* [adapter] keys given (bits 0-15), [roles] keys (16-31) */
} parse;

/* inih's reader, counting lines; a line longer than inih takes is an error, not two lines */
static char *read_line(char *buf, int size, void *stream) {
  reader *rd = stream;
  rd->line++;
  if (rd->at == rd->size) return NULL;
  const char *start = rd->data + rd->at, *nl = memchr(start, '\n', rd->size - rd->at);
  const size_t n = nl ? (size_t)(nl - start) + 1 : rd->size - rd->at;
  if (n > (size_t)size - 1) {
    rd->too_long = rd->line;
    return NULL;
  }
  memcpy(buf, start, n);
  buf[n] = '\0';
  rd->at += n;
  return buf;
}

/* path read whole into *out (size *n), refused past MANIFEST_MAX_BYTES before
 * more is read; a FIFO with no writer is not waited for (dv_input.h) */
static int read_manifest(const char *path, char **out, size_t *n, dv_error *err) {
  FILE *f = dv_input_open(path);
  struct stat st;
  int status = DV_OK;
  char *buf = NULL;
  if (!f) return dv_fail(err, DV_EINPUT, "%s: cannot be read: %s", path, strerror(errno));
  if (fstat(fileno(f), &st)) {
    status = dv_fail(err, DV_EINPUT, "%s: cannot be read: %s", path, strerror(errno));
    goto cleanup;
  }
  if (S_ISDIR(st.st_mode)) {
    status = dv_fail(err, DV_EINPUT, "%s: is a directory", path);
    goto cleanup;
  }
  if (S_ISREG(st.st_mode) && st.st_size > MANIFEST_MAX_BYTES) {
    status = dv_fail(err, DV_EINPUT, "%s: more than the %d KiB a manifest may have", path,
                     MANIFEST_MAX_BYTES / 1024);
    goto cleanup;
  }
  if (!(buf = malloc(MANIFEST_MAX_BYTES + 1))) {
    status = dv_fail(err, DV_ESYSTEM, "%s: out of memory", path);
    goto cleanup;
  }
  const size_t got = fread(buf, 1, MANIFEST_MAX_BYTES + 1, f);
  if (ferror(f))
    status = dv_fail(err, DV_EINPUT, "%s: cannot be read: %s", path, strerror(errno));
  else if (got > MANIFEST_MAX_BYTES)
    status = dv_fail(err, DV_EINPUT, "%s: more than the %d KiB a manifest may have", path,
                     MANIFEST_MAX_BYTES / 1024);
  else if (got == 0 && S_ISFIFO(st.st_mode))
    status =
        dv_fail(err, DV_EINPUT, "%s: a pipe with nothing to read (no writer has it open)", path);
  if (status) goto cleanup;
  *out = buf, *n = got, buf = NULL;

cleanup:
  free(buf);
  fclose(f);
  return status;
}

static int fail(parse *p, const char *key, const char *fmt, const char *what) {
  if (!p->failed && p->rd.line)
    dv_fail(p->err, DV_EINPUT, "%s:%d: %s: %s%s", p->path, p->rd.line, key, fmt, what);
  else if (!p->failed)
    dv_fail(p->err, DV_EINPUT, "%s: %s: %s%s", p->path, key, fmt, what);
  p->failed = 1;
  return 0;
}

static int copy(parse *p, char *dst, size_t size, const char *key, const char *value) {
  if (strlen(value) >= size) return fail(p, key, "too long: ", value);
  memcpy(dst, value, strlen(value) + 1);
  return 1;
}

static int number(parse *p, const char *key, const char *value, double lo, double *out) {
  if (dv_scenario_parse_number(value, out) || !isfinite(*out) || *out < lo)
    return fail(p, key, "not a number in range: ", value);
  return 1;
}

/* the index of key among a's settings, or -1 */
static int find(const dv_adapter *a, const char *key) {
  const dv_settings_section read = {a->name, a->specs, a->nsettings, 0, NULL};
  const dv_setting_spec *s = dv_settings_find(&read, key);
  return s ? (int)(s - a->specs) : -1;
}

/* the setting called key, added when new */
static size_t setting_index(parse *p, const char *key) {
  dv_adapter *a = p->a;
  const int known = find(a, key);
  if (known >= 0) return (size_t)known;
  if (a->nsettings == DV_ADAPTER_MAX_SETTINGS - 1) /* one is kept for half_thickness */
    return fail(p, key, "too many settings", ""), (size_t)-1;
  const size_t i = a->nsettings++;
  dv_setting_spec *s = &a->specs[i];
  copy(p, a->setting[i].key, sizeof a->setting[i].key, "setting", key);
  *s = (dv_setting_spec){
      a->setting[i].key,  DV_SETTING_REAL,  8 * i, 0, 0, 0, -INFINITY, INFINITY, NULL, NULL,
      a->setting[i].unit, a->setting[i].doc};
  return i;
}

static int choices(parse *p, dv_adapter_setting *set, dv_setting_spec *s, const char *value) {
  char buf[512];
  size_t n = 0;
  snprintf(buf, sizeof buf, "%s", value);
  for (char *save = NULL, *w = strtok_r(buf, " ,", &save); w; w = strtok_r(NULL, " ,", &save)) {
    if (n == DV_ADAPTER_MAX_CHOICES) return fail(p, s->key, "too many choices: ", value);
    if (!copy(p, set->names[n], sizeof set->names[n], s->key, w)) return 0;
    set->choices[n] = set->names[n];
    n++;
  }
  if (!n) return fail(p, s->key, "no choices", "");
  set->choices[n] = NULL;
  s->type = DV_SETTING_CHOICE, s->choices = set->choices, s->lo = 0, s->hi = (double)(n - 1);
  return 1;
}

static int setting_key(parse *p, const char *name, const char *key, const char *value) {
  if (!name[0] || strspn(name, "abcdefghijklmnopqrstuvwxyz0123456789_") != strlen(name))
    return fail(p, name, "a setting's name: lower-case letters, digits and '_' only", "");
  const size_t i = setting_index(p, name);
  if (i == (size_t)-1) return 0;
  dv_adapter_setting *set = &p->a->setting[i];
  dv_setting_spec *s = &p->a->specs[i];
  if (strcmp(key, "type") == 0) {
    if (strcmp(value, "real") == 0) return s->type = DV_SETTING_REAL, 1;
    if (strcmp(value, "int") == 0) return s->type = DV_SETTING_INT, 1;
    if (strcmp(value, "flag") == 0) return choices(p, set, s, "off on");
    if (strcmp(value, "choice") == 0) return s->type = DV_SETTING_CHOICE, 1;
    return fail(p, key, "one of real, int, choice, flag, not ", value);
  }
  if (strcmp(key, "choices") == 0) return choices(p, set, s, value);
  if (strcmp(key, "default") == 0) {
    if (strcmp(value, "scene") == 0) return s->def = NAN, 1;
    if (s->type == DV_SETTING_CHOICE) {
      for (size_t v = 0; s->choices && s->choices[v]; v++)
        if (strcmp(s->choices[v], value) == 0) return s->def = (double)v, 1;
      return fail(p, key, "not one of the choices (give choices before default): ", value);
    }
    return number(p, key, value, -INFINITY, &s->def);
  }
  if (strcmp(key, "lo") == 0) return number(p, key, value, -INFINITY, &s->lo);
  if (strcmp(key, "hi") == 0) return number(p, key, value, -INFINITY, &s->hi);
  if (strcmp(key, "unit") == 0) return copy(p, set->unit, sizeof set->unit, key, value);
  if (strcmp(key, "doc") == 0) return copy(p, set->doc, sizeof set->doc, key, value);
  return fail(p, key, "unknown key in [setting.", name), 0;
}

static int model_key(parse *p, const char *value_name, const char *key, const char *value) {
  size_t m = 0;
  while (m < p->nmodels && strcmp(p->model_c[m], value_name) != 0) m++;
  if (m == p->nmodels) {
    if (m == DV_ADAPTER_MAX_CHOICES + 1) return fail(p, key, "too many [model] sections", "");
    copy(p, p->model_c[p->nmodels++], DV_ADAPTER_NAME, "model", value_name);
  }
  dv_step_model *sm = &p->a->models[m];
  if (strcmp(key, "c") == 0) return number(p, key, value, 0.0, &sm->c);
  if (strcmp(key, "soft_steps") == 0) return number(p, key, value, 0.0, &sm->soft_steps);
  if (strcmp(key, "step_cost") == 0) return number(p, key, value, 0.0, &sm->step_cost);
  return fail(p, key, "unknown key in [model]", "");
}

/* a key of [adapter] or [roles] given a second time (one key a bit) */
static int twice(parse *p, const char *section, const char *key) {
  static const char *const keys[] = {
      "name",   "description", "command", "requires", "timeout", "stand_in",           "protocol",
      "step",   "friction",    "choice",  "softness", "stiffer", "softness_min_steps", "step_lo",
      "step_hi"};
  for (unsigned k = 0; k < sizeof keys / sizeof keys[0]; k++)
    if (strcmp(keys[k], key) == 0) {
      const unsigned bit = 1u << (k + (section[0] == 'r' ? 16 : 0));
      if (p->given & bit) return fail(p, key, "given twice", "");
      p->given |= bit;
    }
  return 1;
}

static int adapter_key(parse *p, const char *key, const char *value) {
  dv_adapter *a = p->a;
  if (!twice(p, "adapter", key)) return 0;
  if (strcmp(key, "name") == 0) {
    if (!value[0] || strspn(value, "abcdefghijklmnopqrstuvwxyz0123456789_") != strlen(value))
      return fail(p, key, "lower-case letters, digits and '_' only: ", value);
    return copy(p, a->name, sizeof a->name, key, value);
  }
  if (strcmp(key, "description") == 0)
    return copy(p, a->description, sizeof a->description, key, value);
  if (strcmp(key, "command") == 0) {
    if (!value[0] || strpbrk(value, "\"'")) /* run as words, by no shell */
      return fail(p, key, "words separated by spaces, no quotes: ", value[0] ? value : "(empty)");
    return copy(p, a->command, sizeof a->command, key, value);
  }
  if (strcmp(key, "requires") == 0) return copy(p, a->requires, sizeof a->requires, key, value);
  if (strcmp(key, "timeout") == 0) {
    if (!number(p, key, value, 0.001, &a->timeout)) return 0;
    return a->timeout <= TIMEOUT_MAX ? 1 : fail(p, key, "at most 600 s, not ", value);
  }
  if (strcmp(key, "stand_in") == 0) return number(p, key, value, 1e-9, &a->stand_in);
  if (strcmp(key, "protocol") == 0) {
    double v;
    if (!number(p, key, value, 0, &v)) return 0;
    return v == DV_ADAPTER_PROTOCOL ? 1 : fail(p, key, "diskval speaks protocol 1, not ", value);
  }
  return fail(p, key, "unknown key in [adapter]", "");
}

static int roles_key(parse *p, const char *key, const char *value) {
  dv_adapter *a = p->a;
  if (!twice(p, "roles", key)) return 0;
  if (strcmp(key, "step") == 0) return copy(p, a->step_key, sizeof a->step_key, key, value);
  if (strcmp(key, "friction") == 0)
    return copy(p, a->friction_key, sizeof a->friction_key, key, value);
  if (strcmp(key, "choice") == 0) return copy(p, a->choice_key, sizeof a->choice_key, key, value);
  if (strcmp(key, "softness") == 0)
    return copy(p, a->softness_key, sizeof a->softness_key, key, value);
  if (strcmp(key, "stiffer") == 0) return number(p, key, value, 1e-9, &a->contact.stiffer);
  if (strcmp(key, "softness_min_steps") == 0)
    return number(p, key, value, 0.0, &a->contact.softness_min_steps);
  if (strcmp(key, "step_lo") == 0) return number(p, key, value, 1e-12, &a->search.lo);
  if (strcmp(key, "step_hi") == 0) return number(p, key, value, 1e-12, &a->search.hi);
  return fail(p, key, "unknown key in [roles]", "");
}

static int knob_key(parse *p, const char *name, const char *key, const char *value) {
  dv_adapter *a = p->a;
  size_t i = 0;
  while (i < a->nextra && strcmp(p->knob_name[i], name) != 0) i++;
  if (i == a->nextra) {
    if (i == DV_ADAPTER_MAX_EXTRA) return fail(p, key, "too many [knob] sections", "");
    if (!copy(p, p->knob_name[i], sizeof p->knob_name[i], "knob", name)) return 0;
    a->nextra++;
  }
  if (strcmp(key, "what") == 0)
    return copy(p, a->extra_what[i], sizeof a->extra_what[i], key, value);
  if (strcmp(key, "set") == 0) {
    char k[DV_ADAPTER_NAME * 2], v[DV_ADAPTER_NAME * 2];
    if (sscanf(value, "%63s %63s", k, v) != 2) return fail(p, key, "KEY VALUE, not ", value);
    return copy(p, a->extra_key[i], sizeof a->extra_key[i], key, k) &&
           copy(p, a->extra_value[i], sizeof a->extra_value[i], key, v);
  }
  return fail(p, key, "unknown key in [knob.", name);
}

static int handler(void *user, const char *section, const char *key, const char *value) {
  parse *p = user;
  if (p->failed) return 0;
  if (strcmp(section, "adapter") == 0) return adapter_key(p, key, value);
  if (strcmp(section, "roles") == 0) return roles_key(p, key, value);
  if (strcmp(section, "model") == 0) return model_key(p, "", key, value);
  if (strncmp(section, "model.", 6) == 0) return model_key(p, section + 6, key, value);
  if (strncmp(section, "setting.", 8) == 0) return setting_key(p, section + 8, key, value);
  if (strncmp(section, "knob.", 5) == 0) return knob_key(p, section + 5, key, value);
  return fail(p, key, "unknown section ", section);
}

/* the checks across sections, and the tables built from them */
/* each setting on its own: choices, a range, a default inside it */
static int check_setting(parse *p, const dv_setting_spec *s) {
  char range[64];
  if (s->type == DV_SETTING_CHOICE && !(s->choices && s->choices[0]))
    return fail(p, s->key, "a choice with no choices = line", "");
  if (s->type == DV_SETTING_INT && !(s->lo >= -2147483647.0 && s->hi <= 2147483647.0))
    return fail(p, s->key, "an int's lo and hi must be given, within the int range", "");
  if (!(s->lo <= s->hi)) return fail(p, s->key, "lo is above hi", "");
  snprintf(range, sizeof range, "[%g, %g]", s->lo, s->hi);
  if (!isnan(s->def) && !(s->def >= s->lo && s->def <= s->hi))
    return fail(p, s->key, "the default is outside its range ", range);
  return 1;
}

static int finish(parse *p) {
  dv_adapter *a = p->a;
  for (size_t i = 0; i < a->nsettings; i++)
    if (!check_setting(p, &a->specs[i])) return 0;
  static const char *const required[] = {"name", "command"};
  const char *const given[] = {a->name, a->command};
  for (size_t k = 0; k < 2; k++)
    if (!given[k][0]) return fail(p, required[k], "missing in [adapter]", "");
  if (strcmp(a->step_key, "timestep") != 0) /* what the settings choice varies (engine_choose.h) */
    return fail(p, "step", "must be the setting timestep, not ",
                a->step_key[0] ? a->step_key : "none");
  if (!a->choice_key[0])
    return fail(p, "choice", "missing in [roles]: a choice or flag setting best and sweeps vary",
                "");
  const char *roles[] = {a->step_key, a->friction_key, a->choice_key, a->softness_key};
  for (size_t k = 0; k < 4; k++)
    if ((k < 2 || roles[k][0]) && find(a, roles[k]) < 0)
      return fail(p, k < 2 ? (k ? "friction" : "step") : roles[k],
                  "a role names no [setting.KEY] (or none is given): ", roles[k]);
  for (size_t k = 0; k < 4; k++) /* the step, friction and softness are numbers diskval sets */
    if (k != 2 && roles[k][0] && a->specs[find(a, roles[k])].type != DV_SETTING_REAL)
      return fail(p, roles[k], "a role's setting must be of type real", "");
  if (find(a, DV_ADAPTER_HALF_KEY) >= 0)
    return fail(p, DV_ADAPTER_HALF_KEY, "diskval sets it from the scene", "");
  const int choice = a->choice_key[0] ? find(a, a->choice_key) : -1;
  if (choice >= 0 && a->specs[choice].type != DV_SETTING_CHOICE)
    return fail(p, "choice", "names a setting that is not a choice: ", a->choice_key);
  /* every model sits at its choice value's index */
  dv_step_model models[DV_ADAPTER_MAX_CHOICES + 1];
  memcpy(models, a->models, sizeof models);
  memset(a->models, 0, sizeof a->models);
  size_t nvalues = 1;
  while (choice >= 0 && a->specs[choice].choices[nvalues]) nvalues++;
  for (size_t m = 0; m < p->nmodels; m++) {
    size_t v = 0;
    if (!p->model_c[m][0]) { /* [model]: every value's that has none of its own */
      for (v = 0; v < nvalues; v++)
        if (!(a->model_given >> v & 1u)) a->models[v] = models[m];
      continue;
    }
    if (choice < 0) return fail(p, "model", "[model.VALUE] without a choice role: ", p->model_c[m]);
    while (a->specs[choice].choices[v] && strcmp(a->specs[choice].choices[v], p->model_c[m])) v++;
    if (!a->specs[choice].choices[v]) return fail(p, "model", "no such choice: ", p->model_c[m]);
    a->models[v] = models[m];
    a->model_given |= 1u << v;
  }
  for (size_t m = 0; m < p->nmodels; m++)
    if (!p->model_c[m][0]) a->model_given = (1u << nvalues) - 1u;
  if (!a->model_given) return fail(p, "model", "no [model] section", "");
  /* a value with no model of its own is no candidate, but runs when given: its
   * step and softness derived from the first model */
  size_t first = 0;
  while (!(a->model_given >> first & 1u)) first++;
  for (size_t v = 0; v < nvalues; v++)
    if (!(a->model_given >> v & 1u)) a->models[v] = a->models[first];
  for (size_t e = 0; e < a->nextra; e++) {
    const int k = find(a, a->extra_key[e]);
    dv_settings_block block;
    char what[160];
    if (!a->extra_what[e][0]) return fail(p, p->knob_name[e], "[knob] without what =", "");
    if (k < 0 || dv_setting_parse(&a->specs[k], a->extra_value[e], &block, what, sizeof what))
      return fail(p, p->knob_name[e],
                  "set names no setting, or a value it cannot take: ", a->extra_key[e]);
    a->extra[e] = (dv_engine_extra_knob){a->extra_what[e], a->extra_key[e], a->extra_value[e]};
  }
  return 1;
}

/* the half-thickness every adapter is given (adapter.h) */
static void add_half_thickness(dv_adapter *a) {
  const size_t i = a->nsettings++;
  dv_adapter_setting *set = &a->setting[i];
  snprintf(set->key, sizeof set->key, "%s", DV_ADAPTER_HALF_KEY);
  snprintf(set->unit, sizeof set->unit, "m");
  snprintf(set->doc, sizeof set->doc,
           "of the cylinder modelled; default: [disk] thickness / 2, or the stand-in %g m for a "
           "thin disk",
           a->stand_in);
  a->specs[i] = (dv_setting_spec){
      set->key, DV_SETTING_REAL, 8 * i,   0, DV_SETTING_OPEN_LO, NAN, 0.0, 1.0, NULL,
      NULL,     set->unit,       set->doc};
}

int dv_adapter_load(const char *dir, dv_adapter *a, dv_error *err) {
  char path[1100];
  memset(a, 0, sizeof *a);
  a->timeout = 60.0;
  a->stand_in = 5e-4;
  a->contact.stiffer = 0.25;
  if (!realpath(dir, a->dir)) snprintf(a->dir, sizeof a->dir, "%s", dir);
  snprintf(path, sizeof path, "%s/manifest.ini", a->dir);
  char *data = NULL;
  size_t size = 0;
  if (read_manifest(path, &data, &size, err)) return -1;
  parse p = {a, {data, size, 0, 0, 0}, path, err, 0, {{0}}, 0, {{0}}, 0};
  const int r = ini_parse_stream(read_line, &p.rd, handler, &p);
  free(data);
  if (p.failed) return -1;
  if (p.rd.too_long)
    return dv_fail(err, DV_EINPUT, "%s:%d: syntax: a line longer than %d characters", path,
                   p.rd.too_long, INI_MAX_LINE - 2);
  if (r) return dv_fail(err, DV_EINPUT, "%s:%d: syntax: not KEY = VALUE nor [SECTION]", path, r);
  p.rd.line = 0;
  if (!finish(&p)) return -1;
  add_half_thickness(a);
  return 0;
}
