/* engine_reduced: the reference (reduced equations, reduced/) as an engine. */
#include <gsl/gsl_version.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_version.h>

#include "dv_format.h"
#include "dv_engine.h"
#include "red_reference.h"
#include "dv_reference.h"
#include "engine_scene.h"
#include "red_period.h"
#include "red_rolling.h"

typedef struct reduced_engine {
  red_reference ref;
  red_rolling thin; /* the same disk in Newton-Euler form, for the contact force */
  red_integrator *in;
  red_period *period; /* NULL: step to the end */
  double t_end;
  int event;
  double t_event; /* s: where the event ended the run */
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
  red_period_free(e->period);
  free(e);
}

static void *reduced_alloc(const dv_scenario *sc, dv_error *err) {
  const dv_reduced_settings *s = dv_reference_settings(sc);
  reduced_engine *e = calloc(1, sizeof *e);
  if (!e) return dv_fail(err, DV_ESYSTEM, "out of memory: the reduced reference's state"), NULL;
  red_reference_init(&e->ref, &sc->disk, s->theta_limit);
  red_rolling_init(&e->thin, &sc->disk, 0.0, INFINITY, s->theta_limit);
  e->t_end = sc->duration;
  e->event = -1;
  e->t_event = NAN;
  e->in = red_integrator_alloc(&e->ref.sys, red_steppers[s->integrator], s->rtol, s->atol, err);
  if (!e->in) return reduced_free(e), NULL;
  red_integrator_set_max_steps(e->in, s->max_steps);
  /* only a free-stepping integrator's step ends carry its dense output */
  if (s->fold == DV_FOLD_PERIOD && red_steppers[s->integrator]->caps & RED_CAP_DENSE) {
    e->period = red_period_alloc(&sc->disk, s->rtol, s->atol, err);
    if (!e->period) return reduced_free(e), NULL;
    red_integrator_observe(e->in, red_period_record, e->period);
  }
  return e;
}

static int reduced_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  reduced_engine *e = p;
  e->event = -1;
  e->t_event = NAN;
  if (e->period && red_period_reset(e->period, 0.0, state, err)) return DV_ESYSTEM;
  return red_integrator_reset(e->in, 0.0, e->t_end, state, err);
}

/* y at t from the recorded or folded period; 1 where it has no answer */
static int from_period(reduced_engine *e, double t, double *y, dv_error *err) {
  if (!e->period || red_period_state(e->period) == RED_PERIOD_OFF) return 1;
  if (!red_period_covers(e->period, t)) {
    const int status = red_integrator_step_to(e->in, t, err);
    if (status) return status;
  }
  if (!red_period_covers(e->period, t)) return 1; /* an event, or no fold */
  return red_period_eval(e->period, t, y);
}

static int reduced_advance(void *p, double t, dv_sample *out, dv_error *err) {
  reduced_engine *e = p;
  double y[RED_NSTATE] = {0}, s[RR_NSTATE];
  int status = from_period(e, t, y, err);
  if (status == DV_OK)
    out->t = t;
  else if (status > 0)
    status = red_integrator_advance(e->in, t, &out->t, y, &e->event, err);
  if (e->event >= 0 && isnan(e->t_event)) e->t_event = out->t;
  red_rolling_from_state(&e->thin, y, s);
  dv_reference_sample(&e->thin, s, y, out); /* exactly the integrated state, not its round trip */
  return status;
}

static void reduced_stats(const void *p, dv_engine_stats *out) {
  const reduced_engine *e = p;
  char detail[96];
  dv_engine_limit_detail(e->event == RED_EVENT_THETA_LOW, e->ref.theta_limit, e->t_event, detail,
                         sizeof detail);
  dv_reference_stats(e->in, e->event, detail, out);
  if (out->outcome == DV_OUTCOME_EVENT) out->lay_down = e->event == RED_EVENT_THETA_LOW ? -1 : 1;
  if (e->period) snprintf(out->method, sizeof out->method, "%s", red_period_note(e->period));
}

static const char *integrator_at(size_t i) {
  for (size_t k = 0; k < i; k++)
    if (!red_steppers[k]) return NULL;
  return red_steppers[i] ? red_steppers[i]->name : NULL;
}

/* the step budget a scenario leaves out: RED_STEPS_PER_SCALE steps per
 * shortest time scale of the scene over its duration, at least
 * RED_DEFAULT_MAX_STEPS (rk8pd at the defaults takes about 13 per scale) */
