/* engine_matched: the geometry-matched reference (red_rolling.h) as an
 * engine: the disk of the engine's half-thickness, rolling without slip,
 * ending where the rolling model stops describing the physics. */
#include <gsl/gsl_version.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_reference.h"
#include "red_rolling.h"

typedef struct matched_engine {
  red_rolling rr;
  red_integrator *in;
  double t_end;
  int event;
  double t_event;
} matched_engine;

static const char *matched_version(void) {
  return "GSL " GSL_VERSION;
}

static void matched_free(void *p) {
  matched_engine *e = p;
  if (!e) return;
  red_integrator_free(e->in);
  free(e);
}

static void *matched_alloc(const dv_scenario *sc, dv_error *err) {
  matched_engine *e = calloc(1, sizeof *e);
  if (!e) return dv_fail(err, DV_ESYSTEM, "out of memory"), NULL;
  red_rolling_init(&e->rr, &sc->disk, sc->matched.half_thickness, sc->matched.friction,
                   sc->reduced.theta_limit);
  e->t_end = sc->duration;
  e->event = -1;
  const red_stepper_type *T = red_stepper_find(sc->reduced.integrator);
  e->in = T ? red_integrator_alloc(&e->rr.sys, T, sc->reduced.rtol, sc->reduced.atol, err) : NULL;
  if (!e->in) return matched_free(e), NULL;
  return e;
}

static int matched_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  matched_engine *e = p;
  double s[RR_NSTATE];
  e->event = -1;
  red_rolling_from_state(&e->rr, state, s);
  return red_integrator_reset(e->in, 0.0, e->t_end, s, err);
}

static int matched_advance(void *p, double t, dv_sample *out, dv_error *err) {
  matched_engine *e = p;
  double s[RR_NSTATE];
  const int status = red_integrator_advance(e->in, t, &out->t, s, &e->event, err);
  if (status < 0) return status;
  if (e->event >= 0) e->t_event = out->t;
  dv_reference_sample(&e->rr, s, out);
  return status;
}

static void matched_stats(const void *p, dv_engine_stats *out) {
  const matched_engine *e = p;
  char detail[128];
  snprintf(detail, sizeof detail, "%s at t = %.9g s",
           e->event == RR_EVENT_NORMAL_FORCE ? "the normal force reached zero"
           : e->event == RR_EVENT_FRICTION ? "the friction needed reached mu times the normal force"
           : e->event == RR_EVENT_UPRIGHT  ? "the thick disk reached upright (a rim-corner impact)"
                                           : "theta reached its lying-down limit",
           e->t_event);
  dv_reference_stats(e->in, e->event, detail, out);
}

const dv_engine_type dv_engine_matched = {
    "matched",
    "reference for a disk of finite thickness (Newton-Euler rolling, validity window)",
    matched_version,
    matched_alloc,
    matched_reset,
    matched_advance,
    matched_stats,
    matched_free};
