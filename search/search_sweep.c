/* dv_sweep: grids of settings run in a pool of processes over shared memory. */
#include "search_sweep.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "exec_pool.h"
#include "run_scenario.h"
#include "scenario.h"
#include "run_progress.h"
#include "run_trajectory.h"
#include "dv_clock.h"

int dv_search_values_parse(const char *list, const char *as_typed, dv_vary *out, dv_error *err) {
  const char *dots = strstr(list, "..");
  out->n = 0;
  if (dots) { /* a..b:n on a log scale */
    char first[64], *end;
    snprintf(first, sizeof first, "%.*s", (int)(dots - list), list); /* "1..40": not "1." */
    double a = strtod(first, &end);
    if (*end) a = NAN;
    const double b = strtod(dots + 2, &end);
    const long n = (*end == ':') ? strtol(end + 1, &end, 10) : 0;
    if (*end || !(a > 0.0) || !(b > 0.0) || n < 2 || n > DV_SWEEP_MAX_VALUES)
      return dv_fail(err, DV_EINPUT, "%s: a range is a..b:n with a, b > 0 and 2 <= n <= %d",
                     as_typed, DV_SWEEP_MAX_VALUES);
    for (long i = 0; i < n; i++)
      snprintf(out->values[i], sizeof out->values[i], "%.6g",
               a * pow(b / a, (double)i / (double)(n - 1)));
    out->n = (size_t)n;
    return DV_OK;
  }
  /* v1,v2,...: every value whole, or an error */
  for (const char *v = list; *v;) {
    const size_t n = strcspn(v, ",");
    if (n >= sizeof out->values[0])
      return dv_fail(err, DV_EINPUT, "%s: a value has at most %zu characters", as_typed,
                     sizeof out->values[0] - 1);
    if (n && out->n == DV_SWEEP_MAX_VALUES)
      return dv_fail(err, DV_EINPUT, "%s: at most %d values", as_typed, DV_SWEEP_MAX_VALUES);
    if (n) snprintf(out->values[out->n++], sizeof out->values[0], "%.*s", (int)n, v);
    v += n + (v[n] == ',');
  }
  return out->n ? DV_OK : dv_fail(err, DV_EINPUT, "%s: no values", as_typed);
}

int dv_search_vary_parse(const char *spec, const char *engine, dv_vary *out, dv_error *err) {
  const char *eq = strchr(spec, '=');
  char as_typed[200];
  memset(out, 0, sizeof *out);
  if (!eq || eq == spec || !eq[1])
    return dv_fail(err, DV_EINPUT, "--vary %s: expected key=values", spec);
  const int bare = memchr(spec, '.', (size_t)(eq - spec)) == NULL;
  const int len = snprintf(out->key, sizeof out->key, "%s%s%s%.*s", bare ? "engines." : "",
                           bare ? engine : "", bare ? "." : "", (int)(eq - spec), spec);
  if (len < 0 || (size_t)len >= sizeof out->key)
    return dv_fail(err, DV_EINPUT, "--vary %s: the key is too long", spec);
  snprintf(as_typed, sizeof as_typed, "--vary %s", spec);
  return dv_search_values_parse(eq + 1, as_typed, out, err);
}

static int discard(void *ctx, const dv_sample *s) {
  return 0;
}

/* the median wall time of the engine alone, first run given */
static double median_wall(const dv_engine_type *e, const dv_scenario *sc, double first) {
  double w[5] = {first};
  for (int i = 1; i < 5; i++) {
    dv_engine_stats st;
    const double t0 = dv_clock_now();
    dv_run_collect(e, sc, discard, NULL, &st, NULL);
    w[i] = dv_clock_now() - t0;
  }
  return gsl_stats_median(w, 1, 5);
}

typedef struct job {
  const dv_scenario *sc; /* loaded once: no point reads the file again */
  const dv_engine_type *engine;
  const dv_vary *vary;
  size_t nvary;
  int repeat_short; /* time a run shorter than 0.2 s five times */
  const dv_comparison *refs; /* references already run (NULL: run them) */
} job;

