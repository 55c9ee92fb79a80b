/* run_turning: turning points and nutation period (run_turning.h); checked by
 * tests/shadow/test_turning against synthetic nutations with known answers. */
#include "run_turning.h"

#include <math.h>
#include <stdlib.h>

/* a turning point: time, theta, heading; kind +1 maximum, -1 minimum */
typedef struct turn {
  double t, theta, phi;
  int kind;
} turn;

/* the cubic Hermite interpolant on [0, h] through (y0, d0), (y1, d1): its value at s */
static double hermite(double h, double y0, double y1, double d0, double d1, double s) {
  const double u = s / h, u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * y0 + (u3 - 2 * u2 + u) * h * d0 + (-2 * u3 + 3 * u2) * y1 +
         (u3 - u2) * h * d1;
}

/* its derivative at s */
static double hermite_rate(double h, double y0, double y1, double d0, double d1, double s) {
  const double u = s / h, u2 = u * u;
  return ((6 * u2 - 6 * u) * (y0 - y1) + (3 * u2 - 4 * u + 1) * h * d0 +
          (3 * u2 - 2 * u) * h * d1) /
         h;
}

/* the turning point between samples a and b, where theta_dot changes sign */
static turn locate(const dv_sample *a, const dv_sample *b, int kind) {
  const double h = b->t - a->t, y0 = a->y[RED_TH], y1 = b->y[RED_TH];
  const double d0 = a->y[RED_VTH], d1 = b->y[RED_VTH];
  double lo = 0.0, hi = h; /* the rate is d0 at lo and d1 at hi, of opposite signs */
  for (int k = 0; k < 60; k++) {
    const double mid = 0.5 * (lo + hi);
    if ((hermite_rate(h, y0, y1, d0, d1, mid) > 0) == (d0 > 0))
      lo = mid;
    else
      hi = mid;
  }
  const double s = 0.5 * (lo + hi);
  return (turn){a->t + s, hermite(h, y0, y1, d0, d1, s),
                hermite(h, a->y[RED_PH], b->y[RED_PH], a->y[RED_VPH], b->y[RED_VPH], s), kind};
}

/* the turning points of tr up to t_end into out (tr->n of room), swings
 * below DV_TURNING_MIN_SWING (from the start or the turn before) removed;
 * their count. A start's rate of +-1e-17 (a start at a turn) is no turn, being
 * no swing from the start; a real turn in the first interval is one. A small
 * reversal is skipped and a turn of the last one's kind after it keeps the
 * more extreme of the two: theta_dot's rounding noise on a plateau (a steady
 * circle after a swing) changes sign any number of times, and the turn before
 * it must not come and go with that count's parity */
static size_t turning_points(const dv_traj *tr, double t_end, turn *out) {
  size_t n = 0;
  const double theta0 = tr->n ? tr->s[0].y[RED_TH] : 0.0;
  for (size_t i = 1; i < tr->n && tr->s[i].t <= t_end + 1e-12; i++) {
    const double d0 = tr->s[i - 1].y[RED_VTH], d1 = tr->s[i].y[RED_VTH];
    const int kind = d0 > 0 && d1 <= 0 ? 1 : d0 < 0 && d1 >= 0 ? -1 : 0;
    if (!kind) continue;
    const turn p = locate(&tr->s[i - 1], &tr->s[i], kind);
    if (n == 0 && kind * (p.theta - theta0) < DV_TURNING_MIN_SWING)
      continue; /* a small swing from the start, or one away from p's kind */
    if (n > 0 && kind == out[n - 1].kind) {
      if (kind * (p.theta - out[n - 1].theta) > 0) out[n - 1] = p;
      continue;
    }
    if (n > 0 && fabs(p.theta - out[n - 1].theta) < DV_TURNING_MIN_SWING)
      continue; /* a small reversal: no turn */
    out[n++] = p;
  }
  return n;
}

size_t dv_run_turning_points(const dv_traj *tr, double t_end, double *t, double *theta, int *kind) {
  turn *all = malloc((tr->n + 1) * sizeof *all);
  if (!all) return 0;
  const size_t n = turning_points(tr, t_end, all);
  for (size_t i = 0; i < n; i++) {
    t[i] = all[i].t;
    theta[i] = all[i].theta;
    kind[i] = all[i].kind;
  }
  free(all);
  return n;
}

