/* search_verify_suite: verification of every scenario, and its files. */
#include "search_verify_suite.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "dv_clock.h"
#include "exec_pool.h"
#include "io_file.h"
#include "report_escape.h"
#include "run_meta.h"
#include "run_progress.h"

typedef struct suite_job {
  const dv_scenario *scs; /* loaded once, before any case runs */
  const dv_engine_type *const *engines;
  size_t nengines;
} suite_job;

/* dv_exec_pool's task k: scenario k / nengines in engine k % nengines */
static void verify_task(size_t k, void *result, void *ctx) {
  const suite_job *j = ctx;
  dv_verify_case *c = result;
  dv_error err = {{0}};
  const double t0 = dv_clock_now();
  const dv_engine_type *engine = j->engines[k % j->nengines];
  const dv_engine_type *own[DV_VERIFY_SUITE_MAX_ENGINES + 1];
  const dv_scenario *sc = &j->scs[k / j->nengines];
  c->status = DV_OK;
  int named = 1; /* a scenario that names its engines verifies only those */
  if (sc->engines[0] &&
      !dv_engine_parse_list(sc->engines, own, DV_VERIFY_SUITE_MAX_ENGINES + 1, NULL)) {
    named = 0;
    for (size_t i = 0; own[i]; i++) named |= own[i] == engine;
  }
  if (!named) {
    c->status = DV_EVENT;
    snprintf(err.msg, sizeof err.msg, "the scenario names its engines: %s", sc->engines);
  } else {
    c->status = dv_search_verify(sc, engine->name, &c->v, &err);
  }
  c->wall_s = dv_clock_now() - t0;
  snprintf(c->message, sizeof c->message, "%s", err.msg);
}

int dv_search_verify_suite(const dv_scenario *scs, size_t n, const dv_engine_type *const *engines,
                           size_t nengines, int jobs, double timeout, dv_verify_case *cases,
                           dv_error *err) {
  for (size_t k = 0; k < n * nengines; k++) {
    memset(&cases[k], 0, sizeof cases[k]);
    snprintf(cases[k].scenario, sizeof cases[k].scenario, "%s", scs[k / nengines].name);
    snprintf(cases[k].engine, sizeof cases[k].engine, "%s", engines[k % nengines]->name);
    cases[k].status = DV_ESYSTEM; /* until its task reports */
    snprintf(cases[k].message, sizeof cases[k].message, "not run (its process ended early)");
    for (int i = 0; i < DV_VERIFY_LEVELS; i++) cases[k].v.step[i] = cases[k].v.error[i] = NAN;
    cases[k].v.order = cases[k].v.extrapolated = cases[k].v.uncertainty = NAN;
  }
  const suite_job j = {scs, engines, nengines};
  unsigned char *done = calloc(n * nengines, 1);
  if (!done) return dv_fail(err, DV_ESYSTEM, "out of memory");
  const dv_exec_options opt = {
      .jobs = jobs, .on_result = dv_run_progress_on_result, .done = done, .timeout = timeout};
  dv_run_progress_tasks_begin("verification", n * nengines);
  const int pool = dv_exec_pool(n * nengines, sizeof *cases, verify_task, (void *)&j, cases, &opt);
  dv_run_progress_tasks_end();
  for (size_t k = 0; k < n * nengines; k++) {
    if (done[k] == DV_EXEC_TIMED_OUT) {
      snprintf(cases[k].message, sizeof cases[k].message, "timed out after %g s", timeout);
      cases[k].wall_s = timeout;
    } else if (done[k] != DV_EXEC_ARRIVED && pool == DV_EXEC_INTERRUPTED) {
      snprintf(cases[k].message, sizeof cases[k].message, "not run: interrupted");
    }
  }
  free(done);
  if (pool == DV_EXEC_NOMEM) return dv_fail(err, DV_ESYSTEM, "out of memory");
  if (pool == DV_EXEC_INTERRUPTED) return DV_VERIFY_SUITE_INTERRUPTED;
  return pool == DV_EXEC_WORKER ? DV_VERIFY_SUITE_WORKER : DV_OK;
}

/* the one line that says how a case ended */
static void describe(const dv_verify_case *c, char *text, size_t size) {
  char order[32] = "none (flat)";
  if (!isnan(c->v.order)) snprintf(order, sizeof order, "%.3g", c->v.order);
  if (c->status < 0)
    snprintf(text, size, "error: %s", c->message);
  else if (c->status == DV_EVENT)
    snprintf(text, size, "skipped: %s", c->message);
  else if (c->v.verdict == DV_CONVERGE_NOT_JUDGED) {
    char why[256];
    dv_search_convergence_why(c->v.step, c->v.error, DV_VERIFY_LEVELS, c->v.verdict, why,
                              sizeof why);
    snprintf(text, size, "not judged: %s (errors %.3g .. %.3g rad, order %s)", why, c->v.error[0],
             c->v.error[DV_VERIFY_LEVELS - 1], order);
  } else
    snprintf(text, size,
             "%s: extrapolated discrepancy %.3g rad (floor %g, uncertainty %.2g), order %s%s%s",
             dv_search_convergence_name(c->v.verdict), c->v.extrapolated, DV_VERIFY_FLOOR,
             c->v.uncertainty, order, c->v.cause[0] ? ", cause: " : "", c->v.cause);
}

