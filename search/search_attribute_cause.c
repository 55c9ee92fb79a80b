/* search_attribute_cause: compare's and suite's cause of an engine's excess,
 * from the comparison's own run, quick or over every knob (search_attribute.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_phase.h"
#include "run_progress.h"
#include "run_scenario.h"
#include "search_attribute.h"
#include "search_sweep.h"

/* a penetration deeper than this share of the radius points at the contact */
#define DEEP 1e-3
/* the window where the error appears ends this share past its first failing
 * sample (and at least two of the scene's shortest time scales past it) */
#define MARGIN 0.5
/* a window longer than this share of the compared one is not worth a run of its own */
#define WORTH 0.5

static int over(const dv_engine_result *r, int m) {
  return dv_run_limit_check(r->vs_ref.value[m], r->tolerance[m]) == DV_LIMIT_OVER;
}

size_t dv_search_cause_signature(const dv_comparison *c, const dv_engine_result *r,
                                 const char **first, size_t max) {
  const dv_engine_search *se = r->engine->search;
  const dv_failure f = r->stats.failure;
  const int contact = f == DV_FAILURE_SANK || f == DV_FAILURE_LOST_CONTACT ||
                      r->stats.penetration_max > DEEP * c->sc->disk.r;
  if (max < 1 || !se) return 0;
  /* a choice of time integrator (MuJoCo's, Simbody's): where MuJoCo's failures
   * were removed; a solver's choice (ODE's stepper, Bullet's, DART's) never
   * removed one measured, and their energy drifts with the step */
  const int integrator = se->choice_key && strcmp(se->choice_key, "integrator") == 0;
  if ((over(r, DV_ENERGY_DRIFT) || over(r, DV_INVARIANT_DRIFT)) && integrator)
    first[0] = se->choice_key;
  else if (contact && r->engine->contact->softness_key)
    first[0] = "contact softness";
  else if (over(r, DV_SLIP_MAX))
    first[0] = "friction";
  else if (integrator)
    first[0] = se->choice_key;
  else
    first[0] = se->step_key;
  return 1;
}

/* is a judged metric of r over its limit over [0, t] of its run against ref */
static int failing_by(const dv_engine_result *r, const dv_traj *ref, unsigned judged, double t) {
  dv_metrics m;
  dv_run_compare(&r->traj, ref, t, &m);
  for (int k = 0; k < DV_NMETRICS; k++)
    if (judged >> k & 1u && dv_run_limit_check(m.value[k], r->tolerance[k]) == DV_LIMIT_OVER)
      return 1;
  return 0;
}

/* where the error appears: the end of the window from the start to r's first
 * failing sample plus a margin; 0 where that is most of the run, or where a
 * judged metric is not one a window's samples measure (the turning points') */
static double short_window(const dv_comparison *c, const dv_engine_result *r, unsigned judged) {
  const dv_traj *ref = r->half_thickness > 0.0 ? &r->matched : &c->thin;
  dv_metrics whole;
  dv_run_compare(&r->traj, ref, INFINITY, &whole);
  for (int k = 0; k < DV_NMETRICS; k++)
    if (judged >> k & 1u && dv_run_limit_check(whole.value[k], r->tolerance[k]) != DV_LIMIT_OVER)
      return 0.0;
  if (r->traj.n < 2 || !(whole.t_window > 0.0)) return 0.0;
  size_t lo = 0, hi = r->traj.n - 1; /* failing by sample hi, not by lo */
  while (hi - lo > 1) {
    const size_t mid = lo + (hi - lo) / 2;
    if (failing_by(r, ref, judged, r->traj.s[mid].t))
      hi = mid;
    else
      lo = mid;
  }
  const double t_fail = r->traj.s[hi].t;
  const double end = t_fail + fmax(MARGIN * t_fail, 2.0 * c->min_window);
  return end < WORTH * whole.t_window ? end : 0.0;
}

/* quick over a short window: the base run over it; 0 and window 0 where it
 * does not show the error (the whole run is the base then) */
