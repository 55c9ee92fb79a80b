/* dv_mpi: a master-worker farm over MPI (or a plain loop without it). */
#include "exec_mpi.h"

#include <stdlib.h>

#ifdef DV_HAVE_MPI
#include <dlfcn.h>
#include <stdio.h>
#include <unistd.h>

#include "exec_mpi_module.h"
#endif

static int world_rank = 0, world_size = 1, started = 0;
#ifdef DV_HAVE_MPI
static const dv_exec_mpi_calls *mpi; /* the module, once opened */

/* exec_mpi.so from the build tree's folder, else the installed one; NULL with why on stderr */
static const dv_exec_mpi_calls *open_module(void) {
  char path[1100];
  snprintf(path, sizeof path, "%s/exec_mpi.so", DV_EXEC_BUILD_DIR);
  if (access(path, F_OK)) snprintf(path, sizeof path, "%s/exec_mpi.so", DV_EXEC_INSTALL_DIR);
  void *handle = dlopen(path, RTLD_NOW | RTLD_GLOBAL); /* Open MPI's own plugins need its symbols */
  const dv_exec_mpi_calls *m = handle ? dlsym(handle, DV_EXEC_MPI_MODULE_SYMBOL) : NULL;
  if (m && m->abi == DV_EXEC_MPI_MODULE_ABI) return m; /* never closed */
  fprintf(stderr, "diskval: MPI: not available: %s\n",
          !handle ? dlerror() : m ? "a module of another build" : "no entry in exec_mpi.so");
  return NULL;
}
#endif

/* launched by a process manager that expects MPI_Init */
static int under_launcher(void) {
  return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMI_SIZE") || getenv("PMIX_RANK") ||
         getenv("SLURM_STEP_ID");
}

int dv_exec_mpi_init(int *argc, char ***argv) {
#ifdef DV_HAVE_MPI
  if (!under_launcher()) return world_size;
  /* every rank running the whole command alone would write over the others */
  if (!(mpi = open_module())) exit(2);
  if (mpi->init(argc, argv, &world_rank, &world_size))
    fprintf(stderr, "diskval: MPI_Init failed\n"), exit(2);
  started = 1;
#endif
  return world_size;
}

void dv_exec_mpi_finalize(void) {
#ifdef DV_HAVE_MPI
  if (started) mpi->finalize();
#endif
  started = 0;
}

int dv_exec_mpi_rank(void) {
  return world_rank;
}

int dv_exec_mpi_size(void) {
  return world_size;
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


int dv_exec_mpi_farm(size_t n, size_t size, dv_exec_task_fn work, void *ctx, void *results,
                     unsigned char *done, dv_exec_result_fn on_result) {
  if (world_size < 2) return run_locally(n, size, work, ctx, results, done, on_result);
#ifdef DV_HAVE_MPI
  if (world_rank == 0) return mpi->master(world_size, n, size, results, done, on_result, ctx);
  mpi->worker(size, work, ctx);
  return 1;
#else
  return run_locally(n, size, work, ctx, results, done, on_result);
#endif
}
