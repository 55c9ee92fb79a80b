/* test_league_writers: league.csv, league.md, league.html and the figures of
 * a league made here (2 objects, 3 engines and one not available, 2 targets,
 * cells of every outcome, a why full of characters that need escaping, a not
 * run cell of NaN metrics), and the summary they share.
 *
 * The CSV reads back (RFC 4180) as a header and a row per cell, each of the
 * header's width, its text and numbers exact, NaN as "nan" (as in sweep.csv);
 * the page links every run cell to its report once and no other, and no text
 * of a cell opens a tag; the Markdown names every object and engine and its
 * tables' rows have their header's columns; every figure is an SVG.
 *
 * usage: test_league_writers [KEEP_DIR]  (with KEEP_DIR, the files are written
 * there and kept, e.g. to look at the page in a browser) */
#define _DEFAULT_SOURCE /* mkdtemp, open_memstream */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "dv_test.h"
#include "league.h"
#include "report_escape.h"

/* what a table shows of it, up to the first ':', needs escaping in HTML and Markdown too */
#define WHY "slips | <b>sinks</b> & \"it's\": 0.3 rad, at dt 1e-3 s (cost cap)"
#define NFIELDS 21

static const char *const objects[] = {"coin_thin", "hoop"};
static const char *const engines[] = {"ode", "mujoco", "bullet"};
static const double targets[] = {1e-2, 1e-3};
enum { NOBJ = 2, NENG = 3, NTGT = 2, NCELLS = NOBJ * NENG * NTGT };

/* the outcome of object o, engine e, target t: each outcome at least once */
static dv_league_outcome outcome_of(size_t o, size_t e, size_t t) {
  if (e == 2 && o == 0) return DV_LEAGUE_CANNOT_MODEL;
  if (e == 0 && o == 1) return DV_LEAGUE_NOT_RUN;
  if (e == 1 && o == 0 && t == 1) return DV_LEAGUE_NOT_REACHED;
  if (e == 2 && o == 1) return DV_LEAGUE_NOT_REACHED;
  return DV_LEAGUE_REACHED;
}

/* a cell: reached ones at cost 0.01 x (1 + e) x (1 + t) s/s, 100 steps per 0.1 s
 * simulated (1000 steps/s) at target 1e-2, 400 at 1e-3 */
static void make_cell(dv_league_cell *c, size_t o, size_t e, size_t t) {
  memset(c, 0, sizeof *c);
  snprintf(c->object, sizeof c->object, "%s", objects[o]);
  snprintf(c->scenario_file, sizeof c->scenario_file, "league/%s, v2.ini", objects[o]);
  snprintf(c->engine, sizeof c->engine, "%s", engines[e]);
  snprintf(c->engine_version, sizeof c->engine_version, "%s 1.%zu", engines[e], e);
  c->target = targets[t];
  c->path_target = targets[t] * 0.1;
  c->outcome = outcome_of(o, e, t);
  snprintf(c->key, sizeof c->key, "%016zx", (o * NENG + e) * NTGT + t);
  c->theta_max_err = c->path_max_err = c->wall_per_sim_s = c->order = c->step = c->sim_s = NAN;
  c->steps = -1;
  if (c->outcome == DV_LEAGUE_CANNOT_MODEL)
    snprintf(c->why, sizeof c->why, "no shape for a disk 2 mm thick");
  if (c->outcome != DV_LEAGUE_REACHED && c->outcome != DV_LEAGUE_NOT_REACHED) return;
  snprintf(c->choice_key, sizeof c->choice_key, "engines.%s.integrator", engines[e]);
  snprintf(c->choice, sizeof c->choice, "rk4");
  snprintf(c->step_key, sizeof c->step_key, "engines.%s.timestep", engines[e]);
  c->step = t ? 2.5e-4 : 1e-3;
  c->theta_max_err = targets[t] * 0.8;
  c->path_max_err = c->path_target * 0.5;
  c->wall_per_sim_s = 0.01 * (double)(1 + e) * (double)(1 + t);
  c->steps = t ? 400 : 100;
  c->sim_s = 0.1;
  c->order = 3.9;
  snprintf(c->verdict, sizeof c->verdict, c->outcome == DV_LEAGUE_REACHED ? "pass" : "fail");
  snprintf(c->report, sizeof c->report, "cells/%s/%s/%zu", objects[o], engines[e], t);
  if (c->outcome == DV_LEAGUE_NOT_REACHED) {
    snprintf(c->why, sizeof c->why, "%s", WHY);
    snprintf(c->cause, sizeof c->cause, "time step, 80%%");
  }
  /* the search's probes: the chosen rk4 over 3 steps (one shared by both targets), euler */
  const double steps[] = {4e-3, 1e-3, 2.5e-4};
  for (size_t k = 0; k < 4; k++) {
    dv_league_point *p = &c->points[c->npoints++];
    snprintf(p->choice, sizeof p->choice, k < 3 ? "rk4" : "euler");
    p->step = k < 3 ? steps[k] : 1e-3;
    p->theta_err = 10 * pow(p->step, 2);
    p->path_err = p->theta_err / 10;
    p->cost = 1e-5 / p->step;
    p->ok = k != 0 || t == 0;
  }
}

