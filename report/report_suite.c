/* dv_suite_report: summary.json, index.html (the matrix: scenarios down, engines across),
 * JUnit XML and each scenario's page, from their report.json. */
#include "report_suite.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>

#include "dv_input.h"
#include "io_file.h"
#include "report_escape.h"
#include "report_suite_internal.h"
#include "run_verdict.h"

#define MAX_REPORT_BYTES (64L << 20) /* a larger report.json is taken as broken */
#define PATH_CAP 4096

typedef dvs_entry entry;

#define MAX_COLUMNS 64 /* engine columns; the suite's scenarios name at most this many */
#define MAX_REASONS 24 /* distinct reasons counted per class; the rest are "other" */

/* fixed layout, one line per text and ellipses: no width or height grows with the text */
static const char css[] =
    "body{font-family:sans-serif;margin:12px;color:#222;font-size:14px}"
    "table{border-collapse:collapse;table-layout:fixed;width:100%}"
    "th,td{border:1px solid #bbb;padding:2px 4px;font-size:12px;line-height:15px;"
    "white-space:nowrap;overflow:hidden;text-overflow:ellipsis;text-align:left}"
    "thead th{background:#eee}th.s{width:11em;background:#f6f6f6}"
    "td a,th a{color:inherit;text-decoration:none;display:block;overflow:hidden;"
    "text-overflow:ellipsis}td a span{display:block;overflow:hidden;text-overflow:ellipsis}"
    ".pass{background:#c8f0c8;color:#075207}.fail{background:#f6c4c4;color:#8b0000}"
    ".nj{background:#e2e2e2;color:#444}.err{background:#ffe0a0;color:#7a4200}"
    "h1 span{padding:0 .3em}ul{margin:.3em 0}p{margin:.4em 0}";

/* reasons and how many times each came up */
typedef struct tally {
  const char *what[MAX_REASONS];
  int count[MAX_REASONS];
  int n, other;
} tally;

/* count one more of what in t */
static void add(tally *t, const char *what) {
  for (int i = 0; i < t->n; i++)
    if (!strcmp(t->what[i], what)) {
      t->count[i]++;
      return;
    }
  if (t->n == MAX_REASONS) {
    t->other++;
    return;
  }
  t->what[t->n] = what;
  t->count[t->n++] = 1;
}

/* ": 3 diverged, 2 lost contact" for t (nothing when empty) */
static void put_tally(FILE *fp, const tally *t, const char *pre) {
  for (int i = 0; i < t->n; i++) {
    fprintf(fp, "%s%d ", i ? ", " : pre, t->count[i]);
    dv_report_escape(fp, t->what[i], 0);
  }
  if (t->other) fprintf(fp, ", %d other", t->other);
}

/* the counts by class at the top, and why by class: outcome, deciding metric */
static void put_summary(FILE *fp, const dvs_entry *es, size_t n, size_t ncols) {
  int count[DVS_NCLASSES] = {0};
  static const tally none;
  tally fails = none, metrics = none, unjudged = none;
  for (size_t i = 0; i < n; i++) {
    const cJSON *eng, *worst;
    count[DVS_ERROR] += es[i].error[0] != 0;
    cJSON_ArrayForEach(eng, es[i].engines) {
      const dvs_class k = dvs_class_of(eng);
      const char *outcome = *text(eng, "outcome") ? text(eng, "outcome") : "no outcome";
      count[k]++;
      if (k == DVS_NOT_JUDGED) add(&unjudged, outcome);
      if (k != DVS_FAIL) continue;
      add(&fails, outcome);
      if (!strcmp(outcome, "exceeds tolerance") && (worst = dvs_deciding_limit(eng)))
        add(&metrics, worst->string);
    }
  }
  /* a class's colour only where it has cells: "0 fail" in red reads as a failure */
  fprintf(fp,
          "<p>%zu scenarios, %zu engines: <b class=\"%s\">%d pass</b>, "
          "<b class=\"%s\">%d fail</b>, <b class=\"%s\">%d not judged</b>, "
          "<b class=\"%s\">%d harness error%s</b>.</p>\n<ul>\n",
          n, ncols, count[DVS_PASS] ? "pass" : "none", count[DVS_PASS],
          count[DVS_FAIL] ? "fail" : "none", count[DVS_FAIL],
          count[DVS_NOT_JUDGED] ? "nj" : "none", count[DVS_NOT_JUDGED],
          count[DVS_ERROR] ? "err" : "none", count[DVS_ERROR], count[DVS_ERROR] == 1 ? "" : "s");
  if (count[DVS_FAIL]) {
    fputs("<li>fail", fp);
    put_tally(fp, &fails, ": ");
    put_tally(fp, &metrics, "; over their limit: ");
    fputs("</li>\n", fp);
  }
  if (count[DVS_NOT_JUDGED]) {
    fputs("<li>not judged", fp);
    put_tally(fp, &unjudged, ": ");
    fputs("</li>\n", fp);
  }
  if (count[DVS_ERROR]) {
    fputs("<li>harness errors (no report): ", fp);
    int k = 0;
    for (size_t i = 0; i < n; i++)
      if (es[i].error[0]) dv_report_escape_put(fp, k++ ? ", " : "", es[i].name, 0, "");
    fputs("</li>\n", fp);
  }
  fputs("</ul>\n", fp);
}

