/* props_shadow: the shadow of an early error, apart from run/ (props_shadow.h). */
#include "props_shadow.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dv_reference.h"
#include "engine_scene.h"
#include "run_trajectory.h"

/* s: two sample times are the same one (the judge's pairing) */
#define SAME_TIME 1e-9

double props_rate_scale(const dv_scenario *sc) {
  const double *y = sc->initial;
  return fmax(fmax(fabs(y[RED_VPS]), fabs(y[RED_VPH])), sqrt(sc->disk.g / sc->disk.r));
}

void props_nudges(const dv_scenario *sc, const double *early, double nudge[PROPS_DIRS]) {
  const double rates = props_rate_scale(sc);
  for (int j = 0; j < PROPS_DIRS; j++) {
    const double unit = j == RED_TH ? 1.0 : rates;
    nudge[j] = fmin(fmax(early ? early[j] : 0.0, PROPS_NUDGE * unit), PROPS_THETA_LIMIT * unit);
  }
}

const dv_engine_type *props_body_of(const dv_scenario *sc, dv_scenario *body) {
  *body = *sc;
  if (!(sc->thickness > 0.0)) return dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
  const dv_engine_type *matched = dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE);
  dv_scenario_set_number(body, matched->name, "half_thickness", 0.5 * sc->thickness, NULL);
  return matched;
}

/* the spread of run from ref, as running maxima, into theta and path (at
 * least what is there) */
static void add_run(const props_shadow *s, const dv_traj *run, double *theta, double *path) {
  double th = 0.0, p = 0.0;
  for (size_t i = 0; i < s->ref.n; i++) {
    const dv_sample *a = i < run->n ? &run->s[i] : NULL, *b = &s->ref.s[i];
    if (!a || fabs(a->t - b->t) > SAME_TIME) {
      th = p = INFINITY; /* past its end: nothing is predictable */
    } else {
      th = fmax(th, fabs(a->y[RED_TH] - b->y[RED_TH]));
      p = fmax(p, hypot(a->contact[0] - b->contact[0], a->contact[1] - b->contact[1]));
    }
    theta[i] = fmax(theta[i], th);
    path[i] = fmax(path[i], p);
  }
}

int props_shadow_run(const dv_scenario *sc, const double nudge[PROPS_DIRS], props_shadow *s,
                     dv_error *err) {
  static dv_scenario body, moved; /* large: not on the stack */
  memset(s, 0, sizeof *s);
  memcpy(s->nudge, nudge, sizeof s->nudge);
  const dv_engine_type *type = props_body_of(sc, &body);
  dv_engine_stats st;
  int status = dv_run_collect(type, &body, dv_run_traj_keep, &s->ref, &st, err);
  if (status < 0) return status;
  const size_t n = s->ref.n ? s->ref.n : 1;
  s->theta = calloc(n, sizeof *s->theta);
  s->path = calloc(n, sizeof *s->path);
  double *th_j = calloc(n, sizeof *th_j), *p_j = calloc(n, sizeof *p_j);
  if (!s->theta || !s->path || !th_j || !p_j)
    return free(th_j), free(p_j), dv_fail(err, DV_ESYSTEM, "out of memory (the shadow)");
  const double lim = dv_reference_settings(sc)->theta_limit;
  /* each direction's spread (the larger of its two sides), summed over the directions */
  for (int j = 0; j < PROPS_DIRS && status >= 0; j++) {
    memset(th_j, 0, n * sizeof *th_j), memset(p_j, 0, n * sizeof *p_j);
    for (int side = -1; side <= 1 && status >= 0; side += 2) {
      moved = body;
      moved.initial[j] += side * nudge[j];
      const double th = moved.initial[RED_TH];
      if (j == RED_TH && !(th > lim && th < M_PI - lim)) continue; /* it would start lying down */
      dv_traj run = {0};
      status = dv_run_collect(type, &moved, dv_run_traj_keep, &run, &st, err);
      if (status >= 0) add_run(s, &run, th_j, p_j);
      dv_run_traj_free(&run);
    }
    for (size_t i = 0; i < s->ref.n; i++) s->theta[i] += th_j[i], s->path[i] += p_j[i];
  }
  free(th_j), free(p_j);
  return status < 0 ? status : DV_OK;
}

void props_shadow_free(props_shadow *s) {
  if (!s) return;
  dv_run_traj_free(&s->ref);
  free(s->theta);
  free(s->path);
  memset(s, 0, sizeof *s);
}

void props_early_errors(const dv_traj *tr, const dv_traj *ref, double t_early,
                        double early[PROPS_DIRS]) {
  for (int j = 0; j < PROPS_DIRS; j++) early[j] = 0.0;
  for (size_t i = 0; i < tr->n && i < ref->n && ref->s[i].t <= t_early + 1e-12; i++)
    if (fabs(tr->s[i].t - ref->s[i].t) < SAME_TIME)
      for (int j = 0; j < PROPS_DIRS; j++)
        early[j] = fmax(early[j], fabs(tr->s[i].y[j] - ref->s[i].y[j]));
}

double props_early_until(const dv_scenario *sc, const dv_traj *ref) {
  dv_scene_scales sc_s;
  dv_engine_scene_scales(sc, &sc_s);
  double shortest = INFINITY;
  for (int k = 0; k < DV_SCALE_DURATION; k++) shortest = fmin(shortest, sc_s.t[k]);
  return (ref->n ? ref->s[0].t : 0.0) + fmax(shortest, sc->output_dt);
}

