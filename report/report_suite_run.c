/* dv_suite: report directories built aside and renamed; the scenarios in the exec pool. */
#include "report_suite_run.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "exec_pool.h"
#include "io_temp.h"
#include "report_scenario.h"
#include "report_suite_dir.h"
#include "run_parallel.h"
#include "run_progress.h"
#include "run_scenario.h"

/* what a failing engine's cause task hands back */
typedef struct cause_result {
  int said; /* 0: the cause explain gave, < 0: none (nor its process's end) */
  char cause[sizeof(((dv_engine_result *)0)->cause)];
} cause_result;

/* the failing engines of a comparison, their causes searched in the pool */
typedef struct cause_job {
  const dv_scenario *sc;
  const dv_report_explain *explain;
  const dv_comparison *c;
  size_t which[DV_MAX_ENGINES]; /* the failing engines' indices in c */
} cause_job;

/* dv_exec_pool's task: the cause of the k-th failing engine */
static void cause_task(size_t k, void *result, void *ctx) {
  const cause_job *j = ctx;
  cause_result *r = result;
  const dv_engine_result *e = &j->c->r[j->which[k]];
  r->said = j->explain->cause(j->explain->ctx, j->sc, j->c, e, r->cause, sizeof r->cause);
}

/* the cause of each engine's excess, added to its failures: each searched in
 * its own process, up to jobs at a time (one that dies: its cause unknown) */
static int explain_failures(const dv_scenario *sc, const dv_report_explain *explain, int jobs,
                            dv_comparison *c, dv_error *err) {
  cause_job j = {sc, explain, c, {0}};
  size_t n = 0;
  for (size_t i = 0; explain && i < c->n; i++)
    if (c->r[i].verdict == DV_VERDICT_EXCEEDS) j.which[n++] = i;
  if (!n) return DV_OK;
  cause_result results[DV_MAX_ENGINES];
  unsigned char done[DV_MAX_ENGINES];
  for (size_t k = 0; k < n; k++) {
    results[k].said = 0;
    snprintf(results[k].cause, sizeof results[k].cause,
             "unknown (its search's process ended without a result: crashed or killed)");
  }
  /* one job (a suite's scenario): here, so that a stop reaches the suite's pool alone */
  if (jobs <= 1)
    for (size_t k = 0; k < n; k++) cause_task(k, &results[k], &j), done[k] = DV_EXEC_ARRIVED;
  const dv_exec_options opt = {.jobs = jobs, .done = done, .local = 1};
  const int pool =
      jobs <= 1 ? DV_EXEC_DONE : dv_exec_pool(n, sizeof *results, cause_task, &j, results, &opt);
  if (pool == DV_EXEC_NOMEM) return dv_fail(err, DV_ESYSTEM, "out of memory");
  if (pool == DV_EXEC_INTERRUPTED) /* die of it, as in one process (temporaries removed) */
    return raise(dv_exec_stopped_by()),
           dv_fail(err, DV_EVENT, "interrupted (signal %d)", dv_exec_stopped_by());
  for (size_t k = 0; k < n; k++) {
    dv_engine_result *r = &c->r[j.which[k]];
    if (results[k].said) continue;
    snprintf(r->cause, sizeof r->cause, "%s", results[k].cause);
    for (size_t f = 0; f < r->nfailures; f++) {
      const size_t len = strlen(r->failures[f]);
      snprintf(r->failures[f] + len, sizeof r->failures[f] - len, "; cause: %s", r->cause);
    }
  }
  return DV_OK;
}

/* compare sc into a new directory tmp, in up to jobs processes; its dv_suite_result */
static int compare_into(const char *tmp, const dv_scenario *sc,
                        const dv_engine_type *const *engines, int verbose,
                        const dv_report_explain *explain, int jobs, dv_error *err) {
  size_t n = 0;
  while (engines[n]) n++;
  dv_comparison *c = calloc(1, sizeof *c);
  if (!c) return dv_fail(err, DV_ESYSTEM, "out of memory"), DV_SUITE_ERROR;
  int status = dv_run_scenario_jobs(sc, NULL, engines, n, NULL, jobs, c, err);
  if (!status) status = explain_failures(sc, explain, jobs, c, err);
  if (!status) status = dv_report_scenario_write(tmp, c, err);
  if (!status && verbose) dv_report_scenario_print(stdout, c);
  const int pass = c->pass;
  dv_run_comparison_free(c);
  free(c);
  return status ? DV_SUITE_ERROR : pass ? DV_SUITE_PASS : DV_SUITE_FAIL;
}

int dv_report_suite_run_one(const dv_scenario *sc, const dv_engine_type *const *engines,
                            const char *out_dir, int verbose, const dv_report_explain *explain,
                            int jobs, dv_error *err) {
  char tmp[1300];
  const dv_engine_type *own[DV_MAX_ENGINES + 1];
  int code = DV_SUITE_ERROR;
  /* a scenario may name its own engines */
  if (sc->engines[0] && dv_engine_parse_list(sc->engines, own, DV_MAX_ENGINES + 1, err)) {
  } else if (!dv_report_dir_begin(tmp, sizeof tmp, out_dir, sc->name, err)) {
    code = compare_into(tmp, sc, sc->engines[0] ? own : engines, verbose, explain, jobs, err);
    if (code == DV_SUITE_ERROR)
      dv_report_dir_discard(tmp);
    else if (dv_report_dir_install(tmp, out_dir, sc->name, err))
      code = DV_SUITE_ERROR;
  }
  dv_error ignored;
  if (code == DV_SUITE_ERROR) dv_report_dir_write_error(out_dir, sc, err->msg, &ignored);
  return code;
}

