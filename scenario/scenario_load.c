/* scenario_load: reading (inih), then validating, a scenario file against
 * the core sections and the engines' tables. */
#include <errno.h>
#include <ini.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "dv_input.h"
#include "scenario.h"
#include "scenario_core.h"

#define MAX_SECTIONS (DV_NCORE_SECTIONS + DV_MAX_ENGINE_SECTIONS)
/* distinct known section headers: the core and engine sections, [tolerance]
 * and one [tolerance.ENGINE] per engine (an unknown one ends the read) */
#define MAX_SEEN (2 * MAX_SECTIONS + 1)
#define MAX_KEYS 256 /* keys over every section */

typedef struct parse_ctx {
  const char *path; /* for messages */
  int line;         /* current line, counted by the reader */
  const char *data; /* the whole file, NUL-terminated */
  size_t size, pos; /* its length; the reader's position */
  int failed;       /* first error kept */
  dv_error *err;
  dv_scenario *sc;
  size_t nsec;
  const dv_settings_section *sec[MAX_SECTIONS];
  char sec_name[MAX_SECTIONS][64]; /* as in the file: "disk", "engines.ode" */
  void *block[MAX_SECTIONS];       /* where each section's values go */
  size_t first[MAX_SECTIONS];      /* its first key's index in text[] and text_line[] */
  char text[MAX_KEYS][256];
  int text_line[MAX_KEYS]; /* 0: not given; < 0: from --set number -line */
  char seen[MAX_SEEN][64];
  int seen_line[MAX_SEEN];
  int nseen;
} parse_ctx;

static int known_section(const parse_ctx *c, const char *name);

