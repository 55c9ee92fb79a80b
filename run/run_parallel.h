/* run_parallel: a comparison's runs as tasks of the exec pool.
 *
 * dv_run_scenario_jobs makes the comparison dv_run_scenario_hooked makes,
 * its runs spread over up to jobs processes: the thin reference and its
 * amplification (one task), the matched reference of each half-thickness
 * (one task each, once for every engine of that body), and each engine's run
 * with its settings probes (one task each). The metrics and the judging
 * follow in the calling process, engine by engine in the given order, as
 * dv_run_scenario_hooked does, so the comparison is the same whatever jobs.
 *
 * A task's trajectory comes back in its result slot of the pool (exec_pool.h):
 * every slot holds as many samples as the scene's output grid (its duration
 * over output_dt, and an event's), so it is fixed in size before any task
 * runs, goes through shared memory or over MPI alike, and leaves nothing
 * behind when a task dies. An engine whose process dies (a crash, a kill) is
 * that engine's error; a reference's is the comparison's, as when it fails.
 * A scene whose slots would exceed DV_RUN_SLOT_MAX bytes, or whose slots
 * (held twice) beside a comparison's own memory (scenario.h) would pass its
 * memory_budget, runs in this process, engine after engine
 * (dv_run_scenario_hooked).
 */
#ifndef DV_RUN_PARALLEL_H
#define DV_RUN_PARALLEL_H

#include "run_scenario.h"

/* bytes of one task's result slot (its samples and amplification) beyond which
 * the comparison runs in this process: 64 MiB, some 400000 samples */
#define DV_RUN_SLOT_MAX (64u << 20)

/* dv_run_scenario_hooked in up to jobs processes (one job: in this process); SIGINT,
 * SIGTERM or SIGHUP stop it (DV_EVENT, err saying so) */
int dv_run_scenario_jobs(const dv_scenario *sc, const dv_scenario *ref_sc,
                         const dv_engine_type *const *engines, size_t n, const dv_run_hook *hook,
                         int jobs, dv_comparison *out, dv_error *err);

#endif
