/* dv_reference: what the two reference engines (reduced, matched) share. */
#ifndef DV_REFERENCE_H
#define DV_REFERENCE_H

#include "dv_engine.h"
#include "engine_friction.h"
#include "red_rolling.h"
#include "red_solver.h"

/* [engines.reduced]: the reference solver's settings, table in engine_reduced.c */
typedef struct dv_reduced_settings {
  int integrator;     /* index into red_steppers */
  double rtol, atol;  /* of the integrator */
  double theta_limit; /* rad; every run ends where theta < limit or > pi - limit */
  int max_steps;      /* step budget of a run (red_solver.h's progress guard) */
  int fold;           /* DV_FOLD_*: later periods from the first (red_period.h) */
} dv_reduced_settings;

enum { DV_FOLD_PERIOD = 0, DV_FOLD_OFF };

/* [engines.matched]: the geometry-matched reference, table in engine_matched.c */
typedef struct dv_matched_settings {
  double half_thickness; /* m, cylinder half-length matched to the engine's */
  double friction;       /* the validity window ends where |F_h| > friction F_z
                          * (default: [disk] friction) */
} dv_matched_settings;

const dv_reduced_settings *dv_reference_settings(const dv_scenario *sc);

/* what a search over a reference varies: its integrator and rtol */
extern const dv_engine_search dv_reference_search;
const dv_matched_settings *dv_matched_settings_of(const dv_scenario *sc);

/* the validity window's friction coefficient: [engines.matched] friction where
 * given, else [disk] friction (engine_friction.h) */
double dv_matched_friction(const dv_scenario *sc);

/* an engine whose friction only ends its run where rolling needs more (one that
 * cannot slip): as dv_engine_derive_friction, but where its key is not given the
 * validity window's, dv_matched_friction */
void dv_reference_derive_friction(const dv_scenario *sc, const char *engine, double *value,
                                  char *why, size_t size, const char **keys);

/* the end of the thin reference's validity along its samples: the last one
 * before the rolling contact force turns away from the ground or leaves the
 * friction cone of dv_matched_friction; INFINITY when it never does */
double dv_reference_valid_until(const dv_scenario *sc, const dv_sample *s, size_t n);

/* a sample from a rolling state: canonical state (y, or from s where y is
 * NULL), contact point, energy and the contact force rolling needs (NaN
 * where undefined); no slip, no depth */
void dv_reference_sample(const red_rolling *rr, const double s[RR_NSTATE], const double *y,
                         dv_sample *out);

/* stats of a reference run: the integrator's counts, the event (or -1) and
 * its description */
void dv_reference_stats(const red_integrator *in, int event, const char *detail,
                        dv_engine_stats *out);

#endif
