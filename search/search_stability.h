/* dv_stability: stability limits of the engines on a set of scenarios.
 *
 * For every scenario and engine, the largest timestep at which the run stays
 * finite and within the scenario's theta_max_err tolerance for that engine
 * (0.1 rad where it has none), by bisection (dv_search.h), every probe kept;
 * then the failure mode just above the limit. Written as stability.json,
 * stability.md and stability.html into the suite's directory.
 */
#ifndef DV_STABILITY_H
#define DV_STABILITY_H

#include <stddef.h>

#include "dv_engine.h"
#include "scenario.h"

int dv_search_stability_run(const dv_scenario *scenarios, size_t n, const dv_engine_type *const *engines,
                     const char *const *sets, size_t nsets, const char *out_dir, int jobs,
                     dv_error *err);

#endif
