/* dv_pool: a process pool over shared memory, or an MPI farm. */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS */
#include "exec_pool.h"

#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

int dv_exec_pool_run(size_t n, size_t size, dv_exec_task_fn work, void *ctx, void *results, int jobs,
                void (*on_result)(size_t k, void *ctx)) {
  if (dv_exec_mpi_size() > 1) {
    unsigned char *done = calloc(n ? n : 1, 1);
    if (!done) return -1;
    const int status = dv_exec_mpi_farm(n, size, work, ctx, results, done, on_result);
    free(done);
    return status;
  }
  const size_t bytes = sizeof(atomic_size_t) + n * size;
  void *shared = mmap(NULL, bytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (shared == MAP_FAILED) return -1;
  atomic_size_t *next = shared;
  char *slots = (char *)shared + sizeof(atomic_size_t);
  atomic_init(next, 0);
  memcpy(slots, results, n * size);
  fflush(NULL);
  int workers = 0;
  for (int w = 0; w < jobs && (size_t)w < n; w++) {
    const pid_t pid = fork();
    if (pid == 0) {
      for (size_t k; (k = atomic_fetch_add(next, 1)) < n;) work(k, slots + k * size, ctx);
      fflush(NULL);
      _exit(0);
    }
    if (pid > 0) workers++;
  }
  if (!workers) /* no process could be made: run them here */
    for (size_t k; (k = atomic_fetch_add(next, 1)) < n;) work(k, slots + k * size, ctx);
  while (workers > 0 && wait(NULL) > 0) workers--;
  memcpy(results, slots, n * size);
  munmap(shared, bytes);
  for (size_t k = 0; on_result && k < n; k++) on_result(k, ctx);
  return 0;
}
