/* run_horizon: the reference's amplification and an engine's horizon (run_horizon.h). */
#include "run_horizon.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_reference.h"
#include "run_limits.h"
#include "run_trajectory.h"

const char *const dv_nudge_dir_names[DV_NUDGE_DIRS] = {"theta", "theta_dot", "phi_dot", "psi_dot"};

/* the nudges of theta(0) by +- size that start inside the lying-down limits (0: none) */
static void theta_nudges(const dv_scenario *sc, double size, double nudge[2]) {
  const double lim = dv_reference_settings(sc)->theta_limit, th = sc->initial[RED_TH];
  for (int k = 0; k < 2; k++) {
    const double t0 = th + (k ? 1 : -1) * size;
    nudge[k] = t0 > lim && t0 < M_PI - lim ? t0 - th : 0.0;
  }
  if (nudge[0] == 0.0 && nudge[1] == 0.0) /* the limits lie within a nudge of each side */
    nudge[th < M_PI_2] = 0.5 * (th < M_PI_2 ? M_PI - lim - th : lim - th);
}

const dv_engine_type *dv_run_body(const dv_scenario *sc, dv_scenario *body_sc) {
  *body_sc = *sc;
  if (!(sc->thickness > 0.0)) return dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
  const dv_engine_type *matched = dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE);
  dv_scenario_set_number(body_sc, matched->name, "half_thickness", 0.5 * sc->thickness, NULL);
  return matched;
}

/* the reference of sc's body (thin, or matched to its thickness) run from
 * direction dir nudged by +- size; each run's |theta - theta_ref| /
 * |nudge| as a running max into gain (may be NULL; INFINITY past a run's
 * end), its spreads into shadow (may be NULL), spread (each metric's
 * largest value to t_end, not reset) and, for theta, ends (may be NULL) */
static int nudged_runs(const dv_scenario *sc, const dv_traj *ref, int dir, double size,
                       double t_end, double *gain, dv_shadow *shadow, double spread[DV_NMETRICS],
                       dv_run_end ends[2], double *nudge_made, dv_error *err) {
  dv_scenario body_sc;
  const dv_engine_type *body = dv_run_body(sc, &body_sc);
  double nudge[2] = {-size, size};
  if (dir == RED_TH) theta_nudges(sc, size, nudge);
  *nudge_made = fmax(fabs(nudge[0]), fabs(nudge[1]));
  for (size_t i = 0; gain && i < ref->n; i++) gain[i] = 0.0;
  for (int k = 0; k < 2; k++) {
    if (ends) ends[k] = (dv_run_end){.nudge = nudge[k]};
    if (nudge[k] == 0.0) continue;
    dv_scenario moved_sc = body_sc;
    moved_sc.initial[dir] += nudge[k];
    dv_traj tr = {0};
    dv_engine_stats st;
    const int status = dv_run_collect(body, &moved_sc, dv_run_traj_keep, &tr, &st, err);
    if (status < 0) {
      dv_error cause = *err;
      dv_run_traj_free(&tr);
      return dv_fail(err, status, "the %s reference with %s nudged by %+g (for the spread): %s",
                     body->name, dv_nudge_dir_names[dir], nudge[k], cause.msg);
    }
    if (ends) ends[k] = (dv_run_end){nudge[k], 1, tr.n ? tr.s[tr.n - 1].t : 0.0, st.lay_down};
    double run_max = 0.0;
    for (size_t i = 0; gain && i < ref->n; i++) {
      const int shared = i < tr.n && fabs(tr.s[i].t - ref->s[i].t) < 1e-9;
      if (shared)
        run_max = fmax(run_max, fabs(tr.s[i].y[RED_TH] - ref->s[i].y[RED_TH]) / fabs(nudge[k]));
      gain[i] = fmax(gain[i], shared ? run_max : INFINITY); /* past its end: unpredictable */
    }
    if (shadow && dv_shadow_add_run(shadow, &tr, ref)) {
      dv_run_traj_free(&tr);
      return dv_fail(err, DV_ESYSTEM, "out of memory (the spread)");
    }
    dv_metrics moved; /* over the compared window: a spread past it excuses nothing */
    dv_run_compare(&tr, ref, t_end, &moved);
    for (int m = 0; m < DV_NMETRICS; m++) spread[m] = fmax(spread[m], moved.value[m]);
    dv_run_traj_free(&tr);
  }
  return DV_OK;
}

/* an engine's early errors (rad, then rad/s), each floored at a's nudge and
 * capped at the theta limit (the rates': over the rate scale) */
static void early_nudges(const dv_amplification *a, const double early[DV_NUDGE_DIRS],
                         double e[DV_NUDGE_DIRS]) {
  for (int j = 0; j < DV_NUDGE_DIRS; j++)
    e[j] = fmin(fmax(early[j], a->size[j]),
                DV_HORIZON_SPREAD * (j == RED_TH ? 1.0 : a->rate_scale));
}

