/* engine_reduced: the reference (reduced equations, reduced/) as an engine. */
#include <gsl/gsl_version.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_version.h>

#include "dv_engine.h"
#include "red_reference.h"
#include "red_rolling.h"

typedef struct reduced_engine {
  red_reference ref;
  red_rolling thin; /* the same disk in Newton-Euler form, for the contact force */
  red_integrator *in;
  double t_end;
  int event;
} reduced_engine;

static const char *reduced_version(void) {
  static char text[96];
  if (!text[0]) {
    char sundials[32] = "?";
    SUNDIALSGetVersion(sundials, (int)sizeof sundials);
    snprintf(text, sizeof text, "GSL %s, SUNDIALS %s", GSL_VERSION, sundials);
  }
  return text;
}

static void reduced_free(void *p) {
  reduced_engine *e = p;
  if (!e) return;
  red_integrator_free(e->in);
  free(e);
}

static void *reduced_alloc(const dv_scenario *sc, dv_error *err) {
  reduced_engine *e = calloc(1, sizeof *e);
  if (!e) return dv_fail(err, DV_ESYSTEM, "out of memory"), NULL;
  red_reference_init(&e->ref, &sc->disk, sc->reduced.theta_limit);
  red_rolling_init(&e->thin, &sc->disk, 0.0, INFINITY, sc->reduced.theta_limit);
  e->t_end = sc->duration;
  e->event = -1;
  const red_stepper_type *T = red_stepper_find(sc->reduced.integrator);
  if (!T) {
    reduced_free(e);
    return dv_fail(err, DV_EINPUT, "unknown integrator '%s'", sc->reduced.integrator), NULL;
  }
  e->in = red_integrator_alloc(&e->ref.sys, T, sc->reduced.rtol, sc->reduced.atol, err);
  if (!e->in) return reduced_free(e), NULL;
  return e;
}

static int reduced_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  reduced_engine *e = p;
  e->event = -1;
  return red_integrator_reset(e->in, 0.0, e->t_end, state, err);
}

static int reduced_advance(void *p, double t, dv_sample *out, dv_error *err) {
  reduced_engine *e = p;
  const int status = red_integrator_advance(e->in, t, &out->t, out->y, &e->event, err);
  red_contact_point(&e->ref.disk, out->y, out->contact);
  out->energy = red_energy(&e->ref.disk, out->y);
  out->slip = out->penetration = 0.0;
  out->contacts = 1;
  double s[RR_NSTATE], wdot[3];
  red_rolling_from_state(&e->thin, out->y, s);
  if (red_rolling_dynamics(&e->thin, s, wdot, out->force))
    out->force[0] = out->force[1] = out->force[2] = NAN;
  return status;
}

static void reduced_stats(const void *p, dv_engine_stats *out) {
  const reduced_engine *e = p;
  red_stats s;
  red_integrator_stats(e->in, &s);
  memset(out, 0, sizeof *out);
  out->steps = s.steps;
  out->rhs_evals = s.rhs_evals;
  out->contacts_max = 1;
  out->outcome = e->event >= 0 ? DV_OUTCOME_EVENT : DV_OUTCOME_COMPLETED;
  if (e->event >= 0)
    snprintf(out->detail, sizeof out->detail, "theta reached %s limit %g rad",
             e->event == RED_EVENT_THETA_LOW ? "the lower" : "the upper",
             e->event == RED_EVENT_THETA_LOW ? e->ref.theta_limit : M_PI - e->ref.theta_limit);
}

const dv_engine_type dv_engine_reduced = {
    "reduced",       "reference: the reduced equations (GSL / SUNDIALS integrators)",
    reduced_version, reduced_alloc,
    reduced_reset,   reduced_advance,
    reduced_stats,   reduced_free};
