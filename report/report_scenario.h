/* dv_scenario_report: one scenario's comparison as files (format: dv_report.h). */
#ifndef DV_SCENARIO_REPORT_H
#define DV_SCENARIO_REPORT_H

#include <stdio.h>

#include "run_scenario.h"

/* write trajectories, plots, report.json and report.md into the existing dir */
int dv_report_scenario_write(const char *dir, const dv_comparison *c, dv_error *err);

/* one line per engine for a terminal: verdict, theta and path errors */
void dv_report_scenario_print(FILE *fp, const dv_comparison *c);

#endif
