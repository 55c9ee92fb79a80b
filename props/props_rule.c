/* props_rule: the properties b, t, k and n of props.h over one scene, each
 * boundary computed here apart from run/ (props_shadow.h).
 *
 *   b  the judge's limits, early window and pointwise end are the rule's;
 *      a ramp (theta, or the phase along the path) from the early window's
 *      end, full at the pointwise end, sized by bisection so that its
 *      unexcused error by the floor's shadow (the judged early error is the
 *      reference's own, 1e-10) is 0.8x and 1.25x the limit.
 *   t  the reference on a clock slowed by 1 - eps (theta_ref((1 - eps) t),
 *      its rates times 1 - eps): its early error is eps times the rates, so
 *      the shadow grows with eps too; eps is sought (regula falsi on the
 *      reference solved again and the shadow run again at each try) where
 *      the unexcused theta error (and the path's) is 0.8x and 1.25x the
 *      limit. Slowed, not sped up: a run that lay down sooner than the
 *      reference would end the window there.
 *   k  the reference with its rates scaled from the early window's end on
 *      so that its energy is E(t) = E_ref(t) - k (t - t_early) E0: its
 *      drift is k (t - t_early) to the rounding; k is sought where the
 *      drift is 0.8x and 1.25x its limit, 0.01.
 *   n  the reference solved again from its start nudged in theta and each
 *      rate by 1e-6 to 1e-4 (rad; times the rate scale for a rate), each
 *      sign drawn: an engine's early error, which the shadow excuses.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dv_pose.h"
#include "props_shadow.h"
#include "run_trajectory.h"

/* t: the share of its target a slowed clock's unexcused error may miss it
 * by (the bracket stays 0.78x to 0.82x and 1.22x to 1.28x: each side of the
 * limit by 18% or more); not a tolerance on the judge, which is checked at
 * the unexcused error computed here for the clock found (PROPS_AGREE) */
#define PROPS_WARP_CLOSE 0.025
#define PROPS_WARP_TRIES 14 /* solves at most per target (each one reference and 8 nudged runs) */
#define PROPS_WARP_MAX 0.3  /* a clock slower than this share is no engine's error */
/* k: the rates are scaled by c, c^2 = 1 - bled / kinetic; the file check
 * allows an angle's misses of the trapezoid of its rates to add up to 0.08
 * of its travel (DV_ROWS_DRIFT, engine_watch.h): c^2 >= 0.9 keeps them, at
 * most 1 / c - 1, under 0.054 of it, the rest for the samples' own (property
 * a passes them; at c^2 >= 0.8 they came to 0.118) */
#define PROPS_BLEED_MIN 0.9
/* n: the nudges' range, the engines' early errors (run_horizon.h: measured
 * 7.2e-10 to 5.5e-5 rad at the derived settings) */
#define PROPS_NUDGE_LO 1e-6
#define PROPS_NUDGE_HI 1e-4

/* the first metric r's failures name (PROPS_NO_METRIC: none) */
static int named(const dv_engine_result *r) {
  for (int m = 0; m < DV_NMETRICS; m++)
    if (props_names(r, (dv_metric_id)m)) return m;
  return PROPS_NO_METRIC;
}

/* b: the judge's limits, early window and pointwise end are those the rule
 * states (DESIGN.md 6), computed here apart from run/ (props_shadow.h) */