static int fail_at(parse_ctx *c, int line, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static int fail_at(parse_ctx *c, int line, const char *key, const char *fmt, ...) {
  if (c->failed) return -1;
  char what[320];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(what, sizeof what, fmt, ap);
  va_end(ap);
  c->failed = 1;
  if (line < 0)
    dv_fail(c->err, DV_EINPUT, "--set:%d: %s: %s", -line, key, what);
  else
    dv_fail(c->err, DV_EINPUT, "%s:%d: %s: %s", c->path, line, key, what);
  return -1;
}

/* remember the first line of each section header; an unknown one is an error at once */
static int see_header(parse_ctx *c, const char *p) {
  const char *end = strchr(p, ']');
  char name[64];
  if (!end) {
    const size_t len = strcspn(p, "\r\n");
    return fail_at(c, c->line, "syntax", "'%.*s' has no closing ']'", (int)(len > 60 ? 60 : len),
                   p);
  }
  size_t len = (size_t)(end - p - 1);
  if (len >= sizeof name) len = sizeof name - 1;
  memcpy(name, p + 1, len);
  name[len] = '\0';
  for (int i = 0; i < c->nseen; i++)
    if (!strcmp(c->seen[i], name)) return 0;
  if (!known_section(c, name) || c->nseen == MAX_SEEN)
    return fail_at(c, c->line, name, "unknown section [%s]", name);
  memcpy(c->seen[c->nseen], name, sizeof name);
  c->seen_line[c->nseen++] = c->line;
  return 0;
}

/* inih reader: one line per call from the file read whole, counted; over-long
 * lines, NUL bytes and unknown sections are errors; a UTF-8 byte order mark on
 * line 1 is skipped */
static char *read_line(char *buf, int size, void *stream) {
  parse_ctx *c = stream;
  if (c->failed || c->pos >= c->size) return NULL;
  const char *text = c->data + c->pos;
  const char *eol = memchr(text, '\n', c->size - c->pos);
  size_t n = eol ? (size_t)(eol - text) + 1 : c->size - c->pos;
  c->pos += n;
  c->line++;
  if (c->line == 1 && n >= 3 && !memcmp(text, "\xef\xbb\xbf", 3)) text += 3, n -= 3;
  if (memchr(text, '\0', n))
    return fail_at(c, c->line, "syntax", "a NUL byte inside the line"), NULL;
  if (n + 1 > (size_t)size)
    return fail_at(c, c->line, "syntax", "line longer than %d characters", size - 2), NULL;
  memcpy(buf, text, n);
  buf[n] = '\0';
  const char *p = buf + strspn(buf, " \t");
  if (*p == '[' && see_header(c, p)) return NULL;
  return buf;
}

/* path read whole into c->data, refused past DV_SCENARIO_MAX_BYTES before
 * more is read: a scenario is a few KiB, and /dev/zero never ends; a FIFO
 * with no writer is not waited for (dv_input.h). A file that cannot be read
 * has no line to point at. */
/* the files read while keeping (dv_scenario_keep_texts): each path's bytes */
typedef struct kept_text {
  char *path, *data;
  size_t size;
} kept_text;
static kept_text *kept;
static size_t nkept, kept_cap;
static int keeping;

void dv_scenario_keep_texts(int on) {
  keeping = on;
}

/* path's kept text into c->data (a copy, the parser's to free): 1, or 0 when none */
static int read_kept(parse_ctx *c, const char *path) {
  for (size_t i = 0; i < nkept; i++) {
    if (strcmp(kept[i].path, path)) continue;
    char *copy = malloc(kept[i].size + 1);
    if (!copy) return 0; /* read again */
    memcpy(copy, kept[i].data, kept[i].size + 1);
    c->data = copy, c->size = kept[i].size;
    return 1;
  }
  return 0;
}

/* keep c->data as path's text (nothing when out of memory: read again) */
static void keep(const parse_ctx *c, const char *path) {
  if (nkept == kept_cap) {
    kept_text *more = realloc(kept, (kept_cap ? 2 * kept_cap : 8) * sizeof *more);
    if (!more) return;
    kept = more, kept_cap = kept_cap ? 2 * kept_cap : 8;
  }
  kept_text k = {strdup(path), malloc(c->size + 1), c->size};
  if (k.path && k.data) {
    memcpy(k.data, c->data, c->size + 1);
    kept[nkept++] = k;
  } else {
    free(k.path);
    free(k.data);
  }
}

static int read_file(parse_ctx *c, const char *path) {
  if (keeping && read_kept(c, path)) return DV_OK;
  struct stat st;
  const double mib = DV_SCENARIO_MAX_BYTES / 1048576.0;
  if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
    return dv_fail(c->err, DV_EINPUT, "%s: is a directory, not a scenario file", path);
  FILE *f = dv_input_open(path);
  if (!f) return dv_fail(c->err, DV_EINPUT, "%s: cannot open: %s", path, strerror(errno));
  int status = DV_OK;
  char *buf = NULL;
  if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) && st.st_size > DV_SCENARIO_MAX_BYTES) {
    status =
        dv_fail(c->err, DV_EINPUT, "%s: %.1f MiB, more than the %g MiB a scenario file may have",
                path, (double)st.st_size / 1048576.0, mib);
    goto cleanup;
  }
  if (!(buf = malloc(DV_SCENARIO_MAX_BYTES + 2))) {
    status = dv_fail(c->err, DV_ESYSTEM, "%s: out of memory: a %g MiB read buffer", path, mib);
    goto cleanup;
  }
  const size_t got = fread(buf, 1, DV_SCENARIO_MAX_BYTES + 1, f);
  if (ferror(f))
    status = dv_fail(c->err, DV_EINPUT, "%s: read error: %s", path, strerror(errno));
  else if (got > DV_SCENARIO_MAX_BYTES)
    status =
        dv_fail(c->err, DV_EINPUT, "%s: more than the %g MiB a scenario file may have", path, mib);
  else if (got == 0 && fstat(fileno(f), &st) == 0 && S_ISFIFO(st.st_mode))
    status =
        dv_fail(c->err, DV_EINPUT, "%s: a pipe with nothing to read (no writer has it open)", path);
  if (status) goto cleanup;
  buf[got] = '\0';
  c->data = buf, c->size = got, buf = NULL;
  if (keeping) keep(c, path);

cleanup:
  free(buf);
  fclose(f);
  return status;
}

static int section_line(const parse_ctx *c, const char *section) {
  for (int i = 0; i < c->nseen; i++)
    if (strcmp(c->seen[i], section) == 0) return c->seen_line[i];
  return 0;
}

static int find_section(const parse_ctx *c, const char *name) {
  for (size_t s = 0; s < c->nsec; s++)
    if (!strcmp(c->sec_name[s], name)) return (int)s;
  return -1;
}

static int engine_named(const parse_ctx *c, const char *name) {
  for (size_t s = DV_NCORE_SECTIONS; s < c->nsec; s++)
    if (!strcmp(c->sec[s]->name, name)) return 1;
  return 0;
}

