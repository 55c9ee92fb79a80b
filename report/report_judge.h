/* report_judge: recorded trajectories judged (run_judge.h) into a scenario's
 * report directory, laid out as compare's (report_suite_run.h): OUT/<name>/
 * built under a temporary name and renamed when complete.
 */
#ifndef DV_REPORT_JUDGE_H
#define DV_REPORT_JUDGE_H

#include "report_suite_run.h"
#include "run_judge.h"

/* judge the n replays on sc, write OUT/<name>/ and, when junit is not NULL,
 * that JUnit XML; a line per trajectory on stdout; each one's theta_max_err
 * into theta_err[] when not NULL (a convergence check over steps). A dv_suite_result:
 * DV_SUITE_ERROR with err, and nothing written, for a file too sparse to
 * judge; with an error report in OUT/<name>/ when a reference fails. The
 * caller holds out_dir's lock. */
int dv_report_judge_run(const dv_scenario *sc, dv_replay *replays, size_t n, const char *out_dir,
                        const char *junit, double *theta_err, dv_error *err);

#endif