static void documented(props_scene_ctx *s, const dv_engine_result *base, const props_frame *f,
                       double stop) {
  static const dv_metric_id ms[2] = {DV_THETA_MAX_ERR, DV_PATH_MAX_ERR};
  for (int k = 0; k < 2; k++) {
    const double judged = base->tolerance[ms[k]] - base->excused[ms[k]];
    s->t->checks[PROP_B]++;
    s->t->gap[PROPS_GAP_LIMIT] =
        fmax(s->t->gap[PROPS_GAP_LIMIT], fabs(judged - f->lim[k]) / f->lim[k]);
    /* the same reference run, summed alike: measured equal (seed 1 scenes 0-59, seed 2026
     * scenes 0-499: the summary's "limits"); 1e-6 would let a sum in another order pass */
    if (!(fabs(judged - f->lim[k]) <= 1e-6 * f->lim[k]))
      props_fail(s, PROP_B, ms[k], "%s's limit is %.9g, the documented %.9g",
                 dv_metric_names[ms[k]], judged, f->lim[k]);
  }
  s->t->checks[PROP_B] += 2;
  s->t->gap[PROPS_GAP_EARLY] =
      fmax(s->t->gap[PROPS_GAP_EARLY], fabs(base->early_until - f->t_early));
  if (base->horizon != stop)
    s->t->gap[PROPS_GAP_END] = fmax(s->t->gap[PROPS_GAP_END], fabs(base->horizon - stop));
  /* s: the same sum of the same numbers (measured equal, the summary's "early window") */
  if (!(fabs(base->early_until - f->t_early) <= 1e-9))
    props_fail(s, PROP_B, PROPS_NO_METRIC,
               "the early window ends at %.9g s, the scene's shortest time scale at %.9g s",
               base->early_until, f->t_early);
  /* s: the same runs, the same samples: the same sample time, or both never (measured
   * equal, the summary's "pointwise end") */
  if (!(base->horizon == stop || fabs(base->horizon - stop) <= 1e-9))
    props_fail(s, PROP_B, PROPS_NO_METRIC,
               "pointwise judging ends at %.9g s, the floor's shadow reaches the motion's "
               "size at %.9g s",
               base->horizon, stop);
}

/* b: the error series of tr against sh's reference with e's ramp of size x
 * added (theta: to theta; the path: along the contact path's tangent) */
static void planted(const dv_traj *tr, const props_shadow *sh, const props_error *e, int path,
                    double x, double *err) {
  for (size_t i = 0; i < sh->ref.n; i++) {
    const dv_sample *a = i < tr->n ? &tr->s[i] : NULL, *b = &sh->ref.s[i];
    if (!a || fabs(a->t - b->t) > 1e-9) {
      err[i] = NAN;
      continue;
    }
    const double ramp = props_ramp(e, b->t);
    double u[2] = {0.0, 0.0};
    if (path) props_tangent(tr, i, u);
    err[i] = path ? hypot(a->contact[0] + x * ramp * u[0] - b->contact[0],
                          a->contact[1] + x * ramp * u[1] - b->contact[1])
                  : fabs(a->y[RED_TH] + x * ramp - b->y[RED_TH]);
  }
}

/* b: the size of the ramp whose unexcused error is want (bisection: it
 * grows with the size); NAN where none up to want plus the largest spread */
static double ramp_size(const dv_traj *tr, const props_shadow *sh, const props_error *e, int path,
                        const props_frame *f, double stop, double want, double *err) {
  double lo = 0.0, hi = want;
  for (size_t i = 0; i < sh->ref.n && sh->ref.s[i].t < stop; i++)
    if (isfinite(path ? sh->path[i] : sh->theta[i]))
      hi = fmax(hi, 2.0 * want + (path ? sh->path[i] : sh->theta[i]));
  planted(tr, sh, e, path, hi, err);
  if (!(props_unexcused(sh, err, path, f->t_early, stop, f->t_end) >= want)) return NAN;
  for (int it = 0; it < 100 && hi - lo > 1e-13 * hi; it++) {
    const double mid = 0.5 * (lo + hi);
    planted(tr, sh, e, path, mid, err);
    *(props_unexcused(sh, err, path, f->t_early, stop, f->t_end) < want ? &lo : &hi) = mid;
  }
  return hi;
}

/* b: a ramp added to tr (theta, or the phase along the path), 0 over the
 * early window and full at the pointwise end, sized so that its unexcused
 * error, by the shadow computed here, is 0.8x and 1.25x metric m's limit */
static void bracket(props_scene_ctx *s, const dv_traj *tr, const props_shadow *sh,
                    const props_frame *f, double stop, dv_metric_id m, int path) {
  const double limit = f->lim[path];
  double *err = malloc((sh->ref.n ? sh->ref.n : 1) * sizeof *err);
  for (int above = 0; err && above < 2; above++) {
    props_error e = props_none();
    e.t_from = f->t_early;
    e.t_full = fmin(stop, f->t_end);
    const double want = (above ? PROPS_ABOVE : PROPS_BELOW) * limit;
    const double size = ramp_size(tr, sh, &e, path, f, stop, want, err);
    if (isnan(size)) {
      s->t->skipped[PROP_B]++;
      continue;
    }
    planted(tr, sh, &e, path, size, err);
    const double got = props_unexcused(sh, err, path, f->t_early, stop, f->t_end);
    *(path ? &e.phase : &e.theta) = size;
    dv_comparison c;
    dv_error why = {0};
    char what[96];
    snprintf(what, sizeof what, "a %s ramp of %.4g %s", path ? "phase" : "theta", size,
             path ? "m" : "rad");
    if (props_judge(&s->sc, tr, &e, 0, &c, &why)) {
      s->t->runs[PROP_B][m]++, s->t->wrong[PROP_B][m]++, s->t->checks[PROP_B]++;
      props_fail(s, PROP_B, m, "%s: refused: %s", what, why.msg);
      continue;
    }
    props_check_bracket(s, PROP_B, m, above, limit, got, &c.r[0], what);
    dv_run_comparison_free(&c);
  }
  free(err);
}

