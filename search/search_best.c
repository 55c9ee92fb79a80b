/* dv_search: the cheapest settings that meet a tolerance, and stability
 * limits, by bracketing and bisection over probe runs. */
#include "search_best.h"

#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>

#include "dv_clock.h"
#include "dv_phase.h"
#include "run_limits.h"
#include "run_progress.h"
#include "scenario.h"

/* what a search varies: the engine's declared keys, and the names of its choices */
typedef struct space {
  const char *engine;
  const dv_engine_search *search;
  const dv_setting_spec *choice;     /* the choice key's spec */
  char choice_key[96], step_key[96]; /* engines.SECTION.KEY */
  double lo, hi;                     /* range of the step */
  double wall_exponent;              /* a run's wall ~ step^-this, until two probes measure it */
} space;
typedef struct ctx {
  const dv_scenario *sc; /* loaded once: every probe varies it in memory */
  space sp;
  dv_search *out;
  dv_search_bounds bounds;
} ctx;

/* how far a probe is from meeting the search: its theta error over the
 * tolerance and, with the path, the larger of that and its path's share */
static double shortfall(const dv_search *s, const dv_sweep_point *q) {
  const double theta = q->metric[DV_THETA_MAX_ERR] / s->tolerance;
  if (isnan(s->path_tolerance)) return theta;
  const double path = q->metric[DV_PATH_MAX_ERR] / s->path_tolerance;
  /* slip at its own limit, not scaled: within the margin when within the limit */
  const double slip = s->margin * q->metric[DV_SLIP_MAX] / q->limit[DV_SLIP_MAX];
  return isnan(path) || isnan(theta) ? NAN : fmax(fmax(theta, path), slip > 0.0 ? slip : 0.0);
}

/* the path target, from the first probe that compared: the scene's path limit
 * scaled as the default theta limit is scaled to the tolerance */
static void take_path_tolerance(const ctx *c, const dv_sweep_point *q) {
  dv_search *s = c->out;
  const double path = q->limit[DV_PATH_MAX_ERR];
  if (c->bounds.with_path && isnan(s->path_tolerance) && path > 0.0 && isfinite(path))
    s->path_tolerance = path * s->tolerance / DV_LIMIT_THETA;
}

/* one probe: choice (NULL: the scenario's) and step */
static int probe(ctx *c, const char *choice, double step, dv_error *err) {
  dv_search *s = c->out;
  if (s->nprobes == DV_SEARCH_MAX_PROBES) /* not with at most DV_SEARCH_MAX_CHOICES */
    return dv_fail(err, DV_ESYSTEM, "%s: more than %d probes", c->sp.engine, DV_SEARCH_MAX_PROBES),
           -1;
  dv_probe *p = &s->probes[s->nprobes++];
  char over[2][160];
  const char *ptrs[2];
  size_t n = 0;
  snprintf(over[n], sizeof over[n], "%s=%.9g", c->sp.step_key, step);
  ptrs[n] = over[n];
  n++;
  if (choice) {
    snprintf(over[n], sizeof over[n], "%s=%s", c->sp.choice_key, choice);
    ptrs[n] = over[n];
    n++;
  }
  snprintf(p->choice, sizeof p->choice, "%s", choice ? choice : "default");
  p->step = step;
  if (dv_search_sweep_probe_in(c->bounds.refs, c->sc, c->sp.engine, ptrs, n, &p->point, err))
    return -1;
  take_path_tolerance(c, &p->point);
  const double e = shortfall(s, &p->point);
  /* a run that lay down before the reference's end compared too short a window */
  const int fell = p->point.verdict == DV_VERDICT_ENDED_BY_EVENT;
  p->state = !p->point.ok || fell ? DV_PROBE_FAILED
             : e <= s->margin     ? DV_PROBE_MEETS
             : e <= 1.0           ? DV_PROBE_MARGINAL
                                  : DV_PROBE_EXCEEDS;
  p->pass = p->state == DV_PROBE_MEETS || (s->margin >= 1.0 && p->state == DV_PROBE_MARGINAL);
  p->steps_per_sim_s = p->point.sim_s > 0.0 ? (double)p->point.steps / p->point.sim_s : NAN;
  p->cost = NAN;
  return p->pass;
}

