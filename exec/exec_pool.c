/* dv_pool: a process per task over shared memory, or an MPI farm. */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS */
#include "exec_pool.h"

#include "dv_clock.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* one run of the pool: the tasks, their shared result slots, their processes */
typedef struct pool {
  size_t n, size;
  dv_exec_task_fn work;
  void *ctx;
  char *results;            /* the caller's */
  char *slots;              /* shared with the tasks' processes, n * size bytes */
  pid_t *pids;              /* task k's process while it runs, else 0 */
  double *started;          /* when task k's process was made (dv_clock_now) */
  unsigned char *timed_out; /* task k was killed at the time limit */
  const dv_exec_options *opt;
  sigset_t caller_mask; /* restored in every task's process and at the end */
  sigset_t stops;       /* the signals that stop it (stop_signals) */
  int running;
} pool;

/* the signal that stopped the last pool, or 0 */
static int last_stop;

/* dv_clock_now() time at which every timed task ends (0: none) */
static double deadline;

void dv_exec_set_deadline(double at) {
  deadline = at > 0.0 ? at : 0.0;
}

static const int stop_list[] = {SIGINT, SIGTERM, SIGHUP};
enum { NSTOPS = sizeof stop_list / sizeof *stop_list };

/* SIGINT, SIGTERM and SIGHUP, but not a SIGHUP ignored (nohup: the run
 * outlives its terminal) */
static void stop_signals(sigset_t *set) {
  struct sigaction hup;
  sigemptyset(set);
  sigaddset(set, SIGINT);
  sigaddset(set, SIGTERM);
  if (sigaction(SIGHUP, NULL, &hup) || hup.sa_handler != SIG_IGN) sigaddset(set, SIGHUP);
}

/* a stop signal already pending (held), taken: its number, or 0 */
static int take_pending(const sigset_t *stops) {
  const struct timespec now = {0, 0};
  const int sig = sigtimedwait(stops, NULL, &now);
  return sig > 0 ? sig : 0;
}

void dv_exec_hold_stops(void) {
  sigset_t stops;
  stop_signals(&stops);
  sigprocmask(SIG_BLOCK, &stops, NULL);
}

int dv_exec_take_stop(void) {
  sigset_t stops;
  stop_signals(&stops);
  return take_pending(&stops);
}

int dv_exec_stopped_by(void) {
  return last_stop;
}

/* never called: the stop signals stay blocked and are taken with
 * sigwaitinfo, but an ignored signal (a background job's SIGINT) would be
 * discarded, so the pool puts a handler of its own in place */
static void on_stop(int sig) {
  (void)sig;
}

/* in task k's new process: default signals, the task, its result in its slot */
static void run_child(const pool *p, size_t k, pid_t parent) {
  prctl(PR_SET_PDEATHSIG, SIGKILL); /* a task outlives no parent, not even a SIGKILLed one */
  if (getppid() != parent) _exit(1);
  deadline = 0.0; /* the parent's to enforce, not the task's own pools' */
  sigset_t mask = p->caller_mask;
  for (int i = 0; i < NSTOPS; i++)
    if (sigismember(&p->stops, stop_list[i])) {
      signal(stop_list[i], SIG_DFL);
      sigdelset(&mask, stop_list[i]); /* a caller's hold (dv_exec_hold_stops) is not the task's */
    }
  sigprocmask(SIG_SETMASK, &mask, NULL); /* a pending stop ends it here */
  p->work(k, p->slots + k * p->size, p->ctx);
  fflush(NULL);
  _exit(0);
}

/* task k has ended: take its result if it arrived */
static void finish(pool *p, size_t k, int ran) {
  if (ran) memcpy(p->results + k * p->size, p->slots + k * p->size, p->size);
  if (p->opt->done)
    p->opt->done[k] = ran ? DV_EXEC_ARRIVED : p->timed_out[k] ? DV_EXEC_TIMED_OUT : DV_EXEC_LOST;
  if (p->opt->on_result) p->opt->on_result(k, ran, p->ctx);
}

/* reap every task process that has ended, without blocking; a task's result
 * arrived when its process exited with 0 */
static void reap(pool *p) {
  for (size_t k = 0; k < p->n && p->running > 0; k++) {
    int ws = 0;
    if (p->pids[k] <= 0) continue;
    const pid_t r = waitpid(p->pids[k], &ws, WNOHANG);
    if (r == 0 || (r < 0 && errno != ECHILD)) continue; /* ECHILD: reaped by someone else */
    p->pids[k] = 0;
    p->running--;
    finish(p, k, r > 0 && WIFEXITED(ws) && WEXITSTATUS(ws) == 0);
  }
}

/* pass signal sig on to every running task */
static void forward(const pool *p, int sig) {
  for (size_t k = 0; k < p->n; k++)
    if (p->pids[k] > 0) kill(p->pids[k], sig);
}

/* kill the tasks past the time limit; the seconds until the next one's
 * limit (-1: none runs under a limit) */
