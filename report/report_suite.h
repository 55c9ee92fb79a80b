/* dv_suite_report: the suite's outputs, gathered from the per-scenario reports.
 *
 * Input: out_dir and n directory names relative to it, one per scenario, each
 * holding report.json (schema in dv_report.h) and the files it names. A
 * scenario whose report.json is missing, unreadable, not a JSON object or
 * without engines (e.g. the harness failed on it) is a harness error: it
 * still appears, and never stops the others. An error report (one with an
 * "error": CAUSE, report_suite_dir.h) is a harness error with that cause.
 *
 * Output, each file written atomically (dv_io_file.h):
 *   out_dir/summary.json
 *     {"pass": bool, "scenarios": [{"scenario", "dir", "pass", "engines":
 *     {ENGINE: {"pass", "outcome", "theta_max_err", "path_max_err",
 *     "wall_per_sim_s", "failures": [..], "limits": {..}, "reference": {..}}}}]}:
 *     limits and reference copied from the report (null when it has none);
 *     scenarios in the order given,
 *     engines in report order, a field the report lacks is null. An errored
 *     scenario has "pass": false, "engines": {}, "error": TEXT, and is named
 *     by its report if it has a name, else by its dir. A scenario passes when
 *     its report says so and every engine's "pass" is true (absent: false);
 *     the suite when every scenario passes (true for n == 0).
 *   out_dir/index.html
 *     self-contained (inline CSS, no scripts, no network) and well-formed
 *     XML: a summary table, one row per scenario x engine (numbers %.3g, an
 *     en dash when absent) or per errored scenario, then a section per
 *     scenario: description, reference outcome, the plots its report lists
 *     as <img src="DIR/NAME">, links to report.md, report.json and the
 *     trajectory CSVs. A file is referenced only if it exists; a name with
 *     '/' never. URLs are percent-encoded.
 *   junit_path, unless NULL ("-": stdout; relative to the working directory)
 *     <testsuites tests= failures= errors= time=>, per scenario a
 *     <testsuite name=SCENARIO ... time=> whose <properties> name its file
 *     and reference, timed by its reference runs and its engines'; per
 *     engine a <testcase classname=SCENARIO name=ENGINE time=S>, S its run's
 *     wall_s (older reports: wall_per_sim_s x window_end), "%.6f", whose
 *     <properties> give, passing or not, outcome, reference (engine,
 *     half-thickness or thin disk, integrator and rtol), for every metric
 *     METRIC, METRIC.limit, METRIC.margin ("%.6g", "none" when not judged)
 *     and METRIC.limit_from, window_end, pointwise_end, decided and
 *     decided_why; a
 *     failing engine then carries <failure message=FIRST>ALL</failure> (its
 *     outcome and detail when it lists no failure). An errored scenario is a
 *     test suite of one test case, named after its dir, carrying <error>.
 *     Valid against tests/fixtures/junit.xsd (what GitLab and Jenkins read).
 * All report text is HTML/XML-escaped and made valid UTF-8 (bad bytes and
 * control characters become '?'). Identical inputs give identical bytes: no
 * clock, no absolute paths; only the timing numbers vary with the reports.
 *
 * Returns DV_OK once every file is committed, whatever the verdict (read it
 * from summary.json); DV_EINPUT for a NULL out_dir or dir, or a path too
 * long; DV_ESYSTEM when a file cannot be written, with err set. All files are
 * opened before any is committed: an unwritable one leaves none written.
 */
#ifndef DV_SUITE_REPORT_H
#define DV_SUITE_REPORT_H

#include <stddef.h>

#include "dv_error.h"

/* write out_dir/summary.json, out_dir/index.html and the JUnit XML */
int dv_report_suite_write(const char *out_dir, const char *const *scenario_dirs, size_t n,
                          const char *junit_path, dv_error *err);

/* the same for a run that did not end (SIGINT): scenario i with
 * not_ended[i] != NULL is a harness error with that text as its cause, and
 * its directory (an earlier run's report, or none) is not read: the files
 * describe this run only */
int dv_report_suite_write_ended(const char *out_dir, const char *const *scenario_dirs,
                                const char *const *not_ended, size_t n, const char *junit_path,
                                dv_error *err);

/* the JUnit XML alone of one report directory out_dir/dir (judge --junit) */
int dv_report_suite_write_junit(const char *out_dir, const char *dir, const char *junit_path,
                                dv_error *err);

#endif