/* the league: cells object-major, then engine, then target, as league.h says */
static void make_league(dv_league *lg, dv_league_cell *cells) {
  memset(lg, 0, sizeof *lg);
  snprintf(lg->date, sizeof lg->date, "2024-05-01T12:00:00Z");
  snprintf(lg->machine, sizeof lg->machine, "Linux x86_64 <cpu> & 2 cores");
  snprintf(lg->diskval_version, sizeof lg->diskval_version, "0.38");
  lg->cost_cap = DV_LEAGUE_COST_CAP;
  lg->ntargets = NTGT;
  memcpy(lg->targets, targets, sizeof targets);
  lg->nobjects = NOBJ;
  for (size_t o = 0; o < NOBJ; o++) {
    snprintf(lg->objects[o].name, sizeof lg->objects[o].name, "%s", objects[o]);
    snprintf(lg->objects[o].description, sizeof lg->objects[o].description, "a <real> object");
  }
  lg->nengines = NENG + 1;
  for (size_t e = 0; e < NENG; e++) {
    snprintf(lg->engines[e].name, sizeof lg->engines[e].name, "%s", engines[e]);
    snprintf(lg->engines[e].version, sizeof lg->engines[e].version, "%s 1.%zu", engines[e], e);
    lg->engines[e].available = 1;
  }
  snprintf(lg->engines[NENG].name, sizeof lg->engines[NENG].name, "dart");
  snprintf(lg->engines[NENG].why, sizeof lg->engines[NENG].why, "not built: <none>");
  lg->ncells = NCELLS;
  lg->cells = cells;
  for (size_t o = 0, i = 0; o < NOBJ; o++)
    for (size_t e = 0; e < NENG; e++)
      for (size_t t = 0; t < NTGT; t++) make_cell(&cells[i++], o, e, t);
}

/* the whole file at path (caller frees), or NULL; its size in *size */
static char *slurp(const char *dir, const char *name, long *size) {
  char path[4200];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *fp = fopen(path, "rb");
  char *buf = NULL;
  *size = -1;
  if (!fp) return NULL;
  if (fseek(fp, 0, SEEK_END) == 0 && (*size = ftell(fp)) >= 0 && fseek(fp, 0, SEEK_SET) == 0 &&
      (buf = malloc((size_t)*size + 1)))
    buf[fread(buf, 1, (size_t)*size, fp)] = '\0';
  fclose(fp);
  return buf;
}

/* ---- the CSV, read back as RFC 4180 says ---- */
#define MAXROWS 64
typedef struct csv {
  size_t nrows;
  size_t nfields[MAXROWS];
  char *field[MAXROWS][32]; /* into the buffer, unquoted in place */
  int bad;                  /* a quote in an unquoted field, or text after a closing quote */
} csv;

static void csv_parse(char *s, csv *t) {
  memset(t, 0, sizeof *t);
  char *w = s;
  while (*s && t->nrows < MAXROWS) {
    size_t r = t->nrows, f = 0;
    for (;;) {
      char *start = w;
      if (*s == '"') {
        for (s++; *s && !(s[0] == '"' && s[1] != '"'); s++) *w++ = *s == '"' ? *++s : *s;
        if (*s == '"') s++;
        t->bad |= *s && *s != ',' && *s != '\n';
      } else {
        for (; *s && *s != ',' && *s != '\n'; s++) {
          t->bad |= *s == '"';
          *w++ = *s;
        }
      }
      const char end = *s;
      *w++ = '\0';
      if (f < 32) t->field[r][f] = start;
      f++;
      if (end) s++;
      if (end != ',') break;
    }
    t->nfields[t->nrows++] = f;
  }
}

