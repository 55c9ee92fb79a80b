/* engine_scene: the time scales of a scene (engine_scene.h). */
#include "engine_scene.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <math.h>
#include <string.h>

#include "dv_reference.h"
#include "red_invariants.h"
#include "red_potential.h"
#include "red_steady.h"

const char *const dv_scale_names[DV_NSCALES] = {"spin period", "turning period", "wobble period",
                                                "growth time", "fall time",      "duration"};

#define NGRID 400 /* samples of U over the reachable range */

/* the effective potential of one level set of f1, f2, as a GSL function */
typedef struct level {
  const red_disk *disk;
  double f1, f2;
  double sign; /* +1: U, -1: -U (to find a maximum) */
} level;

static double potential(double th, void *p) {
  const level *lv = p;
  double U;
  return red_effective_potential(lv->disk, lv->f1, lv->f2, th, &U) ? NAN : lv->sign * U;
}

/* the 2 pi / |Im| and 1 / Re of the linearisation's eigenvalues at a steady y */
static void from_eigenvalues(const red_disk *d, const double *y, dv_scene_scales *out) {
  double eig[RED_NREDUCED][2], im = 0.0, re = 0.0, big = 0.0;
  int stable;
  dv_error err;
  if (red_linear_stability(d, y, eig, &stable, &err)) return;
  for (int i = 0; i < RED_NREDUCED; i++) {
    im = fmax(im, fabs(eig[i][1]));
    re = fmax(re, eig[i][0]);
    big = fmax(big, hypot(eig[i][0], eig[i][1]));
  }
  if (im > 1e-6 * big) out->t[DV_SCALE_WOBBLE] = 2.0 * M_PI / im;
  if (re > 1e-6 * big) out->t[DV_SCALE_GROWTH] = 1.0 / re;
}

/* the lowest value of lv (U or -U) strictly inside [lo, hi], refined by Brent's
 * method; 0 with *at set, or -1 when the lowest sample is at an end */
static int interior_minimum(level *lv, double lo, double hi, double *at) {
  const double h = (hi - lo) / (NGRID + 1);
  double best = INFINITY;
  int ib = -1;
  for (int i = 1; i <= NGRID; i++) {
    const double v = potential(lo + i * h, lv);
    if (v < best) best = v, ib = i;
  }
  if (ib <= 1 || ib >= NGRID) return -1;
  gsl_function fn = {potential, lv};
  gsl_min_fminimizer *s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  gsl_error_handler_t *old = gsl_set_error_handler_off();
  int status = s ? gsl_min_fminimizer_set(s, &fn, lo + ib * h, lo + (ib - 1) * h, lo + (ib + 1) * h)
                 : GSL_ENOMEM;
  for (int i = 0; status == GSL_SUCCESS && i < 100; i++) {
    status = gsl_min_fminimizer_iterate(s);
    if (!status && gsl_min_test_interval(gsl_min_fminimizer_x_lower(s),
                                         gsl_min_fminimizer_x_upper(s), 1e-12, 0.0) == GSL_SUCCESS)
      break;
  }
  *at = s && !status ? gsl_min_fminimizer_x_minimum(s) : lo + ib * h;
  gsl_set_error_handler(old);
  if (s) gsl_min_fminimizer_free(s);
  return 0;
}

/* U''(th) by central differences */
static double curvature(level *lv, double th) {
  const double h = 1e-4, sign = lv->sign;
  lv->sign = 1.0;
  const double d2 =
      (potential(th + h, lv) - 2.0 * potential(th, lv) + potential(th - h, lv)) / (h * h);
  lv->sign = sign;
  return d2;
}

/* wobble at the minimum of U inside the reachable range, growth at its maximum */
static void from_potential(const red_disk *d, const double *y, dv_scene_scales *out) {
  level lv = {d, 0.0, 0.0, 1.0};
  const double inertia = d->A + d->m * d->r * d->r;
  const double lo = out->theta_range[0], hi = out->theta_range[1];
  double at;
  if (!(hi > lo) || red_invariants(d, y, &lv.f1, &lv.f2)) return;
  if (interior_minimum(&lv, lo, hi, &at) == 0) {
    const double k = curvature(&lv, at);
    if (k > 0.0) out->t[DV_SCALE_WOBBLE] = 2.0 * M_PI * sqrt(inertia / k);
  }
  lv.sign = -1.0;
  if (interior_minimum(&lv, lo, hi, &at) == 0) {
    const double k = curvature(&lv, at);
    if (k < 0.0) out->t[DV_SCALE_GROWTH] = sqrt(inertia / -k);
  }
}

