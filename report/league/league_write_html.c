/* dv_league_write_html: league.html, the matrix at a glance.
 *
 * Per target a table, objects down, engines across; each cell coloured by its
 * outcome (reached green, not reached red, cannot model and not run grey),
 * with its cost and settings in a few characters, what stops it on hover and
 * in a short line, and a link to the report that backs it. Then each engine's
 * summary, the figures, and the machine, date and versions. One file: inline
 * CSS, no script, nothing fetched; fixed-layout tables that wrap their text,
 * so ten engines fit a 1366 px window without scrolling sideways. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io_file.h"
#include "league.h"
#include "league_words.h"
#include "report_escape.h"

static const char css[] =
    "body{font-family:sans-serif;font-size:13px;margin:1em;color:#222}"
    "table{border-collapse:collapse;table-layout:fixed;width:100%;margin-bottom:1em}"
    "th,td{border:1px solid #bbb;padding:2px 3px;vertical-align:top;overflow-wrap:anywhere}"
    "th{background:#eee;font-size:12px}td{font-size:12px;line-height:1.25}"
    "th.o{width:11em;text-align:left}td a{color:inherit;text-decoration:none;display:block}"
    "td a:hover{text-decoration:underline}td small,th small{display:block;font-size:10.5px;"
    "font-weight:normal;color:#444}"
    ".ok{background:#c8f0c8;color:#075207}.no{background:#f6c4c4;color:#8b0000}"
    ".na{background:#e4e4e4;color:#555}b{font-weight:bold}p.w{max-width:70em}";

/* a path relative to the page as an href: bytes other than unreserved ones and
 * '/' percent-encoded */
