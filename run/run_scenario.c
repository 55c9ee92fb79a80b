/* dv_run: references, engines, metrics and tolerances for one scenario. */
#include "run_scenario.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "dv_reference.h"
#include "engine_scene.h"
#include "run_decided.h"
#include "run_horizon.h"
#include "run_limits.h"
#include "run_progress.h"
#include "run_trajectory.h"
#include "run_turning.h"
#include "dv_clock.h"

/* did the matched reference end at an event where the thick disk crosses
 * upright (standing on the upright line it runs on, red_rolling.h) */
static int crossed_upright(const dv_traj *tr, const dv_engine_stats *st) {
  return st->outcome == DV_OUTCOME_EVENT && tr->n > 0 &&
         fabs(cos(tr->s[tr->n - 1].y[RED_TH])) < 1e-9;
}

/* where the matched run leaves the friction cone: its events end it where it
 * crosses the cone's edge, but a start outside the cone crosses nothing
 * (INFINITY: it never leaves) */
static double matched_valid_end(const dv_scenario *sc, const dv_traj *tr,
                                const dv_engine_stats *st) {
  size_t n = tr->n;
  if (st->outcome == DV_OUTCOME_EVENT && n > 0) n--; /* its event's sample is on the edge */
  return dv_reference_valid_until(sc, tr->s, n);
}

double dv_run_cost_rate(double wall_s, double sim_s, double output_dt) {
  return sim_s >= output_dt && sim_s > 0.0 ? wall_s / sim_s : NAN;
}