/* b: the limits, the early window and the pointwise end the judge took;
 * tr's error bracketed around the limits by the floor's shadow */
static void prop_b(props_scene_ctx *s, const dv_traj *tr, const dv_engine_result *base,
                   const props_frame *f, const props_shadow *least) {
  double early[PROPS_DIRS], nudge[PROPS_DIRS];
  dv_error err = {0};
  /* the judged early error is tr's own (the reference's again: 1e-10 rad), so the floor's
   * shadow, unless it is more */
  props_early_errors(tr, &least->ref, f->t_early, early);
  props_nudges(&s->sc, early, nudge);
  int same = 1;
  for (int j = 0; j < PROPS_DIRS; j++) same &= nudge[j] == least->nudge[j];
  props_shadow own;
  const props_shadow *sh = least;
  if (!same) {
    if (props_shadow_run(&s->sc, nudge, &own, &err) < 0) {
      props_shadow_free(&own);
      return props_fail(s, PROP_B, PROPS_NO_METRIC, "the nudged references fail: %s", err.msg);
    }
    sh = &own;
  }
  const double stop = props_frame_stop(sh, f);
  documented(s, base, f, stop);
  if (fmin(stop, f->t_end) > f->t_early + 2 * s->sc.output_dt) {
    bracket(s, tr, sh, f, stop, DV_THETA_MAX_ERR, 0);
    double travel = 0.0; /* the phase shift needs a path to shift along */
    for (size_t i = 1; i < tr->n; i++)
      travel = fmax(travel, hypot(tr->s[i].contact[0] - tr->s[0].contact[0],
                                  tr->s[i].contact[1] - tr->s[0].contact[1]));
    if (travel > 10.0 * f->lim[1]) bracket(s, tr, sh, f, stop, DV_PATH_MAX_ERR, 1);
  }
  if (!same) props_shadow_free(&own);
}

/* t: one slowed clock and what the rule makes of it */
typedef struct warp {
  double eps;
  dv_traj tr;          /* the reference at (1 - eps) t, rates times 1 - eps, at the scene's times */
  double unexcused[2]; /* theta (rad), path (m) */
  double t_end;        /* s: its compared window's end: the last sample it shares with the
                        * reference (a reference's event between the samples it misses) */
  double lim[2];       /* rad, m: the limits over that window */
} warp;

/* t: the reference on a clock slowed by 1 - w->eps into w->tr, and its
 * unexcused errors by its own shadow; < 0 when a run fails */