/* a case that did not fail: converged, or skipped */
static int fine(const dv_verify_case *c) {
  return c->status == DV_EVENT || (c->status == DV_OK && c->v.verdict == DV_CONVERGES);
}

/* verify.md: a row per case */
static int write_md(const char *dir, const dv_verify_case *cases, size_t n, dv_error *err) {
  dv_io_file out;
  int status = dv_io_open_in(&out, dir, "verify.md", err);
  if (status) return status;
  fprintf(out.fp,
          "# Verification: do the engines converge to the reference?\n\n"
          "| scenario | engine | errors at dt, dt/2, dt/4, dt/8 (rad) | verdict |\n"
          "|---|---|---|---|\n");
  for (size_t k = 0; k < n; k++) {
    char text[640];
    describe(&cases[k], text, sizeof text);
    fputs("| ", out.fp); /* the names too: a user's or an adapter's words */
    dv_report_escape_markdown(out.fp, cases[k].scenario);
    fputs(" | ", out.fp);
    dv_report_escape_markdown(out.fp, cases[k].engine);
    fprintf(out.fp, " | %.3g, %.3g, %.3g, %.3g | ", cases[k].v.error[0], cases[k].v.error[1],
            cases[k].v.error[2], cases[k].v.error[3]);
    dv_report_escape_markdown(out.fp, text); /* an engine's error among it: text, not markup */
    fputs(" |\n", out.fp);
  }
  return dv_io_commit(&out, err);
}

/* verify.json: the same as numbers */
static int write_json(const char *dir, const dv_verify_case *cases, size_t n, dv_error *err) {
  cJSON *o = cJSON_CreateObject(), *list = cJSON_AddArrayToObject(o, "cases");
  cJSON_AddNumberToObject(o, "floor", DV_VERIFY_FLOOR);
  for (size_t k = 0; k < n; k++) {
    const dv_verify_case *c = &cases[k];
    cJSON *e = cJSON_CreateObject();
    cJSON_AddStringToObject(e, "scenario", c->scenario);
    cJSON_AddStringToObject(e, "engine", c->engine);
    cJSON_AddStringToObject(e, "verdict",
                            c->status < 0           ? "error"
                            : c->status == DV_EVENT ? "skipped"
                                                    : dv_search_convergence_name(c->v.verdict));
    cJSON_AddStringToObject(e, "detail", c->status != DV_OK ? c->message : c->v.cause);
    cJSON_AddItemToObject(e, "steps", cJSON_CreateDoubleArray(c->v.step, DV_VERIFY_LEVELS));
    cJSON_AddItemToObject(e, "errors", cJSON_CreateDoubleArray(c->v.error, DV_VERIFY_LEVELS));
    cJSON_AddItemToObject(e, "order", dv_io_json_number(c->v.order));
    cJSON_AddItemToObject(e, "extrapolated", dv_io_json_number(c->v.extrapolated));
    cJSON_AddItemToObject(e, "uncertainty", dv_io_json_number(c->v.uncertainty));
    cJSON_AddNumberToObject(e, "wall_s", c->wall_s);
    cJSON_AddItemToArray(list, e);
  }
  return dv_io_json_write(dir, "verify.json", o, err);
}

/* the JUnit XML: a test case per scenario and engine */
static int write_junit(const char *path, const dv_verify_case *cases, size_t n, dv_error *err) {
  dv_io_file out;
  int status = dv_io_open(&out, path, err);
  if (status) return status;
  size_t failures = 0;
  for (size_t k = 0; k < n; k++) failures += !fine(&cases[k]);
  fprintf(out.fp,
          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
          "<testsuite name=\"diskval verify\" tests=\"%zu\" failures=\"%zu\">\n",
          n, failures);
  for (size_t k = 0; k < n; k++) {
    const dv_verify_case *c = &cases[k];
    char text[640];
    describe(c, text, sizeof text);
    dv_report_escape_put(out.fp, "  <testcase classname=\"", c->scenario, 1, "\" name=\"");
    dv_report_escape_put(out.fp, "", c->engine, 1, "\"");
    fprintf(out.fp, " time=\"%.3f\">", c->wall_s);
    if (c->status == DV_EVENT)
      dv_report_escape_put(out.fp, "<skipped message=\"", text, 1, "\"/>");
    else if (!fine(c))
      dv_report_escape_put(out.fp, "<failure message=\"", text, 1, "\"/>");
    else
      dv_report_escape_put(out.fp, "<system-out>", text, 0, "</system-out>");
    fputs("</testcase>\n", out.fp);
  }
  fputs("</testsuite>\n", out.fp);
  return dv_io_commit(&out, err);
}

int dv_search_verify_write(const char *dir, const char *junit, const dv_verify_case *cases,
                           size_t n, dv_error *err) {
  int status = write_md(dir, cases, n, err);
  if (!status) status = write_json(dir, cases, n, err);
  if (!status) status = write_junit(junit, cases, n, err);
  return status;
}