static double enforce_timeout(pool *p) {
  if (!(p->opt->timeout > 0.0)) return -1.0;
  const double now = dv_clock_now();
  double next = -1.0;
  for (size_t k = 0; k < p->n; k++) {
    if (p->pids[k] <= 0 || p->timed_out[k]) continue;
    double left = p->started[k] + p->opt->timeout - now;
    if (deadline > 0.0 && deadline - now < left) left = deadline - now;
    if (left <= 0.0) {
      kill(p->pids[k], SIGKILL); /* reaped, and reported, as any ended task */
      p->timed_out[k] = 1;
    } else if (next < 0.0 || left < next) {
      next = left;
    }
  }
  return next;
}

/* wait for a signal of wanted, at most seconds (< 0: for ever); the signal or -1 */
static int wait_signal(const sigset_t *wanted, double seconds) {
  if (seconds < 0.0) return sigwaitinfo(wanted, NULL);
  const struct timespec ts = {(time_t)seconds, (long)((seconds - (double)(time_t)seconds) * 1e9)};
  return sigtimedwait(wanted, NULL, &ts);
}

/* fork a process per task, up to jobs at a time, until all ended or a stop */
static int run_forked(pool *p) {
  const int jobs = p->opt->jobs > 0 ? p->opt->jobs : 1;
  sigset_t wanted;
  stop_signals(&p->stops);
  wanted = p->stops;
  sigaddset(&wanted, SIGCHLD); /* blocked, so that a task's end is never missed */
  struct sigaction sa, old[NSTOPS];
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_stop;
  sigemptyset(&sa.sa_mask);
  sigprocmask(SIG_BLOCK, &wanted, &p->caller_mask);
  for (int i = 0; i < NSTOPS; i++)
    if (sigismember(&p->stops, stop_list[i])) sigaction(stop_list[i], &sa, &old[i]);
  int stop = 0;
  size_t next = 0;
  for (;;) {
    reap(p);
    /* a stop that came before (held by the caller) starts no task */
    if (!stop && (stop = take_pending(&p->stops))) forward(p, stop);
    while (!stop && p->running < jobs && next < p->n) {
      fflush(NULL); /* nothing buffered (by on_result too) is written twice */
      const pid_t self = getpid(), pid = fork();
      if (pid == 0) run_child(p, next, self);
      if (pid < 0 && p->running > 0) break; /* again once one has ended */
      if (pid < 0) {
        finish(p, next, 0); /* no process at all: the task is not run */
      } else {
        p->pids[next] = pid;
        p->started[next] = dv_clock_now();
        p->running++;
      }
      next++;
    }
    if (p->running == 0) break; /* all ended, or stopped */
    /* a task's end, a stop, or the next time limit */
    const int sig = wait_signal(&wanted, enforce_timeout(p));
    if (sig > 0 && sig != SIGCHLD) {
      stop = sig;
      forward(p, sig);
    }
  }
  /* a stop that came after the last task ended still counts */
  for (int sig; (sig = take_pending(&p->stops));) stop = sig;
  for (int i = 0; i < NSTOPS; i++)
    if (sigismember(&p->stops, stop_list[i])) sigaction(stop_list[i], &old[i], NULL);
  sigprocmask(SIG_SETMASK, &p->caller_mask, NULL);
  last_stop = stop;
  return stop ? DV_EXEC_INTERRUPTED : DV_EXEC_DONE;
}

int dv_exec_pool(size_t n, size_t size, dv_exec_task_fn work, void *ctx, void *results,
                 const dv_exec_options *opt) {
  if (dv_exec_mpi_size() > 1 && !opt->local) {
    unsigned char *done = opt->done ? opt->done : calloc(n ? n : 1, 1);
    if (!done) return DV_EXEC_NOMEM;
    const int status = dv_exec_mpi_farm(n, size, work, ctx, results, done, opt->on_result);
    if (done != opt->done) free(done);
    return status;
  }
  const size_t bytes = n * size > 0 ? n * size : 1;
  pool p = {.n = n, .size = size, .work = work, .ctx = ctx, .results = results, .opt = opt};
  p.slots = mmap(NULL, bytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  p.pids = calloc(n ? n : 1, sizeof *p.pids);
  p.started = calloc(n ? n : 1, sizeof *p.started);
  p.timed_out = calloc(n ? n : 1, sizeof *p.timed_out);
  int status = DV_EXEC_NOMEM;
  if (p.slots != MAP_FAILED && p.pids && p.started && p.timed_out) {
    if (opt->done) memset(opt->done, 0, n);
    memcpy(p.slots, results, n * size); /* a task starts from the caller's "not run" */
    status = run_forked(&p);
  }
  if (p.slots != MAP_FAILED) munmap(p.slots, bytes);
  free(p.pids);
  free(p.started);
  free(p.timed_out);
  return status;
}

int dv_exec_pool_run(size_t n, size_t size, dv_exec_task_fn work, void *ctx, void *results,
                     int jobs, dv_exec_result_fn on_result) {
  const dv_exec_options opt = {.jobs = jobs, .on_result = on_result};
  return dv_exec_pool(n, size, work, ctx, results, &opt);
}