static int slowed(props_scene_ctx *s, const props_frame *f, const props_shadow *least, warp *w,
                  dv_error *err) {
  const double clock = 1.0 - w->eps;
  int status = props_solve_from(&s->sc, NULL, clock, &w->tr, err);
  if (status < 0) return status;
  /* the first row the scene's start, as the file check wants it (run/file/): the
   * clock's error starts with the first step, as an engine's does */
  for (size_t i = 1; i < w->tr.n; i++) {
    w->tr.s[i].t /= clock;
    for (int k = RED_VTH; k <= RED_VPS; k++) w->tr.s[i].y[k] *= clock;
  }
  double early[PROPS_DIRS], nudge[PROPS_DIRS];
  props_early_errors(&w->tr, &least->ref, f->t_early, early);
  props_nudges(&s->sc, early, nudge);
  props_shadow own;
  const props_shadow *sh = least;
  if (memcmp(nudge, least->nudge, sizeof nudge)) {
    if ((status = props_shadow_run(&s->sc, nudge, &own, err)) < 0)
      return props_shadow_free(&own), status;
    sh = &own;
  }
  const dv_traj *ref = &sh->ref;
  double *e[2] = {malloc((ref->n + 1) * sizeof(double)), malloc((ref->n + 1) * sizeof(double))};
  props_frame own_f = *f;
  own_f.t_end = 0.0;
  if (e[0] && e[1]) {
    for (size_t i = 0; i < ref->n; i++) {
      const dv_sample *a = i < w->tr.n ? &w->tr.s[i] : NULL, *b = &ref->s[i];
      const int shared = a && fabs(a->t - b->t) < 1e-9;
      e[0][i] = shared ? fabs(a->y[RED_TH] - b->y[RED_TH]) : NAN;
      e[1][i] = shared ? hypot(a->contact[0] - b->contact[0], a->contact[1] - b->contact[1]) : NAN;
      if (shared && b->t <= f->t_end + 1e-12) own_f.t_end = b->t;
    }
    props_limits(&s->sc, ref, own_f.t_end, own_f.lim);
    const double stop = props_frame_stop(sh, &own_f);
    for (int k = 0; k < 2; k++)
      w->unexcused[k] = props_unexcused(sh, e[k], k, f->t_early, stop, own_f.t_end);
    w->t_end = own_f.t_end;
    memcpy(w->lim, own_f.lim, sizeof w->lim);
  } else {
    status = dv_fail(err, DV_ESYSTEM, "out of memory");
  }
  free(e[0]), free(e[1]);
  if (sh == &own) props_shadow_free(&own);
  return status;
}

/* t: the slowed clock whose unexcused error in k (0 theta, 1 path) is
 * near share of its limit into w (its trajectory kept); 1 found, 0 none (no
 * clock up to PROPS_WARP_MAX reaches it, or the tries ran out), < 0 a run failed */
static int seek(props_scene_ctx *s, const props_frame *f, const props_shadow *least, int k,
                double share, warp *w, dv_error *err) {
  double lo = 0.0, flo = -share, hi = NAN, fhi = NAN, eps = 1e-4;
  for (int tries = 0; tries < PROPS_WARP_TRIES; tries++) {
    dv_run_traj_free(&w->tr);
    memset(w, 0, sizeof *w);
    w->eps = eps;
    const int status = slowed(s, f, least, w, err);
    if (status < 0) return status;
    const double g = w->unexcused[k] / w->lim[k] - share; /* in limits */
    if (fabs(g) <= PROPS_WARP_CLOSE * share) return 1;
    if (g < 0.0)
      lo = eps, flo = g;
    else
      hi = eps, fhi = g;
    if (isnan(hi)) { /* not yet past it: slow the clock more */
      if (eps >= PROPS_WARP_MAX) break;
      eps = fmin(PROPS_WARP_MAX, eps * (flo > -0.5 * share ? 2.0 : 8.0));
    } else { /* regula falsi, kept inside the bracket */
      const double x = lo - flo * (hi - lo) / (fhi - flo);
      eps = fmin(fmax(x, lo + 0.1 * (hi - lo)), hi - 0.1 * (hi - lo));
    }
  }
  dv_run_traj_free(&w->tr);
  memset(w, 0, sizeof *w);
  return 0;
}

/* t: the slowed clock bracketed around the theta and the path limits */
static void prop_t(props_scene_ctx *s, const props_frame *f, const props_shadow *least) {
  static const dv_metric_id ms[2] = {DV_THETA_MAX_ERR, DV_PATH_MAX_ERR};
  for (int k = 0; k < 2; k++)
    for (int above = 0; above < 2; above++) {
      warp w = {0};
      dv_error err = {0};
      const int found = seek(s, f, least, k, above ? PROPS_ABOVE : PROPS_BELOW, &w, &err);
      if (found < 0) {
        props_fail(s, PROP_T, ms[k], "a slowed clock's runs fail: %s", err.msg);
        break;
      }
      if (!found) { /* the clock's error stays within the spread of its own early error */
        s->t->skipped[PROP_T]++;
        break;
      }
      dv_comparison c;
      char what[96];
      snprintf(what, sizeof what, "the reference on a clock slowed by %.4g", w.eps);
      const props_error none = props_none();
      if (props_judge(&s->sc, &w.tr, &none, 0, &c, &err)) {
        s->t->runs[PROP_T][ms[k]]++, s->t->wrong[PROP_T][ms[k]]++, s->t->checks[PROP_T]++;
        props_fail(s, PROP_T, ms[k], "%s: refused: %s", what, err.msg);
      } else {
        const dv_verdict v = c.r[0].verdict;
        /* the window it shares with the reference is shorter than the scene's (the
         * reference's event between two of its samples) and too short to judge */
        if (w.t_end < f->t_end && (v == DV_VERDICT_NOT_JUDGED || v == DV_VERDICT_OUTSIDE_VALIDITY))
          s->t->skipped[PROP_T]++;
        else
          props_check_bracket(s, PROP_T, ms[k], above, w.lim[k], w.unexcused[k], &c.r[0], what);
        dv_run_comparison_free(&c);
      }
      dv_run_traj_free(&w.tr);
    }
}

