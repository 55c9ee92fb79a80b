/* dv_suite_report: the suite's outputs, gathered from the per-scenario reports.
 *
 * Input: out_dir and n directory names relative to it, one per scenario, each
 * holding report.json (schema in dv_report.h) and the files it names. A
 * scenario whose report.json is missing, unreadable, not a JSON object or
 * without engines (e.g. the harness failed on it) is a harness error: it
 * still appears, and never stops the others.
 *
 * Output, each file written atomically (dv_io_file.h):
 *   out_dir/summary.json
 *     {"pass": bool, "scenarios": [{"scenario", "dir", "pass", "engines":
 *     {ENGINE: {"pass", "outcome", "theta_max_err", "path_max_err",
 *     "wall_per_sim_s", "failures": [..]}}}]}: scenarios in the order given,
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
 *     <testsuites><testsuite name="diskval" tests= failures= errors= time=>,
 *     per scenario x engine a <testcase classname=SCENARIO name=ENGINE
 *     time=S> with S = wall_per_sim_s x window_end (duration if absent),
 *     "%.3f"; a failing engine carries <failure message=FIRST>ALL</failure>
 *     (its outcome and detail when it lists no failure). An errored scenario
 *     is one test case, named after its dir, carrying <error>.
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

#endif