/* twice the largest distance of ref's contact points to t_end from their mean */
static double extent(const dv_traj *ref, double t_end) {
  double mean[2] = {0.0, 0.0}, far = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < ref->n && ref->s[i].t <= t_end + 1e-12; i++)
    mean[0] += ref->s[i].contact[0], mean[1] += ref->s[i].contact[1], n++;
  if (!n) return 0.0;
  mean[0] /= n, mean[1] /= n;
  for (size_t i = 0; i < ref->n && ref->s[i].t <= t_end + 1e-12; i++)
    far = fmax(far, hypot(ref->s[i].contact[0] - mean[0], ref->s[i].contact[1] - mean[1]));
  return 2.0 * far;
}

void props_motion_size(const dv_traj *ref, double t_end, const double lim[2], double size[2]) {
  double lo = INFINITY, hi = -INFINITY;
  for (size_t i = 0; i < ref->n && ref->s[i].t <= t_end + 1e-12; i++)
    lo = fmin(lo, ref->s[i].y[RED_TH]), hi = fmax(hi, ref->s[i].y[RED_TH]);
  size[0] = fmax(hi > lo ? 0.5 * (hi - lo) : 0.0, PROPS_SIZE_FLOOR * lim[0]);
  size[1] = fmax(extent(ref, t_end), PROPS_SIZE_FLOOR * lim[1]);
}

double props_pointwise_stop(const props_shadow *s, double t_early, double t_end,
                            const double size[2]) {
  for (size_t i = 0; i < s->ref.n && s->ref.s[i].t <= t_end + 1e-12; i++)
    if (s->ref.s[i].t > t_early + 1e-12 && (s->theta[i] >= size[0] || s->path[i] >= size[1]))
      return s->ref.s[i].t;
  return INFINITY;
}

double props_unexcused(const props_shadow *s, const double *err, int path, double t_early,
                       double stop, double t_end) {
  const double *spread = path ? s->path : s->theta;
  double most = 0.0;
  for (size_t i = 0; i < s->ref.n && s->ref.s[i].t <= t_end + 1e-12 && s->ref.s[i].t < stop; i++)
    if (!isnan(err[i]))
      most = fmax(most, err[i] - (s->ref.s[i].t <= t_early + 1e-12 ? 0.0 : spread[i]));
  return most;
}

void props_limits(const dv_scenario *sc, const dv_traj *ref, double t_end, double lim[2]) {
  double rolled = 0.0;
  for (size_t i = 1; i < ref->n && ref->s[i].t <= t_end + 1e-9; i++)
    rolled += hypot(ref->s[i].contact[0] - ref->s[i - 1].contact[0],
                    ref->s[i].contact[1] - ref->s[i - 1].contact[1]);
  lim[0] = PROPS_THETA_LIMIT;
  lim[1] = fmax(fmin(0.01 * rolled, 0.1 * extent(ref, t_end)), 0.01 * sc->disk.r);
}

double props_frame_stop(const props_shadow *s, const props_frame *f) {
  double size[2];
  props_motion_size(&s->ref, f->t_end, f->lim, size);
  return props_pointwise_stop(s, f->t_early, f->t_end, size);
}

/* of a limit: how far the judge's unexcused value may lie from the one
 * computed here (the same reference runs, the same samples: measured at
 * most 8e-14 of the limit over seed 1 scenes 0-59 and 1.7e-13 over seed
 * 2026 scenes 0-499, b, t and k, the summary's "unexcused values"; a shadow
 * from another nudge moves it by 1e-4 of the limit and more) */
#define PROPS_AGREE 1e-6

void props_check_bracket(props_scene_ctx *s, int prop, dv_metric_id m, int above, double lim,
                         double want, const dv_engine_result *r, const char *what) {
  const double v = r->vs_ref.value[m], judged = v - r->excused[m];
  const char *name = dv_metric_names[m], *unit = dv_metric_units[m];
  s->t->runs[prop][m]++;
  s->t->checks[prop]++;
  s->t->gap[PROPS_GAP_AGREE] = fmax(s->t->gap[PROPS_GAP_AGREE], fabs(judged - want) / lim);
  int wrong = 1;
  if (r->verdict == DV_VERDICT_NOT_JUDGED || r->verdict == DV_VERDICT_OUTSIDE_VALIDITY)
    props_fail(s, prop, m, "%s: not judged, where the error-free run is: %s", what,
               props_failures(r));
  else if (above && !(props_names(r, m) && judged > lim))
    props_fail(s, prop, m,
               "%s: %s unexcused %.6g %s (%.6g measured less %.3g excused), %.3gx its limit %.6g "
               "%s: not named (%s: %s)",
               what, name, judged, unit, v, r->excused[m], want / lim, lim, unit,
               dv_run_verdict_name(r->verdict), props_failures(r));
  else if (!above && (props_names(r, m) || !(judged <= lim)))
    props_fail(s, prop, m,
               "%s: %s unexcused %.6g %s (%.6g measured less %.3g excused), %.3gx its limit %.6g "
               "%s: fails (%s)",
               what, name, judged, unit, v, r->excused[m], want / lim, lim, unit,
               props_failures(r));
  else if (!(fabs(judged - want) <= PROPS_AGREE * lim))
    props_fail(s, prop, m,
               "%s: %s unexcused %.9g %s by the judge, %.9g computed apart (%.3g of the limit)",
               what, name, judged, unit, want, fabs(judged - want) / lim);
  else
    wrong = 0;
  s->t->wrong[prop][m] += wrong;
}
