/* run_within: work in a process of its own under a wall-time limit (run_within.h). */
#include "run_within.h"

#include <errno.h>
#include <signal.h>
#include <string.h>

#include "dv_clock.h"
#include "exec_pool.h"
#include "run_progress.h"
#include "run_trajectory.h"

/* the work, as the pool's task */
typedef struct within_task {
  void (*work)(void *ctx, void *result);
  void *ctx;
} within_task;

static void task(size_t k, void *result, void *ctx) {
  const within_task *t = ctx;
  (void)k;
  t->work(t->ctx, result);
}

dv_run_within_end dv_run_within(double timeout, void (*work)(void *ctx, void *result), void *ctx,
                                void *result, size_t size) {
  if (!(timeout > 0.0) || dv_exec_mpi_size() > 1) /* no limit under mpirun, as in suite */
    return work(ctx, result), DV_RUN_WITHIN_DONE;
  unsigned char done = DV_EXEC_LOST;
  within_task t = {work, ctx};
  const dv_exec_options opt = {.jobs = 1, .done = &done, .timeout = timeout};
  const int pool = dv_exec_pool(1, size, task, &t, result, &opt);
  if (pool == DV_EXEC_INTERRUPTED) return DV_RUN_WITHIN_STOPPED;
  return pool != DV_EXEC_DONE        ? DV_RUN_WITHIN_LOST
         : done == DV_EXEC_ARRIVED   ? DV_RUN_WITHIN_DONE
         : done == DV_EXEC_TIMED_OUT ? DV_RUN_WITHIN_TIMED_OUT
                                     : DV_RUN_WITHIN_LOST;
}

void dv_run_within_deadline(double timeout) {
  dv_exec_set_deadline(timeout > 0.0 ? dv_clock_now() + timeout : 0.0);
}

int dv_run_within_refuse(double estimate, double timeout, const char *whose, dv_error *err) {
  if (!(timeout > 0.0) || !(estimate > DV_RUN_WITHIN_REFUSE * timeout)) return 0;
  return dv_fail(err, DV_EINPUT,
                 "would take about %.3g s (%s rate timed for %g s), more than %g times the "
                 "time limit of %g s: not started",
                 estimate, whose, DV_PROGRESS_PROBE_S, DV_RUN_WITHIN_REFUSE, timeout),
         -1;
}

int dv_run_within_stop(dv_error *err) {
  if (dv_exec_stopped_by()) raise(dv_exec_stopped_by()); /* SIGHUP too */
  raise(SIGINT);
  raise(SIGTERM);
  return dv_fail(err, DV_ESYSTEM, "interrupted by a signal");
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

int dv_run_write_csv_within(const dv_engine_type *engine, const dv_scenario *sc, FILE *fp,
                            FILE *forces, double timeout, dv_engine_stats *stats, dv_error *err) {
  memset(stats, 0, sizeof *stats);
  stats->outcome = DV_OUTCOME_ERROR;
  if (timeout > 0.0 &&
      dv_run_within_refuse(dv_run_progress_estimate_run(sc, engine), timeout, "its", err))
    return DV_EINPUT;
  dv_run_progress_plan_run(sc, engine); /* a long run says so before its first sample */
  simulate_job job = {engine, sc, fp, forces, timeout > 0.0 && dv_exec_mpi_size() <= 1};
  simulate_result r = {DV_ESYSTEM, {0}, {{0}}};
  dv_fail(&r.err, DV_ESYSTEM, "its process ended without a result (crashed or killed)");
  const dv_run_within_end end = dv_run_within(timeout, simulate_task, &job, &r, sizeof r);
  *stats = r.stats;
  *err = r.err;
  if (end == DV_RUN_WITHIN_DONE) return r.status;
  stats->outcome = DV_OUTCOME_ERROR;
  if (end == DV_RUN_WITHIN_STOPPED) return dv_run_within_stop(err);
  if (end == DV_RUN_WITHIN_TIMED_OUT) dv_fail(err, DV_ESYSTEM, "timed out after %g s", timeout);
  return DV_ESYSTEM;
}