/* the bracketing and bisection of one choice's step, one probe at a time, so
 * that the real search and its forecast take the same path */
typedef struct bracket {
  double pass, fail, h; /* h: the next step to probe, NAN when done */
  int bisecting, n;     /* the phase and the probes made in it */
} bracket;

static bracket bracket_start(double start) { return (bracket){NAN, NAN, start, 0, 0}; }

/* record the probe of b->h and choose the next: from start by factors of 2
 * until the answer changes, then bisection on a log scale to the resolution */
static void bracket_record(bracket *b, int ok, double lo, double hi) {
  if (ok)
    b->pass = b->h;
  else
    b->fail = b->h;
  const int bracketed = !isnan(b->pass) && !isnan(b->fail);
  b->n++;
  if (!b->bisecting) {
    const double next = ok ? b->h * 2.0 : b->h / 2.0;
    if (!bracketed && b->n < DV_SEARCH_BRACKET && next <= hi && next >= lo) {
      b->h = next;
      return;
    }
    b->bisecting = 1, b->n = 0;
  }
  b->h = bracketed && b->n < DV_SEARCH_BISECTIONS &&
                 fmax(b->pass, b->fail) / fmin(b->pass, b->fail) > DV_SEARCH_RESOLUTION
             ? sqrt(b->pass * b->fail)
             : NAN;
}

/* the wall seconds the rest of b will take, forecast from the choice's last
 * probes: theta error ~ step^p and the engine's run ~ step^-q (p and q from its
 * last two probes where they differ in step, else 1 and the engine's q), plus
 * the rest of the last probe's wall time (the comparison) */
static double forecast(const ctx *c, const bracket *b, const dv_probe *last, const dv_probe *prev,
                       double probe_wall) {
  const double last_wall = last->point.wall_s, prev_wall = prev ? prev->point.wall_s : NAN;
  const double overhead = fmax(probe_wall - last_wall, 0.0);
  const dv_search *s = c->out;
  double p = 1.0, q = c->sp.wall_exponent;
  const double e1 = last->point.metric[DV_THETA_MAX_ERR], h1 = last->step;
  if (prev && prev->step != h1) {
    const double e0 = prev->point.metric[DV_THETA_MAX_ERR], r = log(prev->step / h1);
    if (e0 > 0.0 && e1 > 0.0 && isfinite(e0) && isfinite(e1))
      p = fmin(fmax(log(e0 / e1) / r, 0.5), 8.0);
    if (prev_wall > 0.0 && last_wall > 0.0) q = fmin(fmax(-log(prev_wall / last_wall) / r, 0.0), 2.0);
  }
  bracket m = *b;
  double wall = 0.0;
  for (int i = 0; !isnan(m.h) && i < DV_SEARCH_BRACKET + DV_SEARCH_BISECTIONS; i++) {
    wall += overhead + last_wall * pow(h1 / m.h, q);
    const double e = e1 > 0.0 && isfinite(e1) ? e1 * pow(m.h / h1, p) : 0.0;
    bracket_record(&m, e <= s->margin * s->tolerance, c->sp.lo, c->sp.hi);
  }
  return wall;
}

/* one choice's search under way */
typedef struct lane {
  const char *choice;  /* NULL: the scenario's */
  bracket b;
  int last, prev, prev2; /* its last three probes, or -1 */
  double wall_per_step; /* s, of its last probe */
  double last_wall;     /* s, its last probe's */
  int fail_probe;      /* the probe just above its limit, or -1 */
  int skipped;         /* not searched: another choice ties it at less cost */
} lane;

