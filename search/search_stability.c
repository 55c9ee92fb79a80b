/* dv_stability: bisection for the largest stable timestep, per scenario and
 * engine, in a pool of processes; the tables as JSON, Markdown and HTML. */
#include "search_stability.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_meta.h"
#include "run_progress.h"
#include "io_file.h"
#include "exec_pool.h"
#include "report_escape.h"
#include "search_best.h"

#define DEFAULT_TOL 0.1 /* rad, where a scenario gives no theta tolerance */

typedef struct task {
  const dv_scenario *sc;
  const dv_engine_type *engine;
  double tol;
} task;

/* the scenario's theta_max_err limit for engine, its own first */
static double theta_tolerance(const dv_scenario *sc, const char *engine) {
  const double tol = dv_scenario_tolerance(sc, engine, DV_THETA_MAX_ERR, NULL);
  return isinf(tol) ? DEFAULT_TOL : tol;
}

/* the failure just above the limit */
static const char *mode(const dv_search *s) {
  if (!s->nprobes) return "not run";
  return s->first_failure >= 0 ? dv_search_failure_mode(&s->probes[s->first_failure])
                               : "none found";
}

/* the detail of that failure, "" when there is none */
static const char *detail(const dv_search *s) {
  return s->first_failure >= 0 ? s->probes[s->first_failure].point.detail : "";
}

/* stability.json: every row with every probe */
static int write_json(const char *dir, const dv_stability_row *rows, size_t n, dv_error *err) {
  cJSON *o = cJSON_CreateArray();
  for (size_t i = 0; i < n; i++) {
    const dv_search *s = rows[i].search;
    cJSON *e = cJSON_CreateObject();
    cJSON_AddStringToObject(e, "scenario", rows[i].scenario);
    cJSON_AddStringToObject(e, "engine", rows[i].engine);
    cJSON_AddNumberToObject(e, "tolerance", s->tolerance);
    cJSON_AddItemToObject(e, "largest_stable_timestep", dv_io_json_number(s->limit));
    cJSON_AddStringToObject(e, "failure_mode", mode(s));
    cJSON *probes = cJSON_AddArrayToObject(e, "probes");
    for (size_t k = 0; k < s->nprobes; k++) {
      const dv_probe *p = &s->probes[k];
      cJSON *q = cJSON_CreateObject();
      cJSON_AddNumberToObject(q, "timestep", p->step);
      cJSON_AddItemToObject(q, "theta_max_err",
                            dv_io_json_number(p->point.metric[DV_THETA_MAX_ERR]));
      cJSON_AddStringToObject(q, "outcome", dv_run_verdict_name(p->point.verdict));
      cJSON_AddStringToObject(q, "failure_mode", dv_search_failure_mode(p));
      cJSON_AddStringToObject(q, "detail", p->point.detail);
      cJSON_AddBoolToObject(q, "pass", p->pass);
      cJSON_AddItemToArray(probes, q);
    }
    cJSON_AddItemToArray(o, e);
  }
  return dv_io_json_write(dir, "stability.json", o, err);
}

/* the columns both tables begin with; then the Markdown's detail, the page's probes */
static const char *const columns[] = {"scenario", "engine", "tolerance (rad)",
                                      "largest stable timestep (s)", "failure above it"};
enum { NCOLUMNS = sizeof columns / sizeof *columns };

/* stability.md: a table row per scenario and engine */
static void write_markdown(FILE *fp, const dv_stability_row *rows, size_t n) {
  fputs(
      "# Stability limits\n\nLargest timestep that stays finite and within the theta "
      "tolerance (bisection; every probe in stability.json).\n\n|",
      fp);
  for (int k = 0; k < NCOLUMNS; k++) fprintf(fp, " %s |", columns[k]);
  fputs(" detail |\n|", fp);
  for (int k = 0; k <= NCOLUMNS; k++) fputs("---|", fp);
  fputc('\n', fp);
  for (size_t i = 0; i < n; i++) {
    const dv_search *s = rows[i].search;
    char cut[121]; /* the engine's words: the first 120 bytes, as text (never markup) */
    snprintf(cut, sizeof cut, "%s", detail(s));
    fputs("| ", fp); /* the names too: a user's or an adapter's words */
    dv_report_escape_markdown(fp, rows[i].scenario);
    fputs(" | ", fp);
    dv_report_escape_markdown(fp, rows[i].engine);
    fprintf(fp, " | %g | %.3g | %s | ", s->tolerance, s->limit, mode(s));
    dv_report_escape_markdown(fp, cut);
    fputs(" |\n", fp);
  }
}

