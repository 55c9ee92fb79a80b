/* report_within: compare under a wall-time limit (compare --timeout S): a
 * scenario's comparison and report, as dv_report_suite_run_one makes them,
 * in a process of its own killed at the limit (run_within.h). */
#ifndef DV_REPORT_WITHIN_H
#define DV_REPORT_WITHIN_H

#include "report_suite_run.h"

/* dv_report_suite_run_one(sc, engines, out_dir, verbose 1, explain, jobs) within
 * timeout s (<= 0: no limit): its dv_suite_result. Refused before it starts
 * (DV_SUITE_ERROR, nothing written) when its probed cost is more than
 * DV_RUN_WITHIN_REFUSE times the limit; killed at the limit, DV_SUITE_ERROR
 * "timed out after S s", its temporaries removed and that error report in
 * out_dir, as a suite's scenario. The caller holds out_dir's lock. */
int dv_report_compare_within(const dv_scenario *sc, const dv_engine_type *const *engines,
                             const char *out_dir, const dv_report_explain *explain, int jobs,
                             double timeout, dv_error *err);

#endif