static void add_failure(dv_engine_result *r, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

static void add_failure(dv_engine_result *r, const char *fmt, ...) {
  if (r->nfailures == DV_MAX_FAILURES) return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(r->failures[r->nfailures++], sizeof r->failures[0], fmt, ap);
  va_end(ap);
}

int dv_run_metric_pointwise(dv_metric_id metric) {
  return metric == DV_THETA_MAX_ERR || metric == DV_THETA_RMS_ERR || metric == DV_PATH_MAX_ERR ||
         metric == DV_PATH_RMS_ERR || metric == DV_PHASE_ERR;
}

/* the engine's largest error in each nudged direction against ref over its
 * early window: the scene's shortest time scale (engine_scene.h), at least
 * one output_dt */
static void early_errors(const dv_comparison *c, const dv_traj *eng, const dv_traj *ref,
                         double e[DV_NUDGE_DIRS], double *until) {
  const double t0 = ref->n ? ref->s[0].t : 0.0;
  *until = t0 + fmax(c->min_window, c->sc->output_dt);
  for (int j = 0; j < DV_NUDGE_DIRS; j++) e[j] = 0.0;
  for (size_t i = 0; i < eng->n && i < ref->n && ref->s[i].t <= *until + 1e-12; i++)
    if (fabs(eng->s[i].t - ref->s[i].t) < 1e-9)
      for (int j = 0; j < DV_NUDGE_DIRS; j++)
        e[j] = fmax(e[j], fabs(eng->s[i].y[j] - ref->s[i].y[j]));
}

int dv_run_metric_shadowed(dv_metric_id metric) {
  return dv_run_metric_pointwise(metric) || metric == DV_TURNING_LAG;
}

/* the motion's size in theta (rad) and in the contact point (m) over ref to
 * t_end: half the reference's theta swing and its path's extent, each at
 * least DV_SHADOW_SIZE_FLOOR default limits (a steady motion has no swing;
 * a scene's tighter limit asks for more, never for less of the window) */
static void motion_size(const dv_scenario *sc, const dv_traj *ref, double t_end, double size[2]) {
  double lo = INFINITY, hi = -INFINITY;
  for (size_t i = 0; i < ref->n && ref->s[i].t <= t_end + 1e-12; i++)
    lo = fmin(lo, ref->s[i].y[RED_TH]), hi = fmax(hi, ref->s[i].y[RED_TH]);
  size[0] = fmax(hi > lo ? 0.5 * (hi - lo) : 0.0, DV_SHADOW_SIZE_FLOOR * DV_LIMIT_THETA);
  size[1] = fmax(dv_run_motion_extent(ref, t_end),
                 DV_SHADOW_SIZE_FLOOR * dv_run_default_path_limit(sc, ref, t_end));
}

/* where the shadow reaches the motion's size (INFINITY: never), never
 * within the early window; which measure reached it into *which (0 theta, 1
 * path, 2 a nudged run ended there) */
static double unpredictable_from(const dv_traj *ref, const dv_shadow *sh, double t_end,
                                 double early_until, const double size[2], int *which) {
  for (size_t i = 0; i < ref->n && i < sh->n && ref->s[i].t <= t_end + 1e-12; i++) {
    if (ref->s[i].t <= early_until + 1e-12) continue;
    const double th = sh->env[DV_SHADOW_THETA][i], path = sh->env[DV_SHADOW_PATH][i];
    *which = isinf(th) || isinf(path) ? 2 : !(th >= size[0]);
    if (th >= size[0] || path >= size[1]) return ref->s[i].t;
  }
  return INFINITY;
}

/* m judged: its value where it is judged (the whole window's stays in
 * whole), and its limit widened by what the shadow excuses of it: unexcused
 * is what is held against the limit, so value <= limit + excused exactly
 * when unexcused <= limit */
static void excuse(dv_engine_result *r, dv_metric_id m, double judged, double unexcused) {
  r->vs_ref.value[m] = judged;
  r->excused[m] = isfinite(judged) && isfinite(unexcused) ? fmax(0.0, judged - unexcused) : 0.0;
  if (isfinite(r->tolerance[m])) r->tolerance[m] += r->excused[m];
}

/* the pointwise metrics over the whole window and the turning lag, each
 * judged against its limit plus the shadow of the engine's early error
 * (run_shadow.h): e(t) <= limit + s(t), the early window without excuse
 * (an early error is the engine's own); pointwise judging ends only where
 * s reaches the motion's size. < 0 out of memory */
static int judge_shadowed(const dv_scenario *sc, const dv_traj *ref, const dv_shadow *sh,
                          dv_engine_result *r) {
  const size_t n = ref->n;
  const double t_end = r->vs_ref.t_window;
  double size[2], most[3] = {0, 0, 0}, sq[3] = {0, 0, 0}, raw[3] = {0, 0, 0}, raw_sq[3] = {0, 0, 0};
  dv_shadow_scratch w;
  int which = 0;
  if (dv_shadow_scratch_alloc(&w, n, r->traj.n) || dv_shadow_errors(&r->traj, ref, t_end, w.err))
    return dv_shadow_scratch_free(&w), -1;
  double *const *err = w.err, *tk = w.t, *lag = w.lag;
  motion_size(sc, ref, t_end, size);
  const double stop = unpredictable_from(ref, sh, t_end, r->early_until, size, &which);
  size_t count = 0; /* the samples judged: to where the scene predicts nothing pointwise */
  for (size_t i = 0; i < n && i < sh->n && ref->s[i].t < stop; i++) {
    if (isnan(err[DV_SHADOW_THETA][i])) continue;
    count++;
    const int early = ref->s[i].t <= r->early_until + 1e-12;
    for (int k = 0; k < 3; k++) {
      const double e = isnan(err[k][i]) ? 0.0 : err[k][i];
      const double x = fmax(0.0, e - (early ? 0.0 : sh->env[k][i]));
      most[k] = fmax(most[k], x), sq[k] += x * x;
      raw[k] = fmax(raw[k], e), raw_sq[k] += e * e;
    }
  }
  r->pointwise_end = fmin(stop, t_end);
  r->horizon = stop;
  if (count) {
    excuse(r, DV_THETA_MAX_ERR, raw[DV_SHADOW_THETA], most[DV_SHADOW_THETA]);
    excuse(r, DV_THETA_RMS_ERR, sqrt(raw_sq[DV_SHADOW_THETA] / count),
           sqrt(sq[DV_SHADOW_THETA] / count));
    excuse(r, DV_PATH_MAX_ERR, raw[DV_SHADOW_PATH], most[DV_SHADOW_PATH]);
    excuse(r, DV_PATH_RMS_ERR, sqrt(raw_sq[DV_SHADOW_PATH] / count),
           sqrt(sq[DV_SHADOW_PATH] / count));
    excuse(r, DV_PHASE_ERR, raw[DV_SHADOW_PHASE], most[DV_SHADOW_PHASE]);
  }
  const size_t turns = dv_run_turning_lags(&r->traj, ref, t_end, tk, lag, NULL);
  double lag_most = 0.0;
  for (size_t k = 0; k < turns; k++)
    lag_most = fmax(lag_most, fmax(0.0, fabs(lag[k]) - dv_shadow_at(sh, ref, DV_SHADOW_LAG, tk[k])));
  if (turns) excuse(r, DV_TURNING_LAG, r->vs_ref.value[DV_TURNING_LAG], lag_most);
  r->shadow_at_end[0] = r->shadow_at_end[1] = 0.0;
  for (size_t i = 0; i < n && i < sh->n && ref->s[i].t <= fmin(stop, t_end) + 1e-12; i++)
    for (int k = 0; k < 2; k++) /* the last finite spread: a nudged run may end at the stop */
      if (isfinite(sh->env[k ? DV_SHADOW_PATH : DV_SHADOW_THETA][i]))
        r->shadow_at_end[k] = sh->env[k ? DV_SHADOW_PATH : DV_SHADOW_THETA][i];
  r->motion_size[0] = size[0], r->motion_size[1] = size[1];
  r->unpredictable_by = which;
  dv_shadow_scratch_free(&w);
  return 0;
}

/* the shadow's story in words: the early errors, the spread, where it ends */
static void shadow_words(const dv_comparison *c, dv_engine_result *r) {
  const dv_amplification *a = &c->amp;
  const double rates = fmax(fmax(r->early_of[RED_VTH], r->early_of[RED_VPH]), r->early_of[RED_VPS]);
  char growth[120];
  dv_run_amplification_words(a, growth, sizeof growth);
  const int n = snprintf(r->horizon_why, sizeof r->horizon_why,
           "its early error (to t = %g s: %.2g rad in theta, %.2g rad/s in the rates) as nudges "
           "spreads the reference of the scene's body by %.2g rad in theta and %.2g m in the "
           "contact point by t = %g s; each pointwise error is judged against its limit plus "
           "that spread, the early window without it",
           r->early_until, r->early_err, rates, r->shadow_at_end[0], r->shadow_at_end[1],
           r->pointwise_end);
  if (isfinite(r->horizon) && r->unpredictable_by == 2 && n > 0 && (size_t)n < sizeof r->horizon_why)
    snprintf(r->horizon_why + n, sizeof r->horizon_why - (size_t)n,
             "; there a reference nudged by it has ended (lain down): past it the scene predicts "
             "nothing pointwise; amplification %s",
             growth);
  else if (isfinite(r->horizon) && n > 0 && (size_t)n < sizeof r->horizon_why)
    snprintf(r->horizon_why + n, sizeof r->horizon_why - (size_t)n,
             "; there the spread reaches the motion's size (%.3g %s, %s): past it the scene "
             "predicts nothing pointwise; amplification %s",
             r->motion_size[r->unpredictable_by], r->unpredictable_by ? "m" : "rad",
             r->unpredictable_by ? "the path's extent" : "half the swing in theta", growth);
  else if (n > 0 && (size_t)n < sizeof r->horizon_why)
    snprintf(r->horizon_why + n, sizeof r->horizon_why - (size_t)n, "; amplification %s", growth);
  for (size_t i = 0; i < a->n && a->t[i] <= r->pointwise_end + 1e-12; i++)
    r->horizon_gain = a->gain[i];
}

/* a default period limit at least the period change the engine's own
 * turning error makes in the reference (x DV_PERIOD_PER_TURN_MARGIN): that
 * part of its period error is its amplitude's, which theta_turning_err
 * judges (near upright the time a turn takes grows without bound) */
static void period_limit(const dv_amplification *a, dv_engine_result *r) {
  const int m = DV_NUTATION_PERIOD_ERR;
  const double per_rad = dv_run_period_per_turn(a), turn = r->vs_ref.value[DV_THETA_TURNING_ERR];
  const double allowed = DV_PERIOD_PER_TURN_MARGIN * per_rad * turn;
  if (strncmp(r->limit_why[m], "default", 7) || !(allowed > r->tolerance[m])) return;
  r->tolerance[m] = allowed;
  snprintf(r->limit_why[m], sizeof r->limit_why[m],
           "default: x%g the reference's period change for its turning error %.2g rad (%.3g s/rad)",
           DV_PERIOD_PER_TURN_MARGIN, turn, per_rad);
}

/* a window too short to judge: why into why, 0 when it is long enough */
static int window_too_short(const dv_comparison *c, const dv_metrics *w, double t0, double lay_down,
                            char *why, size_t size) {
  const double span = w->t_window - t0;
  /* a reference that lies down sooner has shown the whole motion: the fall itself */
  const double need = fmin(c->min_window, DV_MIN_WINDOW_FRACTION * (lay_down - t0));
  if (w->n_window < DV_MIN_WINDOW_SAMPLES)
    snprintf(why, size, "%zu samples, at least %d needed", w->n_window, DV_MIN_WINDOW_SAMPLES);
  else if (span < need)
    snprintf(why, size, "%g s, shorter than the scene's shortest time scale %g s", span,
             c->min_window);
  else
    return 0;
  return 1;
}

/* the engine's lying down against the reference's (run_event.h) */
static void judge_event(const dv_comparison *c, const dv_traj *ref, const dv_engine_stats *ref_st,
                        double valid_end, dv_engine_result *r) {
  const dv_run_end eng = {0.0, 1, r->traj.n ? r->traj.s[r->traj.n - 1].t : 0.0, r->stats.lay_down};
  const dv_run_end own = {0.0, 1, ref->n ? ref->s[ref->n - 1].t : 0.0, ref_st->lay_down};
  dv_run_event_judge(c->sc, r->engine->name, &eng, &own, r->nudged, valid_end, &r->event);
  if (r->event.agrees) return;
  r->verdict = r->stats.lay_down ? DV_VERDICT_ENDED_BY_EVENT : DV_VERDICT_EXCEEDS;
  add_failure(r, "%s: %s: %s: %s", c->sc->name, r->engine->name, r->event.why, r->event.note);
}

/* every sample of eng equal to ref's, at the same times (NaN: a column eng
 * lacks; the contact point where eng has no whole state): the reference's
 * own output, under another name */
static int same_samples(const dv_traj *eng, const dv_traj *ref) {
  if (eng->n != ref->n || eng->n < 2) return 0;
  for (size_t i = 0; i < eng->n; i++) {
    const dv_sample *a = &eng->s[i], *b = &ref->s[i];
    if (fabs(a->t - b->t) > 1e-9 * fmax(1.0, fabs(b->t))) return 0;
    for (int k = 0; k < RED_NSTATE; k++)
      if (!isnan(a->y[k]) && a->y[k] != b->y[k]) return 0;
    /* the contact point follows from a whole state (the C API computes its own) */
    for (int k = 0; isnan(a->y[RED_PH]) && k < 2; k++)
      if (!isnan(a->contact[k]) && a->contact[k] != b->contact[k]) return 0;
  }
  return 1;
}

static void judge(const dv_comparison *c, const dv_traj *ref, const dv_engine_stats *ref_st,
                  double ref_end, int itself, dv_engine_result *r) {
  const dv_scenario *sc = c->sc;
  const char *name = r->engine->name;
  const double t_ref = fmin(ref_end, ref->n ? ref->s[ref->n - 1].t : 0.0);
  const double t_eng = r->traj.n ? r->traj.s[r->traj.n - 1].t : 0.0;
  r->verdict = DV_VERDICT_AGREES;
  if (r->vs_ref.n_window < 2) /* nothing compared past the shared start: measured nothing, not 0 */
    for (int m = 0; m < DV_NMETRICS; m++) r->vs_ref.value[m] = r->vs_thin.value[m] = NAN;
  const double t0 = ref->n ? ref->s[0].t : 0.0, t_run = ref->n ? ref->s[ref->n - 1].t : 0.0;
  r->window_fraction = t_run > t0 ? (r->vs_ref.t_window - t0) / (t_run - t0) : 0.0;
  char why[160];
  if (itself) {
    r->verdict = DV_VERDICT_NOT_JUDGED;
    add_failure(r,
                "%s: %s: not judged: %s is the reference it would be compared with (the same "
                "engine on the same scenario): its errors are zero and measure nothing",
                sc->name, name, name);
  } else if (same_samples(&r->traj, ref)) {
    r->verdict = DV_VERDICT_NOT_JUDGED;
    add_failure(r,
                "%s: %s: not judged: its every sample is the reference's, exactly (the "
                "reference's own output): its errors are zero and measure nothing",
                sc->name, name);
  } else if (r->not_judged[0]) {
    r->verdict = DV_VERDICT_NOT_JUDGED;
    add_failure(r, "%s: %s: not judged: %s", sc->name, name, r->not_judged);
  } else if (r->status < 0 && t_eng < t_ref - 0.5 * sc->output_dt) {
    const dv_verdict v = dv_run_verdict_of_outcome(r->stats.outcome);
    r->verdict = dv_run_verdict_failed(v) ? v : DV_VERDICT_ERROR;
    add_failure(r, "%s: %s: %s at t = %g s: %s", sc->name, name, dv_run_verdict_name(r->verdict),
                t_eng, r->stats.detail);
  } else if (r->status >= 0) {
    judge_event(c, ref, ref_st, ref_end, r);
  }
  /* a window the reference's run does not fill (it ended before the first
   * samples, or left the validity window at once) measures nothing */
  if (r->verdict == DV_VERDICT_AGREES &&
      (r->vs_ref.n_window < 2 || r->window_fraction < DV_MIN_WINDOW_FRACTION)) {
    const int validity = ref_end < t_run - 0.5 * sc->output_dt;
    r->verdict = validity ? DV_VERDICT_OUTSIDE_VALIDITY : DV_VERDICT_NOT_JUDGED;
    add_failure(r,
                "%s: %s: %s: the compared window ends at t = %g s, %.1f%% of the "
                "reference's %g s (at least %g%% needed): %s",
                sc->name, name, dv_run_verdict_name(r->verdict), r->vs_ref.t_window,
                100 * r->window_fraction, t_run - t0, 100 * DV_MIN_WINDOW_FRACTION,
                validity ? "the contact force rolling needs leaves the friction cone there"
                : r->reference_note[0] ? r->reference_note
                                       : "the engine or the reference ended there");
  } else if (r->verdict == DV_VERDICT_AGREES &&
             window_too_short(c, &r->vs_ref, t0, ref_st->lay_down ? t_run : INFINITY, why,
                              sizeof why)) {
    r->verdict = DV_VERDICT_NOT_JUDGED;
    add_failure(r, "%s: %s: not judged: the compared window, to t = %g s, is too short: %s",
                sc->name, name, r->vs_ref.t_window, why);
  }
  const int judged =
      r->verdict != DV_VERDICT_NOT_JUDGED && r->verdict != DV_VERDICT_OUTSIDE_VALIDITY;
  for (int m = 0; m < DV_NMETRICS && judged; m++) {
    if (dv_run_limit_check(r->vs_ref.value[m], r->tolerance[m]) != DV_LIMIT_OVER) continue;
    char plus[120];
    dv_run_excused_words(r, m, plus, sizeof plus);
    if (!isnan(r->vs_ref.value[m]))
      add_failure(r, "%s: %s: %s = %.6g %s > %.6g %s (%s%s)", sc->name, name, dv_metric_names[m],
                  r->vs_ref.value[m], dv_metric_units[m], r->tolerance[m], dv_metric_units[m],
                  r->limit_why[m], plus);
    else if (r->verdict == DV_VERDICT_AGREES || r->verdict == DV_VERDICT_EXCEEDS)
      add_failure(r, "%s: %s: %s not measured, which never passes its limit %.6g (%s)", sc->name,
                  name, dv_metric_names[m], r->tolerance[m], r->limit_why[m]);
    else /* the run's own failure says why: a failed run measures nothing more */
      continue;
    if (r->verdict == DV_VERDICT_AGREES) r->verdict = DV_VERDICT_EXCEEDS;
  }
  if (r->verdict == DV_VERDICT_AGREES && r->stats.outcome == DV_OUTCOME_EVENT &&
      t_eng < t_ref - 0.5 * sc->output_dt)
    r->verdict = DV_VERDICT_ENDED_BY_EVENT;
  r->pass = r->nfailures == 0;
  dv_run_say_decided(c, ref, ref_st, ref_end, r);
}

/* a reference run that failed: err names the run, what */
static int reference_failed(int status, const char *what, dv_error *err) {
  dv_error cause = *err;
  return dv_fail(err, status, "%s: %s", what, cause.msg);
}

/* the shortest of the scene's own time scales (not its duration) */
static double shortest_scale(const dv_scenario *sc) {
  dv_scene_scales s;
  dv_engine_scene_scales(sc, &s);
  double t = INFINITY;
  for (int k = 0; k < DV_SCALE_DURATION; k++) t = fmin(t, s.t[k]);
  return t;
}

/* run type over sc into tr; wall time and stats */
static int run_into(const dv_engine_type *type, const dv_scenario *sc, dv_traj *tr,
                    dv_engine_stats *st, double *wall, dv_error *err) {
  const double t0 = dv_clock_now();
  const int status = dv_run_collect(type, sc, dv_run_traj_keep, tr, st, err);
  if (wall) *wall = dv_clock_now() - t0;
  return status;
}

int dv_run_scenario(const dv_scenario *sc, const dv_scenario *ref_sc,
                    const dv_engine_type *const *engines, size_t n, dv_comparison *c,
                    dv_error *err) {
  return dv_run_scenario_hooked(sc, ref_sc, engines, n, NULL, c, err);
}

void dv_run_comparison_begin(const dv_scenario *sc, dv_comparison *c) {
  memset(c, 0, sizeof *c);
  c->sc = sc;
  c->pass = 1;
  c->min_window = shortest_scale(sc);
}

int dv_run_thin_reference(const dv_scenario *ref_sc, dv_comparison *c, dv_error *err) {
  const dv_engine_type *thin = dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
  int status = run_into(thin, ref_sc, &c->thin, &c->thin_stats, &c->thin_wall_s, err);
  if (status < 0) {
    char what[64];
    snprintf(what, sizeof what, "the %s reference", thin->name);
    return reference_failed(status, what, err);
  }
  c->thin_valid_end = dv_reference_valid_until(c->sc, c->thin.s, c->thin.n);
  const double t_horizon = dv_clock_now();
  /* the amplification of the scene's body: on a thick scene the matched reference's */
  dv_matched_run body = {0};
  if (ref_sc->thickness > 0.0) {
    dv_run_matched_reference(ref_sc, 0.5 * ref_sc->thickness, &body);
    if (body.status < 0) {
      *err = body.err;
      dv_run_traj_free(&body.traj);
      return reference_failed(body.status, "the reference of the scene's body", err);
    }
  }
  dv_run_progress_role("nudged references");
  status = dv_run_amplification(ref_sc, ref_sc->thickness > 0.0 ? &body.traj : &c->thin, &c->amp,
                                c->spread, err);
  dv_run_progress_role(NULL);
  if (ref_sc->thickness > 0.0 && c->nmatched < DV_MAX_ENGINES)
    c->matched[c->nmatched++] = body; /* the engines of the scene's body are judged against it */
  else
    dv_run_traj_free(&body.traj);
  c->horizon_wall_s = dv_clock_now() - t_horizon;
  if (status < 0) return status; /* err names the nudged run */
  c->horizon = c->amp.horizon;
  return DV_OK;
}

void dv_run_engine_only(const dv_engine_type *engine, const dv_scenario *sc, dv_engine_result *r) {
  dv_error e = {{0}};
  r->status = run_into(engine, sc, &r->traj, &r->stats, &r->wall_s, &e);
  if (r->status < 0 && !r->stats.detail[0])
    snprintf(r->stats.detail, sizeof r->stats.detail, "%.255s", e.msg);
  dv_run_engine_body(engine, sc, r);
}

int dv_run_cannot_model(const dv_engine_type *engine, const dv_scenario *sc, char *why,
                        size_t size) {
  if (dv_engine_own_body(engine, sc)) return 0;
  const double h = dv_engine_half_thickness(engine, sc);
  const dv_engine_contact *k = engine->contact;
  const dv_setting_spec *geom = k->geom_key ? dv_settings_find(engine->settings, k->geom_key) : NULL;
  const char *shape = geom ? dv_setting_choice(geom, (size_t)dv_scenario_get(sc, engine->name,
                                                                             k->geom_key))
                           : NULL;
  char other[64] = "a thin disk";
  if (shape && strcmp(shape, "cylinder") && (!k->thin_choice || strcmp(shape, k->thin_choice)))
    snprintf(other, sizeof other, "its geom %s", shape); /* a stand-in of its own kind */
  else if (h > 0.0)
    snprintf(other, sizeof other, "a cylinder %.3g mm thick", 2e3 * h);
  if (sc->thickness > 0.0)
    snprintf(why, size,
             "cannot model: no cylinder of the scene's %.3g mm (as the scene sets it up, it "
             "would simulate %s): no reference of the scene's body judges another body",
             1e3 * sc->thickness, other);
  else
    snprintf(why, size,
             "cannot model: no thin disk (as the scene sets it up, it would simulate %s): no "
             "reference of the scene's body judges another body",
             other);
  return 1;
}

void dv_run_engine_body(const dv_engine_type *engine, const dv_scenario *sc, dv_engine_result *r) {
  r->engine = engine;
  r->half_thickness = dv_engine_half_thickness(engine, sc);
  /* a stand-in agrees, at best, about a body the scene is not: one rule with the league's */
  r->other_body = dv_run_cannot_model(engine, sc, r->not_judged, sizeof r->not_judged);
}

void dv_run_matched_reference(const dv_scenario *ref_sc, double half_thickness,
                              dv_matched_run *m) {
  const dv_engine_type *matched = dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE);
  dv_scenario match = *ref_sc;
  memset(m, 0, sizeof *m);
  m->half_thickness = half_thickness;
  m->status =
      dv_scenario_set_number(&match, matched->name, "half_thickness", half_thickness, &m->err);
  if (!m->status)
    m->status = run_into(matched, &match, &m->traj, &m->stats, &m->wall_s, &m->err);
}

