/* dv_mpi: tasks farmed out over MPI ranks, when diskval runs under mpirun.
 *
 * Built with MPI where CMake finds it (DV_HAVE_MPI); used only when the
 * process was started by mpirun/srun with more than one rank, so a plain run
 * never needs MPI. Rank 0 hands out task indices one at a time (dynamic
 * assignment: a slow task does not idle the other ranks) and gathers the
 * results; every other rank computes. All ranks parse the same command line,
 * so they agree on the task list without sending it.
 */
#ifndef DV_MPI_H
#define DV_MPI_H

#include <stddef.h>

/* start MPI when launched by mpirun or srun; returns the number of ranks (1 without) */
int dv_exec_mpi_init(int *argc, char ***argv);
void dv_exec_mpi_finalize(void);
int dv_exec_mpi_rank(void);
int dv_exec_mpi_size(void);

/* compute one task into result (size bytes) */
typedef void (*dv_exec_task_fn)(size_t k, void *result, void *ctx);

/* task k has ended; ran: its result arrived (0: its process died or could
 * not be made, and its result is as it was) */
typedef void (*dv_exec_result_fn)(size_t k, int ran, void *ctx);

/* run tasks 0..n-1 over the ranks. On rank 0 the results land in
 * results[k * size] and done[k] is set as each arrives; on_result (may be
 * NULL) is called on rank 0 after each. Other ranks compute until told to
 * stop and return 1. On rank 0: 0 when all are done, 2 when SIGTERM or
 * SIGINT stopped it (done[] says which are missing). */
int dv_exec_mpi_farm(size_t n, size_t size, dv_exec_task_fn work, void *ctx, void *results,
                     unsigned char *done, dv_exec_result_fn on_result);

#endif
