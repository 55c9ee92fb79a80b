/* dv_suite: scenarios run into report directories, one process each.
 *
 * A scenario's directory OUT/<name>/ is built under a temporary name and
 * renamed into place when complete, replacing an older one: an interrupted
 * run never leaves a half-written report, and a failed one leaves an error
 * report with its cause (report_suite_dir.h), never an earlier report. The scenarios are tasks of
 * the exec pool (exec_pool.h): each runs in its own process (MuJoCo's and
 * ODE's error handlers are process-wide), at most jobs at a time, and one
 * that crashes is an error of its own; under mpirun the ranks share them.
 */
#ifndef DV_SUITE_H
#define DV_SUITE_H

#include <stddef.h>

#include "dv_engine.h"
#include "io_file.h" /* dv_io_make_dirs for the output directory */
#include "scenario.h"

/* how one scenario of a suite ended */
typedef enum dv_suite_result {
  DV_SUITE_PASS = 0,
  DV_SUITE_FAIL = 1,
  DV_SUITE_ERROR = 2,
  DV_SUITE_NOT_ENDED = 3 /* still running, or not started, when the suite was interrupted */
} dv_suite_result;

/* explains why an engine exceeds its limits (attribution lives above this
 * layer): the cause of r's excess in c (the comparison it was judged in, its
 * runs reusable) in words into out; 0, or < 0 when it cannot */
struct dv_comparison;
struct dv_engine_result;
typedef struct dv_report_explain {
  int (*cause)(void *ctx, const dv_scenario *sc, const struct dv_comparison *c,
               const struct dv_engine_result *r, char *out, size_t size);
  void *ctx;
} dv_report_explain;

/* compare sc and write OUT/<name>/ (an engine that exceeds a limit gets its
 * cause from explain, when given); print a line per engine to stdout when
 * verbose. The runs, then the causes, go to up to jobs processes
 * (run_parallel.h): the report is the same whatever jobs. Returns a
 * dv_suite_result; DV_SUITE_ERROR with its cause in err and in OUT/<name>/
 * as an error report. */
int dv_report_suite_run_one(const dv_scenario *sc, const dv_engine_type *const *engines,
                            const char *out_dir, int verbose, const dv_report_explain *explain,
                            int jobs, dv_error *err);

/* dv_report_suite_run_all on an MPI worker rank: rank 0 has the results */
#define DV_SUITE_RUN_WORKER 2

/* run scenarios[0..n) in up to jobs processes, each for at most timeout
 * seconds of wall time (<= 0: no limit; none under MPI); each one's
 * dv_suite_result into codes[] and, for DV_SUITE_ERROR, its cause into
 * causes[] and on stderr: a scenario over the time limit ("timed out after
 * N s") or whose process died gets its error report too. The caller holds
 * out_dir's lock (io_lock.h): temporaries that dead runs left there are
 * removed first, those of the scenarios ended early at the end. Progress
 * is counted on the progress line (run_progress.h). SIGINT, SIGTERM or
 * SIGHUP stops it (exec_pool.h): running scenarios are ended, their
 * temporary directories removed, finished reports kept; the others' codes[]
 * are DV_SUITE_NOT_ENDED and their directories an error report saying so
 * (never an earlier run's); returns DV_EVENT then (err says how many
 * finished), else DV_OK, or DV_SUITE_RUN_WORKER. */
int dv_report_suite_run_all(const dv_scenario *scenarios, size_t n,
                            const dv_engine_type *const *engines, const char *out_dir, int jobs,
                            double timeout, const dv_report_explain *explain, int *codes,
                            dv_error *causes, dv_error *err);

#endif