/* stability.html: the same table, every text escaped */
static void write_html(FILE *fp, const dv_stability_row *rows, size_t n) {
  fputs(
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\" /><title>"
      "diskval: stability limits</title><style>body{font-family:sans-serif}"
      "td,th{border:1px solid #aaa;padding:2px 6px}table{border-collapse:collapse}"
      "</style></head><body>\n<h1>Stability limits and failure modes</h1>\n<p>Largest "
      "timestep at which each engine stays finite and within the scenario's theta "
      "tolerance, found by bisection.</p>\n<table><tr>",
      fp);
  for (int k = 0; k < NCOLUMNS; k++) fprintf(fp, "<th>%s</th>", columns[k]);
  fputs("<th>probes</th></tr>\n", fp);
  for (size_t i = 0; i < n; i++) {
    const dv_search *s = rows[i].search;
    dv_report_escape_put(fp, "<tr><td>", rows[i].scenario, 0, "</td>");
    dv_report_escape_put(fp, "<td>", rows[i].engine, 0, "</td>");
    fprintf(fp, "<td>%g</td><td>%.3g</td>", s->tolerance, s->limit);
    dv_report_escape_put(fp, "<td>", mode(s), 0, "</td>");
    fprintf(fp, "<td>%zu</td></tr>\n", s->nprobes);
  }
  fputs("</table>\n</body></html>\n", fp);
}

int dv_search_stability_write(const char *dir, const dv_stability_row *rows, size_t n,
                              dv_error *err) {
  dv_io_file md, html;
  memset(&html, 0, sizeof html);
  int status = write_json(dir, rows, n, err);
  if (!status) status = dv_io_open_in(&md, dir, "stability.md", err);
  if (status) return status;
  status = dv_io_open_in(&html, dir, "stability.html", err);
  if (!status) {
    write_markdown(md.fp, rows, n);
    write_html(html.fp, rows, n);
    status = dv_io_commit(&md, err);
  }
  if (!status) status = dv_io_commit(&html, err);
  dv_io_abort(&md);
  dv_io_abort(&html);
  return status;
}

typedef struct search_ctx {
  const task *tk;
} search_ctx;

/* dv_pool's task: one scenario and engine */
static void search_task(size_t k, void *result, void *ctx) {
  const search_ctx *c = ctx;
  dv_search_stability(c->tk[k].sc, c->tk[k].engine->name, c->tk[k].tol, result, NULL);
}

int dv_search_stability_run(const dv_scenario *scs, size_t n, const dv_engine_type *const *engines,
                            const char *out_dir, int jobs, dv_error *err) {
  size_t ne = 0, nt = 0;
  while (engines[ne]) ne++;
  task *tk = calloc(n * ne + 1, sizeof *tk);
  dv_search *res = calloc(n * ne + 1, sizeof *res);
  dv_stability_row *rows = calloc(n * ne + 1, sizeof *rows);
  int status = tk && res && rows ? DV_OK : dv_fail(err, DV_ESYSTEM, "out of memory");
  for (size_t i = 0; !status && i < n; i++)
    for (size_t k = 0; k < ne; k++)
      if (engines[k]->role == DV_ENGINE_CONTACT) {
        tk[nt] = (task){&scs[i], engines[k], theta_tolerance(&scs[i], engines[k]->name)};
        res[nt] = (dv_search){.tolerance = tk[nt].tol,
                              .best = -1,
                              .limit = NAN,
                              .first_failure = -1}; /* as a search that never ran */
        rows[nt] = (dv_stability_row){scs[i].name, engines[k]->name, &res[nt]};
        nt++;
      }
  search_ctx sc = {tk};
  dv_run_progress_tasks_begin("stability search", nt);
  const int pool = status ? DV_EXEC_DONE
                          : dv_exec_pool_run(nt, sizeof *res, search_task, &sc, res, jobs,
                                             dv_run_progress_on_result);
  dv_run_progress_tasks_end();
  if (pool == DV_EXEC_NOMEM) status = dv_fail(err, DV_ESYSTEM, "out of memory");
  if (!status && pool != DV_EXEC_WORKER) /* a worker rank: rank 0 writes */
    status = dv_search_stability_write(out_dir, rows, nt, err);
  if (!status && pool == DV_EXEC_INTERRUPTED) /* written all the same: what ended */
    status = dv_fail(err, DV_EVENT, "interrupted: the searches that did not end have no limit");
  free(rows);
  free(res);
  free(tk);
  return status;
}
