/* dv_mpi: a master-worker farm over MPI (or a plain loop without it). */
#include "exec_mpi.h"

#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef DV_HAVE_MPI
#include <mpi.h>
#endif

static int world_rank = 0, world_size = 1, started = 0;

/* launched by a process manager that expects MPI_Init */
static int under_launcher(void) {
  return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE") || getenv("PMIX_RANK") ||
         getenv("SLURM_STEP_ID");
}

int dv_exec_mpi_init(int *argc, char ***argv) {
#ifdef DV_HAVE_MPI
  if (under_launcher() && MPI_Init(argc, argv) == MPI_SUCCESS) {
    started = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &world_rank);
    MPI_Comm_size(MPI_COMM_WORLD, &world_size);
  }
#endif
  return world_size;
}

void dv_exec_mpi_finalize(void) {
#ifdef DV_HAVE_MPI
  if (started) MPI_Finalize();
#endif
  started = 0;
}

int dv_exec_mpi_rank(void) {
  return world_rank;
}

int dv_exec_mpi_size(void) {
  return world_size;
}

static volatile sig_atomic_t stop_requested;

/* SIGINT or SIGTERM on rank 0: hand out no more tasks */
static void on_stop(int sig) {
  stop_requested = sig;
}

/* without other ranks: every task here, in order */
static int run_locally(size_t n, size_t size, dv_exec_task_fn work, void *ctx, void *results,
                       unsigned char *done, dv_exec_result_fn on_result) {
  for (size_t k = 0; k < n; k++) {
    work(k, (char *)results + k * size, ctx);
    done[k] = 1;
    if (on_result) on_result(k, 1, ctx);
  }
  return 0;
}

#ifdef DV_HAVE_MPI
enum { TAG_TASK = 1, TAG_RESULT = 2 };
#define STOP ((unsigned long long)-1)

/* rank 0: hand out indices, collect results; polls so that a signal is seen */
static int master(size_t n, size_t size, void *results, unsigned char *done,
                  dv_exec_result_fn on_result, void *ctx) {
  const size_t msg = sizeof(unsigned long long) + size;
  char *buf = malloc(msg);
  if (!buf) MPI_Abort(MPI_COMM_WORLD, 2);
  size_t next = 0, pending = 0;
  for (int r = 1; r < world_size; r++) {
    unsigned long long k = next < n ? next++ : STOP;
    MPI_Send(&k, 1, MPI_UNSIGNED_LONG_LONG, r, TAG_TASK, MPI_COMM_WORLD);
    if (k != STOP) pending++;
  }
  struct sigaction sa, old_term, old_int;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_stop;
  sigaction(SIGTERM, &sa, &old_term);
  sigaction(SIGINT, &sa, &old_int);
  stop_requested = 0;
  sigset_t stops, old_mask; /* held by the caller (dv_exec_hold_stops): taken here */
  sigemptyset(&stops);
  sigaddset(&stops, SIGTERM);
  sigaddset(&stops, SIGINT);
  sigprocmask(SIG_UNBLOCK, &stops, &old_mask);
  while (pending > 0 && !stop_requested) {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, TAG_RESULT, MPI_COMM_WORLD, &flag, &st);
    if (!flag) {
      nanosleep(&(struct timespec){0, 1000000}, NULL);
      continue;
    }
    MPI_Recv(buf, (int)msg, MPI_BYTE, st.MPI_SOURCE, TAG_RESULT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    unsigned long long k;
    memcpy(&k, buf, sizeof k);
    memcpy((char *)results + k * size, buf + sizeof k, size);
    done[k] = 1;
    pending--;
    if (on_result) on_result((size_t)k, 1, ctx);
    unsigned long long task = next < n ? next++ : STOP;
    MPI_Send(&task, 1, MPI_UNSIGNED_LONG_LONG, st.MPI_SOURCE, TAG_TASK, MPI_COMM_WORLD);
    if (task != STOP) pending++;
  }
  sigprocmask(SIG_SETMASK, &old_mask, NULL);
  sigaction(SIGTERM, &old_term, NULL);
  sigaction(SIGINT, &old_int, NULL);
  free(buf);
  return stop_requested ? 2 : 0;
}

/* any other rank: compute until told to stop */
static void worker(size_t size, dv_exec_task_fn work, void *ctx) {
  const size_t msg = sizeof(unsigned long long) + size;
  char *buf = malloc(msg);
  if (!buf) MPI_Abort(MPI_COMM_WORLD, 2);
  for (;;) {
    unsigned long long k;
    MPI_Recv(&k, 1, MPI_UNSIGNED_LONG_LONG, 0, TAG_TASK, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (k == STOP) break;
    memset(buf, 0, msg);
    memcpy(buf, &k, sizeof k);
    work((size_t)k, buf + sizeof k, ctx);
    MPI_Send(buf, (int)msg, MPI_BYTE, 0, TAG_RESULT, MPI_COMM_WORLD);
  }
  free(buf);
}
#endif

int dv_exec_mpi_farm(size_t n, size_t size, dv_exec_task_fn work, void *ctx, void *results,
                     unsigned char *done, dv_exec_result_fn on_result) {
  if (world_size < 2) return run_locally(n, size, work, ctx, results, done, on_result);
#ifdef DV_HAVE_MPI
  if (world_rank == 0) return master(n, size, results, done, on_result, ctx);
  worker(size, work, ctx);
  return 1;
#else
  return run_locally(n, size, work, ctx, results, done, on_result);
#endif
}