/* the k-th point of the grid: values and the overrides that set them */
static void point_values(const job *jb, size_t k, dv_sweep_point *pt, char (*over)[160]) {
  for (size_t v = jb->nvary; v-- > 0;) {
    const dv_vary *vy = &jb->vary[v];
    snprintf(pt->values[v], sizeof pt->values[v], "%s", vy->values[k % vy->n]);
    snprintf(over[v], sizeof over[v], "%s=%s", vy->key, vy->values[k % vy->n]);
    k /= vy->n;
  }
}

/* point k as it is before it runs, and stays when it never does (an
 * interrupted sweep): its settings, and no measurement (NaN), "missing" */
static void not_run(const job *jb, size_t k, dv_sweep_point *pt) {
  char over[DV_SWEEP_MAX_VARY][160];
  memset(pt, 0, sizeof *pt);
  point_values(jb, k, pt, over);
  for (int m = 0; m < DV_NMETRICS; m++) pt->metric[m] = NAN;
  pt->theta_thin = pt->wall_per_sim_s = pt->sim_s = pt->wall_s = NAN;
  pt->steps = -1;
  pt->verdict = DV_VERDICT_MISSING;
}

/* does an override in over[0..n) set engine's key */
static int sets(const char *const *over, size_t n, const char *engine, const char *key) {
  char pat[96];
  snprintf(pat, sizeof pat, "%s.%s=", engine, key);
  for (size_t i = 0; i < n; i++)
    if (strstr(over[i], pat)) return 1;
  return 0;
}

/* over, then the settings the scene chose for the engine (engine_choose.h)
 * that over leaves alone: its choice key (the integrator), and its step and
 * contact softness unless over sets the choice key or the step, which are
 * then chosen again for them. A point varies its own keys; the rest stays
 * the scenario's. */
static size_t pin_chosen(const job *jb, const char *const *over, size_t nover, const char **with,
                         char pins[][160]) {
  const dv_engine_search *se = jb->engine->search;
  const dv_engine_contact *k = jb->engine->contact;
  size_t n = 0, npins = 0;
  for (size_t i = 0; i < nover; i++) with[n++] = over[i];
  if (!se || !se->choice_key) return n;
  const char *name = se->section;
  const int rechoose =
      sets(over, nover, name, se->choice_key) || sets(over, nover, name, se->step_key);
  const char *keys[3] = {se->choice_key, rechoose ? NULL : se->step_key,
                         rechoose || !k ? NULL : k->softness_key};
  for (int i = 0; i < 3; i++) {
    if (!keys[i] || sets(over, nover, name, keys[i]) ||
        !dv_scenario_is_derived(jb->sc, name, keys[i]))
      continue;
    const dv_setting_spec *sp = dv_settings_find(jb->engine->settings, keys[i]);
    const double v = dv_scenario_get(jb->sc, name, keys[i]);
    if (!sp) continue;
    if (sp->type == DV_SETTING_CHOICE) {
      const char *choice = dv_setting_choice(sp, (size_t)v);
      if (!choice) continue;
      snprintf(pins[npins], sizeof pins[npins], "engines.%s.%s=%s", name, keys[i], choice);
    } else
      snprintf(pins[npins], sizeof pins[npins], "engines.%s.%s=%.17g", name, keys[i], v);
    with[n++] = pins[npins++];
  }
  return n;
}

/* every override is one of engine's own settings: the references still hold
 * (a scenario key, a short window's duration, changes them) */
static int engine_only(const dv_engine_type *engine, const char *const *over, size_t nover) {
  char prefix[96];
  snprintf(prefix, sizeof prefix, "engines.%s.", engine->name);
  for (size_t i = 0; i < nover; i++)
    if (strncmp(over[i], prefix, strlen(prefix))) return 0;
  return 1;
}