/* append "CHOICE: why" to the search's stopped list */
static void say_stopped(dv_search *s, const lane *l, const char *why) {
  const size_t used = strlen(s->stopped);
  snprintf(s->stopped + used, sizeof s->stopped - used, "%s%s: %s", used ? "; " : "",
           l->choice ? l->choice : "default", why);
}

/* whether a bound ends lane before its next probe: a finer step whose cost,
 * forecast, is over the cap (a coarser one costs less than a run made), or
 * errors that have stopped falling with the step */
static int bounded(ctx *c, lane *l) {
  dv_search *s = c->out;
  char why[200];
  if (l->last < 0) return 0;
  const dv_probe *last = &s->probes[l->last];
  const double own = last->point.steps > 0 && last->point.sim_s > 0.0
                         ? last->point.wall_s / last->point.sim_s * last->step / l->b.h
                         : NAN;
  if (c->bounds.cost_cap > 0.0 && l->b.h < last->step && own > c->bounds.cost_cap) {
    snprintf(why, sizeof why,
             "the cost cap: a step of %.3g s would cost about %.3g s a simulated s (cap %g)",
             l->b.h, own, c->bounds.cost_cap);
    say_stopped(s, l, why);
    return 1;
  }
  if (!c->bounds.stop_at_floor || l->b.bisecting || l->prev2 < 0) return 0;
  const dv_probe *first = &s->probes[l->prev2], *mid = &s->probes[l->prev];
  if (first->state != DV_PROBE_EXCEEDS || mid->state != DV_PROBE_EXCEEDS ||
      last->state != DV_PROBE_EXCEEDS || !(last->step < mid->step && mid->step < first->step))
    return 0;
  const double e0 = shortfall(s, &first->point), e2 = shortfall(s, &last->point);
  const double order = log(e0 / e2) / log(first->step / last->step);
  if (!(order < DV_FLOOR_ORDER)) return 0;
  snprintf(why, sizeof why,
           "the error stops falling with the step (%.3g x the target at %.3g s, %.3g x at "
           "%.3g s: order %.2g)",
           e0, first->step, e2, last->step, order);
  say_stopped(s, l, why);
  return 1;
}

/* probe lane's next step; 1 passed, 0 not, -1 an error (the lane ends), -2
 * a bound ended the lane before it */
static int step_lane(ctx *c, lane *l, dv_error *err) {
  if (bounded(c, l)) {
    l->b.h = NAN;
    return -2;
  }
  char given[32]; /* the step as a run is given it (9 digits): what the probe, the limit and a
                     rerun of the settings all hold */
  snprintf(given, sizeof given, "%.9g", l->b.h);
  l->b.h = strtod(given, NULL);
  const double began = dv_clock_now();
  const int ok = probe(c, l->choice, l->b.h, err);
  const double wall = dv_clock_now() - began;
  if (ok < 0) {
    l->b.h = NAN;
    return -1;
  }
  const dv_probe *p = &c->out->probes[c->out->nprobes - 1];
  l->prev2 = l->prev;
  l->prev = l->last;
  l->last = (int)c->out->nprobes - 1;
  if (p->point.steps > 0) l->wall_per_step = wall / (double)p->point.steps;
  l->last_wall = wall;
  if (!ok) l->fail_probe = l->last;
  bracket_record(&l->b, ok, c->sp.lo, c->sp.hi);
  return ok;
}

/* lane i of n begins its next probe: the progress line counts the lanes of phase name */
static void phase_lane(const ctx *c, const char *name, size_t i, size_t n, const lane *l) {
  char subject[64];
  snprintf(subject, sizeof subject, "%s %s %.4g s", c->sp.engine, l->choice ? l->choice : "step",
           l->b.h);
  dv_phase_item(name, i + 1, n, subject);
}