/* what a scenario's task hands back */
typedef struct task_result {
  int code;       /* its dv_suite_result */
  dv_error cause; /* why, for DV_SUITE_ERROR */
} task_result;

/* a suite run: what its tasks share, and its progress */
typedef struct suite_run {
  const dv_scenario *scs;
  size_t n;
  const dv_engine_type *const *engines;
  const char *out_dir;
  const dv_report_explain *explain;
  const task_result *results; /* each scenario's once it has ended */
} suite_run;

/* dv_exec_pool's task: scenario k into its report directory; its dv_suite_result */
static void run_task(size_t k, void *result, void *ctx) {
  const suite_run *s = ctx;
  task_result *r = result;
  /* a scenario's own runs one at a time: the suite runs scenarios side by side */
  r->code =
      dv_report_suite_run_one(&s->scs[k], s->engines, s->out_dir, 0, s->explain, 1, &r->cause);
}

/* how the progress line shows a dv_suite_result */
static const char *const verdicts[] = {
    [DV_SUITE_PASS] = "pass", [DV_SUITE_FAIL] = "FAIL", [DV_SUITE_ERROR] = "ERROR"};

/* after each scenario: the progress line says which ended, and how */
static void progress(size_t k, int ran, void *ctx) {
  const suite_run *s = ctx;
  char note[96];
  snprintf(note, sizeof note, "%.60s: %s", s->scs[k].name,
           verdicts[ran ? s->results[k].code : DV_SUITE_ERROR]);
  dv_run_progress_task_ended(note);
}

/* what the pool leaves for a scenario without a result: an error and its cause */
static void lost(const dv_scenario *sc, const char *out_dir, unsigned char done, double timeout,
                 task_result *r) {
  r->code = DV_SUITE_ERROR;
  if (done == DV_EXEC_TIMED_OUT)
    dv_fail(&r->cause, DV_ESYSTEM, "timed out after %g s", timeout);
  else
    dv_fail(&r->cause, DV_ESYSTEM, "its process ended without a result (crashed or killed)");
  dv_error ignored;
  dv_report_dir_write_error(out_dir, sc, r->cause.msg, &ignored);
}

int dv_report_suite_run_all(const dv_scenario *scs, size_t n, const dv_engine_type *const *engines,
                            const char *out_dir, int jobs, double timeout,
                            const dv_report_explain *explain, int *codes, dv_error *causes,
                            dv_error *err) {
  task_result *results = calloc(n ? n : 1, sizeof *results);
  unsigned char *done = calloc(n ? n : 1, 1);
  if (!results || !done)
    return free(results), free(done), dv_fail(err, DV_ESYSTEM, "out of memory");
  for (size_t i = 0; i < n; i++) results[i].code = DV_SUITE_ERROR; /* a scenario that never ends */
  suite_run s = {scs, n, engines, out_dir, explain, results};
  const dv_exec_options opt = {
      .jobs = jobs, .on_result = progress, .done = done, .timeout = timeout};
  /* left by runs that died here; by rank 0 only, before any task starts (a
   * pid means nothing on another host) */
  if (dv_exec_mpi_rank() == 0) dv_io_temp_remove_stale(out_dir);
  dv_run_progress_tasks_begin("scenario", n);
  const int pool = dv_exec_pool(n, sizeof *results, run_task, &s, results, &opt);
  dv_run_progress_tasks_end();
  int status = DV_OK;
  size_t finished = 0;
  if (pool == DV_EXEC_NOMEM) status = dv_fail(err, DV_ESYSTEM, "out of memory");
  if (pool == DV_EXEC_WORKER) status = DV_SUITE_RUN_WORKER;
  for (size_t i = 0; pool == DV_EXEC_DONE && i < n; i++) {
    if (done[i] != DV_EXEC_ARRIVED) lost(&scs[i], out_dir, done[i], timeout, &results[i]);
    if (results[i].code == DV_SUITE_ERROR)
      fprintf(stderr, "diskval suite: %s: %s\n", scs[i].name, results[i].cause.msg);
  }
  for (size_t i = 0; i < n; i++) {
    codes[i] = done[i] == DV_EXEC_ARRIVED || pool == DV_EXEC_DONE ? results[i].code
               : pool == DV_EXEC_INTERRUPTED                      ? DV_SUITE_NOT_ENDED
                                                                  : DV_SUITE_ERROR;
    causes[i] = results[i].cause;
    if (codes[i] == DV_SUITE_NOT_ENDED) {
      dv_fail(&causes[i], DV_EVENT, "did not end: the suite was interrupted");
      /* not an earlier run's report beside this run's summary (it may say pass) */
      dv_error ignored;
      dv_report_dir_write_error(out_dir, &scs[i], causes[i].msg, &ignored);
    }
    finished += done[i] == DV_EXEC_ARRIVED && codes[i] != DV_SUITE_ERROR;
  }
  /* the temporaries of the scenarios stopped or killed at their time limit */
  if ((pool == DV_EXEC_DONE || pool == DV_EXEC_INTERRUPTED) && dv_exec_mpi_rank() == 0)
    dv_io_temp_remove_stale(out_dir);
  if (pool == DV_EXEC_INTERRUPTED)
    status =
        dv_fail(err, DV_EVENT, "interrupted: %zu of %zu scenarios finished, their reports in %s",
                finished, n, out_dir);
  free(results);
  free(done);
  return status;
}
