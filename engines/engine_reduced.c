/* engine_reduced: the reference (reduced equations, reduced/) as an engine. */
#include <gsl/gsl_version.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_version.h>

#include "dv_engine.h"
#include "red_reference.h"
#include "dv_reference.h"
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
  double y[RED_NSTATE], s[RR_NSTATE];
  const int status = red_integrator_advance(e->in, t, &out->t, y, &e->event, err);
  red_rolling_from_state(&e->thin, y, s);
  dv_reference_sample(&e->thin, s, out);
  memcpy(out->y, y, sizeof y); /* exactly the integrated state, not its round trip */
  return status;
}

static void reduced_stats(const void *p, dv_engine_stats *out) {
  const reduced_engine *e = p;
  char detail[96];
  snprintf(detail, sizeof detail, "theta reached %s limit %g rad",
           e->event == RED_EVENT_THETA_LOW ? "the lower" : "the upper",
           e->event == RED_EVENT_THETA_LOW ? e->ref.theta_limit : M_PI - e->ref.theta_limit);
  dv_reference_stats(e->in, e->event, detail, out);
}

const dv_engine_type dv_engine_reduced = {
    "reduced",       "reference: the reduced equations (GSL / SUNDIALS integrators)",
    reduced_version, reduced_alloc,
    reduced_reset,   reduced_advance,
    reduced_stats,   reduced_free};