/* the matched run for half-thickness h in refs, or NULL */
static const dv_matched_run *matched_of(const dv_comparison *refs, double h) {
  for (size_t k = 0; refs && k < refs->nmatched; k++)
    if (refs->matched[k].half_thickness == h) return &refs->matched[k];
  return NULL;
}

/* r's matched reference into r->matched: refs' run for its half-thickness,
 * else run here (and kept in c's cache when refs is c); < 0 when it failed */
static int matched_for(dv_comparison *c, const dv_comparison *refs, const dv_scenario *ref_sc,
                       dv_engine_result *r, dv_error *err) {
  const dv_matched_run *m = matched_of(refs, r->half_thickness);
  dv_matched_run own;
  if (!m && refs == c && c->nmatched < DV_MAX_ENGINES) {
    dv_run_matched_reference(ref_sc, r->half_thickness, &c->matched[c->nmatched]);
    m = &c->matched[c->nmatched++];
  } else if (!m) {
    dv_run_matched_reference(ref_sc, r->half_thickness, &own);
    m = &own;
  }
  int status = m->status;
  if (status < 0) {
    *err = m->err;
    char what[128];
    snprintf(what, sizeof what, "the %s reference (h = %g m) of %s",
             dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE)->name, r->half_thickness,
             r->engine->name);
    status = reference_failed(status, what, err);
  } else {
    r->matched_stats = m->stats;
    r->matched_wall_s = m->wall_s;
    r->matched.n = 0;
    status = DV_OK; /* the run's DV_EVENT (it ended at an event) is no failure */
    for (size_t i = 0; i < m->traj.n && !status; i++)
      if (dv_run_traj_push(&r->matched, &m->traj.s[i]))
        status = dv_fail(err, DV_ESYSTEM, "out of memory");
  }
  if (m == &own) dv_run_traj_free(&own.traj);
  return status;
}