/* the column of the header named name, or -1 */
static int column(const csv *t, const char *name) {
  for (size_t f = 0; f < t->nfields[0] && f < 32; f++)
    if (!strcmp(t->field[0][f], name)) return (int)f;
  return -1;
}

static void check_csv(const char *dir, const dv_league *lg) {
  long size;
  char *text = slurp(dir, "league.csv", &size);
  csv t;
  CHECK(text != NULL, "no league.csv");
  if (!text) return;
  csv_parse(text, &t);
  CHECK(!t.bad, "league.csv: a quote out of place");
  CHECK(t.nrows == 1 + lg->ncells, "league.csv: %zu rows, want 1 + %zu", t.nrows, lg->ncells);
  CHECK(t.nfields[0] == NFIELDS, "league.csv: header of %zu fields", t.nfields[0]);
  for (size_t r = 1; r < t.nrows; r++)
    CHECK(t.nfields[r] == t.nfields[0], "league.csv row %zu: %zu fields, the header %zu", r,
          t.nfields[r], t.nfields[0]);
  const int why = column(&t, "why"), theta = column(&t, "theta_max_err"),
            steps = column(&t, "steps"), target = column(&t, "target"),
            reached = column(&t, "reached"), file = column(&t, "scenario_file"),
            cost = column(&t, "wall_per_sim_s");
  CHECK(
      why >= 0 && theta >= 0 && steps >= 0 && target >= 0 && reached >= 0 && file >= 0 && cost >= 0,
      "league.csv: a column missing from its header");
  for (size_t r = 1;
       why >= 0 && theta >= 0 && steps >= 0 && target >= 0 && reached >= 0 && file >= 0 &&
       cost >= 0 && r < t.nrows && r <= lg->ncells && t.nfields[r] == NFIELDS;
       r++) {
    const dv_league_cell *c = &lg->cells[r - 1];
    CHECK(!strcmp(t.field[r][why], c->why), "row %zu: why reads back as [%s]", r, t.field[r][why]);
    CHECK(!strcmp(t.field[r][file], c->scenario_file), "row %zu: file [%s]", r, t.field[r][file]);
    CHECK(strtod(t.field[r][target], NULL) == c->target, "row %zu: target %s", r,
          t.field[r][target]);
    CHECK(strtod(t.field[r][cost], NULL) == c->wall_per_sim_s || isnan(c->wall_per_sim_s),
          "row %zu: cost %s", r, t.field[r][cost]);
    CHECK(!strcmp(t.field[r][reached], c->outcome == DV_LEAGUE_REACHED ? "true" : "false"),
          "row %zu: reached %s", r, t.field[r][reached]);
    if (isnan(c->theta_max_err)) { /* as sweep.csv writes what it does not have */
      CHECK(!strcmp(t.field[r][theta], "nan"), "row %zu: NaN error as [%s]", r, t.field[r][theta]);
      CHECK(!strcmp(t.field[r][steps], "nan"), "row %zu: no steps as [%s]", r, t.field[r][steps]);
    }
  }
  free(text);
}

/* ---- the page ---- */
static size_t count(const char *text, const char *what) {
  size_t n = 0;
  for (const char *p = text; (p = strstr(p, what)); p += strlen(what)) n++;
  return n;
}

