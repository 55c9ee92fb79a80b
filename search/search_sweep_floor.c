/* dv_search_sweep_floor_causes: why a sweep's errors stop falling with the
 * step, from attribution at the largest step on each curve's floor. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "search_attribute.h"
#include "search_sweep.h"

/* the ok points of the curve through point first: steps and errors */
static size_t curve_points(const dv_sweep *s, size_t key, size_t first, double *h, double *e) {
  size_t n = 0;
  for (size_t i = 0; i < s->n; i++) {
    int same = 1;
    for (size_t v = 0; v < s->nvary; v++)
      if (v != key && strcmp(s->p[i].values[v], s->p[first].values[v])) same = 0;
    if (!same || !s->p[i].ok) continue;
    h[n] = atof(s->p[i].values[key]);
    e[n++] = s->p[i].metric[DV_THETA_MAX_ERR];
  }
  return n;
}

int dv_search_sweep_curve_fit(const dv_sweep *s, size_t k, dv_step_fit *out) {
  double *h = malloc(2 * (s->n + 1) * sizeof *h);
  if (!h) return DV_ESYSTEM;
  const size_t key = dv_search_sweep_curve_key(s);
  dv_search_fit_convergence(h, h + s->n + 1, curve_points(s, key, k, h, h + s->n + 1), out);
  free(h);
  return DV_OK;
}

int dv_search_sweep_curve_first(const dv_sweep *s, size_t k) {
  char label[96], other[96];
  dv_search_sweep_curve_label(s, k, label, sizeof label);
  for (size_t j = 0; j < k; j++) {
    dv_search_sweep_curve_label(s, j, other, sizeof other);
    if (!strcmp(other, label)) return 0;
  }
  return 1;
}

/* attribute the floor of the curve through point first at step */
static void attribute_floor(const dv_scenario *sc, const dv_sweep *s, size_t key, size_t first,
                            double step, char *cause, size_t size) {
  char over[DV_SWEEP_MAX_VARY][160];
  const char *all[DV_SWEEP_MAX_VARY];
  dv_scenario *at = malloc(sizeof *at);
  dv_attribution a;
  dv_error err = {{0}};
  for (size_t v = 0; v < s->nvary; v++) {
    if (v == key)
      snprintf(over[v], sizeof over[v], "%s=%.9g", s->vary[v].key, step);
    else
      snprintf(over[v], sizeof over[v], "%s=%s", s->vary[v].key, s->p[first].values[v]);
    all[v] = over[v];
  }
  if (!at)
    snprintf(cause, size, "unknown: out of memory");
  else if (dv_scenario_with(sc, all, s->nvary, at, &err) ||
           dv_search_attribute(at, s->engine, &a, &err))
    snprintf(cause, size, "unknown: %.180s", err.msg);
  else
    dv_search_attribute_cause(&a, cause, size);
  free(at);
}

const char *dv_search_sweep_floor_cause(const dv_sweep *s, const char *label) {
  for (size_t f = 0; f < s->nfloors; f++)
    if (!strcmp(s->floors[f].curve, label)) return s->floors[f].cause;
  return NULL;
}

int dv_search_sweep_floor_causes(const dv_scenario *sc, dv_sweep *s, dv_error *err) {
  const dv_engine_type *e = dv_engine_find(s->engine);
  const size_t key = dv_search_sweep_curve_key(s);
  const char *dot = s->nvary ? strrchr(s->vary[key].key, '.') : NULL;
  s->nfloors = 0;
  if (!e || !e->contact || !dot || strcmp(dot, ".timestep") || !dv_search_sweep_fits_order(s))
    return DV_OK; /* nothing to split */
  for (size_t i = 0; i < s->n && s->nfloors < DV_SWEEP_MAX_FLOORS; i++) {
    dv_step_fit fit;
    if (!dv_search_sweep_curve_first(s, i)) continue;
    if (dv_search_sweep_curve_fit(s, i, &fit)) return dv_fail(err, DV_ESYSTEM, "out of memory");
    if (isnan(fit.floor)) continue;
    dv_search_sweep_curve_label(s, i, s->floors[s->nfloors].curve, sizeof s->floors[0].curve);
    attribute_floor(sc, s, key, i, fit.floor_step, s->floors[s->nfloors].cause,
                    sizeof s->floors[0].cause);
    s->nfloors++;
  }
  return DV_OK;
}
