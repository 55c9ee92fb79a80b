/* dv_reference: samples and stats of the reference engines. */
#include "dv_reference.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void dv_reference_sample(const red_rolling *rr, const double s[RR_NSTATE], const double *y,
                         dv_sample *out) {
  double wdot[3];
  if (y)
    memcpy(out->y, y, RED_NSTATE * sizeof(double));
  else
    red_rolling_to_state(s, out->y);
  out->slip = out->penetration = 0.0;
  out->contacts = 1;
  if (red_rolling_observe(rr, s, out->contact, &out->energy, wdot, out->force))
    out->force[0] = out->force[1] = out->force[2] = NAN;
}

void dv_reference_stats(const red_integrator *in, int event, const char *detail,
                        dv_engine_stats *out) {
  red_stats s;
  red_integrator_stats(in, &s);
  memset(out, 0, sizeof *out);
  out->steps = s.steps;
  out->rhs_evals = s.rhs_evals;
  out->contacts_max = 1;
  out->outcome = event >= 0 ? DV_OUTCOME_EVENT : DV_OUTCOME_COMPLETED;
  if (event >= 0) snprintf(out->detail, sizeof out->detail, "%s", detail);
  if (red_integrator_stalled(in)[0]) { /* the progress guard ended it */
    out->outcome = DV_OUTCOME_ERROR;
    snprintf(out->detail, sizeof out->detail, "%s", red_integrator_stalled(in));
  }
}

const dv_reduced_settings *dv_reference_settings(const dv_scenario *sc) {
  return dv_scenario_settings(sc, dv_engine_of_role(DV_ENGINE_THIN_REFERENCE)->name);
}

const dv_matched_settings *dv_matched_settings_of(const dv_scenario *sc) {
  return dv_scenario_settings(sc, dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE)->name);
}

double dv_matched_friction(const dv_scenario *sc) {
  const dv_engine_type *m = dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE);
  double mu = dv_matched_settings_of(sc)->friction;
  dv_engine_derive_friction(sc, m->name, "friction", 1.0, "", &mu, NULL, 0, NULL);
  return mu;
}

void dv_reference_derive_friction(const dv_scenario *sc, const char *engine, double *value,
                                  char *why, size_t size, const char **keys) {
  const char *matched = dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE)->name;
  if (dv_scenario_is_given(sc, engine, "friction") ||
      !dv_scenario_is_given(sc, matched, "friction")) {
    dv_engine_derive_friction(sc, engine, "friction", 1.0, "", value, why, size, keys);
    return;
  }
  *value = dv_matched_friction(sc);
  size_t n = 0;
  while (keys && keys[n]) n++;
  if (keys) keys[n++] = "friction", keys[n] = NULL;
  if (!why || !size) return;
  const size_t used = strnlen(why, size);
  snprintf(why + used, size - used, "%sfriction %g: [engines.%s] friction, the validity window's",
           used ? "; " : "", *value, matched);
}

double dv_reference_valid_until(const dv_scenario *sc, const dv_sample *s, size_t n) {
  const double mu = dv_matched_friction(sc);
  for (size_t i = 0; i < n; i++) {
    const double *F = s[i].force;
    if (!(F[2] > 0.0) || hypot(F[0], F[1]) > mu * F[2]) return i ? s[i - 1].t : 0.0;
  }
  return INFINITY;
}
