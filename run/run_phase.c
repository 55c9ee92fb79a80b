/* run_phase: the phase error along the reference's contact path (run_phase.h);
 * checked by tests/run/test_phase against shifted circles and lines. */
#include "run_phase.h"

#include <math.h>
#include <stdlib.h>

/* the reference's distinct points q[k] and their arc lengths s[k] */
typedef struct polyline {
  double (*q)[2], *s;
  size_t n;
} polyline;

/* the arc length of p's nearest point on segment k (the last one extended
 * beyond its end), and its distance into *dist */
static double place_on(const polyline *l, size_t k, const double p[2], double *dist) {
  const double *a = l->q[k], *b = l->q[k + 1];
  const double dx = b[0] - a[0], dy = b[1] - a[1], len = hypot(dx, dy);
  double u = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (len * len);
  u = fmax(0.0, k + 2 == l->n ? u : fmin(1.0, u));
  *dist = hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dy);
  return l->s[k] + u * len;
}

double dv_run_phase_series(const double (*e)[2], const double (*ref)[2], size_t n,
                           double *series) {
  for (size_t i = 0; series && i < n; i++) series[i] = i ? NAN : 0.0;
  if (n < 2) return 0.0;
  polyline l = {malloc(n * sizeof *l.q), malloc(n * sizeof *l.s), 0};
  double *arc = malloc(n * sizeof *arc); /* the reference's arc length at each sample */
  if (!l.q || !l.s || !arc) {
    free(l.q), free(l.s), free(arc);
    return NAN;
  }
  for (size_t i = 0; i < n; i++) {
    const double step = l.n ? hypot(ref[i][0] - l.q[l.n - 1][0], ref[i][1] - l.q[l.n - 1][1]) : 0;
    if (isnan(ref[i][0]) || isnan(ref[i][1])) {
      arc[i] = NAN;
      continue;
    }
    if (!l.n || step > 0.0) {
      l.s[l.n] = l.n ? l.s[l.n - 1] + step : 0.0;
      l.q[l.n][0] = ref[i][0];
      l.q[l.n][1] = ref[i][1];
      l.n++;
    }
    arc[i] = l.s[l.n - 1];
  }
  double worst = 0.0;
  size_t k = 0; /* the segment the engine was placed on last */
  for (size_t i = 0; i < n && l.n >= 2; i++) {
    if (isnan(e[i][0]) || isnan(e[i][1]) || isnan(arc[i])) continue;
    double d, dn, s = place_on(&l, k, e[i], &d);
    /* walk down the distance, forward then back: the nearest place near the last one */
    while (k + 2 < l.n) {
      const double sn = place_on(&l, k + 1, e[i], &dn);
      if (!(dn < d)) break;
      k++, s = sn, d = dn;
    }
    while (k > 0) {
      const double sn = place_on(&l, k - 1, e[i], &dn);
      if (!(dn < d)) break;
      k--, s = sn, d = dn;
    }
    worst = fmax(worst, fabs(s - arc[i]));
    if (series) series[i] = fabs(s - arc[i]);
  }
  free(l.q), free(l.s), free(arc);
  return worst;
}

double dv_run_phase_err(const double (*e)[2], const double (*ref)[2], size_t n) {
  return dv_run_phase_series(e, ref, n, NULL);
}