/* the wall seconds lanes[from..n) have left, forecast */
static double left(const ctx *c, const lane *lanes, size_t n, size_t from) {
  double total = 0.0;
  for (size_t i = from; i < n; i++)
    if (!lanes[i].skipped && lanes[i].last >= 0 && !isnan(lanes[i].b.h))
      total += forecast(c, &lanes[i].b, &c->out->probes[lanes[i].last],
                        lanes[i].prev >= 0 ? &c->out->probes[lanes[i].prev] : NULL,
                        lanes[i].last_wall);
  return total;
}

/* a line on stderr for the probe just ended, with the forecast of the rest */
static void tell(const ctx *c, double rest) {
  const dv_probe *p = &c->out->probes[c->out->nprobes - 1];
  char err[32] = "no error measured";
  if (p->state != DV_PROBE_FAILED)
    snprintf(err, sizeof err, "theta error %.3e rad", p->point.metric[DV_THETA_MAX_ERR]);
  dv_run_progress_say("%s %s %.4g: %s, %s; about %.0f s left", c->sp.engine, p->choice, p->step,
                      err, dv_probe_state_name(p->state), rest);
}

static int setup(const dv_scenario *sc, const char *engine, double tol, dv_search *out, ctx *c,
                 double *start, dv_error *err) {
  memset(out, 0, sizeof *out);
  const dv_engine_type *type = dv_engine_find(engine);
  const dv_engine_search *search = type ? type->search : NULL;
  const dv_engine_type *owner = search ? dv_engine_find(search->section) : NULL;
  if (!search || !owner || !owner->settings)
    return dv_fail(err, DV_EINPUT, "no search space for engine '%s'", engine);
  if (!(tol > 0.0)) return dv_fail(err, DV_EINPUT, "the tolerance must be > 0");
  *start = dv_scenario_get(sc, search->section, search->step_key);
  *c = (ctx){.sc = sc, .out = out};
  c->sp.engine = engine;
  c->sp.search = search;
  c->sp.choice = dv_settings_find(owner->settings, search->choice_key);
  size_t nchoices = 0;
  while (c->sp.choice && dv_setting_choice(c->sp.choice, nchoices)) nchoices++;
  if (nchoices > DV_SEARCH_MAX_CHOICES)
    return dv_fail(err, DV_EINPUT, "%s: %zu choices of %s, a search takes at most %d", engine,
                   nchoices, search->choice_key, DV_SEARCH_MAX_CHOICES);
  snprintf(c->sp.choice_key, sizeof c->sp.choice_key, "engines.%s.%s", search->section,
           search->choice_key);
  snprintf(c->sp.step_key, sizeof c->sp.step_key, "engines.%s.%s", search->section,
           search->step_key);
  c->sp.lo = search->lo;
  c->sp.hi = search->hi;
  snprintf(out->engine, sizeof out->engine, "%s", engine);
  snprintf(out->choice_key, sizeof out->choice_key, "%s", c->sp.choice_key);
  snprintf(out->step_key, sizeof out->step_key, "%s", c->sp.step_key);
  out->tolerance = tol;
  out->path_tolerance = NAN;
  out->margin = 1.0;
  out->best = out->first_failure = -1;
  c->sp.wall_exponent = type->contact ? 1.0 : 0.125; /* a timestep; rtol, an 8th order's */
  out->limit = NAN;
  return DV_OK;
}

/* the calibration of choice, or NULL */
static const dv_step_cost *step_cost_of(const dv_search *s, const char *choice) {
  for (size_t k = 0; k < s->nchoices; k++)
    if (!strcmp(s->step_cost[k].choice, choice)) return &s->step_cost[k];
  return NULL;
}

/* seconds per step of every choice probed: the median of wall / steps over
 * its probes that ran; then every probe's cost */
