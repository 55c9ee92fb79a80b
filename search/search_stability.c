/* dv_stability: bisection for the largest stable timestep, per scenario and
 * engine, in a pool of processes; the tables as JSON, Markdown and HTML. */
#include "search_stability.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_meta.h"
#include "io_file.h"
#include "exec_pool.h"
#include "search_best.h"

#define DEFAULT_TOL 0.1 /* rad, where a scenario gives no theta tolerance */

typedef struct task {
  const dv_scenario *sc;
  const dv_engine_type *engine;
  double tol;
} task;

/* the scenario's theta_max_err limit for engine, its own first */
static double theta_tolerance(const dv_scenario *sc, const char *engine) {
  const double tol = dv_scenario_tolerance(sc, engine, DV_THETA_MAX_ERR);
  return isinf(tol) ? DEFAULT_TOL : tol;
}

static const char *mode(const dv_search *s) {
  return s->first_failure >= 0 ? dv_search_failure_mode(&s->probes[s->first_failure]) : "none found";
}

static int write_text(const char *dir, const char *name, const char *text, dv_error *err) {
  char path[1200];
  dv_io_file out;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  int status = dv_io_open(&out, path, err);
  if (status) return status;
  fputs(text, out.fp);
  return dv_io_commit(&out, err);
}

static int write_tables(const char *dir, const task *tk, const dv_search *res, size_t n,
                        dv_error *err) {
  cJSON *o = cJSON_CreateArray();
  size_t cap = 4096 + n * 4096;
  char *md = malloc(cap), *html = malloc(2 * cap);
  if (!md || !html)
    return free(md), free(html), cJSON_Delete(o), dv_fail(err, DV_ESYSTEM, "out of memory");
  size_t lm = 0, lh = 0;
  lm += snprintf(md + lm, cap - lm,
                 "# Stability limits\n\nLargest timestep that stays finite and within the theta "
                 "tolerance (bisection; every probe in stability.json).\n\n| scenario | engine | "
                 "tolerance (rad) | largest stable timestep (s) | failure above it | detail |\n"
                 "|---|---|---|---|---|---|\n");
  lh += snprintf(html + lh, 2 * cap - lh,
                 "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\" /><title>"
                 "diskval: stability limits</title><style>body{font-family:sans-serif}"
                 "td,th{border:1px solid #aaa;padding:2px 6px}table{border-collapse:collapse}"
                 "</style></head><body>\n<h1>Stability limits and failure modes</h1>\n<p>Largest "
                 "timestep at which each engine stays finite and within the scenario's theta "
                 "tolerance, found by bisection.</p>\n<table><tr><th>scenario</th><th>engine</th>"
                 "<th>tolerance (rad)</th><th>largest stable timestep (s)</th><th>failure above "
                 "it</th><th>probes</th></tr>\n");
  for (size_t i = 0; i < n; i++) {
    const dv_search *s = &res[i];
    const char *m = mode(s);
    const char *detail = s->first_failure >= 0 ? s->probes[s->first_failure].point.detail : "";
    lm += snprintf(md + lm, cap - lm, "| %s | %s | %g | %.3g | %s | %.120s |\n", tk[i].sc->name,
                   tk[i].engine->name, s->tolerance, s->limit, m, detail);
    lh +=
        snprintf(html + lh, 2 * cap - lh,
                 "<tr><td>%s</td><td>%s</td><td>%g</td><td>%.3g</td><td>%s</td><td>%zu</td></tr>\n",
                 tk[i].sc->name, tk[i].engine->name, s->tolerance, s->limit, m, s->nprobes);
    cJSON *e = cJSON_CreateObject();
    cJSON_AddStringToObject(e, "scenario", tk[i].sc->name);
    cJSON_AddStringToObject(e, "engine", tk[i].engine->name);
    cJSON_AddNumberToObject(e, "tolerance", s->tolerance);
    cJSON_AddItemToObject(e, "largest_stable_timestep", dv_io_json_number(s->limit));
    cJSON_AddStringToObject(e, "failure_mode", m);
    cJSON *probes = cJSON_AddArrayToObject(e, "probes");
    for (size_t k = 0; k < s->nprobes; k++) {
      const dv_probe *p = &s->probes[k];
      cJSON *q = cJSON_CreateObject();
      cJSON_AddNumberToObject(q, "timestep", p->step);
      cJSON_AddItemToObject(q, "theta_max_err", dv_io_json_number(p->point.metric[DV_THETA_MAX_ERR]));
      cJSON_AddStringToObject(q, "outcome", dv_run_verdict_name(p->point.verdict));
      cJSON_AddStringToObject(q, "failure_mode", dv_search_failure_mode(p));
      cJSON_AddStringToObject(q, "detail", p->point.detail);
      cJSON_AddBoolToObject(q, "pass", p->pass);
      cJSON_AddItemToArray(probes, q);
    }
    cJSON_AddItemToArray(o, e);
  }
  lh += snprintf(html + lh, 2 * cap - lh, "</table>\n</body></html>\n");
  char *json = cJSON_Print(o);
  cJSON_Delete(o);
  int status = json ? write_text(dir, "stability.json", json, err) : DV_ESYSTEM;
  if (!status) status = write_text(dir, "stability.md", md, err);
  if (!status) status = write_text(dir, "stability.html", html, err);
  free(json);
  free(md);
  free(html);
  return status;
}

typedef struct search_ctx {
  const task *tk;
  const char *const *sets;
  size_t nsets;
} search_ctx;

/* dv_pool's task: one scenario and engine */
static void search_task(size_t k, void *result, void *ctx) {
  const search_ctx *c = ctx;
  dv_search_stability(c->tk[k].sc->path, c->sets, c->nsets, c->tk[k].engine->name, c->tk[k].tol,
                      result, NULL);
}

int dv_search_stability_run(const dv_scenario *scs, size_t n, const dv_engine_type *const *engines,
                     const char *const *sets, size_t nsets, const char *out_dir, int jobs,
                     dv_error *err) {
  size_t ne = 0, nt = 0;
  while (engines[ne]) ne++;
  task *tk = calloc(n * ne + 1, sizeof *tk);
  if (!tk) return dv_fail(err, DV_ESYSTEM, "out of memory");
  for (size_t i = 0; i < n; i++)
    for (size_t k = 0; k < ne; k++)
      if (engines[k]->role == DV_ENGINE_CONTACT)
        tk[nt++] = (task){&scs[i], engines[k], theta_tolerance(&scs[i], engines[k]->name)};
  dv_search *res = calloc(nt + 1, sizeof *res);
  if (!res) return free(tk), dv_fail(err, DV_ESYSTEM, "out of memory");
  search_ctx sc = {tk, sets, nsets};
  const int pool = dv_exec_pool_run(nt, sizeof *res, search_task, &sc, res, jobs, NULL);
  if (pool == 1) return free(res), free(tk), DV_OK; /* a worker rank */
  const int status = write_tables(out_dir, tk, res, nt, err);
  free(res);
  free(tk);
  return status;
}
