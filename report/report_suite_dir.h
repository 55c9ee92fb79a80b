/* dv_report_dir: a scenario's report directory OUT/<name>/, replaced whole.
 *
 * A report is built in a temporary directory beside it
 * (OUT/.<name>.tmp.PID.XXXXXX, io_temp.h) and put in place by renames: the
 * old one set aside (OUT/.<name>.old.PID), the new one moved in, the old
 * one removed; the temporaries of <name> that dead runs left are removed
 * first (io_temp.h). A scenario that fails gets an error report instead, so no
 * earlier report outlives a failed run:
 *   report.json  {"scenario": NAME, "file": PATH, "pass": false,
 *                 "error": CAUSE, "engines": {}}
 *   report.md    the name and the cause
 */
#ifndef DV_REPORT_DIR_H
#define DV_REPORT_DIR_H

#include <stddef.h>

#include "dv_error.h"
#include "scenario.h"

/* make a new temporary directory for name's report in out_dir; its path in tmp */
int dv_report_dir_begin(char *tmp, size_t size, const char *out_dir, const char *name,
                        dv_error *err);

/* put the complete directory tmp in place of out_dir/name; on failure tmp
 * is removed and the old report kept */
int dv_report_dir_install(const char *tmp, const char *out_dir, const char *name, dv_error *err);

/* replace out_dir/<sc's name> by an error report saying cause; when even
 * that cannot be written, the old report is removed */
int dv_report_dir_write_error(const char *out_dir, const dv_scenario *sc, const char *cause,
                              dv_error *err);

#endif
