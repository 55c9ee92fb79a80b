/* dv_pool: independent tasks run in parallel, on one machine or over MPI.
 *
 * Under mpirun the ranks share the tasks (dv_mpi.h). Otherwise up to jobs
 * forked processes each take the next task from a counter in shared memory
 * and write its result there; a task that crashes its process leaves its
 * result as it was (the caller initialises results to say "not run").
 */
#ifndef DV_POOL_H
#define DV_POOL_H

#include <stddef.h>

#include "exec_mpi.h"

/* run tasks 0..n-1; results[k * size] receives task k's result.
 * Returns 0, 1 on an MPI worker rank (rank 0 has the results), 2 when an
 * MPI run was stopped early (missing results untouched), -1 without memory. */
int dv_exec_pool_run(size_t n, size_t size, dv_exec_task_fn work, void *ctx, void *results, int jobs,
                void (*on_result)(size_t k, void *ctx));

#endif
