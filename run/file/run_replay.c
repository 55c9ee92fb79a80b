/* run_replay: a recorded trajectory served as an engine (run_replay.h). */
#include "run_replay.h"

#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_reference.h"

/* the interpolated columns */
enum { F_TH, F_PH, F_PS, F_X, F_Y, F_CX, F_CY, F_VTH, F_VPH, F_VPS, F_E, F_SLIP, NF };

static double field(const dv_sample *s, int k) {
  static const int y[] = {[F_TH] = RED_TH, [F_PH] = RED_PH,   [F_PS] = RED_PS,   [F_X] = RED_X,
                          [F_Y] = RED_Y,   [F_VTH] = RED_VTH, [F_VPH] = RED_VPH, [F_VPS] = RED_VPS};
  switch (k) {
    case F_CX:
      return s->contact[0];
    case F_CY:
      return s->contact[1];
    case F_E:
      return s->energy;
    case F_SLIP:
      return s->slip;
    default:
      return s->y[y[k]];
  }
}

static void set_field(dv_sample *s, int k, double v) {
  switch (k) {
    case F_CX:
      s->contact[0] = v;
      break;
    case F_CY:
      s->contact[1] = v;
      break;
    case F_E:
      s->energy = v;
      break;
    case F_SLIP:
      s->slip = v;
      break;
    case F_TH:
      s->y[RED_TH] = v;
      break;
    case F_PH:
      s->y[RED_PH] = v;
      break;
    case F_PS:
      s->y[RED_PS] = v;
      break;
    case F_X:
      s->y[RED_X] = v;
      break;
    case F_Y:
      s->y[RED_Y] = v;
      break;
    case F_VTH:
      s->y[RED_VTH] = v;
      break;
    case F_VPH:
      s->y[RED_VPH] = v;
      break;
    case F_VPS:
      s->y[RED_VPS] = v;
      break;
  }
}

typedef struct replay_run {
  dv_replay *rp;
  const dv_trajfile *f;
  size_t n;     /* rows served: up to and with the lying-down row */
  int lay_down; /* the last row served lies down: -1 lower, +1 upper limit */
  double theta_limit, duration;
  double *t, *v[NF];
  /* Akima's interpolant serves, Steffen's estimates its error (NULL for a
   * column the file cannot give) */
  gsl_interp *steffen[NF], *akima[NF];
  gsl_interp_accel *acc;
  dv_engine_stats stats;
  int ended;
} replay_run;

static void replay_free(void *p) {
  replay_run *r = p;
  if (!r) return;
  for (int k = 0; k < NF; k++) {
    gsl_interp_free(r->steffen[k]);
    gsl_interp_free(r->akima[k]);
    free(r->v[k]);
  }
  gsl_interp_accel_free(r->acc);
  free(r->t);
  free(r);
}

/* every row between the sample times (k output_dt, to 1e-9 s relative) against
 * the Akima interpolant through the rows at them, into rp: 0 when it cannot */
static int check_between(replay_run *r, double output_dt) {
  const size_t n = r->n;
  size_t *at = malloc(n * sizeof *at), m = 0;
  double *tg = malloc(n * sizeof *tg), *vg = malloc(n * sizeof *vg);
  int ok = at && tg && vg;
  for (size_t i = 0; ok && i < n; i++) {
    const double k = round(r->t[i] / output_dt);
    if (fabs(r->t[i] - k * output_dt) <= 1e-9 * fmax(1.0, fabs(r->t[i]))) tg[m] = r->t[i], at[m++] = i;
  }
  const int fields[] = {F_TH, F_CX, F_CY};
  gsl_interp *in = NULL, *st = NULL;
  if (ok && m < n && m >= gsl_interp_type_min_size(gsl_interp_akima)) {
    in = gsl_interp_alloc(gsl_interp_akima, m);
    st = gsl_interp_alloc(gsl_interp_steffen, m);
    ok = in && st;
  }
  double *dev = ok && in ? calloc(n, sizeof *dev * 3) : NULL;
  ok = ok && (!in || dev);
  for (int k = 0; ok && in && k < 3; k++) {
    const double *v = r->v[fields[k]];
    if (!v) continue;
    for (size_t j = 0; j < m; j++) vg[j] = v[at[j]];
    if (gsl_interp_init(in, tg, vg, m) || gsl_interp_init(st, tg, vg, m)) continue;
    for (size_t i = 0, j = 0; i < n; i++) {
      if (j < m && at[j] == i) {
        j++;
        continue;
      }
      if (r->t[i] <= tg[0] || r->t[i] >= tg[m - 1]) continue; /* no rows at both sides */
      /* beyond twice the interpolation's own uncertainty there (Akima
       * against Steffen, as between samples): a row off by less may be right
       * (run_judge.h: DV_JUDGE_BETWEEN_SHARE, measured) */
      const double a = gsl_interp_eval(in, tg, vg, r->t[i], NULL);
      const double b = gsl_interp_eval(st, tg, vg, r->t[i], NULL);
      dev[3 * i + k] = fmax(0.0, fabs(v[i] - a) - 2.0 * fabs(a - b));
    }
  }
  dv_replay *rp = r->rp;
  for (size_t i = 0; ok && dev && i < n; i++) {
    const double th = dev[3 * i], p = hypot(dev[3 * i + 1], dev[3 * i + 2]);
    if (th > rp->between_theta) rp->between_theta = th, rp->between_theta_line = r->f->line[i];
    if (p > rp->between_path) rp->between_path = p, rp->between_path_line = r->f->line[i];
  }
  gsl_interp_free(in);
  gsl_interp_free(st);
  free(dev);
  free(at);
  free(tg);
  free(vg);
  return ok;
}