/* run one point: the scenario with over[0..nover) */
static void run_overrides(const job *jb, const char *const *over, size_t nover,
                          dv_sweep_point *pt) {
  dv_scenario *sc = malloc(sizeof *sc), *ref = malloc(sizeof *ref);
  dv_comparison *c = malloc(sizeof *c);
  dv_error err = {{0}};
  pt->verdict = DV_VERDICT_INVALID;
  pt->failure = DV_FAILURE_NONE;
  for (int m = 0; m < DV_NMETRICS; m++) pt->metric[m] = pt->limit[m] = NAN;
  if (!sc || !ref || !c) {
    snprintf(pt->detail, sizeof pt->detail, "out of memory");
    goto cleanup;
  }
  const char *with[DV_SWEEP_MAX_VARY + 8];
  char pins[3][160];
  if (nover > DV_SWEEP_MAX_VARY + 5) {
    snprintf(pt->detail, sizeof pt->detail, "too many settings varied at once");
    goto cleanup;
  }
  const size_t nwith = pin_chosen(jb, over, nover, with, pins);
  if (dv_scenario_with(jb->sc, with, nwith, sc, &err)) {
    snprintf(pt->detail, sizeof pt->detail, "%.191s", err.msg);
    goto cleanup;
  }
  /* a reference's own settings are measured against a tighter reference */
  const dv_scenario *ref_sc = NULL;
  if (jb->engine->tighten) {
    *ref = *jb->sc;
    if (jb->engine->tighten(ref, &err)) {
      snprintf(pt->detail, sizeof pt->detail, "%.191s", err.msg);
      goto cleanup;
    }
    ref_sc = ref;
  }
  const dv_engine_type *engines[1] = {jb->engine};
  const int status = jb->refs && !ref_sc && engine_only(jb->engine, over, nover)
                         ? dv_run_engine_against(jb->refs, sc, NULL, jb->engine, c, &err)
                         : dv_run_scenario(sc, ref_sc, engines, 1, c, &err);
  if (status) {
    pt->verdict = DV_VERDICT_ERROR;
    snprintf(pt->detail, sizeof pt->detail, "%.191s", err.msg);
    dv_run_comparison_free(c);
    goto cleanup;
  }
  const dv_engine_result *r = &c->r[0];
  const double sim = r->traj.n ? r->traj.s[r->traj.n - 1].t : 0.0;
  const int repeat = jb->repeat_short && r->wall_s < 0.2;
  pt->timed_runs = repeat ? 5 : 1;
  const double wall = repeat ? median_wall(jb->engine, sc, r->wall_s) : r->wall_s;
  pt->sim_s = sim;
  pt->wall_s = r->wall_s;
  memcpy(pt->metric, r->vs_ref.value, sizeof pt->metric);
  memcpy(pt->limit, r->tolerance, sizeof pt->limit);
  pt->theta_thin = r->vs_thin.value[DV_THETA_MAX_ERR];
  pt->thinner = r->other_body && r->status >= 0;
  pt->wall_per_sim_s = dv_run_cost_rate(wall, sim, sc->output_dt);
  pt->steps = r->stats.steps;
  /* a point not judged (its run is its reference's) measured nothing: never a pass */
  const int judged = r->verdict != DV_VERDICT_NOT_JUDGED;
  pt->ok = !dv_run_verdict_failed(r->verdict) && judged;
  pt->verdict = r->verdict;
  pt->failure = r->stats.failure;
  /* a run that measured nothing says why (its window), not how the engine ended */
  const int measured = judged && r->verdict != DV_VERDICT_OUTSIDE_VALIDITY;
  snprintf(pt->detail, sizeof pt->detail, "%.191s",
           measured || !r->nfailures ? r->stats.detail : r->failures[0]);
  dv_run_comparison_free(c);
cleanup:
  free(sc);
  free(ref);
  free(c);
}

static void run_point(const job *jb, size_t k, dv_sweep_point *pt);

typedef struct checkpoint_ctx {
  const job *jb;
  dv_sweep *out;
  dv_sweep_point *pts;
  size_t n;
  const char *dir;
} checkpoint_ctx;

