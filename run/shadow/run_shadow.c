/* run_shadow: the spread of the nudged references (run_shadow.h); checked by
 * tests/shadow/test_shadow against runs shifted by known amounts. */
#include "run_shadow.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "run_phase.h"
#include "run_turning.h"

int dv_shadow_alloc(dv_shadow *s, size_t n) {
  memset(s, 0, sizeof *s);
  s->n = n;
  for (int k = 0; k < DV_SHADOW_N; k++)
    if (!(s->env[k] = calloc(n ? n : 1, sizeof *s->env[k]))) return dv_shadow_free(s), -1;
  return 0;
}

void dv_shadow_free(dv_shadow *s) {
  if (!s) return;
  for (int k = 0; k < DV_SHADOW_N; k++) free(s->env[k]);
  memset(s, 0, sizeof *s);
}

void dv_shadow_sum(dv_shadow *into, const dv_shadow *from) {
  for (int k = 0; k < DV_SHADOW_N; k++)
    for (size_t i = 0; i < into->n && i < from->n; i++) into->env[k][i] += from->env[k][i];
}

void dv_shadow_clear(dv_shadow *s) {
  for (int k = 0; k < DV_SHADOW_N; k++)
    for (size_t i = 0; i < s->n; i++) s->env[k][i] = 0.0;
}

/* the samples e and ref share at equal times, from the start, up to t_end */
static size_t shared(const dv_traj *e, const dv_traj *ref, double t_end) {
  size_t n = 0;
  while (n < e->n && n < ref->n && ref->s[n].t <= t_end + 1e-12 &&
         fabs(e->s[n].t - ref->s[n].t) < 1e-9)
    n++;
  return n;
}

int dv_shadow_errors(const dv_traj *e, const dv_traj *ref, double t_end, double *err[3]) {
  const size_t n = shared(e, ref, t_end);
  for (int k = 0; k < 3; k++)
    for (size_t i = 0; i < ref->n; i++) err[k][i] = NAN;
  double(*pa)[2] = malloc((n ? n : 1) * sizeof *pa), (*pb)[2] = malloc((n ? n : 1) * sizeof *pb);
  if (!pa || !pb) return free(pa), free(pb), -1;
  for (size_t i = 0; i < n; i++) {
    const dv_sample *a = &e->s[i], *b = &ref->s[i];
    err[DV_SHADOW_THETA][i] = fabs(a->y[RED_TH] - b->y[RED_TH]);
    err[DV_SHADOW_PATH][i] = hypot(a->contact[0] - b->contact[0], a->contact[1] - b->contact[1]);
    pa[i][0] = a->contact[0], pa[i][1] = a->contact[1];
    pb[i][0] = b->contact[0], pb[i][1] = b->contact[1];
  }
  dv_run_phase_series((const double(*)[2])pa, (const double(*)[2])pb, n, err[DV_SHADOW_PHASE]);
  free(pa);
  free(pb);
  return 0;
}

double dv_shadow_at(const dv_shadow *s, const dv_traj *ref, dv_shadow_kind kind, double t) {
  size_t i = 0;
  while (i + 1 < s->n && i + 1 < ref->n && ref->s[i].t < t - 1e-12) i++;
  return s->n ? s->env[kind][i] : 0.0;
}

int dv_shadow_scratch_alloc(dv_shadow_scratch *s, size_t nref, size_t ne) {
  for (int k = 0; k < 3; k++) s->err[k] = malloc((nref ? nref : 1) * sizeof(double));
  s->t = malloc((nref + ne + 1) * sizeof *s->t);
  s->lag = malloc((nref + ne + 1) * sizeof *s->lag);
  return s->err[0] && s->err[1] && s->err[2] && s->t && s->lag ? 0 : -1;
}

void dv_shadow_scratch_free(dv_shadow_scratch *s) {
  for (int k = 0; k < 3; k++) free(s->err[k]);
  free(s->t);
  free(s->lag);
  memset(s, 0, sizeof *s);
}

int dv_shadow_add_run(dv_shadow *into, const dv_traj *run, const dv_traj *ref) {
  const size_t n = ref->n;
  dv_shadow_scratch w;
  if (dv_shadow_scratch_alloc(&w, n, run->n) || dv_shadow_errors(run, ref, INFINITY, w.err))
    return dv_shadow_scratch_free(&w), -1;
  const size_t nturns = dv_run_turning_lags(run, ref, INFINITY, w.t, w.lag, NULL);
  double most[3] = {0.0, 0.0, 0.0}, most_lag = 0.0;
  for (size_t i = 0; i < n && i < into->n; i++) {
    for (int k = 0; k < 3; k++) /* NAN: past the run's end, or a point the phase skipped */
      most[k] = isnan(w.err[k][i])
                    ? (k == DV_SHADOW_PHASE && !isnan(w.err[0][i]) ? most[k] : INFINITY)
                    : fmax(most[k], w.err[k][i]);
    for (size_t j = 0; j < nturns; j++)
      if (w.t[j] <= ref->s[i].t + 1e-12) most_lag = fmax(most_lag, fabs(w.lag[j]));
    if (isnan(w.err[DV_SHADOW_THETA][i])) most_lag = INFINITY;
    for (int k = 0; k < 3; k++) into->env[k][i] = fmax(into->env[k][i], most[k]);
    into->env[DV_SHADOW_LAG][i] = fmax(into->env[DV_SHADOW_LAG][i], most_lag);
  }
  dv_shadow_scratch_free(&w);
  return 0;
}