static void *replay_alloc(const dv_engine_type *self, const dv_scenario *sc, dv_error *err) {
  dv_replay *rp = (dv_replay *)self->data; /* the caller's, for the run's findings */
  const dv_trajfile *f = rp->file;
  replay_run *r = calloc(1, sizeof *r);
  if (!r) return dv_fail(err, DV_ESYSTEM, "out of memory"), NULL;
  r->rp = rp;
  r->f = f;
  r->theta_limit = dv_reference_settings(sc)->theta_limit;
  r->duration = sc->duration;
  r->n = f->n;
  for (size_t i = 0; i < f->n; i++) { /* the run ends where the disk lies down */
    const double th = f->s[i].y[RED_TH];
    if (th <= r->theta_limit || th >= M_PI - r->theta_limit) {
      r->n = i + 1;
      r->lay_down = th <= r->theta_limit ? -1 : 1;
      break;
    }
  }
  r->t = malloc(f->n * sizeof *r->t);
  r->acc = gsl_interp_accel_alloc();
  int ok = r->t && r->acc;
  for (size_t i = 0; ok && i < f->n; i++) r->t[i] = f->s[i].t;
  /* the interpolants need their minimum of rows (a file lying down in its
   * first rows is served row by row) */
  const int interp = r->n >= gsl_interp_type_min_size(gsl_interp_akima);
  for (int k = 0; ok && interp && k < NF; k++) {
    if (isnan(field(&f->s[0], k))) continue; /* a column the file does not give */
    r->v[k] = malloc(r->n * sizeof *r->v[k]);
    r->steffen[k] = gsl_interp_alloc(gsl_interp_steffen, r->n);
    r->akima[k] = gsl_interp_alloc(gsl_interp_akima, r->n);
    ok = r->v[k] && r->steffen[k] && r->akima[k];
    for (size_t i = 0; ok && i < r->n; i++) r->v[k][i] = field(&f->s[i], k);
    ok = ok && !gsl_interp_init(r->steffen[k], r->t, r->v[k], r->n) &&
         !gsl_interp_init(r->akima[k], r->t, r->v[k], r->n);
  }
  ok = ok && (!interp || check_between(r, sc->output_dt));
  if (!ok) return replay_free(r), dv_fail(err, DV_ESYSTEM, "out of memory"), NULL;
  snprintf(r->stats.method, sizeof r->stats.method,
           "replayed from %.60s: %zu rows, %s form%s; between rows Akima, error: against Steffen",
           f->path, f->n, f->form == DV_TRAJ_POSE ? "pose" : "state",
           f->has_rates ? "" : ", rates derived");
  return r;
}

static int replay_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  (void)state; /* the file's start was checked against the scenario's when read */
  (void)err;
  replay_run *r = p;
  r->ended = 0;
  r->stats.outcome = DV_OUTCOME_COMPLETED;
  return DV_OK;
}

/* the row at time t (to 1e-9 s relative), or -1; *below: the last row before t */
static long row_at(const replay_run *r, double t, size_t *below) {
  size_t lo = 0, hi = r->n - 1;
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    if (r->t[mid] <= t)
      lo = mid;
    else
      hi = mid;
  }
  *below = lo;
  const double tol = 1e-9 * fmax(1.0, fabs(t));
  if (fabs(r->t[lo] - t) <= tol) return (long)lo;
  if (fabs(r->t[hi] - t) <= tol) return (long)hi;
  return -1;
}