int dv_run_engine_shadow(const dv_scenario *sc, const dv_traj *ref, const dv_amplification *a,
                         const double early[DV_NUDGE_DIRS], double t_end, dv_shadow *shadow,
                         double spread[DV_NMETRICS], dv_run_end ends[2], dv_error *err) {
  memcpy(ends, a->ends, sizeof a->ends);
  for (int m = 0; m < DV_NMETRICS; m++) spread[m] = 0.0;
  dv_shadow one;
  if (dv_shadow_alloc(shadow, ref->n) || dv_shadow_alloc(&one, ref->n))
    return dv_shadow_free(shadow), dv_fail(err, DV_ESYSTEM, "out of memory (the spread)");
  double e[DV_NUDGE_DIRS];
  early_nudges(a, early, e);
  /* the amplification's runs measured their spreads over the reference's whole run */
  const int whole = !(t_end < a->measured_to - 1e-9);
  int status = DV_OK;
  for (int j = 0; j < DV_NUDGE_DIRS && status >= 0; j++) {
    double made;
    if (!(e[j] > a->size[j]) && a->shadow_of[j].n == ref->n && whole) { /* a's own runs */
      for (int m = 0; m < DV_NMETRICS; m++) spread[m] = fmax(spread[m], a->spread_of[j][m]);
      dv_shadow_sum(shadow, &a->shadow_of[j]);
      continue;
    }
    dv_shadow_clear(&one);
    status = nudged_runs(sc, ref, j, e[j], t_end, NULL, &one, spread, j == RED_TH ? ends : NULL,
                         &made, err);
    dv_shadow_sum(shadow, &one);
  }
  dv_shadow_free(&one);
  return status;
}

/* an engine's early errors (rad, then rad/s), each floored at a's nudge */
static void floor_errors(const dv_amplification *a, const double early[DV_NUDGE_DIRS],
                         double e[DV_NUDGE_DIRS]) {
  for (int j = 0; j < DV_NUDGE_DIRS; j++) e[j] = fmax(early[j], a->size[j]);
}

/* least-squares slope of y on x and its residual sum of squares */
static double fit(const double *x, const double *y, size_t n, double *rss) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < n; i++) {
    sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  }
  const double den = n * sxx - sx * sx, slope = den > 0 ? (n * sxy - sx * sy) / den : NAN;
  const double icpt = (sy - slope * sx) / n;
  *rss = 0.0;
  for (size_t i = 0; i < n; i++) *rss += pow(y[i] - icpt - slope * x[i], 2);
  return slope;
}

/* the growth's shape: ln G against ln t (a power of t) and against t (an
 * exponential), over the samples where G rises to a new maximum (the
 * growth, not the plateaus between), G >= 2 and nudge * G is below the
 * spread; the better fit names it */
static void classify(dv_amplification *a) {
  size_t n = 0, last = 0;
  double *lt = malloc((a->n ? a->n : 1) * sizeof *lt), *lg = malloc((a->n ? a->n : 1) * sizeof *lg);
  double *tt = malloc((a->n ? a->n : 1) * sizeof *tt);
  for (size_t i = 1; lt && lg && tt && i < a->n && a->t[i] <= a->measured_to; i++) {
    if (a->gain[i] * DV_HORIZON_NUDGE >= DV_HORIZON_SPREAD || !isfinite(a->gain[i])) break;
    if (a->gain[i] >= 2.0 && a->gain[i] > 1.001 * a->gain[i - 1] && a->t[i] > 0.0) {
      tt[n] = a->t[i];
      lt[n] = log(a->t[i]);
      lg[n++] = log(a->gain[i]);
      last = i;
    }
  }
  a->exponent = a->efold = NAN;
  if (n < 3) {
    snprintf(a->growth, sizeof a->growth, "%s", n ? "too short" : "bounded");
  } else {
    double rss_pow, rss_exp;
    a->exponent = fit(lt, lg, n, &rss_pow);
    const double rate = fit(tt, lg, n, &rss_exp);
    a->efold = rate > 0 ? 1.0 / rate : NAN;
    snprintf(a->growth, sizeof a->growth, "%s",
             rss_exp < rss_pow               ? "exponential"
             : fabs(a->exponent - 1.0) < 0.5 ? "linear"
                                             : "power");
    a->factor = a->gain[last];
    a->factor_t = a->t[last];
  }
  free(lt);
  free(lg);
  free(tt);
}