static void check_html(const char *dir, const dv_league *lg) {
  long size;
  char *text = slurp(dir, "league.html", &size);
  CHECK(text != NULL, "no league.html");
  if (!text) return;
  size_t run = 0;
  for (size_t i = 0; i < lg->ncells; i++) {
    const dv_league_cell *c = &lg->cells[i];
    char href[400];
    if (c->outcome != DV_LEAGUE_REACHED && c->outcome != DV_LEAGUE_NOT_REACHED) continue;
    run++;
    snprintf(href, sizeof href, "href=\"%s/report.md\"", c->report);
    CHECK(count(text, href) == 1, "league.html: %zu links %s", count(text, href), href);
  }
  CHECK(count(text, "/report.md\"") == run, "league.html: %zu links to reports, %zu run cells",
        count(text, "/report.md\""), run);
  CHECK(!strstr(text, "<b>sinks") && !strstr(text, "<none>") && !strstr(text, "<cpu>") &&
            !strstr(text, "<real>"),
        "league.html: a text opens a tag");
  CHECK(strstr(text, "slips | &lt;b&gt;sinks&lt;/b&gt; &amp; &quot;it&#39;s&quot;") != NULL,
        "league.html: the why's escaped words are missing");
  CHECK(!strstr(text, "<script") && !strstr(text, "http://") && !strstr(text, "https://"),
        "league.html: a script or something to fetch");
  free(text);
}

/* ---- the Markdown ---- */
/* the '|' not escaped by a backslash on the line at p */
static size_t pipes(const char *p) {
  size_t n = 0;
  for (; *p && *p != '\n'; p++) {
    if (*p == '\\' && p[1]) {
      p++;
      continue;
    }
    n += *p == '|';
  }
  return n;
}

/* whether text holds name as literal Markdown text ("coin\_thin") */
static int has_md(const char *text, const char *name) {
  char *md = NULL;
  size_t len = 0;
  FILE *fp = open_memstream(&md, &len);
  if (!fp) return 0;
  dv_report_escape_markdown(fp, name);
  fclose(fp);
  const int found = md && strstr(text, md) != NULL;
  free(md);
  return found;
}

static void check_md(const char *dir, const dv_league *lg) {
  long size;
  char *text = slurp(dir, "league.md", &size);
  CHECK(text != NULL, "no league.md");
  if (!text) return;
  for (size_t o = 0; o < lg->nobjects; o++)
    CHECK(has_md(text, lg->objects[o].name), "league.md: no %s", lg->objects[o].name);
  for (size_t e = 0; e < lg->nengines; e++)
    CHECK(has_md(text, lg->engines[e].name), "league.md: no %s", lg->engines[e].name);
  size_t head = 0, tables = 0, rows = 0; /* a table's rows have its header's columns */
  for (const char *line = text; *line; line = strchr(line, '\n') ? strchr(line, '\n') + 1 : "") {
    if (*line != '|') {
      head = 0;
      continue;
    }
    if (!head) head = pipes(line), tables++;
    rows++;
    CHECK(pipes(line) == head, "league.md: a row of %zu columns in a table of %zu: %.60s",
          pipes(line) - 1, head - 1, line);
  }
  /* per target a matrix (head, rule, 2 objects) and a summary (head, rule, 3 engines) */
  CHECK(tables == 2 * NTGT && rows == NTGT * (4 + 5), "league.md: %zu tables of %zu rows", tables,
        rows);
  CHECK(!strstr(text, "<b>"), "league.md: a why's tag is raw");
  CHECK(!strstr(text, "at dt 1e-3 s"), "league.md: a cell shows its whole why, not its start");
  free(text);
}