/* the engines of every scenario, each once, in the order they first appear */
static size_t columns(const dvs_entry *es, size_t n, const char **cols) {
  size_t ncols = 0;
  for (size_t i = 0; i < n; i++) {
    const cJSON *eng;
    cJSON_ArrayForEach(eng, es[i].engines) {
      size_t k = 0;
      while (k < ncols && strcmp(cols[k], eng->string)) k++;
      if (k == ncols && ncols < MAX_COLUMNS) cols[ncols++] = eng->string;
    }
  }
  return ncols;
}

/* "<a href=DIR/index.html>" when the scenario has its page, else "<a>" */
static void open_link(FILE *fp, const char *out_dir, const dvs_entry *e) {
  if (dvs_file_exists(out_dir, e->dir, "index.html"))
    dvs_put_url(fp, "<a href=\"", e->dir, "index.html", "\">");
  else
    fputs("<a>", fp);
}

/* one cell: the verdict's colour, value / limit of the deciding metric, the reference */
static void put_cell(FILE *fp, const char *out_dir, const dvs_entry *e, const cJSON *eng) {
  if (!eng) {
    fputs("<td>&#8211;</td>", fp);
    return;
  }
  const dvs_class k = dvs_class_of(eng);
  const cJSON *worst = dvs_deciding_limit(eng);
  char body[48];
  dvs_judged_words(eng, body, sizeof body);
  fprintf(fp, "<td class=\"%s\" title=\"", dvs_class_css[k]);
  dv_report_escape(fp, eng->string, 1);
  fputs(" on ", fp);
  dv_report_escape(fp, e->name, 1);
  fputs(" ", fp);
  dv_report_escape(fp, body, 1);
  fputs(": ", fp);
  dv_report_escape(fp, text(eng, "decided"), 1);
  fputs("\">", fp);
  open_link(fp, out_dir, e);
  if ((k == DVS_PASS || !strcmp(text(eng, "outcome"), "exceeds tolerance")) && worst) {
    dvs_put_num(fp, "<span><b>", item(worst, "margin"), "&#215;</b> ");
    dv_report_escape_put(fp, "", worst->string, 0, "</span>");
  } else {
    dv_report_escape_put(fp, "<span><b>", *text(eng, "outcome") ? text(eng, "outcome") : "?", 0,
                         "</b></span>");
  }
  /* "vs" said once, in the legend: the cell names the body */
  const char *shown = strncmp(body, "vs ", 3) ? body : body + 3;
  dv_report_escape_put(fp, "<span>", shown, 0, "</span></a></td>");
}

