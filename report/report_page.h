/* report_page: a report directory's own page, for a person to read at a glance.
 *
 * dir/index.html, from dir/report.json (report_format.h) and the files beside
 * it: the scenario (description, file, duration, the reference), a table of
 * one row per engine (verdict, the line that decided, the body whose reference
 * judged it, theta and path error against their limits, cost) whose every
 * cell is one line, then per engine why its verdict is what it is in
 * sentences ("decided_why" when the report has it, else its window, horizon,
 * reference note, cause), then the plots the report lists that exist, and
 * links to its files. An error report (or a report.json that cannot be read)
 * gives a page that says so. Self-contained: inline CSS, no scripts, no
 * network; all text escaped; same report, same bytes. Written atomically.
 *
 * Returns DV_OK, or DV_EINPUT (a path too long) / DV_ESYSTEM (not written)
 * with err set.
 */
#ifndef DV_REPORT_PAGE_H
#define DV_REPORT_PAGE_H

#include "dv_error.h"

/* write dir/index.html from dir/report.json */
int dv_report_page_write(const char *dir, dv_error *err);

#endif
