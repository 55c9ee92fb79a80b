/* test_exec: the exec pool, the one runner of sweeps, searches, maps and suites.
 *   - every task runs, in a process of its own, at most jobs at a time; each
 *     result arrives and on_result hears of every task once;
 *   - a task whose process is killed (or exits with a status) leaves its
 *     result as the caller set it, done[k] == 0, and the others go on;
 *   - a SIGTERM or SIGINT sent to the pool's process alone (even with SIGINT
 *     ignored, as in a background job) ends the running tasks, starts no
 *     more and returns DV_EXEC_INTERRUPTED; the caller's signal dispositions
 *     are as they were afterwards;
 *   - with a time limit, a task that runs longer is killed: its done[k] is
 *     DV_EXEC_TIMED_OUT, its result as the caller set it, the others arrive.
 * usage: test_exec */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS */
#include <signal.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>

#include "dv_clock.h"
#include "dv_test.h"
#include "exec_pool.h"

enum { N = 12, JOBS = 3 };

typedef struct result {
  long value; /* k * k, or -1: not run */
  pid_t pid;  /* the process that ran it */
  int peak;   /* tasks running at once, as this one saw it */
} result;

/* what the tasks share: how many run at this moment */
typedef struct shared {
  atomic_int running;
} shared;

typedef struct ctx {
  shared *sh;
  int crash, status; /* the task that dies by a signal, the one that exits with 3 */
  int stop;          /* the task that sends stop_signal to the pool's process */
  int stop_signal;
  int slow;                    /* the task that sleeps 10 s */
  double timeout;              /* the pool's time limit */
  int ended[N], ran[N], calls; /* what on_result heard */
} ctx;

/* a task: k * k after a short while, or a crash, an exit, a stop */
static void task(size_t k, void *out, void *arg) {
  ctx *c = arg;
  result *r = out;
  const int now = atomic_fetch_add(&c->sh->running, 1) + 1;
  if ((int)k == c->crash) raise(SIGKILL); /* a crash, without a core file */
  if ((int)k == c->status) _exit(3);
  if ((int)k == c->stop) kill(getppid(), c->stop_signal);
  if (c->stop >= 0 || (int)k == c->slow)
    sleep(10); /* until the pool ends it (or the test fails on time) */
  else
    nanosleep(&(struct timespec){0, 20000000}, NULL); /* long enough to overlap */
  r->value = (long)(k * k);
  r->pid = getpid();
  r->peak = now;
  atomic_fetch_sub(&c->sh->running, 1);
}

/* on_result: remember every call */
static void on_result(size_t k, int ran, void *arg) {
  ctx *c = arg;
  c->ended[k]++;
  c->ran[k] = ran;
  c->calls++;
}

/* run the pool over N tasks with c's crash, exit and stop; results and done into r, done */
static int run(ctx *c, result *r, unsigned char *done) {
  for (size_t k = 0; k < N; k++) r[k] = (result){-1, 0, 0};
  memset(c->ended, 0, sizeof c->ended);
  memset(c->ran, 0, sizeof c->ran);
  c->calls = 0;
  atomic_store(&c->sh->running, 0);
  const dv_exec_options opt = {
      .jobs = JOBS, .on_result = on_result, .done = done, .timeout = c->timeout};
  return dv_exec_pool(N, sizeof *r, task, c, r, &opt);
}

static void check_all_run(ctx *c) {
  result r[N];
  unsigned char done[N];
  *c = (ctx){.sh = c->sh, .crash = -1, .status = -1, .stop = -1, .slow = -1};
  CHECK(run(c, r, done) == DV_EXEC_DONE, "pool did not finish");
  for (size_t k = 0; k < N; k++) {
    CHECK(r[k].value == (long)(k * k), "task %zu: %ld", k, r[k].value);
    CHECK(done[k] == 1 && c->ended[k] == 1 && c->ran[k] == 1, "task %zu: done %d, %d calls, ran %d",
          k, done[k], c->ended[k], c->ran[k]);
    CHECK(r[k].pid != getpid() && r[k].pid > 0, "task %zu ran in the caller", k);
    CHECK(r[k].peak >= 1 && r[k].peak <= JOBS, "task %zu: %d tasks at once", k, r[k].peak);
    for (size_t j = 0; j < k; j++)
      CHECK(r[j].pid != r[k].pid, "tasks %zu and %zu: one process", j, k);
  }
  int overlapped = 0; /* a later task ran beside another: ended ones are replaced at once */
  for (size_t k = JOBS; k < N; k++) overlapped |= r[k].peak >= 2;
  CHECK(overlapped, "after the first %d tasks, one task at a time", JOBS);
  CHECK(dv_exec_pool_run(0, sizeof *r, task, c, r, JOBS, NULL) == DV_EXEC_DONE, "no tasks");
}

