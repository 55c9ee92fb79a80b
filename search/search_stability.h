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
#include "search_best.h"

/* one row of the tables: a scenario, an engine and the search on them */
typedef struct dv_stability_row {
  const char *scenario, *engine;
  const dv_search *search;
} dv_stability_row;

/* search every scenario with every contact engine in up to jobs processes
 * and write the tables into out_dir (under mpirun: rank 0 writes them);
 * DV_EVENT when SIGINT or SIGTERM stopped it (the tables hold what ended) */
int dv_search_stability_run(const dv_scenario *scenarios, size_t n,
                            const dv_engine_type *const *engines, const char *out_dir, int jobs,
                            dv_error *err);

/* stability.json, stability.md and stability.html of rows[0..n) into dir;
 * the page escapes every name (dv_report_escape) */
int dv_search_stability_write(const char *dir, const dv_stability_row *rows, size_t n,
                              dv_error *err);

#endif
