/* search_verify: convergence of a contact engine to the reference (search_verify.h). */
#include "search_verify.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dv_engine.h"

const char *dv_search_convergence_name(dv_convergence c) {
  static const char *const names[] = {"converges to the reference", "converges elsewhere",
                                      "does not converge"};
  return (unsigned)c < 3 ? names[c] : "unknown";
}

/* Richardson's e(0) from errors a, b, c at steps halving each time; its order in *p */
static double richardson(double a, double b, double c, double *p) {
  const double d1 = a - b, d2 = b - c;
  *p = d1 > 0.0 && d2 > 0.0 ? log2(d1 / d2) : NAN;
  return *p > 0.2 ? c - d2 / (pow(2.0, *p) - 1.0) : NAN;
}

void dv_search_verify_judge(dv_verification *v) {
  const double *e = v->error;
  const int flat = fabs(e[0] - e[3]) <= DV_VERIFY_FLAT * e[0];
  double p, q;
  const double late = richardson(e[1], e[2], e[3], &p), early = richardson(e[0], e[1], e[2], &q);
  v->order = !flat && p > 0.2 ? p : NAN;
  v->extrapolated = isnan(v->order) ? e[3] : late;
  v->uncertainty = 0.0;
  if (!isnan(v->order) && fabs(p - q) <= DV_VERIFY_ORDER_SPREAD && isfinite(early))
    v->uncertainty = fmax(fabs(late - early), v->extrapolated < 0.0 ? -v->extrapolated : 0.0);
  if (e[3] <= DV_VERIFY_FLOOR ||
      fabs(v->extrapolated) <= fmax(DV_VERIFY_FLOOR, v->uncertainty))
    v->verdict = DV_CONVERGES;
  else /* flat: the step no longer matters, what is left is the model's */
    v->verdict = flat || !isnan(v->order) ? DV_CONVERGES_ELSEWHERE : DV_DOES_NOT_CONVERGE;
}

int dv_search_verify(const dv_scenario *sc, const char *engine_name, dv_verification *out,
                     dv_error *err) {
  memset(out, 0, sizeof *out);
  const dv_engine_type *engine = dv_engine_find(engine_name);
  if (!engine) return dv_fail(err, DV_EINPUT, "unknown engine '%s'", engine_name);
  const dv_engine_contact *k = engine->contact;
  if (!k || !engine->search)
    return dv_fail(err, DV_EINPUT, "%s is not a contact engine: nothing to verify", engine->name);
  const char *name = engine->name;
  const double dt = dv_scenario_get(sc, name, engine->search->step_key);
  const double soft = dv_scenario_get(sc, name, k->softness_key);
  const dv_prober pr = {sc, engine, 1};
  for (int i = 0; i < DV_VERIFY_LEVELS; i++) {
    const double h = dt / (1 << i);
    char step[128], softness[128];
    snprintf(step, sizeof step, "engines.%s.%s=%.9g", name, engine->search->step_key, h);
    snprintf(softness, sizeof softness, "engines.%s.%s=%.9g", name, k->softness_key,
             fmax(soft * h / dt, k->softness_min_steps * h));
    out->step[i] = h;
    const int status = dv_search_probe_theta(&pr, &out->error[i], err, step, softness, NULL, NULL);
    if (status) return status;
  }
  dv_search_verify_judge(out);
  if (out->verdict != DV_CONVERGES_ELSEWHERE) return DV_OK;
  dv_attribution a;
  const int status = dv_search_attribute(sc, name, &a, err);
  if (status) return status;
  dv_search_attribute_cause(&a, out->cause, sizeof out->cause);
  return DV_OK;
}