static void check_crashes(ctx *c) {
  result r[N];
  unsigned char done[N];
  *c = (ctx){.sh = c->sh, .crash = 3, .status = 5, .stop = -1, .slow = -1};
  CHECK(run(c, r, done) == DV_EXEC_DONE, "a crash stopped the pool");
  for (size_t k = 0; k < N; k++) {
    const int dies = k == 3 || k == 5;
    CHECK(r[k].value == (dies ? -1 : (long)(k * k)), "task %zu: %ld", k, r[k].value);
    CHECK(done[k] == !dies && c->ran[k] == !dies && c->ended[k] == 1,
          "task %zu: done %d, ran %d, %d calls", k, done[k], c->ran[k], c->ended[k]);
  }
}

/* a stop sent by task 0 to the pool's process: returns within seconds */
static void check_stop(ctx *c, int sig, void (*disposition)(int)) {
  result r[N];
  unsigned char done[N];
  struct sigaction before, after;
  signal(sig, disposition);
  sigaction(sig, NULL, &before);
  *c = (ctx){.sh = c->sh, .crash = -1, .status = -1, .stop = 0, .stop_signal = sig, .slow = -1};
  const double t0 = dv_clock_now();
  CHECK(run(c, r, done) == DV_EXEC_INTERRUPTED, "signal %d: not interrupted", sig);
  CHECK(dv_clock_now() - t0 < 5.0, "signal %d: the running tasks were not ended", sig);
  for (size_t k = 0; k < N; k++) {
    CHECK(r[k].value == -1 && !done[k], "signal %d: task %zu has a result", sig, k);
    CHECK(c->ended[k] == (k < JOBS), "signal %d: task %zu: %d calls", sig, k, c->ended[k]);
  }
  sigaction(sig, NULL, &after);
  CHECK(after.sa_handler == before.sa_handler, "signal %d: disposition not restored", sig);
  signal(sig, SIG_DFL);
}

/* task 4 sleeps 10 s under a 0.5 s limit (the others take 0.02 s: 25x
 * margin): killed, reported as timed out, the pool done within seconds */
static void check_timeout(ctx *c) {
  result r[N];
  unsigned char done[N];
  *c = (ctx){.sh = c->sh, .crash = -1, .status = -1, .stop = -1, .slow = 4, .timeout = 0.5};
  const double t0 = dv_clock_now();
  CHECK(run(c, r, done) == DV_EXEC_DONE, "a time limit stopped the pool");
  const double wall = dv_clock_now() - t0;
  CHECK(wall >= 0.5 && wall < 5.0, "the slow task was not ended at its limit: %.2f s", wall);
  for (size_t k = 0; k < N; k++) {
    const int slow = k == 4;
    CHECK(r[k].value == (slow ? -1 : (long)(k * k)), "task %zu: %ld", k, r[k].value);
    CHECK(done[k] == (slow ? DV_EXEC_TIMED_OUT : DV_EXEC_ARRIVED) && c->ended[k] == 1 &&
              c->ran[k] == !slow,
          "task %zu: done %d, ran %d, %d calls", k, done[k], c->ran[k], c->ended[k]);
  }
}

int main(void) {
  ctx c = {0};
  c.sh = mmap(NULL, sizeof *c.sh, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (c.sh == MAP_FAILED) return 1;
  atomic_init(&c.sh->running, 0);
  check_all_run(&c);
  check_crashes(&c);
  check_timeout(&c);
  check_stop(&c, SIGTERM, SIG_DFL);
  check_stop(&c, SIGINT, SIG_IGN); /* a background job's: the pool hears it all the same */
  munmap(c.sh, sizeof *c.sh);
  return TEST_RESULT();
}
