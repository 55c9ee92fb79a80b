/* dv_search: the cheapest settings that meet a tolerance, and stability
 * limits, by bracketing and bisection over probe runs. */
#include "search_best.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "scenario.h"

/* what an engine's search varies: a discrete choice and a step */
typedef struct space {
  const char *engine, *choice_key, *step_key;
  const char *const *choices;
  double lo, hi; /* range of the step */
} space;

static const char *const MJ_CHOICES[] = {"euler", "rk4", "implicit", NULL};
static const char *const ODE_CHOICES[] = {"step", "quickstep", NULL};
static const char *const REF_CHOICES[] = {"gsl-rk8pd",   "gsl-rk8pd-stepped", "gsl-msadams",
                                          "cvode-adams", "cvode-bdf",         "arkode-fehlberg13",
                                          NULL};

static const space SPACES[] = {
    {"mujoco", "engines.mujoco.integrator", "engines.mujoco.timestep", MJ_CHOICES, 1e-6, 0.02},
    {"ode", "engines.ode.stepper", "engines.ode.timestep", ODE_CHOICES, 1e-7, 0.02},
    {"reduced", "engines.reduced.integrator", "engines.reduced.rtol", REF_CHOICES, 1e-14, 1e-3},
    {"matched", "engines.reduced.integrator", "engines.reduced.rtol", REF_CHOICES, 1e-14, 1e-3},
};

static const space *find_space(const char *engine) {
  for (size_t i = 0; i < sizeof SPACES / sizeof SPACES[0]; i++)
    if (!strcmp(SPACES[i].engine, engine)) return &SPACES[i];
  return NULL;
}

typedef struct ctx {
  const char *path;
  const char *const *sets;
  size_t nsets;
  const space *sp;
  dv_search *out;
} ctx;

/* one probe: choice (NULL: the scenario's) and step */
static int probe(ctx *c, const char *choice, double step, dv_error *err) {
  dv_search *s = c->out;
  if (s->nprobes == DV_SEARCH_MAX_PROBES) return -1;
  dv_probe *p = &s->probes[s->nprobes++];
  char over[2][160];
  const char *ptrs[2];
  size_t n = 0;
  snprintf(over[n], sizeof over[n], "%s=%.9g", c->sp->step_key, step);
  ptrs[n] = over[n];
  n++;
  if (choice) {
    snprintf(over[n], sizeof over[n], "%s=%s", c->sp->choice_key, choice);
    ptrs[n] = over[n];
    n++;
  }
  snprintf(p->choice, sizeof p->choice, "%s", choice ? choice : "default");
  p->step = step;
  if (dv_search_sweep_probe(c->path, c->sets, c->nsets, c->sp->engine, ptrs, n, &p->point, err)) return -1;
  p->pass = p->point.ok && p->point.metric[DV_THETA_MAX_ERR] <= s->tolerance;
  return p->pass;
}

/* largest passing step for choice: bracket from start by factors of 2, then
 * bisect on a log scale; returns the passing step or NAN, sets *fail_probe */
static double largest(ctx *c, const char *choice, double start, int *fail_probe, dv_error *err) {
  double pass = NAN, fail = NAN, h = start;
  *fail_probe = -1;
  for (int i = 0; i < 24; i++) {
    const int ok = probe(c, choice, h, err);
    if (ok < 0) return pass;
    if (ok) {
      pass = h;
      if (!isnan(fail) || h * 2.0 > c->sp->hi) break;
      h *= 2.0;
    } else {
      fail = h;
      *fail_probe = (int)c->out->nprobes - 1;
      if (!isnan(pass) || h / 2.0 < c->sp->lo) break;
      h /= 2.0;
    }
  }
  for (int i = 0; i < 6 && !isnan(pass) && !isnan(fail); i++) {
    const double mid = sqrt(pass * fail);
    const int ok = probe(c, choice, mid, err);
    if (ok < 0) break;
    if (ok)
      pass = mid;
    else {
      fail = mid;
      *fail_probe = (int)c->out->nprobes - 1;
    }
  }
  return pass;
}

static int setup(const char *path, const char *const *sets, size_t nsets, const char *engine,
                 double tol, dv_search *out, ctx *c, double *start, dv_error *err) {
  memset(out, 0, sizeof *out);
  const space *sp = find_space(engine);
  if (!sp) return dv_fail(err, DV_EINPUT, "no search space for engine '%s'", engine);
  if (!(tol > 0.0)) return dv_fail(err, DV_EINPUT, "the tolerance must be > 0");
  static dv_scenario sc;
  if (dv_scenario_load(path, sets, nsets, &sc, err)) return DV_EINPUT;
  snprintf(out->engine, sizeof out->engine, "%s", engine);
  snprintf(out->choice_key, sizeof out->choice_key, "%s", sp->choice_key);
  snprintf(out->step_key, sizeof out->step_key, "%s", sp->step_key);
  out->tolerance = tol;
  out->best = out->first_failure = -1;
  out->limit = NAN;
  *c = (ctx){path, sets, nsets, sp, out};
  *start = !strcmp(engine, "mujoco") ? sc.mujoco.timestep
           : !strcmp(engine, "ode")  ? sc.ode.timestep
                                     : sc.reduced.rtol;
  return DV_OK;
}

int dv_search_best(const char *path, const char *const *sets, size_t nsets, const char *engine,
                   double tol, dv_search *out, dv_error *err) {
  ctx c;
  double start;
  int status = setup(path, sets, nsets, engine, tol, out, &c, &start, err);
  if (status) return status;
  for (const char *const *ch = c.sp->choices; *ch; ch++) {
    int fail;
    largest(&c, *ch, start, &fail, err);
  }
  for (size_t i = 0; i < out->nprobes; i++) {
    const dv_probe *p = &out->probes[i];
    if (p->pass &&
        (out->best < 0 || p->point.wall_per_sim_s < out->probes[out->best].point.wall_per_sim_s))
      out->best = (int)i;
  }
  return DV_OK;
}

int dv_search_stability(const char *path, const char *const *sets, size_t nsets, const char *engine,
                        double tol, dv_search *out, dv_error *err) {
  ctx c;
  double start;
  int status = setup(path, sets, nsets, engine, tol, out, &c, &start, err);
  if (status) return status;
  out->limit = largest(&c, NULL, start, &out->first_failure, err);
  return DV_OK;
}

const char *dv_search_failure_mode(const dv_probe *p) {
  const dv_sweep_point *q = &p->point;
  if (p->pass) return "none";
  if (!strcmp(q->outcome, "diverged")) {
    if (strstr(q->detail, "reset")) return "silent reset";
    if (strstr(q->detail, "energy")) return "energy blow-up";
    if (strstr(q->detail, "sank")) return "sinks";
    return "NaN";
  }
  if (!strcmp(q->outcome, "lost contact")) return "lost contact";
  if (!strcmp(q->outcome, "ended by event")) return "falls";
  if (!strcmp(q->outcome, "error") || !strcmp(q->outcome, "invalid")) return "error";
  return "drifts";
}