static void calibrate(dv_search *s) {
  double per_step[DV_SEARCH_MAX_PROBES];
  for (size_t i = 0; i < s->nprobes; i++) {
    const char *choice = s->probes[i].choice;
    if (step_cost_of(s, choice) || s->nchoices == DV_SEARCH_MAX_CHOICES) continue;
    size_t n = 0;
    for (size_t j = i; j < s->nprobes; j++) {
      const dv_sweep_point *q = &s->probes[j].point;
      if (!strcmp(s->probes[j].choice, choice) && q->steps > 0 && q->wall_s > 0.0)
        per_step[n++] = q->wall_s / (double)q->steps;
    }
    dv_step_cost *k = &s->step_cost[s->nchoices++];
    snprintf(k->choice, sizeof k->choice, "%s", choice);
    k->runs = (int)n;
    k->median = k->min = k->max = NAN;
    if (!n) continue;
    gsl_stats_minmax(&k->min, &k->max, per_step, 1, n);
    k->median = gsl_stats_median(per_step, 1, n);
  }
  for (size_t i = 0; i < s->nprobes; i++) {
    const dv_step_cost *k = step_cost_of(s, s->probes[i].choice);
    s->probes[i].cost = k ? s->probes[i].steps_per_sim_s * k->median : NAN;
  }
}

/* whether probe a beats probe b: fewer steps within a choice; across choices
 * the lower cost, unless the costs lie within the calibrations' spread (a tie
 * that timing noise could turn), where fewer steps win */
static int cheaper(const dv_search *s, size_t a, size_t b) {
  const dv_probe *pa = &s->probes[a], *pb = &s->probes[b];
  if (!(pa->cost >= 0.0)) return 0;
  if (!(pb->cost >= 0.0)) return 1;
  if (strcmp(pa->choice, pb->choice)) {
    const dv_step_cost *ka = step_cost_of(s, pa->choice), *kb = step_cost_of(s, pb->choice);
    const double spread = fmax(ka->max / ka->min, kb->max / kb->min);
    const double ratio = fmax(pa->cost, pb->cost) / fmin(pa->cost, pb->cost);
    if (!(ratio <= spread)) return pa->cost < pb->cost;
  }
  return pa->steps_per_sim_s < pb->steps_per_sim_s;
}

/* a choice whose first probe's error ties an earlier choice's at the same
 * step (DV_SEARCH_TIE) and whose steps cost DV_SEARCH_TIE_COST times more
 * would search the same curve at more cost: it is not searched */
static void skip_ties(ctx *c, lane *lanes, size_t n) {
  for (size_t j = 1; j < n; j++)
    for (size_t i = 0; i < j && !lanes[j].skipped; i++) {
      if (lanes[i].skipped || lanes[i].last < 0 || lanes[j].last < 0) continue;
      const dv_probe *a = &c->out->probes[lanes[i].last], *b = &c->out->probes[lanes[j].last];
      const double ea = a->point.metric[DV_THETA_MAX_ERR], eb = b->point.metric[DV_THETA_MAX_ERR];
      if (a->state == DV_PROBE_FAILED || b->state == DV_PROBE_FAILED || !(ea > 0.0) ||
          fabs(eb - ea) > DV_SEARCH_TIE * ea ||
          !(lanes[j].wall_per_step > DV_SEARCH_TIE_COST * lanes[i].wall_per_step))
        continue;
      lanes[j].skipped = 1;
      dv_search *s = c->out;
      const size_t used = strlen(s->skipped);
      snprintf(s->skipped + used, sizeof s->skipped - used,
               "%s%s not searched: its error at %.4g (%.4g rad) ties %s's, at %.2gx the cost a step",
               used ? "; " : "", lanes[j].choice, b->step, eb, lanes[i].choice,
               lanes[j].wall_per_step / lanes[i].wall_per_step);
    }
}

/* probe every choice (best), or only the scenario's (stability): each
 * choice's start first, so that ties are seen and the whole search is
 * forecast (and announced when long) before the rest */