/* k: the energy of state y of a body of half-thickness h (J), and its
 * part that does not move (the rates zeroed) into *still */
static double energy(const dv_scenario *sc, const double y[RED_NSTATE], double *still) {
  const dv_geometry geom = {DV_SHAPE_CYLINDER, sc->disk.r, 0.5 * sc->thickness};
  double z[RED_NSTATE];
  dv_pose p;
  memcpy(z, y, sizeof z);
  for (int k = RED_VTH; k <= RED_VPS; k++) z[k] = 0.0;
  dv_pose_from_state(&geom, z, &p);
  if (still) *still = dv_pose_energy(&sc->disk, &p);
  dv_pose_from_state(&geom, y, &p);
  return dv_pose_energy(&sc->disk, &p);
}

/* k: the bleed of rate k into bleed[] (the rates' factor less 1, one a
 * sample of tr); the drift it makes over the window; NAN where a sample's
 * kinetic energy is too small to carry it (c^2 < PROPS_BLEED_MIN) */
static double bleed_at(const dv_scenario *sc, const dv_traj *tr, const props_frame *f, double k,
                       double *bleed) {
  const double e0 = energy(sc, tr->s[0].y, NULL);
  double drift = 0.0;
  for (size_t i = 0; i < tr->n; i++) {
    double still, y[RED_NSTATE];
    const double e = energy(sc, tr->s[i].y, &still);
    /* held from the window's end on: what follows it is read by no metric */
    const double bled = k * fmax(0.0, fmin(tr->s[i].t, f->t_end) - f->t_early) * fabs(e0);
    const double c2 = e - still > 0.0 ? 1.0 - bled / (e - still) : (bled > 0.0 ? -1.0 : 1.0);
    if (c2 < PROPS_BLEED_MIN) return NAN;
    bleed[i] = sqrt(c2) - 1.0;
    memcpy(y, tr->s[i].y, sizeof y);
    for (int j = RED_VTH; j <= RED_VPS; j++) y[j] *= 1.0 + bleed[i];
    if (tr->s[i].t <= f->t_end + 1e-9)
      drift = fmax(drift, fabs(energy(sc, y, NULL) - e0) / fabs(e0));
  }
  return drift;
}

