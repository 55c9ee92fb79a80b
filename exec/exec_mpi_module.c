/* exec_mpi_module: MPI_Init, the master and the workers, as a module (exec_mpi_module.h). */
#include "exec_mpi_module.h"

#include <mpi.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static volatile sig_atomic_t stop_requested;

/* SIGINT or SIGTERM on rank 0: hand out no more tasks */
static void on_stop(int sig) {
  stop_requested = sig;
}

static int init(int *argc, char ***argv, int *rank, int *size) {
  if (MPI_Init(argc, argv) != MPI_SUCCESS) return -1;
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, size);
  return 0;
}

static void finalize(void) {
  MPI_Finalize();
}
enum { TAG_TASK = 1, TAG_RESULT = 2 };
#define STOP ((unsigned long long)-1)

/* rank 0: hand out indices, collect results; polls so that a signal is seen */
static int master(int world_size, size_t n, size_t size, void *results, unsigned char *done,
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

__attribute__((visibility("default"))) const dv_exec_mpi_calls dv_exec_mpi_module = {
    DV_EXEC_MPI_MODULE_ABI, init, finalize, master, worker};