static int search(const dv_scenario *sc, const char *engine, double tol, int every_choice,
                  const dv_search_bounds *bounds, dv_search *out, dv_error *err) {
  ctx c;
  double start = NAN;
  const int status = setup(sc, engine, tol, out, &c, &start, err);
  if (status) return status;
  if (bounds) c.bounds = *bounds;
  lane lanes[DV_SEARCH_MAX_CHOICES];
  size_t n = 0;
  const char *choice;
  if (!every_choice)
    lanes[n++] = (lane){NULL, bracket_start(start), -1, -1, -1, NAN, NAN, -1, 0};
  else
    for (size_t i = 0; c.sp.choice && (choice = dv_setting_choice(c.sp.choice, i)); i++)
      lanes[n++] = (lane){choice, bracket_start(start), -1, -1, -1, NAN, NAN, -1, 0};
  out->margin = every_choice ? DV_SEARCH_MARGIN : 1.0;
  for (size_t i = 0; i < n; i++) {
    phase_lane(&c, "first probe of each choice", i, n, &lanes[i]);
    step_lane(&c, &lanes[i], err);
    tell(&c, left(&c, lanes, n, 0));
  }
  dv_phase_end("first probe of each choice");
  skip_ties(&c, lanes, n);
  if (out->skipped[0]) dv_run_progress_say("%s", out->skipped);
  char what[96];
  snprintf(what, sizeof what, "%.40s: the search of %s", sc->name, engine);
  const double forecast_s = left(&c, lanes, n, 0), began = dv_clock_now();
  dv_run_progress_plan_total(what, forecast_s, "forecast from each choice's first probe");
  dv_run_progress_say("the rest of the search forecast at %.3g s", forecast_s);
  for (size_t i = 0; i < n; i++)
    while (!lanes[i].skipped && !isnan(lanes[i].b.h)) {
      phase_lane(&c, "search of choice", i, n, &lanes[i]);
      if (step_lane(&c, &lanes[i], err) != -2) tell(&c, left(&c, lanes, n, i));
    }
  dv_phase_end("search of choice");
  dv_run_progress_say("the rest of the search took %.3g s (forecast %.3g s)",
                      dv_clock_now() - began, forecast_s);
  if (!every_choice) {
    out->limit = lanes[0].b.pass;
    out->first_failure = lanes[0].fail_probe;
    return DV_OK;
  }
  calibrate(out);
  for (size_t i = 0; i < out->nprobes; i++)
    if (out->probes[i].pass && (out->best < 0 || cheaper(out, i, (size_t)out->best)))
      out->best = (int)i;
  return DV_OK;
}

int dv_search_best(const dv_scenario *sc, const char *engine, double tol, dv_search *out,
                   dv_error *err) {
  return search(sc, engine, tol, 1, NULL, out, err);
}

int dv_search_best_bounded(const dv_scenario *sc, const char *engine, double tol,
                           const dv_search_bounds *bounds, dv_search *out, dv_error *err) {
  return search(sc, engine, tol, 1, bounds, out, err);
}

int dv_search_stability(const dv_scenario *sc, const char *engine, double tol, dv_search *out,
                        dv_error *err) {
  return search(sc, engine, tol, 0, NULL, out, err);
}

const char *dv_search_failure_mode(const dv_probe *p) {
  const dv_sweep_point *q = &p->point;
  if (p->pass) return "none";
  if (q->failure != DV_FAILURE_NONE) return dv_failure_name(q->failure);
  switch (q->verdict) {
    case DV_VERDICT_ENDED_BY_EVENT:
      return "falls";
    case DV_VERDICT_AGREES:
    case DV_VERDICT_EXCEEDS:
      return "drifts";
    default:
      return "error";
  }
}

const char *dv_probe_state_name(dv_probe_state state) {
  static const char *const NAMES[] = {"meets", "marginal", "exceeds", "failed"};
  return state >= DV_PROBE_MEETS && state <= DV_PROBE_FAILED ? NAMES[state] : "failed";
}