static void put_href(FILE *fp, const char *path, const char *suffix) {
  static const char hex[] = "0123456789ABCDEF";
  fputs(" href=\"", fp);
  for (const unsigned char *p = (const unsigned char *)path; *p; p++) {
    if ((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
        strchr("-._~/", *p))
      fputc(*p, fp);
    else
      fprintf(fp, "%%%c%c", hex[*p >> 4], hex[*p & 15]);
  }
  fprintf(fp, "%s\"", suffix);
}

static const char *outcome_class(dv_league_outcome o) {
  return o == DV_LEAGUE_REACHED ? "ok" : o == DV_LEAGUE_NOT_REACHED ? "no" : "na";
}

/* the hover text of a cell: what stops it, its cause, its numbers */
static void cell_title(const dv_league_cell *c, char *buf, size_t size) {
  char theta[32], path[32], t[32], pt[32], order[32];
  dv_league_short_number(c->theta_max_err, 2, theta, sizeof theta);
  dv_league_short_number(c->path_max_err, 2, path, sizeof path);
  dv_league_short_number(c->target, 2, t, sizeof t);
  dv_league_short_number(c->path_target, 2, pt, sizeof pt);
  dv_league_short_number(c->order, 2, order, sizeof order);
  int n = snprintf(buf, size, "%s%s%s%s%s", dv_league_outcome_name(c->outcome),
                   c->why[0] ? ": " : "", c->why, c->cause[0] ? "; cause: " : "", c->cause);
  if (dv_league_cell_was_run(c) && n >= 0 && (size_t)n < size)
    snprintf(buf + n, size - (size_t)n,
             "; theta error %s rad (target %s), path error %s m (target %s), order %s, %s", theta,
             t, path, pt, order, c->verdict);
}

static void put_cell(FILE *fp, const dv_league_cell *c) {
  char cost[32], words[160], why[64], title[1024];
  if (!c) {
    fputs("<td class=\"na\"></td>", fp);
    return;
  }
  cell_title(c, title, sizeof title);
  fprintf(fp, "<td class=\"%s\"", outcome_class(c->outcome));
  dv_report_escape_put(fp, " title=\"", title, 1, "\">");
  const int link = dv_league_cell_was_run(c) && c->report[0];
  if (link) {
    fputs("<a", fp);
    put_href(fp, c->report, "/report.md");
    fputc('>', fp);
  }
  if (dv_league_cell_was_run(c)) {
    dv_league_short_number(c->wall_per_sim_s, 3, cost, sizeof cost);
    dv_league_settings_words(c, words, sizeof words);
    fprintf(fp, "<b>%s</b> s/s", isnan(c->wall_per_sim_s) ? "&#8212;" : cost);
    dv_report_escape_put(fp, "<br />", words, 0, "");
  } else {
    fprintf(fp, "%s", dv_league_outcome_name(c->outcome));
  }
  if (c->outcome != DV_LEAGUE_REACHED && c->why[0]) {
    dv_league_short_why(c, why, sizeof why);
    dv_report_escape_put(fp, "<small>", why, 0, "</small>");
  }
  fputs(link ? "</a></td>" : "</td>", fp);
}

/* the head row: object, then the engines' names (their versions on hover) */
static void put_head(FILE *fp, const dv_league *lg, const char *first) {
  fprintf(fp, "<tr><th class=\"o\">%s</th>", first);
  for (size_t e = 0; e < lg->nengines; e++) {
    if (!lg->engines[e].available) continue;
    dv_report_escape_put(fp, "<th title=\"", lg->engines[e].version, 1, "\">");
    dv_report_escape_put(fp, "", lg->engines[e].name, 0, "</th>");
  }
  fputs("</tr>\n", fp);
}

static void put_matrix(FILE *fp, const dv_league *lg, double t) {
  char target[32];
  dv_league_short_number(t, 3, target, sizeof target);
  fprintf(fp, "<h2>&#952; within %s rad</h2>\n<table>\n", target);
  put_head(fp, lg, "object");
  for (size_t o = 0; o < lg->nobjects; o++) {
    const dv_league_object *ob = &lg->objects[o];
    dv_report_escape_put(fp, "<tr><th class=\"o\" title=\"", ob->description, 1, "\">");
    dv_report_escape_put(fp, "", ob->name, 0, "</th>");
    for (size_t e = 0; e < lg->nengines; e++)
      if (lg->engines[e].available)
        put_cell(fp, dv_league_cell_of(lg, ob->name, lg->engines[e].name, t));
    fputs("</tr>\n", fp);
  }
  fputs("</table>\n", fp);
}

/* engine's standing at t: "4/5 reached, 0.0225 s/s", the objects it misses */
static void put_standing(FILE *fp, const dv_league *lg, const char *engine, double t) {
  dv_league_summary s;
  char cost[32];
  dv_league_summarize(lg, engine, t, &s);
  dv_league_short_number(s.geomean_wall_per_sim_s, 3, cost, sizeof cost);
  const char *cls = s.not_reached ? "no" : s.reached ? "ok" : "na";
  fprintf(fp, "<td class=\"%s\"><b>%zu/%zu</b> reached", cls, s.reached, s.reached + s.not_reached);
  if (s.reached) fprintf(fp, ", %s s/s", cost);
  const char *sep = "<small>not: ";
  for (int cannot = 0; cannot <= 1; cannot++)
    for (size_t o = 0; o < lg->nobjects; o++) {
      const dv_league_cell *c = dv_league_cell_of(lg, lg->objects[o].name, engine, t);
      if (!c || c->outcome != (cannot ? DV_LEAGUE_CANNOT_MODEL : DV_LEAGUE_NOT_REACHED)) continue;
      dv_report_escape_put(fp, sep, c->object, 0, cannot ? " (cannot model)" : "");
      sep = ", ";
    }
  fputs(*sep == ',' ? "</small></td>" : "</td>", fp);
}

static void put_summary(FILE *fp, const dv_league *lg) {
  fputs(
      "<h2>Per engine</h2>\n<p>Reached of the objects run, the geometric mean of the cost "
      "(s of wall per simulated s) over those reached, and the objects not reached.</p>\n"
      "<table>\n<tr><th class=\"o\">engine</th>",
      fp);
  for (size_t t = 0; t < lg->ntargets; t++) {
    char target[32];
    dv_league_short_number(lg->targets[t], 3, target, sizeof target);
    fprintf(fp, "<th>&#952; within %s rad</th>", target);
  }
  fputs("</tr>\n", fp);
  for (size_t e = 0; e < lg->nengines; e++) {
    const dv_league_engine *en = &lg->engines[e];
    dv_report_escape_put(fp, "<tr><th class=\"o\">", en->name, 0, "");
    dv_report_escape_put(fp, "<small>", en->available ? en->version : en->why, 0, "</small></th>");
    for (size_t t = 0; t < lg->ntargets; t++) {
      if (en->available)
        put_standing(fp, lg, en->name, lg->targets[t]);
      else
        fputs("<td class=\"na\">not available</td>", fp);
    }
    fputs("</tr>\n", fp);
  }
  fputs("</table>\n", fp);
}

static void put_figures(FILE *fp, const dv_league *lg) {
  char file[160];
  fputs(
      "<p>Figures: <a href=\"overview.svg\">overview</a> (every reached cell, error against "
      "cost); work against precision:",
      fp);
  for (size_t o = 0; o < lg->nobjects; o++) {
    dv_league_figure_file(lg->objects[o].name, file, sizeof file);
    fputs(o ? ", <a" : " <a", fp);
    put_href(fp, file, "");
    dv_report_escape_put(fp, ">", lg->objects[o].name, 0, "</a>");
  }
  fputs(".</p>\n", fp);
}

static void put_provenance(FILE *fp, const dv_league *lg) {
  char cap[32];
  dv_league_short_number(lg->cost_cap, 3, cap, sizeof cap);
  dv_report_escape_put(fp, "<p class=\"w\">Machine: ", lg->machine, 0, ". ");
  dv_report_escape_put(fp, "Date: ", lg->date, 0, ". ");
  dv_report_escape_put(fp, "diskval ", lg->diskval_version, 0, ". Engines: ");
  for (size_t e = 0; e < lg->nengines; e++) {
    const dv_league_engine *en = &lg->engines[e];
    dv_report_escape_put(fp, e ? "; " : "", en->name, 0, " ");
    dv_report_escape(fp, en->available ? en->version : "not available", 0);
  }
  fprintf(fp,
          ". Cost cap: %s s per simulated s.</p>\n<p class=\"w\">A cell's settings are the "
          "cheapest that best's search finds meeting both its &#952; target and the matching "
          "path target (the scene's path limit scaled as its &#952; limit is); its numbers come "
          "from a compare at those settings with the targets as its limits: the report it links "
          "to, which re-running reproduces.</p>\n",
          cap);
  if (lg->interrupted)
    fputs(
        "<p class=\"w\"><b>The league was interrupted</b>: the cells marked not run are "
        "missing.</p>\n",
        fp);
}

int dv_league_write_html(const char *dir, const dv_league *lg, dv_error *err) {
  dv_io_file out;
  const int status = dv_io_open_in(&out, dir, "league.html", err);
  if (status) return status;
  FILE *fp = out.fp;
  fprintf(fp,
          "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\" />\n"
          "<meta name=\"viewport\" content=\"width=device-width\" />\n"
          "<title>diskval league</title>\n<style>%s</style>\n</head>\n<body>\n"
          "<h1>diskval league: every engine on the same objects</h1>\n"
          "<p class=\"w\">Each cell: the cheapest settings found that keep the &#952; error "
          "and the contact path's error within the targets (the path's: the scene's path limit scaled as "
          "its &#952; limit is), "
          "their cost in s of wall per simulated s; "
          "<span class=\"ok\">reached</span>, <span class=\"no\">not reached</span> (the closest "
          "settings, and what stops them), <span class=\"na\">cannot model or not run</span>. "
          "A cell links to the report that backs it; hover for its numbers.</p>\n",
          css);
  for (size_t t = 0; t < lg->ntargets; t++) put_matrix(fp, lg, lg->targets[t]);
  put_summary(fp, lg);
  put_figures(fp, lg);
  put_provenance(fp, lg);
  fputs("</body>\n</html>\n", fp);
  return dv_io_commit(&out, err);
}