/* the interpolated sample at t, inside the rows; its error estimate into the replay */
static void interpolate(replay_run *r, double t, size_t below, dv_sample *out) {
  const dv_sample *s0 = &r->f->s[below];
  *out = *s0;
  out->t = t;
  double d[NF] = {0};
  for (int k = 0; k < NF; k++) {
    if (!r->steffen[k]) {
      set_field(out, k, NAN);
      continue;
    }
    const double a = gsl_interp_eval(r->akima[k], r->t, r->v[k], t, r->acc);
    const double b = gsl_interp_eval(r->steffen[k], r->t, r->v[k], t, r->acc);
    set_field(out, k, a);
    d[k] = fabs(a - b);
  }
  dv_replay *rp = r->rp;
  const long line = r->f->line[below];
  if (d[F_TH] > rp->interp_theta) rp->interp_theta = d[F_TH], rp->theta_line = line;
  const double dp = hypot(d[F_CX], d[F_CY]);
  if (dp > rp->interp_path) rp->interp_path = dp, rp->path_line = line;
}

static int replay_advance(void *p, double t, dv_sample *out, dv_error *err) {
  replay_run *r = p;
  const double t_end = r->t[r->n - 1], tol = 1e-9 * fmax(1.0, fabs(t));
  /* a file reaching the duration to 1e-6 of it covers it: times summed step
   * by step in float32 end a little short (0.01 summed 500 times: 4.99999) */
  const int short_file = !r->lay_down && t_end < r->duration * (1.0 - 1e-6) - 1e-9;
  size_t below;
  r->rp->t_end = fmax(r->rp->t_end, fmin(t, t_end));
  const dv_trajfile *f = r->f;
  if (f->ground_fault && f->ground_row < r->n && t >= f->s[f->ground_row].t - tol) {
    /* the pose left the ground or sank, as a linked engine's watch would see it */
    r->stats.outcome = dv_failure_outcome(f->ground_fault);
    r->stats.failure = f->ground_fault;
    snprintf(r->stats.detail, sizeof r->stats.detail, "%s", f->ground_detail);
    r->stats.steps = (long)f->ground_row + 1;
    return dv_fail(err, DV_ENUMERIC, "%s", f->ground_detail);
  }
  if (t >= t_end - tol && (r->lay_down || short_file)) { /* the run ends with the file */
    *out = r->f->s[r->n - 1];
    r->stats.outcome = DV_OUTCOME_EVENT;
    r->stats.lay_down = r->lay_down;
    r->rp->ends_early = short_file;
    if (r->lay_down)
      dv_engine_limit_detail(r->lay_down < 0, r->theta_limit, t_end, r->stats.detail,
                             sizeof r->stats.detail);
    else
      snprintf(r->stats.detail, sizeof r->stats.detail,
               "the file ends at t = %g s (line %ld), before the scenario's duration %g s", t_end,
               r->f->line[r->n - 1], r->duration);
    r->stats.steps = (long)r->n;
    dv_stats_add_sample(&r->stats, out);
    return DV_EVENT;
  }
  const long at = row_at(r, fmin(t, t_end), &below);
  if (at >= 0) {
    *out = r->f->s[at];
    out->t = t; /* the harness's time: the row's, to its printed digits */
  } else {
    interpolate(r, t, below, out);
  }
  r->stats.steps = (long)below + 1;
  dv_stats_add_sample(&r->stats, out);
  return DV_OK;
}

static void replay_stats(const void *p, dv_engine_stats *out) {
  *out = ((const replay_run *)p)->stats;
}

static const char *replay_version(void) {
  return "a recorded trajectory";
}

static double replay_half_thickness(const dv_scenario *sc) {
  return 0.5 * sc->thickness; /* the disk the scenario describes */
}

void dv_run_replay_init(dv_replay *rp, const dv_trajfile *f, const char *name) {
  memset(rp, 0, sizeof *rp);
  snprintf(rp->name, sizeof rp->name, "%s", name);
  snprintf(rp->description, sizeof rp->description, "the trajectory %.180s", f->path);
  rp->file = f;
  rp->type = (dv_engine_type){
      .name = rp->name,
      .description = rp->description,
      .role = DV_ENGINE_CONTACT,
      .half_thickness = replay_half_thickness,
      .version = replay_version,
      .reset = replay_reset,
      .advance = replay_advance,
      .stats = replay_stats,
      .free = replay_free,
      .alloc_self = replay_alloc,
      .data = rp,
  };
}

const dv_replay *dv_run_replay_of(const dv_engine_type *type) {
  return type && type->alloc_self == replay_alloc ? type->data : NULL;
}