static void engine_list(const parse_ctx *c, char *buf, size_t size) {
  buf[0] = '\0';
  for (size_t s = DV_NCORE_SECTIONS; s < c->nsec; s++)
    snprintf(buf + strlen(buf), size - strlen(buf), "%s%s", s > DV_NCORE_SECTIONS ? ", " : "",
             c->sec[s]->name);
}

/* [tolerance] and [tolerance.ENGINE] */
static int set_tolerance(parse_ctx *c, int line, const char *section, const char *key,
                         const char *value) {
  const char *engine = section[9] == '.' ? section + 10 : "";
  char names[128], what[320];
  if (*engine && !engine_named(c, engine)) {
    engine_list(c, names, sizeof names);
    return fail_at(c, line, section, "unknown engine '%s' (%s)", engine, names);
  }
  int metric = -1;
  for (int m = 0; m < DV_NMETRICS; m++)
    if (!strcmp(dv_metric_names[m], key)) metric = m;
  if (metric < 0) return fail_at(c, line, key, "unknown tolerance metric in [%s]", section);
  const dv_setting_spec limit_spec = {.key = key, .type = DV_SETTING_REAL, .hi = INFINITY};
  double limit;
  if (dv_setting_parse(&limit_spec, value, &limit, what, sizeof what))
    return fail_at(c, line, key, "%s", what);
  dv_scenario *sc = c->sc;
  for (size_t i = 0; i < sc->ntolerances; i++)
    if (!strcmp(sc->tolerances[i].engine, engine) && (int)sc->tolerances[i].metric == metric) {
      if (line > 0) return fail_at(c, line, key, "given twice in [%s]", section);
      sc->tolerances[i].limit = limit;
      return 0;
    }
  if (sc->ntolerances == DV_MAX_TOLERANCES) return fail_at(c, line, key, "too many tolerances");
  dv_tolerance *t = &sc->tolerances[sc->ntolerances++];
  snprintf(t->engine, sizeof t->engine, "%s", engine);
  t->metric = (dv_metric_id)metric;
  t->limit = limit;
  return 0;
}

static int set_key(parse_ctx *c, int line, const char *section, const char *key,
                   const char *value) {
  if (!section[0]) return fail_at(c, line, key, "key before any [section]");
  if (strncmp(section, "tolerance", 9) == 0 && (section[9] == '\0' || section[9] == '.'))
    return set_tolerance(c, line, section, key, value);
  const int s = find_section(c, section);
  if (s < 0) return fail_at(c, line, section, "unknown section [%s]", section);
  const dv_setting_spec *sp = dv_settings_find(c->sec[s], key);
  if (!sp) return fail_at(c, line, key, "unknown key in [%s]", section);
  const size_t i = c->first[s] + (size_t)(sp - c->sec[s]->specs);
  if (c->text_line[i] > 0 && line > 0)
    return fail_at(c, line, key, "given twice in [%s] (first on line %d)", section,
                   c->text_line[i]);
  snprintf(c->text[i], sizeof c->text[i], "%s", value);
  c->text_line[i] = line;
  return 0;
}