void dvs_write_matrix(FILE *fp, const char *out_dir, const dvs_entry *es, size_t n, int pass) {
  const char *cols[MAX_COLUMNS];
  const size_t ncols = columns(es, n, cols);
  fprintf(fp,
          "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\" />\n"
          "<title>diskval suite: %s</title>\n<style>%s</style>\n</head>\n<body>\n"
          "<h1>diskval suite: <span class=\"%s\">%s</span></h1>\n",
          pass ? "PASS" : "FAIL", css, pass ? "pass" : "fail", pass ? "PASS" : "FAIL");
  put_summary(fp, es, n, ncols);
  fputs("<p>A cell: the verdict's colour; the judged metric nearest (or furthest over) its limit, "
        "as its value over its limit (0.42&#215;: 42 % of the limit); the body whose reference judged "
        "it. Point at a cell for the line that "
        "decided; click it for the scenario's page. Summary: <a href=\"summary.json\">"
        "summary.json</a>.</p>\n",
        fp);
  fputs("<table>\n<thead><tr><th class=\"s\">scenario</th>", fp);
  for (size_t c = 0; c < ncols; c++) {
    dv_report_escape_put(fp, "<th title=\"", cols[c], 1, "\">");
    dv_report_escape_put(fp, "", cols[c], 0, "</th>");
  }
  fputs("</tr></thead>\n<tbody>\n", fp);
  for (size_t i = 0; i < n; i++) {
    const dvs_entry *e = &es[i];
    dv_report_escape_put(fp, "<tr><th class=\"s\" title=\"", e->name, 1, "\">");
    open_link(fp, out_dir, e);
    dv_report_escape_put(fp, "", e->name, 0, "</a></th>");
    if (e->error[0]) {
      fprintf(fp, "<td class=\"err\" colspan=\"%zu\"", ncols ? ncols : 1);
      dv_report_escape_put(fp, " title=\"", e->error, 1, "\">");
      dv_report_escape_put(fp, "<b>ERROR</b> ", e->error, 0, "</td></tr>\n");
      continue;
    }
    for (size_t c = 0; c < ncols; c++)
      put_cell(fp, out_dir, e, cJSON_GetObjectItemCaseSensitive(e->engines, cols[c]));
    fputs("</tr>\n", fp);
  }
  fputs("</tbody>\n</table>\n", fp);
  char stability[4096];
  snprintf(stability, sizeof stability, "%s/stability.html", out_dir);
  if (access(stability, F_OK) == 0) /* written by suite --stability */
    fputs("<p><a href=\"stability.html\">Stability limits and failure modes per engine</a></p>\n",
          fp);
  fputs("</body>\n</html>\n", fp);
}

/* a scenario passed: usable report that says so, every engine passing */
static int scenario_pass(const entry *e) {
  if (e->error[0] || !cJSON_IsTrue(item(e->report, "pass"))) return 0;
  const cJSON *eng;
  cJSON_ArrayForEach(eng, e->engines) if (!engine_pass(eng)) return 0;
  return 1;
}

/* record in e why its report is unusable */
static void unusable(entry *e, const char *why, const char *more) {
  snprintf(e->error, sizeof e->error, "%s/report.json: %s%s", e->dir, why, more);
}

void dvs_load_entry(const char *out_dir, const char *dir, entry *e) {
  char path[PATH_CAP], where[64];
  char *buf = NULL;
  size_t len;
  struct stat st;
  FILE *fp = NULL;
  const char *end = NULL;
  e->dir = e->name = dir;
  if (snprintf(path, sizeof path, "%s/%s/report.json", out_dir, dir) >= (int)sizeof path) {
    unusable(e, "path too long", "");
    goto cleanup;
  }
  if (!(fp = dv_input_open(path))) {
    unusable(e, "cannot open: ", strerror(errno));
    goto cleanup;
  }
  if (fstat(fileno(fp), &st) || !S_ISREG(st.st_mode) || st.st_size > MAX_REPORT_BYTES) {
    unusable(e, "not a regular file of at most 64 MiB", "");
    goto cleanup;
  }
  len = (size_t)st.st_size;
  if (!(buf = malloc(len + 1)) || fread(buf, 1, len, fp) != len) {
    unusable(e, "cannot read: ", strerror(errno));
    goto cleanup;
  }
  buf[len] = '\0';
  if (!(e->report = cJSON_ParseWithOpts(buf, &end, 0))) {
    snprintf(where, sizeof where, " (at byte %ld of %zu)", end ? (long)(end - buf) : 0L, len);
    unusable(e, "not valid JSON", where);
    goto cleanup;
  }
  if (*text(e->report, "scenario")) e->name = text(e->report, "scenario");
  const cJSON *engines = item(e->report, "engines");
  if (!cJSON_IsObject(e->report))
    unusable(e, "not a JSON object", "");
  else if (*text(e->report, "error")) /* an error report: the run's own cause */
    snprintf(e->error, sizeof e->error, "%s", text(e->report, "error"));
  else if (!cJSON_IsObject(engines) || !engines->child)
    unusable(e, "no engines compared", "");
  else
    e->engines = engines;
cleanup:
  if (fp) fclose(fp);
  free(buf);
}

