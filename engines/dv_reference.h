/* dv_reference: what the two reference engines (reduced, matched) share. */
#ifndef DV_REFERENCE_H
#define DV_REFERENCE_H

#include "dv_engine.h"
#include "red_rolling.h"
#include "red_solver.h"

/* a sample from a rolling state: canonical state, contact point, energy and
 * the contact force rolling needs (NaN where undefined); no slip, no depth */
void dv_reference_sample(const red_rolling *rr, const double s[RR_NSTATE], dv_sample *out);

/* stats of a reference run: the integrator's counts, the event (or -1) and
 * its description */
void dv_reference_stats(const red_integrator *in, int event, const char *detail,
                        dv_engine_stats *out);

#endif
