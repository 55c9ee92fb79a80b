/* dv_suite_report: summary.json, index.html and JUnit XML from the scenarios' report.json. */
#include "report_suite.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <math.h>
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

/* the page's only style: pass green, FAIL red, harness ERROR amber */
static const char css[] =
    "body{font-family:sans-serif;margin:1.5em;color:#222}table{border-collapse:collapse}"
    "th,td{border:1px solid #bbb;padding:3px 7px;vertical-align:top}th{background:#eee}"
    "td.n{text-align:right;font-family:monospace}.pass,.fail,.err{font-weight:bold}"
    ".pass{background:#c8f0c8;color:#075207}.fail{background:#f6c4c4;color:#8b0000}"
    ".err{background:#ffe0a0;color:#7a4200}figure{display:inline-block;margin:.5em}"
    "img{max-width:560px;border:1px solid #ddd}section{border-top:2px solid #ccc}";

/* a scenario passed: usable report that says so, every engine passing */
static int scenario_pass(const entry *e) {
  if (e->error[0] || !cJSON_IsTrue(item(e->report, "pass"))) return 0;
  const cJSON *eng;
  cJSON_ArrayForEach(eng, e->engines) if (!engine_pass(eng)) return 0;
  return 1;
}

/* a file name that stays inside its scenario dir */
static int safe_name(const char *s) {
  return s && *s && !strchr(s, '/') && strcmp(s, ".") && strcmp(s, "..");
}

/* record in e why its report is unusable */
static void unusable(entry *e, const char *why, const char *more) {
  snprintf(e->error, sizeof e->error, "%s/report.json: %s%s", e->dir, why, more);
}

