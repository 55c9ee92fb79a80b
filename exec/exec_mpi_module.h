/* exec_mpi_module: the MPI half of dv_mpi as a shared module (exec_mpi.so),
 * opened only when diskval was started by mpirun or srun, so a plain run maps
 * none of MPI's libraries. Its calls take the host's callbacks; it holds no
 * diskval state of its own.
 */
#ifndef DV_EXEC_MPI_MODULE_H
#define DV_EXEC_MPI_MODULE_H

#include <stddef.h>

#include "exec_mpi.h"

#define DV_EXEC_MPI_MODULE_ABI 1
#define DV_EXEC_MPI_MODULE_SYMBOL "dv_exec_mpi_module"

/* what the module exports, as the symbol dv_exec_mpi_module */
typedef struct dv_exec_mpi_calls {
  int abi; /* DV_EXEC_MPI_MODULE_ABI */
  /* MPI_Init; 0 with this process's rank and the number of ranks, else -1 */
  int (*init)(int *argc, char ***argv, int *rank, int *size);
  void (*finalize)(void);
  /* rank 0: hand out tasks and gather results (0 done, 2 stopped by a signal) */
  int (*master)(int size, size_t n, size_t result_size, void *results, unsigned char *done,
                dv_exec_result_fn on_result, void *ctx);
  /* any other rank: compute until told to stop */
  void (*worker)(size_t result_size, dv_exec_task_fn work, void *ctx);
} dv_exec_mpi_calls;

#endif