static void derive_max_steps(dv_scenario *sc, dv_reduced_settings *s) {
  static const char *const keys[] = {"max_steps", NULL};
  dv_scene_scales scales;
  dv_engine_scene_scales(sc, &scales);
  const double t = scales.t[scales.shortest];
  const double budget =
      fmax((double)RED_DEFAULT_MAX_STEPS, fmin(1e9, RED_STEPS_PER_SCALE * sc->duration / t));
  s->max_steps = (int)budget;
  char why[DV_DERIVED_BYTES];
  snprintf(why, sizeof why, "max_steps %d: %g steps per %s (%.3g s) over %g s, at least %ld",
           s->max_steps, RED_STEPS_PER_SCALE, dv_scale_names[scales.shortest], t, sc->duration,
           RED_DEFAULT_MAX_STEPS);
  dv_scenario_set_derived(sc, "reduced", keys, why);
}

/* the lying-down limit is every engine's: the initial tilt must lie inside it;
 * and the step budget, when not given */
static int reduced_check(dv_scenario *sc, void *block, dv_setting_issue *issue) {
  dv_reduced_settings *s = block;
  const double theta = sc->initial[RED_TH];
  if (theta > s->theta_limit && theta < M_PI - s->theta_limit) {
    if (s->max_steps == 0) derive_max_steps(sc, s);
    return 0;
  }
  char value[DV_FORMAT_SIZE], lo[DV_FORMAT_SIZE], hi[DV_FORMAT_SIZE];
  dv_format_double(theta, value, sizeof value);
  dv_format_double(s->theta_limit, lo, sizeof lo);
  dv_format_double(M_PI - s->theta_limit, hi, sizeof hi);
  issue->section = "initial";
  issue->key = "theta";
  snprintf(issue->what, sizeof issue->what, "%s is outside (%s, %s), the lying-down limits", value,
           lo, hi);
  return -1;
}

static const char *const FOLDS[] = {"period", "off", NULL};

#define AT(field) offsetof(dv_reduced_settings, field)
#define OPEN (DV_SETTING_OPEN_LO | DV_SETTING_OPEN_HI)

/* the default integrator comes first in red_steppers */
static const dv_setting_spec KEYS[] = {
    {"integrator", DV_SETTING_CHOICE, AT(integrator), 0, 0, 0, 0, 0, NULL, integrator_at, "",
     "GSL or SUNDIALS integrator (diskval engines lists them)"},
    {"rtol", DV_SETTING_REAL, AT(rtol), 0, OPEN, 1e-12, 0.0, 1.0, NULL, NULL, "", "relative"},
    {"atol", DV_SETTING_REAL, AT(atol), 0, OPEN, 1e-13, 0.0, 1.0, NULL, NULL, "", "absolute"},
    {"theta_limit", DV_SETTING_REAL, AT(theta_limit), 0, OPEN, 0.01, 0.0, M_PI / 2, NULL, NULL,
     "rad", "every run ends where theta < limit or > pi - limit"},
    {"max_steps", DV_SETTING_INT, AT(max_steps), 0, 0, NAN, 1, 1e9, NULL, NULL, "",
     "step budget of a reference run: past it the run ends with an error; default: 1000 steps "
     "per shortest time scale of the scene, at least 1e6"},
    {"fold", DV_SETTING_CHOICE, AT(fold), 0, 0, 0, 0, 0, FOLDS, NULL, "",
     "period: once the reduced state closes over a nutation period, later times come from that "
     "period moved by the disk's symmetries (gsl-rk8pd only); off: step to the end"},
};

static const dv_settings_section SETTINGS = {"reduced", KEYS, sizeof KEYS / sizeof KEYS[0],
                                             sizeof(dv_reduced_settings), reduced_check};

/* the tightest reference: stepping onto every sample at rtol 1e-14 */
static int reduced_tighten(dv_scenario *sc, dv_error *err) {
  if (dv_scenario_set(sc, "reduced", "integrator", "gsl-rk8pd-stepped", err) ||
      dv_scenario_set_number(sc, "reduced", "rtol", 1e-14, err) ||
      dv_scenario_set_number(sc, "reduced", "atol", 1e-16, err))
    return DV_EINPUT;
  return DV_OK;
}

/* the reference's own accuracy: its integrator and rtol */
const dv_engine_search dv_reference_search = {"reduced", "integrator", "rtol",
                                              1e-14,     1e-3,         "rtol=1e-6..1e-13:8"};

const dv_engine_type dv_engine_reduced = {
    .name = "reduced",
    .description = "reference: the reduced equations (GSL / SUNDIALS integrators)",
    .role = DV_ENGINE_THIN_REFERENCE,
    .settings = &SETTINGS,
    .search = &dv_reference_search,
    .tighten = reduced_tighten,
    .version = reduced_version,
    .alloc = reduced_alloc,
    .reset = reduced_reset,
    .advance = reduced_advance,
    .stats = reduced_stats,
    .free = reduced_free,
};