/* the turning points of one kind, in order: into out; their count */
static size_t of_kind(const turn *all, size_t n, int kind, turn *out) {
  size_t m = 0;
  for (size_t i = 0; i < n; i++)
    if (all[i].kind == kind) out[m++] = all[i];
  return m;
}

/* the extreme of kind of tr's theta up to t_end */
static double extreme(const dv_traj *tr, double t_end, int kind) {
  double v = kind > 0 ? -INFINITY : INFINITY;
  for (size_t i = 0; i < tr->n && tr->s[i].t <= t_end + 1e-12; i++)
    v = kind > 0 ? fmax(v, tr->s[i].y[RED_TH]) : fmin(v, tr->s[i].y[RED_TH]);
  return v;
}

/* is tr, at its last sample to t_end, still moving toward a turn of kind
 * (its turn may lie just past the window) */
static int heading_to(const dv_traj *tr, double t_end, int kind) {
  size_t n = 0;
  while (n < tr->n && tr->s[n].t <= t_end + 1e-12) n++;
  return n > 0 && kind * tr->s[n - 1].y[RED_VTH] > 0;
}

double dv_run_theta_rate_max(const dv_traj *tr, double t_end) {
  double v = 0.0;
  for (size_t i = 0; i < tr->n && tr->s[i].t <= t_end + 1e-12; i++)
    v = fmax(v, fabs(tr->s[i].y[RED_VTH]));
  return v;
}

size_t dv_run_turning_lags(const dv_traj *e, const dv_traj *ref, double t_end, double *t,
                           double *lag, dv_turn_id *id) {
  size_t n = 0;
  turn *te = malloc((e->n + 1) * sizeof *te), *tr = malloc((ref->n + 1) * sizeof *tr);
  turn *ke = malloc((e->n + 1) * sizeof *ke), *kr = malloc((ref->n + 1) * sizeof *kr);
  if (!te || !tr || !ke || !kr) goto cleanup;
  const size_t ne = turning_points(e, t_end, te), nr = turning_points(ref, t_end, tr);
  /* the window's end as the runs reach it: neither run's turn past it is known */
  double end = fmin(t_end, fmin(e->n ? e->s[e->n - 1].t : 0.0, ref->n ? ref->s[ref->n - 1].t : 0.0));
  for (int kind = -1; kind <= 1; kind += 2) {
    const size_t me = of_kind(te, ne, kind, ke), mr = of_kind(tr, nr, kind, kr);
    for (size_t k = 0; k < (me > mr ? me : mr); k++) {
      if (id) id[n] = (dv_turn_id){kind, k + 1, k < me && k < mr ? 0 : k < mr ? -1 : 1};
      if (k < me && k < mr) {
        t[n] = kr[k].t, lag[n++] = ke[k].t - kr[k].t;
      } else if (k < mr) { /* the engine's k-th comes after the window's end, if ever */
        t[n] = kr[k].t, lag[n++] = fmax(0.0, end - kr[k].t);
      } else { /* the reference's k-th comes after it: the engine leads by at least that */
        t[n] = ke[k].t, lag[n++] = -fmax(0.0, end - ke[k].t);
      }
    }
  }
cleanup:
  free(te);
  free(tr);
  free(ke);
  free(kr);
  return n;
}

double dv_run_turning_lag_worst(const dv_traj *e, const dv_traj *ref, double t_end,
                                dv_turn_id *worst, double *lag_of) {
  const size_t room = e->n + ref->n + 1;
  double *t = malloc(room * sizeof *t), *lag = malloc(room * sizeof *lag);
  dv_turn_id *id = malloc(room * sizeof *id);
  const size_t n = t && lag && id ? dv_run_turning_lags(e, ref, t_end, t, lag, id) : 0;
  size_t w = 0;
  for (size_t k = 1; k < n; k++)
    if (fabs(lag[k]) > fabs(lag[w])) w = k;
  if (worst) *worst = n ? id[w] : (dv_turn_id){0, 0, 0};
  if (lag_of) *lag_of = n ? lag[w] : NAN;
  const double most = n ? fabs(lag[w]) : NAN;
  free(t);
  free(lag);
  free(id);
  return most;
}