/* two half-thicknesses of one body (the scene's, as an engine and the reference give it) */
static int same_body(double h1, double h2) {
  return fabs(h1 - h2) <= 1e-12 * fmax(h1, h2);
}

/* r (its engine's run made) judged against refs' references in c (refs:
 * where its matched reference may already be); DV_OK, or < 0 when a
 * reference run fails */
static int judge_against(dv_comparison *c, const dv_comparison *refs, const dv_scenario *ref_sc,
                         const dv_run_hook *hook, dv_engine_result *r, dv_error *err) {
  const dv_scenario *sc = c->sc;
  const int same = !ref_sc || ref_sc == sc; /* the references run on the engines' own scene */
  if (!ref_sc) ref_sc = sc;
  const dv_engine_type *thin = dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
  const dv_engine_type *matched = dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE);
  int status;
  const dv_traj *ref = &c->thin;
  double ref_end = c->thin_valid_end;
  if (r->half_thickness > 0.0) {
    if ((status = matched_for(c, refs, ref_sc, r, err)) < 0) return status;
    dv_scenario match = *ref_sc;
    dv_scenario_set_number(&match, matched->name, "half_thickness", r->half_thickness, NULL);
    ref = &r->matched;
    ref_end = matched_valid_end(&match, &r->matched, &r->matched_stats);
    if (crossed_upright(&r->matched, &r->matched_stats)) {
      /* a cylinder at upright switches rim corners, an impact rolling does not
       * describe: the window ends there (the thin disk is another body) */
      const double t_cross = r->matched.s[r->matched.n - 1].t;
      snprintf(r->reference_note, sizeof r->reference_note,
               "the compared window ends at t = %g s, where the scene's body reaches upright and "
               "its rim corners switch (an impact rolling does not describe)",
               t_cross);
      ref_end = fmin(ref_end, t_cross);
    }
  }
  dv_run_compare(&r->traj, &c->thin, c->thin_valid_end, &r->vs_thin);
  if (ref == &c->thin) { /* the same comparison: its Hausdorff distance is O(n^2) */
    r->vs_ref = r->vs_thin;
  } else {
    dv_run_compare(&r->traj, ref, ref_end, &r->vs_ref);
    /* beside the judged comparison, the thin disk's too short to judge measured nothing */
    const double t0 = c->thin.n ? c->thin.s[0].t : 0.0;
    const double t_thin = c->thin.n ? c->thin.s[c->thin.n - 1].t : 0.0;
    char why[160];
    if (window_too_short(c, &r->vs_thin, t0, c->thin_stats.lay_down ? t_thin : INFINITY, why,
                         sizeof why))
      for (int m = 0; m < DV_NMETRICS; m++) r->vs_thin.value[m] = NAN;
  }
  early_errors(c, &r->traj, ref, r->early_of, &r->early_until);
  r->early_err = r->early_of[RED_TH];
  r->nudge = fmax(r->early_err, c->amp.nudge);
  r->pointwise_end = r->vs_ref.t_window;
  r->horizon = INFINITY;
  dv_shadow sh = {0};
  /* an engine of another body is not judged: nothing of its shadow is needed */
  const int shadowed = !r->not_judged[0] && same_body(c->amp.half_thickness, r->half_thickness);
  memcpy(r->nudged, c->amp.ends, sizeof r->nudged);
  memcpy(r->spread, c->spread, sizeof r->spread);
  if (shadowed) { /* its own nudges: the shadow, the spreads and the lying down they allow */
    const double t_spread = dv_clock_now();
    dv_run_progress_role("nudged references");
    status = dv_run_engine_shadow(ref_sc, ref, &c->amp, r->early_of, r->vs_ref.t_window, &sh,
                                  r->spread, r->nudged, err);
    dv_run_progress_role(NULL);
    c->horizon_wall_s += dv_clock_now() - t_spread;
    if (status < 0) return dv_shadow_free(&sh), status;
  }
  r->vs_ref.value[DV_INVARIANT_DRIFT] =
      dv_run_invariant_drift(&sc->disk, &r->traj, r->vs_ref.t_window);
  if (!isnan(r->vs_thin.value[DV_THETA_MAX_ERR])) /* NaN: the thin disk's measured nothing */
    r->vs_thin.value[DV_INVARIANT_DRIFT] = r->vs_ref.value[DV_INVARIANT_DRIFT];
  dv_limit limits[DV_NMETRICS];
  dv_run_limits(sc, r->engine->name, ref, r->vs_ref.t_window, limits);
  for (int m = 0; m < DV_NMETRICS; m++) {
    r->tolerance[m] = limits[m].value;
    memcpy(r->limit_why[m], limits[m].why, sizeof r->limit_why[m]);
    /* a measure the nudges alone move by half its limit is unpredictable */
    if (!dv_run_metric_shadowed((dv_metric_id)m) && r->spread[m] > 0.5 * r->tolerance[m]) {
      r->tolerance[m] = NAN;
      snprintf(r->limit_why[m], sizeof r->limit_why[m],
               "not judged: the reference nudged by its early errors moves it by %.3g",
               r->spread[m]);
    }
  }
  period_limit(&c->amp, r);
  /* turning points and periods: NAN where there is nothing to compare */
  static const dv_metric_id cycles[] = {DV_THETA_TURNING_ERR, DV_TURNING_LAG,
                                        DV_NUTATION_PERIOD_ERR, DV_HEADING_PERIOD_ERR};
  for (size_t k = 0; k < sizeof cycles / sizeof cycles[0]; k++)
    if (isnan(r->vs_ref.value[cycles[k]])) {
      r->tolerance[cycles[k]] = NAN;
      snprintf(r->limit_why[cycles[k]], sizeof r->limit_why[cycles[k]], "not judged: %s",
               k > 1 ? "the reference completes no nutation period in the window"
                     : "neither run turns (a swing of 1e-3 rad) in the window");
    }
  if (ref != &c->thin) { /* f1, f2 are integrals of the thin disk only */
    r->tolerance[DV_INVARIANT_DRIFT] = NAN;
    snprintf(r->limit_why[DV_INVARIANT_DRIFT], sizeof r->limit_why[DV_INVARIANT_DRIFT],
             "not judged: f1, f2 are the thin disk's integrals; a cylinder (h = %g m) does not "
             "conserve them",
             r->half_thickness);
  }
  memcpy(r->whole, r->vs_ref.value, sizeof r->whole);
  if (shadowed) {
    status = judge_shadowed(sc, ref, &sh, r);
    dv_shadow_free(&sh);
    if (status < 0) return dv_fail(err, DV_ESYSTEM, "out of memory (the spread)");
    shadow_words(c, r);
  }
  const dv_engine_stats *ref_st = ref == &c->thin ? &c->thin_stats : &r->matched_stats;
  const int itself = same && r->engine == (ref == &c->thin ? thin : matched);
  if (hook && hook->before_verdict) hook->before_verdict(hook->ctx, c, r);
  judge(c, ref, ref_st, ref_end, itself, r);
  c->pass &= r->pass;
  return DV_OK;
}

