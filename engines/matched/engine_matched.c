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

/* the half-thickness matched: the key's, else the disk's own (a scenario built in code
 * and not derived yet) */
static double half_thickness_of(const dv_scenario *sc) {
  const double h = dv_matched_settings_of(sc)->half_thickness;
  return isnan(h) ? 0.5 * sc->thickness : h;
}

static void *matched_alloc(const dv_scenario *sc, dv_error *err) {
  const dv_reduced_settings *r = dv_reference_settings(sc);
  matched_engine *e = calloc(1, sizeof *e);
  if (!e) return dv_fail(err, DV_ESYSTEM, "out of memory: the matched reference's state"), NULL;
  red_rolling_init(&e->rr, &sc->disk, half_thickness_of(sc), dv_matched_friction(sc),
                   r->theta_limit);
  e->t_end = sc->duration;
  e->event = -1;
  e->in = red_integrator_alloc(&e->rr.sys, red_steppers[r->integrator], r->rtol, r->atol, err);
  if (!e->in) return matched_free(e), NULL;
  red_integrator_set_max_steps(e->in, r->max_steps);
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
  if (e->event == RR_EVENT_UPRIGHT) {
    /* the root of cos theta may land an ulp past upright (seed 1 scene 59 of
     * diskval_props: pi/2 + 2.2e-16), where the sample would stand on the
     * other rim corner: its energy 3.8% off, its contact point 2 h away */
    double y[RED_NSTATE];
    red_rolling_to_state(s, y);
    if (y[RED_VTH] != 0.0) s[RR_TH] = M_PI_2 - copysign(1e-15, y[RED_VTH]);
  }
  dv_reference_sample(&e->rr, s, NULL, out);
  return status;
}

static void matched_stats(const void *p, dv_engine_stats *out) {
  const matched_engine *e = p;
  char detail[128];
  /* lying down in the words of every engine's event, with its limit (run_event.h) */
  if (e->event == RR_EVENT_THETA_LOW || e->event == RR_EVENT_THETA_HIGH)
    dv_engine_limit_detail(e->event == RR_EVENT_THETA_LOW, e->rr.theta_limit, e->t_event, detail,
                           sizeof detail);
  else
    snprintf(detail, sizeof detail, "%s at t = %.9g s",
             e->event == RR_EVENT_NORMAL_FORCE ? "the normal force reached zero"
             : e->event == RR_EVENT_FRICTION
                 ? "the friction needed reached mu times the normal force"
                 : "the thick disk reached upright (a rim-corner impact)",
             e->t_event);
  dv_reference_stats(e->in, e->event, detail, out);
  if (out->outcome == DV_OUTCOME_EVENT && e->event <= RR_EVENT_THETA_HIGH)
    out->lay_down = e->event == RR_EVENT_THETA_LOW ? -1 : 1;
}

#define AT(field) offsetof(dv_matched_settings, field)

static const dv_setting_spec KEYS[] = {
    {"half_thickness", DV_SETTING_REAL, AT(half_thickness), 0, 0, NAN, 0.0, 1.0, NULL, NULL, "m",
     "of the cylinder to match (0: the thin disk); default: [disk] thickness / 2"},
    {"friction", DV_SETTING_REAL, AT(friction), 0, 0, NAN, 0.0, 1e6, NULL, NULL, "",
     "friction coefficient that ends the validity window; default: [disk] friction"},
};

/* the disk's own thickness and friction unless given */
static int matched_check(dv_scenario *sc, void *block, dv_setting_issue *issue) {
  dv_matched_settings *s = block;
  char why[DV_DERIVED_BYTES] = "";
  const char *keys[4] = {NULL};
  (void)issue;
  if (isnan(s->half_thickness)) s->half_thickness = 0.5 * sc->thickness;
  dv_engine_derive_friction(sc, "matched", "friction", 1.0, "", &s->friction, why, sizeof why,
                            keys);
  dv_scenario_set_derived(sc, "matched", keys, why);
  return 0;
}

static const dv_settings_section SETTINGS = {"matched", KEYS, sizeof KEYS / sizeof KEYS[0],
                                             sizeof(dv_matched_settings), matched_check};

static double matched_half_thickness(const dv_scenario *sc) {
  return half_thickness_of(sc);
}

static int matched_tighten(dv_scenario *sc, dv_error *err) {
  return dv_engine_of_role(DV_ENGINE_THIN_REFERENCE)->tighten(sc, err);
}

const dv_engine_type dv_engine_matched = {
    .name = "matched",
    .description =
        "reference for a disk of finite thickness (Newton-Euler rolling, validity window)",
    .role = DV_ENGINE_MATCHED_REFERENCE,
    .settings = &SETTINGS,
    .search = &dv_reference_search,
    .half_thickness = matched_half_thickness,
    .tighten = matched_tighten,
    .version = matched_version,
    .alloc = matched_alloc,
    .reset = matched_reset,
    .advance = matched_advance,
    .stats = matched_stats,
    .free = matched_free,
};