/* dv_exec_mpi_farm's task: one point */
static void farm_point(size_t k, void *result, void *ctx) {
  const checkpoint_ctx *ck = ctx;
  run_point(ck->jb, k, result);
}

/* rank 0, after every result: the tables so far, so a job killed by a dying
 * rank still leaves what finished (points not run say "missing") */
static void checkpoint(size_t k, int ran, void *ctx) {
  checkpoint_ctx *ck = ctx;
  ck->out->p = ck->pts;
  ck->out->n = ck->n;
  dv_search_sweep_write_tables(ck->dir, ck->out, NULL);
  ck->out->p = NULL;
  ck->out->n = 0;
}

/* after every result: the progress line, and under mpirun rank 0's checkpoint */
static void point_ended(size_t k, int ran, void *ctx) {
  const checkpoint_ctx *ck = ctx;
  dv_run_progress_task_ended(NULL);
  if (dv_exec_mpi_size() > 1 && ck->dir) checkpoint(k, ran, ctx);
}

static void run_point(const job *jb, size_t k, dv_sweep_point *pt) {
  char over[DV_SWEEP_MAX_VARY][160];
  const char *ptrs[DV_SWEEP_MAX_VARY];
  memset(pt, 0, sizeof *pt);
  point_values(jb, k, pt, over);
  for (size_t v = 0; v < jb->nvary; v++) ptrs[v] = over[v];
  run_overrides(jb, ptrs, jb->nvary, pt);
}

int dv_search_sweep_probe(const dv_scenario *sc, const char *engine, const char *const *overrides,
                          size_t n, dv_sweep_point *out, dv_error *err) {
  return dv_search_sweep_probe_in(NULL, sc, engine, overrides, n, out, err);
}

int dv_search_sweep_probe_in(const dv_comparison *refs, const dv_scenario *sc, const char *engine,
                             const char *const *overrides, size_t n, dv_sweep_point *out,
                             dv_error *err) {
  const dv_engine_type *e = dv_engine_find(engine);
  if (!e) return dv_fail(err, DV_EINPUT, "unknown engine '%s'", engine);
  const job jb = {sc, e, NULL, 0, 0, refs};
  memset(out, 0, sizeof *out);
  run_overrides(&jb, overrides, n, out);
  return DV_OK;
}

int dv_search_sweep_run(const dv_scenario *sc, const char *engine, const dv_vary *vary,
                        size_t nvary, int jobs, dv_sweep *out, dv_error *err) {
  const char *checkpoint_dir = out->checkpoint_dir;
  memset(out, 0, sizeof *out);
  out->checkpoint_dir = checkpoint_dir;
  const dv_engine_type *e = dv_engine_find(engine);
  if (!e) return dv_fail(err, DV_EINPUT, "unknown engine '%s'", engine);
  if (nvary > DV_SWEEP_MAX_VARY)
    return dv_fail(err, DV_EINPUT, "at most %d --vary", DV_SWEEP_MAX_VARY);
  size_t n = 1;
  for (size_t v = 0; v < nvary; v++) n *= vary[v].n;
  if (n > DV_SWEEP_MAX_POINTS)
    return dv_fail(err, DV_EINPUT, "%zu points: at most %d", n, DV_SWEEP_MAX_POINTS);
  snprintf(out->scenario, sizeof out->scenario, "%s", sc->name);
  snprintf(out->engine, sizeof out->engine, "%s", engine);
  out->nvary = nvary;
  memcpy(out->vary, vary, nvary * sizeof *vary);
  dv_sweep_point *pts = calloc(n, sizeof *pts);
  if (!pts) return dv_fail(err, DV_ESYSTEM, "out of memory");
  const job jb = {sc, e, vary, nvary, 1, NULL};
  for (size_t k = 0; k < n; k++) not_run(&jb, k, &pts[k]);
  checkpoint_ctx ck = {&jb, out, pts, n, checkpoint_dir};
  /* under mpirun, rank 0 keeps the tables current as results arrive */
  /* the reference's own curves follow a contact engine's points: a phase of their own */
  dv_run_progress_tasks_begin(e->role == DV_ENGINE_CONTACT ? "point" : "reference point", n);
  const int pool = dv_exec_pool_run(n, sizeof *pts, farm_point, &ck, pts, jobs, point_ended);
  dv_run_progress_tasks_end();
  if (pool == 1 || pool < 0) { /* a worker rank: rank 0 has the results */
    free(pts);
    return pool == 1 ? DV_EVENT : dv_fail(err, DV_ESYSTEM, "out of memory");
  }
  out->interrupted = pool == 2;
  out->p = pts;
  out->n = n;
  dv_search_pareto(out->p, n);
  return DV_OK;
}