static int window_base(const dv_prober *pr, const char *extra, dv_attribution *out,
                       dv_error *err) {
  dv_sweep_point p;
  dv_attribution w = *out;
  out->window = 0.0;
  if (dv_search_sweep_probe_in(pr->refs, pr->sc, pr->engine->name, &extra, 1, &p, err))
    return DV_EINPUT;
  if (!p.ok) return DV_OK;
  dv_search_attribute_base(&w, p.metric, p.limit,
                           out->own_reference ? p.metric[DV_THETA_MAX_ERR] : p.theta_thin);
  if (!w.judged) return DV_OK;
  *out = w;
  return DV_OK;
}

int dv_search_cause(const dv_scenario *sc, const dv_comparison *c, const dv_engine_result *r,
                    dv_cause_mode mode, dv_attribution *out, dv_error *err) {
  const dv_engine_type *engine = r->engine;
  if (!engine->contact || !engine->search)
    return dv_fail(err, DV_EINPUT, "%s is not a contact engine: nothing to attribute",
                   engine->name);
  memset(out, 0, sizeof *out);
  out->cause = -1;
  out->timestep = dv_scenario_get(sc, engine->name, engine->search->step_key);
  out->own_reference =
      (sc->thickness > 0.0 && dv_engine_own_body(engine, sc)) || !engine->contact->thin_choice;
  out->quick = mode == DV_CAUSE_QUICK;
  dv_search_attribute_base(
      out, r->vs_ref.value, r->tolerance,
      out->own_reference ? r->vs_ref.value[DV_THETA_MAX_ERR] : r->vs_thin.value[DV_THETA_MAX_ERR]);
  const char *first[1] = {NULL};
  const size_t nsig = dv_search_cause_signature(c, r, first, 1);
  const size_t nfirst = out->quick ? nsig : 0;
  if (getenv("DV_CAUSE_TRACE") && *getenv("DV_CAUSE_TRACE"))
    fprintf(stderr,
            "cause trace: %s: signature: energy %.3g, slip %.3g of their limits, penetration "
            "%.3g r, failure %d: %s first\n",
            engine->name, r->vs_ref.value[DV_ENERGY_DRIFT] / r->tolerance[DV_ENERGY_DRIFT],
            r->vs_ref.value[DV_SLIP_MAX] / r->tolerance[DV_SLIP_MAX],
            r->stats.penetration_max / sc->disk.r, (int)r->stats.failure,
            nsig ? first[0] : "nothing");
  /* the comparison's references serve every probe of the whole run: they do not
   * depend on the engine's settings (a window's probes run their own) */
  const dv_prober pr = {sc, engine, out->own_reference, c};
  char extra[64] = "";
  static dv_attribution whole; /* the whole run's base, where the knobs run over a window */
  whole = *out;
  const double end = out->quick && out->judged ? short_window(c, r, out->judged) : 0.0;
  if (end > 0.0) {
    snprintf(extra, sizeof extra, "scenario.duration=%.9g", end);
    out->window = end;
    char subject[64];
    snprintf(subject, sizeof subject, "%s, its base over %.3g s", engine->name, end);
    dv_phase_item("attribution", 1, 1 + dv_search_attribute_knobs_count(sc, engine), subject);
    if (window_base(&pr, extra, out, err)) return dv_phase_end("attribution"), DV_EINPUT;
    if (out->window == 0.0) extra[0] = '\0';
  }
  const double share = out->window > 0.0 ? out->window / r->vs_ref.t_window : 1.0;
  const double budget = DV_CAUSE_QUICK_BUDGET / fmax(share, 1e-3);
  const double full = dv_search_attribute_knobs_cost(sc, engine) - 1.0;
  /* quick: its first knob (a step /4 at most), the budget and, over a window,
   * the whole run of the knob that removed the error there */
  const double runs =
      out->quick ? fmin(full, share * 4.0 + DV_CAUSE_QUICK_BUDGET + (share < 1.0 ? 4.0 : 0.0))
                 : full;
  char what[128], basis[96];
  snprintf(what, sizeof what, "%.40s: %s: its cause (%s%.0f runs' worth)", sc->name, engine->name,
           out->quick ? "quick, at most " : "", ceil(runs));
  snprintf(basis, sizeof basis, "its own run took %.3g s", r->wall_s);
  dv_run_progress_announce(what, runs * r->wall_s, basis);
  const int status =
      dv_search_attribute_knobs_try(&pr, first, nfirst, out->quick ? &budget : NULL,
                                    extra[0] ? extra : NULL, extra[0] ? &whole : NULL, out, err);
  dv_phase_end("attribution");
  return status;
}