int dv_run_amplification(const dv_scenario *sc, const dv_traj *ref, dv_amplification *a,
                         double spread[DV_NMETRICS], dv_error *err) {
  memset(a, 0, sizeof *a);
  const size_t n = ref->n ? ref->n : 1;
  a->n = ref->n;
  a->t = malloc(n * sizeof *a->t);
  a->gain = malloc(n * sizeof *a->gain);
  for (int j = 0; j < DV_NUDGE_DIRS; j++) a->gain_of[j] = malloc(n * sizeof *a->gain_of[j]);
  for (int j = 0; j < DV_NUDGE_DIRS; j++)
    if (!a->gain_of[j]) return dv_fail(err, DV_ESYSTEM, "out of memory (the horizon)");
  if (!a->t || !a->gain) return dv_fail(err, DV_ESYSTEM, "out of memory (the horizon)");
  for (size_t i = 0; i < ref->n; i++) a->t[i] = ref->s[i].t;
  a->rate_scale = dv_run_rate_scale(sc);
  a->half_thickness = sc->thickness > 0.0 ? 0.5 * sc->thickness : 0.0;
  for (int j = 0; j < DV_NUDGE_DIRS; j++) {
    a->size[j] = DV_HORIZON_NUDGE * (j == RED_TH ? 1.0 : a->rate_scale);
    if (dv_shadow_alloc(&a->shadow_of[j], ref->n))
      return dv_fail(err, DV_ESYSTEM, "out of memory (the horizon)");
    const int status =
        nudged_runs(sc, ref, j, a->size[j], INFINITY, a->gain_of[j], &a->shadow_of[j],
                    a->spread_of[j], j == RED_TH ? a->ends : NULL, &a->size[j], err);
    if (status < 0) return status;
  }
  a->nudge = a->size[RED_TH];
  for (int m = 0; spread && m < DV_NMETRICS; m++) {
    spread[m] = 0.0;
    for (int j = 0; j < DV_NUDGE_DIRS; j++) spread[m] = fmax(spread[m], a->spread_of[j][m]);
  }
  for (size_t i = 0; i < ref->n; i++) {
    a->gain[i] = 0.0;
    for (int j = 0; j < DV_NUDGE_DIRS; j++)
      a->gain[i] = fmax(a->gain[i], a->gain_of[j][i] * a->size[j] / DV_HORIZON_NUDGE);
  }
  a->measured_to = ref->n ? ref->s[ref->n - 1].t : 0.0;
  a->factor = 1.0;
  for (size_t i = 0; i < ref->n; i++) {
    if (!isfinite(a->gain[i])) {
      a->measured_to = i ? a->t[i - 1] : 0.0;
      break;
    }
    a->factor = a->gain[i];
    a->factor_t = a->t[i];
  }
  const double none[DV_NUDGE_DIRS] = {0};
  a->horizon = dv_run_horizon_of(a, none, 0.0, DV_HORIZON_SPREAD, NULL);
  classify(a);
  return DV_OK;
}

void dv_run_amplification_free(dv_amplification *a) {
  if (!a) return;
  free(a->t);
  free(a->gain);
  for (int j = 0; j < DV_NUDGE_DIRS; j++) free(a->gain_of[j]);
  for (int j = 0; j < DV_NUDGE_DIRS; j++) dv_shadow_free(&a->shadow_of[j]);
  memset(a, 0, sizeof *a);
}

double dv_run_relative_error(const dv_amplification *a, const double early[DV_NUDGE_DIRS]) {
  double e[DV_NUDGE_DIRS], rel = 0.0;
  floor_errors(a, early, e);
  for (int j = 0; j < DV_NUDGE_DIRS; j++)
    rel = fmax(rel, e[j] / (j == RED_TH ? 1.0 : a->rate_scale));
  /* an early error past the limit is the engine's own failure, judged
   * pointwise: it does not buy itself a shorter horizon */
  return fmin(rel, DV_HORIZON_SPREAD);
}

double dv_run_horizon_of(const dv_amplification *a, const double early[DV_NUDGE_DIRS],
                         double t_early, double limit, double *gain) {
  const double rel = dv_run_relative_error(a, early);
  for (size_t i = 0; i < a->n; i++)
    /* what the dynamics add to the early error: a bounded x1.4 adds little */
    if (a->t[i] >= t_early && !(rel * (a->gain[i] - 1.0) < limit)) {
      if (gain) *gain = a->gain[i];
      return a->t[i];
    }
  if (gain) *gain = a->n ? a->gain[a->n - 1] : 1.0;
  return INFINITY;
}

double dv_run_period_per_turn(const dv_amplification *a) {
  double s = 0.0;
  for (int j = 0; j < DV_NUDGE_DIRS; j++) {
    const double dt = a->spread_of[j][DV_NUTATION_PERIOD_ERR];
    const double dth = a->spread_of[j][DV_THETA_TURNING_ERR];
    /* a direction that moves the turns by less than 1% of the theta nudge
     * (a rate nudged at a turn: a time shift) gives noise over noise */
    if (dth >= 1e-2 * a->size[RED_TH] && isfinite(dt)) s = fmax(s, dt / dth);
  }
  return s;
}

void dv_run_amplification_words(const dv_amplification *a, char *out, size_t size) {
  if (!strcmp(a->growth, "exponential"))
    snprintf(out, size, "exponential (e-folding every %.3g s), x%.3g by t = %g s", a->efold,
             a->factor, a->factor_t);
  else if (!strcmp(a->growth, "linear") || !strcmp(a->growth, "power"))
    snprintf(out, size, "%s (like t^%.2f), x%.3g by t = %g s", a->growth, a->exponent, a->factor,
             a->factor_t);
  else
    snprintf(out, size, "%s, x%.3g by t = %g s", a->growth, a->factor, a->factor_t);
}
