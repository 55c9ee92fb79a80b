/* dv_scenario_report: one scenario's comparison as files (format: dv_report.h). */
#ifndef DV_SCENARIO_REPORT_H
#define DV_SCENARIO_REPORT_H

#include <stdio.h>

#include "dv_run.h"

/* write trajectories, plots, report.json and report.md into the existing dir */
int dv_scenario_report_write(const char *dir, const dv_comparison *c, dv_error *err);

/* one line per engine for a terminal: verdict, theta and path errors */
void dv_scenario_report_print(FILE *fp, const dv_comparison *c);

#endif
