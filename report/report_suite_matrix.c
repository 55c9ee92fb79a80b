/* report_suite_matrix: the suite's index.html, scenarios down and engines across. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "report_escape.h"
#include "report_suite_internal.h"

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
  fprintf(fp,
          "<p>%zu scenarios, %zu engines: <b class=\"pass\">%d pass</b>, "
          "<b class=\"fail\">%d fail</b>, <b class=\"nj\">%d not judged</b>, "
          "<b class=\"err\">%d harness error%s</b>.</p>\n<ul>\n",
          n, ncols, count[DVS_PASS], count[DVS_FAIL], count[DVS_NOT_JUDGED], count[DVS_ERROR],
          count[DVS_ERROR] == 1 ? "" : "s");
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
        "as value / limit; the body whose reference judged it. Point at a cell for the line that "
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
