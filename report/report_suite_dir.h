/* dv_report_dir: a scenario's report directory OUT/<name>/, replaced whole.
 *
 * A report is built in a temporary directory beside it
 * (OUT/.diskval-tmp.PID.XXXXXX, io_temp.h), marked as diskval's (io_owned.h),
 * and put in place by renames: the old one set aside (into another
 * temporary), the new one moved in, the old one removed; the temporaries
 * that dead runs left in OUT are removed first. OUT/<name> is replaced only
 * when it is a report diskval made: anything else there is an error naming
 * it, and nothing is written. A scenario that fails gets an error report
 * instead, so no earlier report outlives a failed run:
 *   report.json  {"scenario": NAME, "file": PATH, "pass": false,
 *                 "error": CAUSE, "engines": {}}
 *   report.md    the name and the cause
 */
#ifndef DV_REPORT_DIR_H
#define DV_REPORT_DIR_H

#include <stddef.h>

#include "dv_error.h"
#include "scenario.h"

/* make a new temporary directory for name's report in out_dir, its path in
 * tmp; DV_EINPUT when out_dir/name is something diskval may not replace */
int dv_report_dir_begin(char *tmp, size_t size, const char *out_dir, const char *name,
                        dv_error *err);

/* remove tmp (from dv_report_dir_begin) and stop tracking it */
void dv_report_dir_discard(const char *tmp);

/* put the complete directory tmp in place of out_dir/name; on failure tmp
 * is removed and the old report kept */
int dv_report_dir_install(const char *tmp, const char *out_dir, const char *name, dv_error *err);

/* before anything runs: out_dir/<each scenario's name> may be replaced
 * (absent, or a report diskval made), and no input of the run (the
 * scenarios' files and inputs[0..ninputs)) lies inside one of them; else
 * DV_EINPUT naming the path */
int dv_report_dir_check(const char *out_dir, const dv_scenario *scs, size_t n,
                        const char *const *inputs, size_t ninputs, dv_error *err);

/* before anything runs: the JUnit file junit (NULL or "-": none) is not
 * named as diskval's own files are (the mark, the lock, a temporary), is none
 * of the run's inputs (the scenarios' files and inputs[0..ninputs)), and
 * lies in none of the reports the run replaces (out_dir/<each name>, even
 * one not made yet, and through a symbolic link); else DV_EINPUT naming it */
int dv_report_dir_check_junit(const char *junit, const char *out_dir, const dv_scenario *scs,
                              size_t n, const char *const *inputs, size_t ninputs, dv_error *err);

/* replace out_dir/<sc's name> by an error report saying cause; when even
 * that cannot be written, the old report is removed */
int dv_report_dir_write_error(const char *out_dir, const dv_scenario *sc, const char *cause,
                              dv_error *err);

#endif