/* k: the energy bled at a constant rate, bracketed around energy_drift's limit */
static void prop_k(props_scene_ctx *s, const dv_traj *tr, const dv_engine_result *base,
                   const props_frame *f) {
  const double limit = 0.01; /* of E0: DESIGN.md 6, run_limits.h */
  const dv_metric_id m = DV_ENERGY_DRIFT;
  s->t->checks[PROP_K]++;
  /* the same constant, unexcused (energy_drift is not shadowed): exact to the rounding */
  if (!(fabs(base->tolerance[m] - base->excused[m] - limit) <= 1e-12)) {
    if (isnan(base->tolerance[m])) { /* the nudges alone move it: not judged */
      s->t->checks[PROP_K]--;
      s->t->skipped[PROP_K]++;
      return;
    }
    props_fail(s, PROP_K, m, "energy_drift's limit is %.9g, the documented %g",
               base->tolerance[m] - base->excused[m], limit);
  }
  double *bleed = malloc(tr->n * sizeof *bleed);
  const double span = f->t_end - f->t_early;
  for (int above = 0; bleed && span > 0.0 && above < 2; above++) {
    const double want = (above ? PROPS_ABOVE : PROPS_BELOW) * limit;
    double lo = 0.0, hi = 2.0 * want / span; /* the drift is k span, to the energy's own drift */
    if (!(bleed_at(&s->sc, tr, f, hi, bleed) >= want)) {
      s->t->skipped[PROP_K]++; /* too little kinetic energy to bleed (a fall from rest) */
      continue;
    }
    for (int it = 0; it < 100 && hi - lo > 1e-13 * hi; it++) {
      const double mid = 0.5 * (lo + hi), d = bleed_at(&s->sc, tr, f, mid, bleed);
      *(!(d >= want) && !isnan(d) ? &lo : &hi) = mid;
    }
    const double drift = bleed_at(&s->sc, tr, f, hi, bleed);
    props_error e = props_none();
    e.bleed = bleed;
    dv_comparison c;
    dv_error err = {0};
    char what[96];
    snprintf(what, sizeof what, "the energy bled at %.4g of E0 a second", hi);
    if (props_judge(&s->sc, tr, &e, 0, &c, &err)) {
      s->t->runs[PROP_K][m]++, s->t->wrong[PROP_K][m]++, s->t->checks[PROP_K]++;
      props_fail(s, PROP_K, m, "%s: refused: %s", what, err.msg);
      continue;
    }
    props_check_bracket(s, PROP_K, m, above, limit, drift, &c.r[0], what);
    dv_run_comparison_free(&c);
  }
  free(bleed);
}

/* n: a stream of props' own for the nudges of a scene */
static double draw(uint64_t *r) {
  uint64_t z = (*r += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return (double)((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
}

/* n: the reference from a start nudged as an engine's early error (its
 * first row tr's, the scene's start, as the file check wants it): it passes */
static void prop_n(props_scene_ctx *s, const dv_traj *own) {
  uint64_t r = s->seed * 0xD1B54A32D192ED03ull ^ ((uint64_t)s->index << 16) ^ 0x6E;
  const double rates = props_rate_scale(&s->sc);
  double nudge[PROPS_DIRS];
  for (int j = 0; j < PROPS_DIRS; j++) {
    const double size = PROPS_NUDGE_LO * exp(draw(&r) * log(PROPS_NUDGE_HI / PROPS_NUDGE_LO));
    nudge[j] = (draw(&r) < 0.5 ? -1.0 : 1.0) * size * (j == RED_TH ? 1.0 : rates);
  }
  dv_traj tr;
  dv_comparison c;
  dv_error err = {0};
  char what[200];
  snprintf(what, sizeof what,
           "the reference from its start nudged by %.2g rad, %.2g, %.2g, %.2g rad/s (theta, "
           "theta_dot, phi_dot, psi_dot)",
           nudge[0], nudge[1], nudge[2], nudge[3]);
  s->t->checks[PROP_N]++;
  if (props_solve_from(&s->sc, nudge, 1.0, &tr, &err) < 0) {
    props_fail(s, PROP_N, PROPS_NO_METRIC, "%s: its run fails: %s", what, err.msg);
    dv_run_traj_free(&tr);
    return;
  }
  const props_error none = props_none();
  if (tr.n && own->n) tr.s[0] = own->s[0];
  if (tr.n < 5) {
    s->t->skipped[PROP_N]++;
  } else if (props_judge(&s->sc, &tr, &none, 0, &c, &err)) {
    props_fail(s, PROP_N, PROPS_NO_METRIC, "%s: refused: %s", what, err.msg);
  } else {
    const dv_engine_result *res = &c.r[0];
    if (res->verdict == DV_VERDICT_NOT_JUDGED || res->verdict == DV_VERDICT_OUTSIDE_VALIDITY)
      s->t->skipped[PROP_N]++;
    else if (!res->pass)
      props_fail(s, PROP_N, named(res), "%s: %s: %s", what, dv_run_verdict_name(res->verdict),
                 props_failures(res));
    dv_run_comparison_free(&c);
  }
  dv_run_traj_free(&tr);
}

void props_rules(props_scene_ctx *s, const dv_traj *tr, const dv_engine_result *base,
                 const props_frame *f, const props_shadow *least, unsigned which) {
  if (which & 1u << PROP_B) prop_b(s, tr, base, f, least);
  if (which & 1u << PROP_T) prop_t(s, f, least);
  if (which & 1u << PROP_K) prop_k(s, tr, base, f);
  if (which & 1u << PROP_N) prop_n(s, tr);
}