static int on_key(void *user, const char *section, const char *key, const char *value) {
  parse_ctx *c = user;
  if (!c->failed) set_key(c, c->line, section, key, value);
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

static int known_section(const parse_ctx *c, const char *name) {
  if (!strcmp(name, "tolerance") || find_section(c, name) >= 0) return 1;
  return !strncmp(name, "tolerance.", 10) && engine_named(c, name + 10);
}

/* the line of key in section s: where it was given, else its section's, else 1 */
static int key_line(const parse_ctx *c, size_t s, const char *key) {
  const dv_setting_spec *sp = key ? dv_settings_find(c->sec[s], key) : NULL;
  if (sp && c->text_line[c->first[s] + (size_t)(sp - c->sec[s]->specs)])
    return c->text_line[c->first[s] + (size_t)(sp - c->sec[s]->specs)];
  const int line = section_line(c, c->sec_name[s]);
  return line ? line : 1;
}

/* every key given is parsed into its place; a required one missing is an error */
static int read_values(parse_ctx *c) {
  char what[320];
  for (size_t s = 0; s < c->nsec; s++) {
    const dv_settings_section *sec = c->sec[s];
    for (size_t k = 0; k < sec->nspecs; k++) {
      const dv_setting_spec *sp = &sec->specs[k];
      const size_t i = c->first[s] + k;
      if (!c->text_line[i]) {
        if (sp->flags & DV_SETTING_REQUIRED)
          return fail_at(c, key_line(c, s, NULL), sp->key, "missing (required in [%s])",
                         c->sec_name[s]);
        continue;
      }
      if (dv_setting_parse(sp, c->text[i], c->block[s], what, sizeof what))
        return fail_at(c, c->text_line[i], sp->key, "%s", what);
      if (s >= DV_NCORE_SECTIONS && k < 32) c->sc->given_keys[s - DV_NCORE_SECTIONS] |= 1u << k;
      if (s < DV_NCORE_SECTIONS && k < 32) c->sc->core_given[s] |= 1u << k;
    }
  }
  return 0;
}

static int validate(parse_ctx *c) {
  for (int i = 0; i < c->nseen; i++) /* sections without keys never reach the handler */
    if (!known_section(c, c->seen[i]))
      return fail_at(c, c->seen_line[i], c->seen[i], "unknown section [%s]", c->seen[i]);
  for (size_t s = 0; s < DV_NCORE_SECTIONS; s++)
    if (!section_line(c, c->sec_name[s]))
      return fail_at(c, 1, c->sec_name[s], "missing section [%s]", c->sec_name[s]);
  if (read_values(c)) return -1;
  for (size_t s = 0; s < c->nsec; s++) {
    dv_setting_issue is = {0};
    const int bad = s < DV_NCORE_SECTIONS
                        ? c->sec[s]->check && c->sec[s]->check(c->sc, c->block[s], &is)
                        : dv_scenario_check_engine(c->sc, s - DV_NCORE_SECTIONS, &is);
    if (!bad) continue;
    char name[64];
    snprintf(name, sizeof name, "engines.%s", is.section);
    int t = find_section(c, is.section);
    if (t < 0) t = find_section(c, name);
    return fail_at(c, t < 0 ? 1 : key_line(c, (size_t)t, is.key), is.key, "%s", is.what);
  }
  return 0;
}

/* the sections of sc: the core ones, then one per engine table */
static void add_sections(parse_ctx *c) {
  dv_scenario *sc = c->sc;
  size_t first = 0;
  for (size_t s = 0; s < DV_NCORE_SECTIONS + sc->nsections; s++) {
    const int core = s < DV_NCORE_SECTIONS;
    c->sec[s] = core ? &dv_scenario_core[s] : sc->sections[s - DV_NCORE_SECTIONS];
    c->block[s] = core ? (void *)sc : (void *)&sc->settings[s - DV_NCORE_SECTIONS];
    snprintf(c->sec_name[s], sizeof c->sec_name[s], "%s%s", core ? "" : "engines.",
             c->sec[s]->name);
    c->first[s] = first;
    first += c->sec[s]->nspecs;
    if (core) dv_settings_defaults(c->sec[s], sc);
  }
  c->nsec = DV_NCORE_SECTIONS + sc->nsections;
}

int dv_scenario_load(const dv_settings_section *const *engines, const char *path,
                     const char *const *overrides, size_t noverrides, dv_scenario *sc,
                     dv_error *err) {
  parse_ctx *c = calloc(1, sizeof *c);
  int status = DV_EINPUT;
  if (!c) return dv_fail(err, DV_ESYSTEM, "%s: out of memory: the parser's state", path);
  dv_scenario_init(sc, engines);
  snprintf(sc->path, sizeof sc->path, "%s", path);
  c->path = path;
  c->err = err;
  c->sc = sc;
  add_sections(c);
  if (c->first[c->nsec - 1] + c->sec[c->nsec - 1]->nspecs > MAX_KEYS) {
    status = dv_fail(err, DV_EINPUT, "%s: more than %d keys in the schema", path, MAX_KEYS);
    goto cleanup;
  }
  if (read_file(c, path)) goto cleanup;
  const int bad_line = ini_parse_stream(read_line, c, on_key, c);
  if (bad_line > 0) fail_at(c, bad_line, "syntax", "expected [section] or key = value");
  for (size_t i = 0; i < noverrides && !c->failed; i++) apply_override(c, (int)i + 1, overrides[i]);
  if (!c->failed && validate(c) == 0 && !c->failed) status = DV_OK;

cleanup:
  free((char *)c->data);
  free(c);
  return status;
}
