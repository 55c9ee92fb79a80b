/* dv_trajectory: run an engine over a scenario and write the trajectory CSV.
 *
 * CSV: one row per output_dt (and one at an event that ends the run), header
 *   t,theta,phi,psi,x,y,contact_x,contact_y,theta_dot,phi_dot,psi_dot,energy
 * in seconds, radians, metres, rad/s and joules.
 */
#ifndef DV_TRAJECTORY_H
#define DV_TRAJECTORY_H

#include <stdio.h>

#include "dv_engine.h"
#include "scenario.h"

#define DV_CSV_HEADER "t,theta,phi,psi,x,y,contact_x,contact_y,theta_dot,phi_dot,psi_dot,energy"

/* one CSV row */
void dv_run_csv_row(FILE *fp, const dv_sample *s);

/* receives each sample; non-zero stops the run, as out of memory (a sink
 * that stops a run on purpose passes no err) */
typedef int (*dv_sample_sink)(void *ctx, const dv_sample *s);

/* run engine over sc, one sample at t = 0, every output_dt and at an event,
 * each passed to sink; stats are filled in any case. Returns DV_OK, DV_EVENT
 * (ended early) or < 0 with err set (the samples so far were delivered). */
int dv_run_collect(const dv_engine_type *engine, const dv_scenario *sc, dv_sample_sink sink,
                   void *ctx, dv_engine_stats *stats, dv_error *err);

#define DV_FORCES_HEADER "t,force_x,force_y,force_z,friction_ratio"

/* run engine over sc, writing CSV rows to fp and, when forces is not NULL,
 * the contact force (N; friction_ratio = |F_h| / F_z) to forces; either may
 * be NULL. Stats are filled in any case.
 * Returns DV_OK, DV_EVENT (ended early) or < 0 with err set. */
int dv_run_write_csv(const dv_engine_type *engine, const dv_scenario *sc, FILE *fp, FILE *forces,
                     dv_engine_stats *stats, dv_error *err);

#endif
