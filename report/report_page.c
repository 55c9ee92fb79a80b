/* report_page: a scenario's own index.html, read back from its report.json (report_page.h),
 * and what it shares with the suite's matrix (report_suite_internal.h). */
#include "report_page.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "io_file.h"
#include "report_escape.h"
#include "report_suite_internal.h"
#include "run_verdict.h"

#define PATH_CAP 4096

void dvs_put_num(FILE *fp, const char *pre, const cJSON *v, const char *post) {
  if (cJSON_IsNumber(v) && isfinite(v->valuedouble))
    fprintf(fp, "%s%.3g%s", pre, v->valuedouble, post);
  else
    fprintf(fp, "%s&#8211;%s", pre, post);
}

void dvs_put_url(FILE *fp, const char *pre, const char *dir, const char *name, const char *post) {
  char url[PATH_CAP];
  if (dir)
    snprintf(url, sizeof url, "%s/%s", dir, name);
  else
    snprintf(url, sizeof url, "%s", name);
  fputs(pre, fp);
  for (const unsigned char *p = (const unsigned char *)url; *p; p++) {
    const int plain = (*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') ||
                      (*p >= '0' && *p <= '9') || strchr("-._~/", *p);
    fprintf(fp, plain ? "%c" : "%%%02X", *p);
  }
  fputs(post, fp);
}

int dvs_safe_name(const char *s) {
  return s && *s && !strchr(s, '/') && strcmp(s, ".") && strcmp(s, "..");
}

int dvs_file_exists(const char *out_dir, const char *dir, const char *name) {
  char path[PATH_CAP];
  struct stat st;
  if (!dvs_safe_name(name)) return 0;
  if (snprintf(path, sizeof path, "%s/%s/%s", out_dir, dir, name) >= (int)sizeof path) return 0;
  return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

const cJSON *dvs_deciding_limit(const cJSON *eng) {
  const cJSON *name = item(eng, "decided_metric");
  return cJSON_IsString(name) ? item(item(eng, "limits"), name->valuestring) : NULL;
}

dvs_class dvs_class_of(const cJSON *eng) {
  const char *outcome = text(eng, "outcome");
  if (!strcmp(outcome, dv_run_verdict_name(DV_VERDICT_NOT_JUDGED)) ||
      !strcmp(outcome, dv_run_verdict_name(DV_VERDICT_OUTSIDE_VALIDITY)))
    return DVS_NOT_JUDGED;
  return engine_pass(eng) ? DVS_PASS : DVS_FAIL;
}

const char *const dvs_class_names[DVS_NCLASSES] = {
    [DVS_PASS] = "pass", [DVS_FAIL] = "fail", [DVS_NOT_JUDGED] = "not judged",
    [DVS_ERROR] = "error"};

/* the CSS class of each verdict class */
const char *const dvs_class_css[DVS_NCLASSES] = {
    [DVS_PASS] = "pass", [DVS_FAIL] = "fail", [DVS_NOT_JUDGED] = "nj", [DVS_ERROR] = "err"};

void dvs_put_verdict_words(FILE *fp, const cJSON *eng) {
  const dvs_class k = dvs_class_of(eng);
  const cJSON *worst = dvs_deciding_limit(eng);
  const char *outcome = text(eng, "outcome");
  if (worst && (k == DVS_PASS || (k == DVS_FAIL && !strcmp(outcome, "exceeds tolerance")))) {
    fputs(k == DVS_PASS ? "passes" : "fails", fp);
    const cJSON *v = item(worst, "value"), *lim = item(worst, "limit");
    dv_report_escape_put(fp, ": ", worst->string, 0, " ");
    dvs_put_num(fp, "", v, k == DVS_PASS ? " &#8804; " : " &gt; ");
    dvs_put_num(fp, "", lim, "");
  } else {
    fputs(k == DVS_PASS ? "passes: " : k == DVS_FAIL ? "fails: " : "", fp);
    dv_report_escape(fp, *outcome ? outcome : "no outcome", 0);
  }
}


/* the table's rows stay one line (ellipses); the long text goes below it */
static const char css[] =
    "body{font-family:sans-serif;margin:12px;color:#222;font-size:14px;line-height:1.35}"
    "table{border-collapse:collapse;table-layout:fixed;width:100%}"
    "th,td{border:1px solid #bbb;padding:2px 5px;font-size:13px;white-space:nowrap;"
    "overflow:hidden;text-overflow:ellipsis;text-align:left}th{background:#eee}"
    "col.e{width:9em}col.j{width:10em}col.n{width:12.5em}col.c{width:5em}"
    "td.n{font-family:monospace}"
    ".pass{background:#c8f0c8;color:#075207}.fail{background:#f6c4c4;color:#8b0000}"
    ".nj{background:#e2e2e2;color:#444}.err{background:#ffe0a0;color:#7a4200}"
    "h1 span{padding:0 .3em}h3{margin:.8em 0 .2em}p,ul{margin:.3em 0;max-width:62em}"
    "figure{display:inline-block;margin:.4em;vertical-align:top;max-width:48%}"
    "img{max-width:100%;border:1px solid #ddd}";

/* a number with its limit: "0.0012 / 0.01" (an en dash for either one absent);
 * where the shadow excused some of it, the limit as the scene's plus that
 * spread: "0.043 / 0.01 + 0.00011" */
static void put_against(FILE *fp, const cJSON *eng, const char *metric) {
  const cJSON *l = item(item(eng, "limits"), metric);
  const cJSON *v = l ? item(l, "value") : item(eng, metric);
  const cJSON *lim = l ? item(l, "limit") : item(item(eng, "tolerances"), metric);
  const cJSON *spread = l ? item(l, "spread") : NULL;
  dvs_put_num(fp, "<td class=\"n\">", v, " / ");
  if (cJSON_IsNumber(spread) && spread->valuedouble > 0.0 && cJSON_IsNumber(lim) &&
      isfinite(lim->valuedouble))
    fprintf(fp, "%.3g + %.2g</td>", lim->valuedouble - spread->valuedouble, spread->valuedouble);
  else
    dvs_put_num(fp, "", lim, "</td>");
}

/* the line that decided eng's verdict; the verdict's words from its limits
 * for a report written before the line existed */
static void put_decided(FILE *fp, const cJSON *eng) {
  if (*text(eng, "decided"))
    dv_report_escape(fp, text(eng, "decided"), 0);
  else
    dvs_put_verdict_words(fp, eng);
}

/* the table: one row per engine, every text on one line */
static void put_table(FILE *fp, const cJSON *engines) {
  const cJSON *eng;
  fputs("<table>\n<colgroup><col class=\"e\" /><col /><col class=\"j\" />"
        "<col class=\"n\" /><col class=\"n\" /><col class=\"c\" /></colgroup>\n"
        "<thead><tr><th>engine</th><th>verdict: what decided it</th><th>judged against</th>"
        "<th>theta err / limit + spread (rad)</th><th>path err / limit + spread (m)</th>"
        "<th title=\"wall-clock s per simulated s\">cost (s/s)</th></tr></thead>\n<tbody>\n",
        fp);
  cJSON_ArrayForEach(eng, engines) {
    char body[48];
    dvs_judged_words(eng, body, sizeof body);
    dv_report_escape_put(fp, "<tr><td title=\"", eng->string, 1, "\">");
    dv_report_escape_put(fp, "<a href=\"#e-", eng->string, 1, "\">");
    dv_report_escape_put(fp, "", eng->string, 0, "</a></td>");
    dv_report_escape_put(fp, "<td title=\"", text(eng, "decided"), 1, "\" ");
    fprintf(fp, "class=\"%s\">", dvs_class_css[dvs_class_of(eng)]);
    put_decided(fp, eng);
    fputs("</td>", fp);
    dv_report_escape_put(fp, "<td>", body, 0, "</td>");
    put_against(fp, eng, "theta_max_err");
    put_against(fp, eng, "path_max_err");
    dvs_put_num(fp, "<td class=\"n wall\">", item(eng, "wall_per_sim_s"), "</td></tr>\n");
  }
  fputs("</tbody>\n</table>\n", fp);
}

/* pre, s, post as a paragraph, nothing when s is empty */
static void put_para(FILE *fp, const char *pre, const char *s, const char *post) {
  if (*s) dv_report_escape_put(fp, pre, s, 0, post);
}

/* why engine eng's verdict is what it is, in sentences: its "decided_why" when
 * the report has one, else the window, horizon and reference fields */
static void put_why(FILE *fp, const cJSON *eng) {
  dv_report_escape_put(fp, "<h3 id=\"e-", eng->string, 1, "\">");
  dv_report_escape_put(fp, "", eng->string, 0, ": ");
  put_decided(fp, eng);
  fputs("</h3>\n", fp);
  if (*text(eng, "decided_why")) {
    put_para(fp, "<p>", text(eng, "decided_why"), "</p>\n");
  } else {
    const cJSON *frac = item(eng, "window_fraction");
    dvs_put_num(fp, "<p>Compared window: to t = ", item(eng, "window_end"), " s");
    if (cJSON_IsNumber(frac))
      fprintf(fp, " (%.0f%% of the reference's run)", 100 * frac->valuedouble);
    dvs_put_num(fp, "; the pointwise errors to t = ", item(eng, "pointwise_end"), " s.</p>\n");
    put_para(fp, "<p>Horizon: ", text(item(eng, "horizon"), "why"), ".</p>\n");
  }
  put_para(fp, "<p>Reference: ", text(eng, "reference_note"), ".</p>\n");
  const cJSON *event = item(eng, "event");
  if (cJSON_IsFalse(item(event, "agrees")))
    put_para(fp, "<p>Lying down: ", text(event, "why"), ".</p>\n");
  put_para(fp, "<p>Cause of the excess: ", text(eng, "cause"), ".</p>\n");
  put_para(fp, "<p>Settings: ", text(eng, "settings_why"), ".</p>\n");
  put_para(fp, "<p>Ran with ", text(eng, "ran_with"), ".</p>\n");
  put_para(fp, "<p>Outcome: ", text(eng, "detail"), ".</p>\n");
  const cJSON *f;
  int nf = 0;
  cJSON_ArrayForEach(f, item(eng, "failures")) if (cJSON_IsString(f))
      dv_report_escape_put(fp, nf++ ? "<li>" : "<ul>\n<li>", f->valuestring, 0, "</li>\n");
  if (nf) fputs("</ul>\n", fp);
}

/* a link to name beside the page when it exists, separated from the previous one */
static void put_link(FILE *fp, const char *out_dir, const dvs_entry *e, const char *name,
                     int *nlinks) {
  if (!dvs_file_exists(out_dir, e->dir, name)) return;
  dvs_put_url(fp, *nlinks ? " &#183; <a href=\"" : "<a href=\"", NULL, name, "\">");
  dv_report_escape_put(fp, "", name, 0, "</a>");
  ++*nlinks;
}

/* the plots the report lists that exist, then its files */
static void put_plots_and_files(FILE *fp, const char *out_dir, const dvs_entry *e) {
  const cJSON *plot, *eng;
  fputs("<h2>Plots</h2>\n<div>\n", fp);
  cJSON_ArrayForEach(plot, item(e->report, "plots")) {
    if (!cJSON_IsString(plot) || !dvs_file_exists(out_dir, e->dir, plot->valuestring)) continue;
    dvs_put_url(fp, "<figure><img src=\"", NULL, plot->valuestring, "\"");
    dv_report_escape_put(fp, " alt=\"", plot->valuestring, 1, "\" />");
    dv_report_escape_put(fp, "<figcaption>", plot->valuestring, 0, "</figcaption></figure>\n");
  }
  fputs("</div>\n<p>Files: ", fp);
  int nlinks = 0;
  char name[4096];
  put_link(fp, out_dir, e, "report.md", &nlinks);
  put_link(fp, out_dir, e, "report.json", &nlinks);
  put_link(fp, out_dir, e, "reduced.csv", &nlinks);
  cJSON_ArrayForEach(eng, e->engines) {
    snprintf(name, sizeof name, "%s.csv", eng->string);
    put_link(fp, out_dir, e, name, &nlinks);
    snprintf(name, sizeof name, "matched-%s.csv", eng->string);
    put_link(fp, out_dir, e, name, &nlinks);
  }
  fputs(nlinks ? "</p>\n" : "none</p>\n", fp);
}

/* the engines judged against the reference of half-thickness h, as ": a, b" */
static void put_judged_by(FILE *fp, const cJSON *engines, double h) {
  const cJSON *eng;
  int n = 0;
  cJSON_ArrayForEach(eng, engines) {
    const cJSON *hj = item(eng, "reference_half_thickness");
    const double he = cJSON_IsNumber(hj) ? hj->valuedouble : 0.0;
    if (he == h) dv_report_escape_put(fp, n++ ? ", " : "; it judged ", eng->string, 0, "");
  }
  if (!n) fputs("; it judged no engine", fp);
}

/* reference run ref of half-thickness h, how it ended and the engines it judged, as a paragraph */
static void put_reference(FILE *fp, const cJSON *ref, double h, const cJSON *engines) {
  if (h > 0)
    fprintf(fp, "<p>Reference of the cylinder of half-thickness %.3g mm: ", 1e3 * h);
  else
    fputs("<p>Reference of the thin disk: ", fp);
  dv_report_escape_put(fp, "", text(ref, "engine"), 0, " (");
  put_para(fp, "", text(ref, "integrator"), "");
  if (cJSON_IsNumber(item(ref, "rtol"))) dvs_put_num(fp, " rtol ", item(ref, "rtol"), "");
  fputs("), ", fp);
  dv_report_escape_put(fp, "", text(ref, "outcome"), 0, "");
  dvs_put_num(fp, " at t = ", item(ref, "t_end"), " s");
  put_para(fp, ": ", text(ref, "detail"), "");
  put_judged_by(fp, engines, h);
  fputs(".</p>\n", fp);
}

/* each reference and the engines it judged: the thin disk's, then each matched cylinder's */
static void put_references(FILE *fp, const cJSON *ref, const cJSON *engines) {
  put_reference(fp, ref, 0.0, engines);
  double seen[16];
  size_t nseen = 0;
  const cJSON *eng;
  cJSON_ArrayForEach(eng, engines) {
    const cJSON *m = item(eng, "reference"), *hj = item(m, "half_thickness");
    if (!cJSON_IsNumber(hj) || !(hj->valuedouble > 0)) continue; /* the thin disk's */
    size_t k = 0;
    while (k < nseen && seen[k] != hj->valuedouble) k++;
    if (k < nseen || nseen == sizeof seen / sizeof *seen) continue;
    seen[nseen++] = hj->valuedouble;
    put_reference(fp, m, hj->valuedouble, engines);
  }
  put_para(fp, "<p>How the scene amplifies a nudge of its start: ",
           text(item(ref, "amplification"), "words"), ".</p>\n");
}

/* the page of e: the scenario, the table, the reasons, the plots */
static void put_page(FILE *fp, const char *out_dir, const dvs_entry *e) {
  const cJSON *r = e->report, *ref = item(r, "reference"), *eng;
  int pass = !e->error[0] && cJSON_IsTrue(item(r, "pass"));
  cJSON_ArrayForEach(eng, e->engines) pass &= engine_pass(eng);
  const char *verdict = e->error[0] ? "ERROR" : pass ? "PASS" : "FAIL";
  const char *klass = e->error[0] ? "err" : pass ? "pass" : "fail";
  dv_report_escape_put(fp,
                       "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\" />\n"
                       "<title>diskval: ",
                       e->name, 0, "");
  fprintf(fp, ": %s</title>\n<style>%s</style>\n</head>\n<body>\n", verdict, css);
  dv_report_escape_put(fp, "<h1>", e->name, 0, ": ");
  fprintf(fp, "<span class=\"%s\">%s</span></h1>\n", klass, verdict);
  if (e->error[0]) {
    dv_report_escape_put(fp, "<p class=\"err\">The harness did not compare it: ", e->error, 0,
                         "</p>\n");
    put_para(fp, "<p>Scenario file ", text(r, "file"), ".</p>\n");
    fputs("</body>\n</html>\n", fp);
    return;
  }
  put_para(fp, "<p>", text(r, "description"), "</p>\n");
  dv_report_escape_put(fp, "<p>Scenario file ", text(r, "file"), 0, "; ");
  dvs_put_num(fp, "duration ", item(r, "duration"), " s, ");
  dvs_put_num(fp, "output every ", item(r, "output_dt"), " s.</p>\n");
  put_references(fp, ref, e->engines);
  put_table(fp, e->engines);
  fputs("<h2>Why each verdict</h2>\n", fp);
  cJSON_ArrayForEach(eng, e->engines) put_why(fp, eng);
  put_plots_and_files(fp, out_dir, e);
  fputs("</body>\n</html>\n", fp);
}

int dvs_write_page(const char *out_dir, const dvs_entry *e, dv_error *err) {
  dv_io_file out;
  char path[sizeof out.path];
  memset(&out, 0, sizeof out);
  if (dv_io_path(path, sizeof path, err, "%s/%s/index.html", out_dir, e->dir)) return DV_EINPUT;
  int status = dv_io_open(&out, path, err);
  if (!status) {
    put_page(out.fp, out_dir, e);
    status = dv_io_commit(&out, err);
  }
  dv_io_abort(&out);
  return status;
}

int dv_report_page_write(const char *dir, dv_error *err) {
  dvs_entry e;
  memset(&e, 0, sizeof e);
  dvs_load_entry(dir, ".", &e);
  e.dir = ".";
  const int status = dvs_write_page(dir, &e, err);
  cJSON_Delete(e.report);
  return status;
}