void dv_search_sweep_free(dv_sweep *s) {
  if (!s) return;
  free(s->p);
  s->p = NULL;
  s->n = 0;
}

/* error a is below b by more than the tie */
static int error_below(double a, double b) {
  return a < b * (1.0 - DV_SEARCH_ERROR_TIE);
}

void dv_search_pareto(dv_sweep_point *p, size_t n) {
  for (size_t i = 0; i < n; i++) {
    const double e = p[i].metric[DV_THETA_MAX_ERR], c = p[i].wall_per_sim_s;
    p[i].pareto = p[i].ok && isfinite(e) && isfinite(c);
    for (size_t j = 0; j < n && p[i].pareto; j++) {
      const double ej = p[j].metric[DV_THETA_MAX_ERR], cj = p[j].wall_per_sim_s;
      /* j dominates: no worse beyond the tie in error, no dearer, and better in one */
      if (j != i && p[j].ok && !error_below(e, ej) && cj <= c && (error_below(ej, e) || cj < c))
        p[i].pareto = 0;
    }
  }
}

double dv_search_fit_order(const double *h, const double *err, size_t n) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  size_t m = 0;
  for (size_t i = 0; i < n; i++) {
    if (!(h[i] > 0.0) || !(err[i] > 0.0) || !isfinite(err[i])) continue;
    const double x = log(h[i]), y = log(err[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    m++;
  }
  const double d = (double)m * sxx - sx * sx;
  return (m < 2 || d == 0.0) ? NAN : ((double)m * sxy - sx * sy) / d;
}

typedef struct step_error {
  double h, e;
} step_error;

static int by_step(const void *a, const void *b) {
  const double x = ((const step_error *)a)->h, y = ((const step_error *)b)->h;
  return (x > y) - (x < y);
}

void dv_search_fit_convergence(const double *h, const double *err, size_t n, dv_step_fit *out) {
  *out = (dv_step_fit){NAN, NAN, NAN, 0, 0};
  step_error *p = malloc((n + 1) * sizeof *p);
  double *x = malloc((2 * n + 1) * sizeof *x), *y = x ? x + n : NULL;
  size_t m = 0;
  for (size_t i = 0; p && x && i < n; i++)
    if (h[i] > 0.0 && err[i] > 0.0 && isfinite(err[i])) p[m++] = (step_error){h[i], err[i]};
  if (m) qsort(p, m, sizeof *p, by_step);
  /* the floor: from the finest step while the errors do not fall with it */
  size_t k = 1;
  while (k < m && log(p[k].e / p[k - 1].e) / log(p[k].h / p[k - 1].h) < DV_FLOOR_ORDER) k++;
  double floor = 0.0;
  if (m >= 2 && k >= 2) {
    for (size_t i = 0; i < k; i++) x[i] = p[i].e;
    floor = gsl_stats_median(x, 1, k);
    out->floor = floor;
    out->floor_step = p[k - 1].h;
    out->nfloor = k;
  }
  /* the order where the errors fall: above twice the floor, less the floor */
  size_t nf = 0;
  for (size_t i = 0; i < m; i++)
    if (floor == 0.0 || p[i].e >= 2.0 * floor) {
      x[nf] = p[i].h;
      y[nf++] = p[i].e - floor;
    }
  out->nfalling = nf;
  out->order = dv_search_fit_order(x, y, nf);
  free(p);
  free(x);
}