/* the summaries: counts by outcome, geometric means over the reached cells alone */
static void check_summary(const dv_league *lg) {
  dv_league_summary s;
  dv_league_summarize(lg, "mujoco", 1e-2, &s);
  CHECK(s.reached == 2 && s.not_reached == 0 && s.cannot_model == 0 && s.not_run == 0,
        "mujoco at 1e-2: %zu %zu %zu %zu", s.reached, s.not_reached, s.cannot_model, s.not_run);
  /* both cost 0.02 s/s at 1000 steps/s: their geometric mean is that, to the rounding of
   * exp(mean log), a few ulp: 4 allowed (measured |diff| 0 and 2.27e-13, 1 ulp of 1000,
   * with DV_TEST_MEASURE=1 build/tests/test_league_writers) */
  CHECK_NEAR(s.geomean_wall_per_sim_s, 0.02, 4 * DBL_EPSILON * 0.02,
             "mujoco's geometric mean cost");
  CHECK_NEAR(s.geomean_steps_per_sim_s, 1000, 4 * DBL_EPSILON * 1000,
             "mujoco's steps per simulated s");
  dv_league_summarize(lg, "bullet", 1e-3, &s);
  CHECK(s.reached == 0 && s.not_reached == 1 && s.cannot_model == 1 && s.not_run == 0,
        "bullet at 1e-3: %zu %zu %zu %zu", s.reached, s.not_reached, s.cannot_model, s.not_run);
  CHECK(isnan(s.geomean_wall_per_sim_s), "bullet reached nothing: geometric mean %g",
        s.geomean_wall_per_sim_s);
  dv_league_summarize(lg, "ode", 1e-3, &s); /* coin 0.02, hoop not run */
  CHECK(s.reached == 1 && s.not_run == 1, "ode at 1e-3: %zu reached %zu not run", s.reached,
        s.not_run);
  /* the hoop alone, 0.04 s/s; coin_thin's 0.04 not reached is left out (measured |diff|
   * 6.94e-18, 1 ulp, as above) */
  dv_league_summarize(lg, "mujoco", 1e-3, &s);
  CHECK(s.reached == 1 && s.not_reached == 1, "mujoco at 1e-3: %zu %zu", s.reached, s.not_reached);
  CHECK_NEAR(s.geomean_wall_per_sim_s, 0.04, 4 * DBL_EPSILON * 0.04, "mujoco's cost at 1e-3");
  const dv_league_cell *c = dv_league_cell_of(lg, "hoop", "bullet", 1e-3);
  CHECK(c == &lg->cells[NCELLS - 1], "the hoop's bullet cell at 1e-3 is the last");
  CHECK(dv_league_cell_of(lg, "hoop", "dart", 1e-3) == NULL, "a cell for dart");
  CHECK(dv_league_cell_of(lg, "hoop", "ode", 5e-3) == NULL, "a cell at 5e-3");
}

int main(int argc, char **argv) {
  static dv_league lg;
  static dv_league_cell cells[NCELLS];
  char tmp[] = "/tmp/league_writers.XXXXXX";
  const char *dir = argc > 1 ? argv[1] : mkdtemp(tmp);
  dv_error err = {""};
  long size;
  if (!dir || (argc > 1 && mkdir(dir, 0777) && access(dir, W_OK))) {
    fprintf(stderr, "no directory to write into\n");
    return 1;
  }
  make_league(&lg, cells);
  CHECK(dv_league_write_csv(dir, &lg, &err) == DV_OK, "csv: %s", err.msg);
  CHECK(dv_league_write_md(dir, &lg, &err) == DV_OK, "md: %s", err.msg);
  CHECK(dv_league_write_html(dir, &lg, &err) == DV_OK, "html: %s", err.msg);
  CHECK(dv_league_write_figures(dir, &lg, &err) == DV_OK, "figures: %s", err.msg);
  check_csv(dir, &lg);
  check_html(dir, &lg);
  check_md(dir, &lg);
  check_summary(&lg);
  const char *const svgs[] = {"work_precision_coin_thin.svg", "work_precision_hoop.svg",
                              "overview.svg"};
  for (size_t i = 0; i < 3; i++) {
    char *text = slurp(dir, svgs[i], &size);
    CHECK(text && size > 0 && strstr(text, "<svg") && strstr(text, "</svg>"), "%s: no SVG",
          svgs[i]);
    free(text);
  }
  int (*const writers[])(const char *, const dv_league *, dv_error *) = {
      dv_league_write_csv, dv_league_write_md, dv_league_write_html, dv_league_write_figures};
  for (size_t i = 0; i < 4; i++) { /* an error in words, nothing printed */
    err.msg[0] = '\0';
    CHECK(
        writers[i]("/nonexistent/dir", &lg, &err) != DV_OK && err.msg[0] && !strchr(err.msg, '\n'),
        "writer %zu: into a missing directory: [%s]", i, err.msg);
  }
  if (argc == 1) { /* nothing else may be left: no temporary */
    const char *const files[] = {"league.csv", "league.md", "league.html",
                                 svgs[0],      svgs[1],     svgs[2]};
    char path[200];
    for (size_t i = 0; i < 6; i++) {
      snprintf(path, sizeof path, "%s/%s", dir, files[i]);
      CHECK(unlink(path) == 0, "%s was not written", files[i]);
    }
    CHECK(rmdir(dir) == 0, "%s: other files left", dir);
  }
  return TEST_RESULT();
}
