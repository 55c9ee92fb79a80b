/* dv_pool: independent tasks run in parallel, on one machine or over MPI.
 *
 * Under mpirun the ranks share the tasks (dv_mpi.h). Otherwise every task
 * runs in a process of its own, forked for it, up to jobs at a time, and
 * writes its result into shared memory: a task that crashes its process (or
 * whose process cannot be made) leaves its result as it was, so the caller
 * initialises results to say "not run". Engines' error handlers and other
 * process-wide state never outlive a task.
 *
 * SIGINT, SIGTERM or SIGHUP (unless ignored, as under nohup) received by
 * the pool's process while it runs, or held before it (dv_exec_hold_stops),
 * stop it: no task is started after that, the signal is passed on to the
 * running tasks' processes (a kill may reach only the parent), and the pool
 * returns DV_EXEC_INTERRUPTED once they have ended; done[] says which
 * finished.
 *
 * With a timeout, a task's process that runs longer is killed (SIGKILL) and
 * its done[k] says DV_EXEC_TIMED_OUT; the others go on. Under MPI there is
 * no time limit.
 */
#ifndef DV_POOL_H
#define DV_POOL_H

#include <stddef.h>

#include "exec_mpi.h"

/* how a pool run ended */
typedef enum dv_exec_status {
  DV_EXEC_NOMEM = -1,      /* no memory for the pool: nothing ran */
  DV_EXEC_DONE = 0,        /* every task ended (some may have died: see ran and done) */
  DV_EXEC_WORKER = 1,      /* an MPI worker rank: rank 0 has the results */
  DV_EXEC_INTERRUPTED = 2, /* stopped by a signal; results not arrived untouched */
} dv_exec_status;

/* how task k ended, in done[k] */
typedef enum dv_exec_end {
  DV_EXEC_LOST = 0,      /* no result: not run, its process died or could not be made */
  DV_EXEC_ARRIVED = 1,   /* its result arrived */
  DV_EXEC_TIMED_OUT = 2, /* no result: killed at the time limit */
} dv_exec_end;

typedef struct dv_exec_options {
  int jobs;                    /* processes at a time (below 1: one) */
  dv_exec_result_fn on_result; /* may be NULL: called as each task ends */
  unsigned char *done;         /* may be NULL: n dv_exec_end, one per task */
  double timeout;              /* s of wall time a task may run (<= 0: no limit) */
  int local; /* processes on this machine even under mpirun (a pool inside an MPI rank's task) */
} dv_exec_options;

/* run tasks 0..n-1; results[k * size] receives task k's result. A dv_exec_status. */
int dv_exec_pool(size_t n, size_t size, dv_exec_task_fn work, void *ctx, void *results,
                 const dv_exec_options *opt);

/* from now on every task run under a timeout (dv_exec_options) is killed at
 * dv_clock_now() time deadline too, whichever comes first, and reported
 * DV_EXEC_TIMED_OUT: a command's whole run under one limit (compare and
 * simulate --timeout, whose probes run before the work). 0: none (the
 * default). A task's own process starts with none. */
void dv_exec_set_deadline(double deadline);

/* the signal that stopped the last pool of this process (DV_EXEC_INTERRUPTED), or 0 */
int dv_exec_stopped_by(void);

/* from now on SIGINT, SIGTERM and SIGHUP (unless ignored) are held
 * (blocked): one that comes before a pool runs stops that pool before its
 * first task, so that a command that reports its interruption is never
 * ended by one without a word; a stop held outside a pool is taken with
 * dv_exec_take_stop */
void dv_exec_hold_stops(void);

/* a held stop signal that came, taken: its number, or 0 */
int dv_exec_take_stop(void);

/* dv_exec_pool with jobs and on_result only */
int dv_exec_pool_run(size_t n, size_t size, dv_exec_task_fn work, void *ctx, void *results,
                     int jobs, dv_exec_result_fn on_result);

#endif