/* a copy of string or number o[key] for the summary, null when absent */
static cJSON *copy_or_null(const cJSON *o, const char *key) {
  const cJSON *v = item(o, key);
  return cJSON_IsString(v) || cJSON_IsNumber(v) ? cJSON_Duplicate(v, 0) : cJSON_CreateNull();
}

/* summary.json as text (caller frees), NULL when out of memory */
static char *summary_text(const entry *es, size_t n, int pass) {
  static const char *const keys[] = {"outcome", "theta_max_err", "path_max_err", "wall_per_sim_s",
                                     "judged"};
  static const char *const objects[] = {"limits", "reference"}; /* copied whole */
  cJSON *root = cJSON_CreateObject();
  cJSON_AddBoolToObject(root, "pass", pass);
  cJSON *list = cJSON_AddArrayToObject(root, "scenarios");
  for (size_t i = 0; i < n; i++) {
    const entry *e = &es[i];
    const cJSON *eng;
    cJSON *s = cJSON_CreateObject();
    cJSON_AddItemToArray(list, s);
    cJSON_AddStringToObject(s, "scenario", e->name);
    cJSON_AddStringToObject(s, "dir", e->dir);
    cJSON_AddBoolToObject(s, "pass", scenario_pass(e));
    if (e->error[0]) cJSON_AddStringToObject(s, "error", e->error);
    cJSON *engines = cJSON_AddObjectToObject(s, "engines");
    cJSON_ArrayForEach(eng, e->engines) {
      cJSON *o = cJSON_AddObjectToObject(engines, eng->string);
      const cJSON *failures = item(eng, "failures");
      cJSON_AddBoolToObject(o, "pass", engine_pass(eng));
      for (size_t k = 0; k < sizeof keys / sizeof *keys; k++)
        cJSON_AddItemToObject(o, keys[k], copy_or_null(eng, keys[k]));
      cJSON_AddItemToObject(
          o, "failures",
          cJSON_IsArray(failures) ? cJSON_Duplicate(failures, 1) : cJSON_CreateArray());
      for (size_t k = 0; k < sizeof objects / sizeof *objects; k++) {
        const cJSON *v = item(eng, objects[k]);
        cJSON_AddItemToObject(o, objects[k],
                              cJSON_IsObject(v) ? cJSON_Duplicate(v, 1) : cJSON_CreateNull());
      }
    }
  }
  char *out = cJSON_Print(root); /* report strings are copied as they are: make it UTF-8 */
  cJSON_Delete(root);
  dv_report_utf8_scrub(out);
  return out;
}

void dvs_judged_words(const cJSON *eng, char *out, size_t size) {
  const cJSON *h = item(item(eng, "reference"), "half_thickness");
  if (!h) h = item(eng, "reference_half_thickness");
  if (*text(eng, "judged"))
    snprintf(out, size, "%s", text(eng, "judged"));
  else
    dv_run_body_words(cJSON_IsNumber(h) ? h->valuedouble : 0.0, out, size);
}

void dvs_tally(const dvs_entry *es, size_t n, int *runs, int *failing, int *errors) {
  for (size_t i = 0; i < n; i++) {
    const cJSON *eng;
    *errors += es[i].error[0] != 0;
    cJSON_ArrayForEach(eng, es[i].engines) {
      ++*runs;
      *failing += !engine_pass(eng);
    }
  }
}