/* turn_err's new candidate err at the ordinal-th turn of kind: kept in *w when largest */
static void consider(double *turn_err, double err, int kind, size_t ordinal, double lag, int only,
                     dv_turning_worst *w) {
  if (!(err > *turn_err)) return;
  *turn_err = err;
  if (w) *w = (dv_turning_worst){kind, ordinal, lag, only};
}

static void compare_turns(const dv_traj *e, const dv_traj *ref, double t_end, double out[3],
                          dv_turning_worst *worst) {
  out[0] = out[1] = out[2] = NAN;
  if (worst) *worst = (dv_turning_worst){0, 0, NAN, 0};
  turn *te = malloc((e->n + 1) * sizeof *te), *tr = malloc((ref->n + 1) * sizeof *tr);
  turn *ke = malloc((e->n + 1) * sizeof *ke), *kr = malloc((ref->n + 1) * sizeof *kr);
  if (!te || !tr || !ke || !kr) goto cleanup;
  const size_t ne = turning_points(e, t_end, te), nr = turning_points(ref, t_end, tr);
  double turn_err = ne || nr ? 0.0 : NAN, period_err = 0.0, heading_err = 0.0;
  int ref_periods = 0;
  for (int kind = -1; kind <= 1; kind += 2) {
    const size_t me = of_kind(te, ne, kind, ke), mr = of_kind(tr, nr, kind, kr);
    const size_t paired = me < mr ? me : mr;
    for (size_t k = 0; k < paired; k++)
      consider(&turn_err, fabs(ke[k].theta - kr[k].theta), kind, k + 1, ke[k].t - kr[k].t, 0,
               worst);
    /* a turn the other run does not make: against that run's extreme of its
     * kind; not the last, where the other is still on its way to it (its turn
     * lies past the window: that is timing, the period's) */
    for (size_t k = paired; k < me; k++)
      if (k + 1 < me || !heading_to(ref, t_end, kind))
        consider(&turn_err, fabs(ke[k].theta - extreme(ref, t_end, kind)), kind, k + 1, NAN, 1,
                 worst);
    for (size_t k = paired; k < mr; k++)
      if (k + 1 < mr || !heading_to(e, t_end, kind))
        consider(&turn_err, fabs(kr[k].theta - extreme(e, t_end, kind)), kind, k + 1, NAN, -1,
                 worst);
    ref_periods += mr > 1;
    for (size_t k = 0; k + 1 < paired; k++) {
      period_err = fmax(period_err, fabs((ke[k + 1].t - ke[k].t) - (kr[k + 1].t - kr[k].t)));
      /* mod 2 pi: a file's phi may be wrapped, or unwrapped to the nearest
       * branch where rows do not resolve its turning (a fall near flat) */
      if (fmin(fmin(sin(ke[k].theta), sin(ke[k + 1].theta)),
               fmin(sin(kr[k].theta), sin(kr[k + 1].theta))) < DV_TURNING_FLAT)
        continue;
      const double dh = (ke[k + 1].phi - ke[k].phi) - (kr[k + 1].phi - kr[k].phi);
      heading_err = fmax(heading_err, fabs(remainder(dh, 2.0 * M_PI)));
    }
    if (mr > 1 && me < 2) period_err = heading_err = INFINITY; /* the engine lost the nutation */
  }
  out[0] = turn_err;
  out[1] = ref_periods ? period_err : NAN;
  out[2] = ref_periods ? heading_err : NAN;
cleanup:
  free(te);
  free(tr);
  free(ke);
  free(kr);
}

void dv_run_turning_compare(const dv_traj *e, const dv_traj *ref, double t_end, double out[3]) {
  compare_turns(e, ref, t_end, out, NULL);
}

void dv_run_turning_worst(const dv_traj *e, const dv_traj *ref, double t_end,
                          dv_turning_worst *out) {
  double err[3];
  compare_turns(e, ref, t_end, err, out);
}