int dv_run_engine_judge(dv_comparison *c, const dv_scenario *ref_sc, const dv_run_hook *hook,
                        dv_engine_result *r, dv_error *err) {
  return judge_against(c, c, ref_sc, hook, r, err);
}

int dv_run_scenario_hooked(const dv_scenario *sc, const dv_scenario *ref_sc,
                           const dv_engine_type *const *engines, size_t n, const dv_run_hook *hook,
                           dv_comparison *c, dv_error *err) {
  dv_run_comparison_begin(sc, c);
  if (!ref_sc) ref_sc = sc;
  if (n > DV_MAX_ENGINES) return dv_fail(err, DV_EINPUT, "at most %d engines", DV_MAX_ENGINES);
  dv_run_progress_plan(sc, ref_sc, engines, n); /* a long comparison says so first */
  int status = dv_run_thin_reference(ref_sc, c, err);
  for (size_t i = 0; i < n && !status; i++) {
    dv_engine_result *r = &c->r[c->n++];
    dv_run_engine_only(engines[i], sc, r);
    status = judge_against(c, c, ref_sc == sc ? NULL : ref_sc, hook, r, err);
  }
  return status;
}

int dv_run_engine_against(const dv_comparison *refs, const dv_scenario *sc,
                          const dv_scenario *ref_sc, const dv_engine_type *engine,
                          dv_comparison *out, dv_error *err) {
  dv_run_comparison_begin(sc, out);
  out->borrowed = 1;
  out->thin = refs->thin;
  out->thin_stats = refs->thin_stats;
  out->thin_wall_s = refs->thin_wall_s;
  out->thin_valid_end = refs->thin_valid_end;
  out->amp = refs->amp;
  out->horizon = refs->horizon;
  memcpy(out->spread, refs->spread, sizeof out->spread);
  dv_engine_result *r = &out->r[out->n++];
  dv_run_engine_only(engine, sc, r);
  return judge_against(out, refs, ref_sc, NULL, r, err);
}

void dv_run_comparison_free(dv_comparison *c) {
  if (!c) return;
  if (!c->borrowed) {
    dv_run_traj_free(&c->thin);
    dv_run_amplification_free(&c->amp);
  }
  memset(&c->thin, 0, sizeof c->thin);
  memset(&c->amp, 0, sizeof c->amp);
  for (size_t i = 0; i < c->n; i++) {
    dv_run_traj_free(&c->r[i].traj);
    dv_run_traj_free(&c->r[i].matched);
  }
  for (size_t k = 0; k < c->nmatched; k++) dv_run_traj_free(&c->matched[k].traj);
  c->n = c->nmatched = 0;
}