/* out_dir/dir is a directory (a scenario's page can be written there) */
static int is_dir(const char *out_dir, const char *dir) {
  char path[PATH_CAP];
  struct stat st;
  return snprintf(path, sizeof path, "%s/%s", out_dir, dir) < (int)sizeof path &&
         stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* load every report, then write the files: the scenarios' pages, then the suite's, all
 * opened before any is committed */
int dv_report_suite_write_ended(const char *out_dir, const char *const *scenario_dirs,
                                const char *const *not_ended, size_t n, const char *junit_path,
                                dv_error *err) {
  dv_io_file outs[3];
  char paths[2][PATH_CAP];
  entry *es = NULL;
  char *summary = NULL;
  int status = DV_OK;
  memset(outs, 0, sizeof outs);
  if (!out_dir || (n && !scenario_dirs))
    return dv_fail(err, DV_EINPUT, "suite report: no output directory or no scenario list");
  for (size_t i = 0; i < n; i++)
    if (!scenario_dirs[i])
      return dv_fail(err, DV_EINPUT, "suite report: scenario %zu has no dir", i);
  snprintf(paths[0], PATH_CAP, "%s/summary.json", out_dir);
  snprintf(paths[1], PATH_CAP, "%s/index.html", out_dir);
  const char *targets[3] = {paths[0], paths[1], junit_path};
  for (int k = 0; k < 3; k++)
    if (targets[k] && strlen(targets[k]) >= sizeof outs[k].path)
      return dv_fail(err, DV_EINPUT, "suite report: path too long: %.200s", targets[k]);
  int pass = 1;
  if ((es = calloc(n ? n : 1, sizeof *es))) {
    for (size_t i = 0; i < n; i++) {
      if (not_ended && not_ended[i]) {
        es[i].dir = es[i].name = scenario_dirs[i];
        snprintf(es[i].error, sizeof es[i].error, "%s", not_ended[i]);
      } else {
        dvs_load_entry(out_dir, scenario_dirs[i], &es[i]);
      }
      pass &= scenario_pass(&es[i]);
    }
    summary = summary_text(es, n, pass);
  }
  if (!summary) {
    status = dv_fail(err, DV_ESYSTEM, "suite report: out of memory");
    goto cleanup;
  }
  for (int k = 0; k < 3 && !status; k++)
    if (targets[k]) status = dv_io_open(&outs[k], targets[k], err);
  for (size_t i = 0; i < n && !status; i++) /* before the matrix: its cells link to them */
    if (is_dir(out_dir, es[i].dir)) status = dvs_write_page(out_dir, &es[i], err);
  if (status) goto cleanup;
  fputs(summary, outs[0].fp);
  fputc('\n', outs[0].fp);
  dvs_write_matrix(outs[1].fp, out_dir, es, n, pass);
  if (junit_path) dvs_write_junit(outs[2].fp, es, n);
  for (int k = 0; k < 3 && !status; k++)
    if (targets[k]) status = dv_io_commit(&outs[k], err);
cleanup:
  for (int k = 0; k < 3; k++) dv_io_abort(&outs[k]);
  for (size_t i = 0; es && i < n; i++) cJSON_Delete(es[i].report);
  free(es);
  free(summary);
  return status;
}

int dv_report_suite_write(const char *out_dir, const char *const *scenario_dirs, size_t n,
                          const char *junit_path, dv_error *err) {
  return dv_report_suite_write_ended(out_dir, scenario_dirs, NULL, n, junit_path, err);
}

int dv_report_suite_write_junit(const char *out_dir, const char *dir, const char *junit_path,
                                dv_error *err) {
  dv_io_file out;
  memset(&out, 0, sizeof out);
  if (strlen(junit_path) >= sizeof out.path)
    return dv_fail(err, DV_EINPUT, "path too long: %.200s", junit_path);
  entry e;
  memset(&e, 0, sizeof e);
  dvs_load_entry(out_dir, dir, &e);
  int status = dv_io_open(&out, junit_path, err);
  if (!status) {
    dvs_write_junit(out.fp, &e, 1);
    status = dv_io_commit(&out, err);
  }
  dv_io_abort(&out);
  cJSON_Delete(e.report);
  return status;
}
