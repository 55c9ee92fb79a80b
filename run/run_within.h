/* run_within: work under a wall-time limit (compare and simulate --timeout).
 *
 * With a limit, the work goes to a process of its own through the exec pool
 * (exec_pool.h), as a suite's scenario does, and is killed (SIGKILL) when it
 * runs longer; without one (or under mpirun, as in suite) it runs in this
 * process, as before. Before it starts, a caller compares the work's probed
 * cost (run_progress.h) with the limit: past DV_RUN_WITHIN_REFUSE times the
 * limit it is refused, nothing run. */
#ifndef DV_RUN_WITHIN_H
#define DV_RUN_WITHIN_H

#include <stddef.h>
#include <stdio.h>

#include "dv_engine.h"
#include "scenario.h"

/* a probe's estimate can be off by this factor: past it, not started */
#define DV_RUN_WITHIN_REFUSE 2.0

/* how the work ended */
typedef enum dv_run_within_end {
  DV_RUN_WITHIN_DONE = 0,      /* result filled */
  DV_RUN_WITHIN_TIMED_OUT = 1, /* killed at the limit */
  DV_RUN_WITHIN_LOST = 2,      /* its process died without a result */
  DV_RUN_WITHIN_STOPPED = 3,   /* SIGINT, SIGTERM or SIGHUP stopped it */
} dv_run_within_end;

/* work(ctx, result) within timeout s of wall time (<= 0: no limit, here);
 * result (size bytes) is shared with the work's process and keeps what the
 * caller put there unless the work ends */
dv_run_within_end dv_run_within(double timeout, void (*work)(void *ctx, void *result), void *ctx,
                                void *result, size_t size);

/* from now on, timeout s from now (<= 0: no limit) ends every work of
 * dv_run_within too, whatever its own limit: a command's whole run under
 * one limit, its settings probes and forecast included (dv_exec_set_deadline) */
void dv_run_within_deadline(double timeout);

/* 0 when work estimated to take estimate s may start under timeout s (<= 0:
 * no limit), else -1 with err "would take about ... : not started"; whose
 * names the rates ("its", "each engine's") */
int dv_run_within_refuse(double estimate, double timeout, const char *whose, dv_error *err);

/* after DV_RUN_WITHIN_STOPPED: end this process as the stop would have
 * without a limit (its temporaries removed, io_temp.h): the signal that
 * stopped it, SIGINT, else (ignored in a background job) SIGTERM; returns,
 * with err set, only if all are ignored */
int dv_run_within_stop(dv_error *err);

/* dv_run_write_csv(engine, sc, fp, forces) within timeout s, announced first
 * when long (dv_run_progress_plan_run), refused when its probe says more than
 * DV_RUN_WITHIN_REFUSE times the limit (DV_EINPUT); a run killed at the limit
 * is DV_ESYSTEM "timed out after S s". Its status, stats and err. */
int dv_run_write_csv_within(const dv_engine_type *engine, const dv_scenario *sc, FILE *fp,
                            FILE *forces, double timeout, dv_engine_stats *stats, dv_error *err);

#endif