/* 2 pi / |rate|, INFINITY at rest */
static double period(double rate) {
  return rate != 0.0 && isfinite(rate) ? 2.0 * M_PI / fabs(rate) : INFINITY;
}

/* what the scales depend on: a key of the last answer */
typedef struct scene_key {
  red_disk disk;
  double initial[RED_NSTATE], duration, theta_limit;
} scene_key;

static void scales_of(const dv_scenario *sc, double limit, dv_scene_scales *out);

/* every engine's settings check asks for the scales of the same scene (over
 * thirty times a scenario load): the last answer is kept, keyed by value */
void dv_engine_scene_scales(const dv_scenario *sc, dv_scene_scales *out) {
  static _Thread_local scene_key last_key;
  static _Thread_local dv_scene_scales last;
  static _Thread_local int known;
  const dv_reduced_settings *rs = dv_reference_settings(sc);
  scene_key key;
  memset(&key, 0, sizeof key); /* padding compared too */
  key.disk = sc->disk;
  memcpy(key.initial, sc->initial, sizeof key.initial);
  key.duration = sc->duration;
  key.theta_limit = rs ? rs->theta_limit : 0.01;
  if (!known || memcmp(&key, &last_key, sizeof key)) {
    scales_of(sc, key.theta_limit, &last);
    last_key = key;
    known = 1;
  }
  *out = last;
}

static void scales_of(const dv_scenario *sc, double limit, dv_scene_scales *out) {
  const red_disk *d = &sc->disk;
  const double *y = sc->initial;
  for (int i = 0; i < DV_NSCALES; i++) out->t[i] = INFINITY;
  out->theta_range[0] = out->theta_range[1] = NAN;
  out->falls = 0;
  out->t[DV_SCALE_FALL] = d->g > 0.0 && d->r > 0.0 ? sqrt(d->r / d->g) : INFINITY;
  out->t[DV_SCALE_DURATION] = sc->duration > 0.0 ? sc->duration : INFINITY;
  const int valid = d->r > 0.0 && d->m > 0.0 && d->A > 0.0 && y[RED_TH] > 0.0 && y[RED_TH] < M_PI &&
                    isfinite(y[RED_VTH] + y[RED_VPH] + y[RED_VPS]);
  if (valid) {
    dv_error err;
    out->t[DV_SCALE_SPIN] = period(y[RED_VPS]);
    out->t[DV_SCALE_TURNING] = period(y[RED_VPH]);
    if (red_theta_range(d, y, limit, out->theta_range, &out->falls, &err))
      out->theta_range[0] = out->theta_range[1] = NAN;
    if (red_is_steady(d, y, 1e-9))
      from_eigenvalues(d, y, out);
    else
      from_potential(d, y, out);
  }
  out->shortest = DV_SCALE_DURATION;
  for (int i = 0; i < DV_NSCALES; i++)
    if (out->t[i] < out->t[out->shortest]) out->shortest = (dv_scale_id)i;
}

/* v inside the range of engine's key (the scenario's table) */
static double in_range(const dv_scenario *sc, const char *engine, const char *key, double v) {
  for (size_t i = 0; i < sc->nsections; i++) {
    const dv_setting_spec *sp =
        strcmp(sc->sections[i]->name, engine) ? NULL : dv_settings_find(sc->sections[i], key);
    if (!sp) continue;
    v = fmin(fmax(v, sp->lo), sp->hi);
    if (sp->flags & DV_SETTING_OPEN_LO && v <= sp->lo) v = nextafter(sp->lo, INFINITY);
    if (sp->flags & DV_SETTING_OPEN_HI && v >= sp->hi) v = nextafter(sp->hi, -INFINITY);
  }
  return v;
}

/* output_dt / k for the smallest whole k that makes it no longer than dt */
static double fit_output(double dt, double output_dt) {
  if (!(output_dt > 0.0) || !(dt < output_dt)) return output_dt > 0.0 ? output_dt : dt;
  return output_dt / ceil(output_dt / dt * (1.0 - 1e-12));
}

/* the step h (a timestep, or a contact time constant) for a scene, and what set it */
typedef struct step_choice {
  double h;          /* s */
  double t;          /* s: the shortest time scale */
  dv_scale_id scale; /* which one */
  double duration;   /* s */
  double needed;     /* s: the h that meets DV_SCENE_ACCURACY */
  int limit;         /* 0 the accuracy, 1 the resolution of t, 2 the cost */
} step_choice;

