/* search_verify: convergence of a contact engine to the reference (search_verify.h). */
#include "search_verify.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_phase.h"

const char *dv_search_convergence_name(dv_convergence c) {
  static const char *const names[] = {"converges to the reference", "converges elsewhere",
                                      "does not converge", "not judged"};
  return (unsigned)c < 4 ? names[c] : "unknown";
}

void dv_search_convergence_why(const double *h, const double *e, int n, dv_convergence verdict,
                               char *why, size_t size) {
  why[0] = '\0';
  if (verdict != DV_CONVERGE_NOT_JUDGED) return;
  for (int i = 1; i < n; i++)
    if (e[i] == e[i - 1]) {
      snprintf(why, size,
               "the trajectories at dt %.3g and %.3g have the same theta error exactly, %.3g rad "
               "(one run given twice, or nothing to fall from?): errors that do not change "
               "cannot show convergence",
               h[i - 1], h[i], e[i]);
      return;
    }
  snprintf(why, size, "the errors do not fall with the step: no convergence shown");
}

/* r2^p (r1^p - 1) / (r2^p - 1): the ratio of successive error differences
 * that order p gives at step ratios r1 = ha/hb, r2 = hb/hc */
static double difference_ratio(double r1, double r2, double p) {
  return pow(r2, p) * (pow(r1, p) - 1.0) / (pow(r2, p) - 1.0);
}

/* Richardson's e(0) from errors a, b, c at steps ha > hb > hc; its order in *p */
static double richardson(double a, double b, double c, double ha, double hb, double hc, double *p) {
  const double d1 = a - b, d2 = b - c, r1 = ha / hb, r2 = hb / hc;
  if (!(d1 > 0.0 && d2 > 0.0)) {
    *p = NAN;
  } else if (r1 == 2.0 && r2 == 2.0) { /* verify's levels */
    *p = log2(d1 / d2);
  } else if (fabs(r1 - r2) <= 1e-9 * r2) {
    *p = log(d1 / d2) / log(r2);
  } else { /* the ratio grows with p: bisect on [0.2, 30], else no order above 0.2 */
    double lo = 0.2, hi = 30.0;
    const double want = d1 / d2;
    if (difference_ratio(r1, r2, lo) > want || difference_ratio(r1, r2, hi) < want) {
      *p = NAN;
    } else {
      for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; i++) {
        const double mid = 0.5 * (lo + hi);
        *(difference_ratio(r1, r2, mid) < want ? &lo : &hi) = mid;
      }
      *p = 0.5 * (lo + hi);
    }
  }
  return *p > 0.2 ? c - d2 / (pow(r2, *p) - 1.0) : NAN;
}

void dv_search_convergence_judge(const double *h, const double *e, int n, dv_convergence_fit *fit) {
  const int z = n - 1;
  const int flat = fabs(e[0] - e[z]) <= DV_VERIFY_FLAT * e[0];
  double p, q = NAN;
  const double late = richardson(e[z - 2], e[z - 1], e[z], h[z - 2], h[z - 1], h[z], &p);
  const double early =
      n >= 4 ? richardson(e[z - 3], e[z - 2], e[z - 1], h[z - 3], h[z - 2], h[z - 1], &q) : NAN;
  fit->order = !flat && p > 0.2 ? p : NAN;
  fit->extrapolated = isnan(fit->order) ? e[z] : late;
  fit->uncertainty = 0.0;
  const double below = fit->extrapolated < 0.0 ? -fit->extrapolated : 0.0;
  if (isnan(fit->order)) {
  } else if (n >= 4) {
    if (fabs(p - q) <= DV_VERIFY_ORDER_SPREAD && isfinite(early))
      fit->uncertainty = fmax(fabs(late - early), below);
  } else {
    fit->uncertainty = fmax(DV_CONVERGE_SAFETY * fabs(e[z] - late), below);
  }
  if (e[z] <= DV_VERIFY_FLOOR || fabs(fit->extrapolated) <= fmax(DV_VERIFY_FLOOR, fit->uncertainty))
    fit->verdict = DV_CONVERGES;
  else /* flat: the step no longer matters, what is left is the model's */
    fit->verdict = flat || !isnan(fit->order) ? DV_CONVERGES_ELSEWHERE : DV_DOES_NOT_CONVERGE;
  /* errors that do not change at all (one run given twice, or errors of 0)
   * and errors that do not fall show no convergence, whatever their size */
  int same = 0;
  for (int i = 1; i < n; i++) same |= e[i] == e[i - 1];
  if (same || (isnan(fit->order) && fit->verdict == DV_CONVERGES))
    fit->verdict = DV_CONVERGE_NOT_JUDGED;
}

void dv_search_verify_judge(dv_verification *v) {
  dv_convergence_fit fit;
  dv_search_convergence_judge(v->step, v->error, DV_VERIFY_LEVELS, &fit);
  v->order = fit.order;
  v->extrapolated = fit.extrapolated;
  v->uncertainty = fit.uncertainty;
  v->verdict = fit.verdict;
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
  const double soft = k->softness_key ? dv_scenario_get(sc, name, k->softness_key) : NAN;
  const dv_prober pr = {sc, engine, 1, NULL};
  for (int i = 0; i < DV_VERIFY_LEVELS; i++) {
    const double h = dt / (1 << i);
    char step[128], softness[128];
    snprintf(step, sizeof step, "engines.%s.%s=%.9g", name, engine->search->step_key, h);
    snprintf(softness, sizeof softness, "engines.%s.%s=%.9g", name, k->softness_key,
             fmax(soft * h / dt, k->softness_min_steps * h));
    out->step[i] = h;
    char subject[64];
    snprintf(subject, sizeof subject, "%s dt %.3g s", name, h);
    dv_phase_item("verification level", (size_t)i + 1, DV_VERIFY_LEVELS, subject);
    const int status = dv_search_probe_theta(&pr, &out->error[i], err, step,
                                             k->softness_key ? softness : NULL, NULL, NULL);
    if (status) return dv_phase_end("verification level"), status;
  }
  dv_phase_end("verification level");
  dv_search_verify_judge(out);
  if (out->verdict != DV_CONVERGES_ELSEWHERE) return DV_OK;
  dv_attribution a;
  const int status = dv_search_attribute(sc, name, &a, err);
  if (status) return status;
  dv_search_attribute_cause(&a, out->cause, sizeof out->cause);
  return DV_OK;
}