/* read and parse out_dir/dir/report.json into e; failures are recorded in e->error */
static void load_entry(const char *out_dir, const char *dir, entry *e) {
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

/* pre, number v with %.3g (an en dash when absent), post */
static void put_num(FILE *fp, const char *pre, const cJSON *v, const char *post) {
  if (cJSON_IsNumber(v))
    fprintf(fp, "%s%.3g%s", pre, v->valuedouble, post);
  else
    fprintf(fp, "%s&#8211;%s", pre, post);
}

/* pre, the relative URL dir/name percent-encoded ('/' kept), post */
static void put_url(FILE *fp, const char *pre, const char *dir, const char *name,
                    const char *post) {
  char url[PATH_CAP];
  snprintf(url, sizeof url, "%s/%s", dir, name);
  fputs(pre, fp);
  for (const unsigned char *p = (const unsigned char *)url; *p; p++) {
    const int plain = (*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') ||
                      (*p >= '0' && *p <= '9') || strchr("-._~/", *p);
    fprintf(fp, plain ? "%c" : "%%%02X", *p);
  }
  fputs(post, fp);
}

/* out_dir/dir/name is a regular file */
static int file_exists(const char *out_dir, const char *dir, const char *name) {
  char path[PATH_CAP];
  struct stat st;
  if (!safe_name(name)) return 0;
  if (snprintf(path, sizeof path, "%s/%s/%s", out_dir, dir, name) >= (int)sizeof path) return 0;
  return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* a link to dir/name when it exists, separated from the previous one */
static void put_link(FILE *fp, const char *out_dir, const char *dir, const char *name,
                     int *nlinks) {
  if (!file_exists(out_dir, dir, name)) return;
  put_url(fp, *nlinks ? " &#183; <a href=\"" : "<a href=\"", dir, name, "\">");
  dv_report_escape_put(fp, "", name, 0, "</a>");
  ++*nlinks;
}

/* one summary-table row of engine eng of scenario i */
/* the metric closest to (or furthest over) its limit: "0.42 (theta_max_err)" */
static void put_margin(FILE *fp, const cJSON *limits) {
  const cJSON *l, *worst = NULL;
  cJSON_ArrayForEach(l, limits) {
    const cJSON *m = item(l, "margin");
    if (cJSON_IsNumber(m) && (!worst || m->valuedouble > item(worst, "margin")->valuedouble))
      worst = l;
  }
  if (!worst) {
    fputs("<td class=\"n\">&#8211;</td>", fp);
    return;
  }
  fprintf(fp, "<td class=\"n\">%.3g (", item(worst, "margin")->valuedouble);
  dv_report_escape_put(fp, "", worst->string, 0, ")</td>");
}

static void put_row(FILE *fp, const entry *e, size_t i, const cJSON *eng) {
  static const char *const metrics[] = {"theta_max_err", "path_max_err", "phase_err",
                                        "path_hausdorff", "energy_drift"};
  const int ok = engine_pass(eng);
  const cJSON *f;
  fprintf(fp, "<tr><td><a href=\"#s%zu\">", i);
  dv_report_escape_put(fp, "", e->name, 0, "</a></td>");
  dv_report_escape_put(fp, "<td>", eng->string, 0, "</td>");
  char body[48];
  dvs_judged_words(eng, body, sizeof body);
  dv_report_escape_put(fp, "<td>", body, 0, "</td>");
  dv_report_escape_put(fp, "<td>", text(eng, "outcome"), 0, "</td>");
  fprintf(fp, "<td class=\"%s\">%s</td>", ok ? "pass" : "fail", ok ? "pass" : "FAIL");
  dv_report_escape_put(fp, "<td>", text(eng, "ran_with"), 0, "</td>");
  for (size_t k = 0; k < sizeof metrics / sizeof *metrics; k++)
    put_num(fp, "<td class=\"n\">", item(eng, metrics[k]), "</td>");
  put_num(fp, "<td class=\"n\">", item(item(eng, "geometry_share"), "theta_max_err"), "</td>");
  put_margin(fp, item(eng, "limits"));
  put_num(fp, "<td class=\"n\">", item(eng, "wall_per_sim_s"), "</td><td>");
  int nf = 0;
  if (cJSON_IsString(item(eng, "decided")))
    dv_report_escape_put(fp, "", text(eng, "decided"), 0, ""), nf = 1;
  cJSON_ArrayForEach(f, item(eng, "failures")) if (cJSON_IsString(f))
      dv_report_escape_put(fp, nf++ ? "<br />" : "", f->valuestring, 0, "");
  fputs("</td></tr>\n", fp);
}

/* the section of scenario i: description, reference, engines, plots, files */
static void put_section(FILE *fp, const char *out_dir, const entry *e, size_t i) {
  fprintf(fp, "<section id=\"s%zu\">\n", i);
  dv_report_escape_put(fp, "<h2>", e->name, 0, "</h2>\n");
  if (e->error[0]) {
    dv_report_escape_put(fp, "<p class=\"err\">harness error: ", e->error, 0, "</p>\n</section>\n");
    return;
  }
  const cJSON *r = e->report, *ref = item(r, "reference"), *eng, *plot;
  dv_report_escape_put(fp, "<p>", text(r, "description"), 0, "</p>\n");
  dv_report_escape_put(fp, "<p>Scenario file ", text(r, "file"), 0, ": ");
  put_num(fp, "duration ", item(r, "duration"), " s, ");
  put_num(fp, "output every ", item(r, "output_dt"), " s.</p>\n");
  dv_report_escape_put(fp, "<p>Reference ", text(ref, "engine"), 0, " (");
  dv_report_escape_put(fp, "", text(ref, "integrator"), 0, ", ");
  put_num(fp, "rtol ", item(ref, "rtol"), "): ");
  dv_report_escape_put(fp, "<b>", text(ref, "outcome"), 0, "</b>");
  put_num(fp, " at t = ", item(ref, "t_end"), " s. ");
  dv_report_escape_put(fp, "", text(ref, "detail"), 0, "</p>\n<ul>\n");
  cJSON_ArrayForEach(eng, e->engines) {
    dv_report_escape_put(fp, "<li>", eng->string, 0, ": ");
    dv_report_escape_put(fp, "", text(eng, "outcome"), 0, *text(eng, "detail") ? " &#8211; " : "");
    dv_report_escape_put(fp, "", text(eng, "detail"), 0, "</li>\n");
  }
  fputs("</ul>\n<div>\n", fp);
  cJSON_ArrayForEach(plot, item(r, "plots")) {
    if (!cJSON_IsString(plot) || !file_exists(out_dir, e->dir, plot->valuestring)) continue;
    put_url(fp, "<figure><img src=\"", e->dir, plot->valuestring, "\"");
    dv_report_escape_put(fp, " alt=\"", plot->valuestring, 1, "\" />");
    dv_report_escape_put(fp, "<figcaption>", plot->valuestring, 0, "</figcaption></figure>\n");
  }
  fputs("</div>\n<p>Files: ", fp);
  int nlinks = 0;
  char name[PATH_CAP];
  put_link(fp, out_dir, e->dir, "report.md", &nlinks);
  put_link(fp, out_dir, e->dir, "report.json", &nlinks);
  put_link(fp, out_dir, e->dir, "reduced.csv", &nlinks);
  cJSON_ArrayForEach(eng, e->engines) {
    snprintf(name, sizeof name, "%s.csv", eng->string);
    put_link(fp, out_dir, e->dir, name, &nlinks);
    snprintf(name, sizeof name, "matched-%s.csv", eng->string);
    put_link(fp, out_dir, e->dir, name, &nlinks);
  }
  fputs(nlinks ? "</p>\n</section>\n" : "none</p>\n</section>\n", fp);
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

/* index.html: title, summary table, one section per scenario */
static void write_html(FILE *fp, const char *out_dir, const entry *es, size_t n, int pass) {
  int runs = 0, failing = 0, errors = 0;
  dvs_tally(es, n, &runs, &failing, &errors);
  fprintf(fp,
          "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\" />\n"
          "<title>diskval suite: %s</title>\n<style>%s</style>\n</head>\n<body>\n"
          "<h1>diskval suite: <span class=\"%s\">%s</span></h1>\n"
          "<p>%zu scenarios, %d engine runs, %d failing, %d harness errors. "
          "Errors against the reference: theta in rad, path and phase (an arc along the "
          "reference's contact path) in m; energy drift relative; "
          "geometry share: part of the theta error explained by the stand-in's geometry.</p>\n",
          pass ? "PASS" : "FAIL", css, pass ? "pass" : "fail", pass ? "PASS" : "FAIL", n, runs,
          failing, errors);
  fputs(
      "<table>\n<tr><th>scenario</th><th>engine</th><th>judged</th><th>outcome</th><th>verdict</th>"
      "<th>ran with</th><th>theta_max_err</th><th>path_max_err</th><th>phase_err</th>"
      "<th>path_hausdorff</th>"
      "<th>energy_drift</th><th>geometry share</th><th>largest margin (value / limit)</th>"
      "<th>wall_per_sim_s</th><th>what decided; failures</th></tr>\n",
      fp);
  for (size_t i = 0; i < n; i++) {
    const cJSON *eng;
    if (es[i].error[0]) {
      fprintf(fp, "<tr><td><a href=\"#s%zu\">", i);
      dv_report_escape_put(fp, "", es[i].name, 0, "</a></td><td>&#8211;</td><td>error</td>");
      dv_report_escape_put(fp, "<td class=\"err\">ERROR</td><td colspan=\"10\"></td><td>",
                           es[i].error, 0, "</td></tr>\n");
    }
    cJSON_ArrayForEach(eng, es[i].engines) put_row(fp, &es[i], i, eng);
  }
  fputs("</table>\n", fp);
  char stability[PATH_CAP];
  snprintf(stability, sizeof stability, "%s/stability.html", out_dir);
  if (access(stability, F_OK) == 0) /* written by suite --stability */
    fputs("<p><a href=\"stability.html\">Stability limits and failure modes per engine</a></p>\n",
          fp);
  for (size_t i = 0; i < n; i++) put_section(fp, out_dir, &es[i], i);
  fputs("</body>\n</html>\n", fp);
}

/* load every report, then write the files: all opened before any is committed */
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
        load_entry(out_dir, scenario_dirs[i], &es[i]);
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
  if (status) goto cleanup;
  fputs(summary, outs[0].fp);
  fputc('\n', outs[0].fp);
  write_html(outs[1].fp, out_dir, es, n, pass);
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
  load_entry(out_dir, dir, &e);
  int status = dv_io_open(&out, junit_path, err);
  if (!status) {
    dvs_write_junit(out.fp, &e, 1);
    status = dv_io_commit(&out, err);
  }
  dv_io_abort(&out);
  cJSON_Delete(e.report);
  return status;
}
