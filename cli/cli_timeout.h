/* cli_timeout: the run of compare and simulate, under --timeout S (0: no
 * limit). With a limit the run goes to a process of its own (exec_pool.h, as
 * a suite's scenario), killed (SIGKILL) when it runs longer; its temporaries
 * are then removed. Before that, the run's cost is probed (run_progress.h)
 * and a run that would take more than DV_CLI_TIMEOUT_REFUSE times the limit
 * is refused, nothing run or written. A SIGINT or SIGTERM ends the process
 * as it would without a limit. */
#ifndef DV_CLI_TIMEOUT_H
#define DV_CLI_TIMEOUT_H

#include <stdio.h>

#include "dv_engine.h"
#include "report_suite_run.h"

/* a probe's estimate can be off by this factor: past it, not started */
#define DV_CLI_TIMEOUT_REFUSE 2.0

/* dv_report_suite_run_one(sc, engines, out_dir, verbose, explain) within
 * timeout s: its dv_suite_result; DV_SUITE_ERROR with err "timed out after S
 * s" (and that error report in out_dir), or err saying it was not started */
int dv_cli_compare_run(const dv_scenario *sc, const dv_engine_type *const *engines,
                       const char *out_dir, const dv_report_explain *explain, double timeout,
                       dv_error *err);

/* dv_run_write_csv(engine, sc, fp, forces) within timeout s, announced
 * first when long (dv_run_progress_plan_run): its status, stats and err; a
 * run killed at the limit is DV_ESYSTEM "timed out after S s", one refused
 * up front DV_EINPUT */
int dv_cli_simulate_run(const dv_engine_type *engine, const dv_scenario *sc, FILE *fp, FILE *forces,
                        double timeout, dv_engine_stats *stats, dv_error *err);

#endif
