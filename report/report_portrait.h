/* report_portrait: the effective potential and phase plane of a scenario's body. */
#ifndef DV_REPORT_PORTRAIT_H
#define DV_REPORT_PORTRAIT_H

#include "dv_error.h"
#include "run_scenario.h"

/* dir/potential.svg and dir/phase.svg for c: the thin disk's from its integrals, a
 * thick disk's from the matched reference's run of its cylinder (the thin disk's
 * where no engine ran the cylinder); colour[k] is engine k's colour number
 * (dv_plot_curve's), colour[c->n] the matched reference's, as in the scenario's
 * plots (dv_report_plot_series_colours) */
int dv_report_portraits(const char *dir, const dv_comparison *c, const int *colour, dv_error *err);

#endif