/* the accuracy's h, no shorter than affordable, no longer than resolves the scene */
static void choose(const dv_scenario *sc, const dv_step_model *m, step_choice *ch) {
  dv_scene_scales s;
  dv_engine_scene_scales(sc, &s);
  ch->scale = DV_SCALE_FALL;
  for (int i = 0; i < DV_SCALE_DURATION; i++)
    if (s.t[i] < s.t[ch->scale]) ch->scale = (dv_scale_id)i;
  ch->duration = sc->duration > 0.0 ? sc->duration : 0.0;
  ch->t = s.t[ch->scale];
  if (!isfinite(ch->t)) { /* no gravity and no state: the duration, else a second */
    ch->scale = DV_SCALE_DURATION;
    ch->t = ch->duration > 0.0 ? ch->duration : 1.0;
  }
  const double per_step = m->soft_steps > 0.0 ? m->soft_steps : 1.0;
  ch->needed =
      ch->duration > 0.0 ? DV_SCENE_ACCURACY * ch->t * ch->t / (m->c * ch->duration) : INFINITY;
  const double finest = per_step * ch->t / DV_SCENE_STEPS_PER_SCALE;
  const double cheapest = per_step * m->step_cost *
                          fmax(1.0 / DV_SCENE_WALL_PER_SIM, ch->duration / DV_SCENE_WALL_PER_RUN);
  ch->h = ch->needed;
  ch->limit = 0;
  if (ch->h < cheapest) ch->h = cheapest, ch->limit = 2;
  if (ch->h > finest) ch->h = finest, ch->limit = 1; /* a step that misses the scene is no use */
}

/* the reason for h (of the timestep dt) */
static void explain(const step_choice *ch, double dt, char *buf, size_t size) {
  const int n =
      snprintf(buf, size, "%s %.3g s / %.0f", dv_scale_names[ch->scale], ch->t, ch->t / dt);
  if (n < 0 || (size_t)n >= size) return;
  if (ch->limit == 2)
    snprintf(buf + n, size - (size_t)n,
             ", the shortest step affordable (%g s of wall time per simulated s, %g s a run); "
             "theta within %g rad over %g s would need %.2g s",
             DV_SCENE_WALL_PER_SIM, DV_SCENE_WALL_PER_RUN, DV_SCENE_ACCURACY, ch->duration,
             ch->needed);
  else if (ch->limit == 1)
    snprintf(buf + n, size - (size_t)n, ", to resolve it%s",
             ch->needed >= ch->h ? " (theta within the accuracy needs no less)" : "");
  else
    snprintf(buf + n, size - (size_t)n, ", for theta within %g rad over %g s", DV_SCENE_ACCURACY,
             ch->duration);
}

void dv_engine_derive_step(const dv_scenario *sc, const dv_step_model *m, double *timestep,
                           double *softness, char *why, size_t size, const char **keys) {
  char what[96] = "", because[224] = "", note[128] = "";
  size_t nkeys = 0;
  const int derive_dt = isnan(*timestep);
  const int derive_soft = m->soft_steps > 0.0 && softness && isnan(*softness);
  step_choice ch = {0};
  if (derive_dt || derive_soft) choose(sc, m, &ch);
  if (derive_dt) {
    const double want =
        in_range(sc, m->engine, "timestep", ch.h / (m->soft_steps > 0.0 ? m->soft_steps : 1.0));
    *timestep = in_range(sc, m->engine, "timestep", fit_output(want, sc->output_dt));
    snprintf(what, sizeof what, "timestep %.3g s", *timestep);
    if (keys) keys[nkeys++] = "timestep";
    if (*timestep < 0.99 * want && sc->output_dt < want)
      snprintf(note, sizeof note, "; output_dt, as the %.3g s asked for is longer", want);
  } else if (sc->output_dt > 0.0 && *timestep > sc->output_dt * (1.0 + 1e-12)) {
    snprintf(note, sizeof note, "timestep %.3g s: output_dt, as the %.3g s given is longer",
             sc->output_dt, *timestep);
    *timestep = sc->output_dt;
  }
  if (derive_soft) {
    *softness = in_range(sc, m->engine, m->soft_key, fmax(ch.h, m->soft_steps * *timestep));
    snprintf(what + strlen(what), sizeof what - strlen(what), "%s%s %.3g s", what[0] ? ", " : "",
             m->soft_key, *softness);
    if (keys) keys[nkeys++] = m->soft_key;
  }
  if (derive_soft && !derive_dt && *softness > ch.h)
    snprintf(because, sizeof because, "%g timesteps", m->soft_steps);
  else if (derive_dt || derive_soft)
    explain(&ch, *timestep, because, sizeof because);
  if (keys) keys[nkeys] = NULL;
  if (!why) return;
  if (what[0])
    snprintf(why, size, "%s: %s%s%s", what, because, !derive_dt && note[0] ? "; " : "", note);
  else
    snprintf(why, size, "%s", note);
}
