/* cli_timeout: compare and simulate under --timeout S. The run goes to a
 * process of its own through the exec pool (as a suite's scenario does),
 * killed at the limit; a run whose probed cost (run_progress.h) is more than
 * DV_CLI_TIMEOUT_REFUSE times the limit is refused before it starts. With no
 * limit the run stays in this process, as before. */
#include "cli_timeout.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "exec_pool.h"
#include "io_temp.h"
#include "report_suite_dir.h"
#include "run_progress.h"
#include "run_scenario.h"
#include "run_trajectory.h"

/* what a run in its own process hands back */
typedef struct within_task {
  void (*run)(void *ctx, void *result);
  void *ctx;
} within_task;

static void task(size_t k, void *result, void *ctx) {
  const within_task *t = ctx;
  (void)k;
  t->run(t->ctx, result);
}

/* run(ctx, result) within timeout s of wall time: DV_EXEC_ARRIVED (result
 * filled), DV_EXEC_TIMED_OUT or DV_EXEC_LOST, or -1 when interrupted */
static int within(double timeout, void (*run)(void *ctx, void *result), void *ctx, void *result,
                  size_t size) {
  if (!(timeout > 0.0) || dv_exec_mpi_size() > 1) /* no limit under mpirun, as in suite */
    return run(ctx, result), DV_EXEC_ARRIVED;
  unsigned char done = DV_EXEC_LOST;
  within_task t = {run, ctx};
  const dv_exec_options opt = {.jobs = 1, .done = &done, .timeout = timeout};
  const int pool = dv_exec_pool(1, size, task, &t, result, &opt);
  return pool == DV_EXEC_INTERRUPTED ? -1 : pool == DV_EXEC_DONE ? done : DV_EXEC_LOST;
}

/* a stop (SIGINT, SIGTERM) ended the run's process: this one ends as a stop
 * ends it without a limit, its temporaries removed (io_temp.h); the pool
 * does not say which, so SIGINT, else (ignored, in a background job) SIGTERM */
static int stop_here(dv_error *err) {
  raise(SIGINT);
  raise(SIGTERM);
  return dv_fail(err, DV_ESYSTEM, "interrupted by a signal");
}

/* estimate seconds against timeout: 0, or -1 with err saying why not to start */
static int affordable(double estimate, double timeout, const char *whose, dv_error *err) {
  if (!(timeout > 0.0) || !(estimate > DV_CLI_TIMEOUT_REFUSE * timeout)) return 0;
  return dv_fail(err, DV_EINPUT,
                 "would take about %.3g s (%s rate timed for %g s), more than %g times "
                 "--timeout %g s: not started",
                 estimate, whose, DV_PROGRESS_PROBE_S, DV_CLI_TIMEOUT_REFUSE, timeout),
         -1;
}

/* a comparison's process: its run_one code and error */
typedef struct compare_job {
  const dv_scenario *sc;
  const dv_engine_type *const *engines;
  const char *out_dir;
  const dv_report_explain *explain;
} compare_job;

typedef struct compare_result {
  int code;
  dv_error err;
} compare_result;

static void compare_task(void *ctx, void *result) {
  const compare_job *j = ctx;
  compare_result *r = result;
  r->code = dv_report_suite_run_one(j->sc, j->engines, j->out_dir, 1, j->explain, &r->err);
}

int dv_cli_compare_run(const dv_scenario *sc, const dv_engine_type *const *engines,
                       const char *out_dir, const dv_report_explain *explain, double timeout,
                       dv_error *err) {
  if (timeout > 0.0) {
    const dv_engine_type *own[DV_MAX_ENGINES + 1], *const *run = engines;
    size_t n = 0;
    if (sc->engines[0] && !dv_engine_parse_list(sc->engines, own, DV_MAX_ENGINES + 1, err))
      run = own; /* the engines run_one will run */
    while (run[n]) n++;
    if (affordable(dv_run_progress_estimate(sc, NULL, run, n), timeout, "each engine's", err))
      return DV_SUITE_ERROR;
  }
  compare_job job = {sc, engines, out_dir, explain};
  compare_result r = {DV_SUITE_ERROR, {{0}}};
  dv_fail(&r.err, DV_ESYSTEM, "its process ended without a result (crashed or killed)");
  const int ended = within(timeout, compare_task, &job, &r, sizeof r);
  if (ended == DV_EXEC_ARRIVED) {
    *err = r.err;
    return r.code;
  }
  dv_io_temp_remove_stale(out_dir, NULL); /* the killed process's report under construction */
  if (ended < 0) return stop_here(err), DV_SUITE_ERROR;
  if (ended == DV_EXEC_TIMED_OUT) dv_fail(&r.err, DV_ESYSTEM, "timed out after %g s", timeout);
  dv_error ignored;
  dv_report_dir_write_error(out_dir, sc, r.err.msg, &ignored);
  *err = r.err;
  return DV_SUITE_ERROR;
}

/* a simulation's process: dv_run_write_csv's status, stats and error */
typedef struct simulate_job {
  const dv_engine_type *engine;
  const dv_scenario *sc;
  FILE *fp, *forces;
  int own_process; /* the rows must reach the file before the process ends */
} simulate_job;

typedef struct simulate_result {
  int status;
  dv_engine_stats stats;
  dv_error err;
} simulate_result;

static void simulate_task(void *ctx, void *result) {
  const simulate_job *j = ctx;
  simulate_result *r = result;
  r->status = dv_run_write_csv(j->engine, j->sc, j->fp, j->forces, &r->stats, &r->err);
  /* here, not at the pool's exit, where a failed write would go unseen; in
   * this process the file's commit checks it */
  if (j->own_process && r->status >= 0 &&
      ((j->fp && fflush(j->fp)) || (j->forces && fflush(j->forces))))
    r->status = dv_fail(&r->err, DV_ESYSTEM, "cannot write the output: %s", strerror(errno));
}

int dv_cli_simulate_run(const dv_engine_type *engine, const dv_scenario *sc, FILE *fp, FILE *forces,
                        double timeout, dv_engine_stats *stats, dv_error *err) {
  memset(stats, 0, sizeof *stats);
  stats->outcome = DV_OUTCOME_ERROR;
  if (timeout > 0.0 && affordable(dv_run_progress_estimate_run(sc, engine), timeout, "its", err))
    return DV_EINPUT;
  dv_run_progress_plan_run(sc, engine); /* a long run says so before its first sample */
  simulate_job job = {engine, sc, fp, forces, timeout > 0.0 && dv_exec_mpi_size() <= 1};
  simulate_result r = {DV_ESYSTEM, {0}, {{0}}};
  dv_fail(&r.err, DV_ESYSTEM, "its process ended without a result (crashed or killed)");
  const int ended = within(timeout, simulate_task, &job, &r, sizeof r);
  *stats = r.stats;
  *err = r.err;
  if (ended == DV_EXEC_ARRIVED) return r.status;
  stats->outcome = DV_OUTCOME_ERROR;
  if (ended < 0) return stop_here(err);
  if (ended == DV_EXEC_TIMED_OUT) dv_fail(err, DV_ESYSTEM, "timed out after %g s", timeout);
  return DV_ESYSTEM;
}
