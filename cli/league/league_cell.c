/* league_cell: a cell is best's search within its targets, then the compare
 * at the settings found, whose report backs the cell's numbers. */
#include "league_cell.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_clock.h"
#include "io_file.h"
#include "io_json.h"
#include "run_scenario.h"
#include "search_best.h"

struct dv_comparison *dv_league_pair_references(const dv_league_pair *pair) {
  dv_comparison *c = malloc(sizeof *c);
  dv_error err = {{0}};
  const dv_engine_type *engine = dv_engine_find(pair->engine->name);
  if (!c || !engine) return free(c), NULL;
  dv_run_comparison_begin(pair->sc, c);
  if (dv_run_thin_reference(pair->sc, c, &err)) return dv_league_pair_references_free(c), NULL;
  const double h = dv_engine_half_thickness(engine, pair->sc);
  if (h > 0.0) {
    dv_run_matched_reference(pair->sc, h, &c->matched[0]);
    c->nmatched = 1;
    if (c->matched[0].status < 0) return dv_league_pair_references_free(c), NULL;
  }
  return c;
}

void dv_league_pair_references_free(struct dv_comparison *refs) {
  if (refs) dv_run_comparison_free(refs);
  free(refs);
}

void dv_league_report_dir(const char *object, const char *engine, double target, char *out,
                          size_t size) {
  snprintf(out, size, "compare/%s/%s-%g", object, engine, target);
}

/* the probes of the chosen choice first, then the others, as far as they fit */
static void keep_points(const dv_search *s, const char *choice, dv_league_cell *c) {
  for (int pass = 0; pass < 2; pass++)
    for (size_t i = 0; i < s->nprobes && c->npoints < DV_LEAGUE_MAX_POINTS; i++) {
      const dv_probe *p = &s->probes[i];
      if ((strcmp(p->choice, choice) == 0) != (pass == 0)) continue;
      dv_league_point *q = &c->points[c->npoints++];
      snprintf(q->choice, sizeof q->choice, "%s", p->choice);
      q->step = p->step;
      q->ok = p->state != DV_PROBE_FAILED;
      q->theta_err = q->ok ? p->point.metric[DV_THETA_MAX_ERR] : NAN;
      q->path_err = q->ok ? p->point.metric[DV_PATH_MAX_ERR] : NAN;
      q->cost = p->cost;
    }
}

/* the probe a cell stands on: the winner, else the one nearest both targets,
 * else (every run failed) the first */
static int chosen_probe(const dv_search *s) {
  if (s->best >= 0) return s->best;
  int near = -1;
  double least = INFINITY;
  for (size_t i = 0; i < s->nprobes; i++) {
    const dv_probe *p = &s->probes[i];
    if (p->state == DV_PROBE_FAILED) continue;
    double r = p->point.metric[DV_THETA_MAX_ERR] / s->tolerance;
    if (!isnan(s->path_tolerance)) r = fmax(r, p->point.metric[DV_PATH_MAX_ERR] / s->path_tolerance);
    if (r < least) least = r, near = (int)i;
  }
  return near >= 0 ? near : s->nprobes ? 0 : -1;
}

/* the observed order of the chosen choice: the slope of its errors against
 * its steps, the floor left out (as a sweep's curve) */
static double observed_order(const dv_search *s, const char *choice) {
  double h[DV_SEARCH_MAX_PROBES], e[DV_SEARCH_MAX_PROBES];
  size_t n = 0;
  for (size_t i = 0; i < s->nprobes; i++) {
    const dv_probe *p = &s->probes[i];
    if (strcmp(p->choice, choice) || p->state == DV_PROBE_FAILED) continue;
    h[n] = p->step, e[n++] = p->point.metric[DV_THETA_MAX_ERR];
  }
  dv_step_fit fit;
  if (n < 2) return NAN;
  dv_search_fit_convergence(h, e, n, &fit);
  return fit.order;
}

/* the word for why no run met the targets, from how the runs failed */
static const char *failure_class(const dv_probe *p) {
  const char *mode = dv_search_failure_mode(p);
  if (!strcmp(mode, "NaN") || !strcmp(mode, "energy blow-up") || !strcmp(mode, "silent reset"))
    return "diverges";
  if (!strcmp(mode, "lost contact")) return "loses contact";
  if (!strcmp(mode, "falls")) return "lies down early";
  return mode;
}

/* why a cell is not reached, measured: every run failed (how), or the
 * nearest run's shortfall and what ended the search (cost cap, floor) */
static void why_not(const dv_search *s, int near, dv_league_cell *c) {
  const dv_probe *p = &s->probes[near];
  if (p->state == DV_PROBE_FAILED) {
    snprintf(c->why, sizeof c->why, "%s: every run failed (%s at %s %.3g s: %.120s)",
             failure_class(p), dv_search_failure_mode(p), p->choice, p->step,
             p->point.detail[0] ? p->point.detail : "no detail");
    return;
  }
  if (isnan(p->point.metric[DV_THETA_MAX_ERR])) { /* no run compared a sample: nothing measured */
    snprintf(c->why, sizeof c->why, "not judged: no run compared anything (%.180s)",
             p->point.detail[0] ? p->point.detail : "no detail");
    return;
  }
  const double slip = p->point.metric[DV_SLIP_MAX], slip_limit = p->point.limit[DV_SLIP_MAX];
  char own[256] = ""; /* what ended the nearest probe's choice */
  char key[40];
  snprintf(key, sizeof key, "%s: ", p->choice);
  const char *at = strstr(s->stopped, key);
  if (!at && s->stopped[0]) at = s->stopped; /* its choice was not searched on (a tie): the first */
  if (at) snprintf(own, sizeof own, "%.*s", (int)strcspn(at, ";"), at);
  const char *word = strstr(own, "cost cap")          ? "cost cap"
                     : strstr(own, "stops falling")   ? "error floor"
                     : slip > slip_limit              ? "slips"
                                                      : "no step reaches it";
  snprintf(c->why, sizeof c->why, "%s: nearest theta %.3g rad, path %.3g m at %s %.3g s%s%.150s",
           word, p->point.metric[DV_THETA_MAX_ERR], p->point.metric[DV_PATH_MAX_ERR], p->choice,
           p->step, own[0] ? "; " : "", own);
}

/* the backing compare's numbers for the engine, from its report.json */
static int read_report(const char *path, const char *engine, dv_league_cell *c, int *slips,
                       dv_error *err) {
  char why[256];
  cJSON *root = dv_io_json_read(path, 64L << 20, why, sizeof why);
  if (!root) return dv_fail(err, DV_ESYSTEM, "%.250s", why);
  const cJSON *error = cJSON_GetObjectItemCaseSensitive(root, "error");
  const cJSON *e = cJSON_GetObjectItemCaseSensitive(
      cJSON_GetObjectItemCaseSensitive(root, "engines"), engine);
  int status = DV_OK;
  if (cJSON_IsString(error))
    status = dv_fail(err, DV_ESYSTEM, "%.400s", error->valuestring);
  else if (!cJSON_IsObject(e))
    status = dv_fail(err, DV_ESYSTEM, "%s: no entry for %s", path, engine);
  else {
    const cJSON *v;
#define NUM(name) (cJSON_IsNumber(v = cJSON_GetObjectItemCaseSensitive(e, name)) ? v->valuedouble : NAN)
#define TEXT(name) (cJSON_IsString(v = cJSON_GetObjectItemCaseSensitive(e, name)) ? v->valuestring : "")
    c->theta_max_err = NUM("theta_max_err");
    const double slip = NUM("slip_max");
    const cJSON *limits = cJSON_GetObjectItemCaseSensitive(e, "limits");
    const cJSON *slip_limit = cJSON_GetObjectItemCaseSensitive(
        cJSON_GetObjectItemCaseSensitive(limits, "slip_max"), "limit");
    *slips = cJSON_IsNumber(slip_limit) && slip > slip_limit->valuedouble;
    c->path_max_err = NUM("path_max_err");
    c->wall_per_sim_s = NUM("wall_per_sim_s");
    const double steps = NUM("steps"), wall = NUM("wall_s");
    c->steps = isfinite(steps) ? (long)steps : -1;
    c->sim_s = c->wall_per_sim_s > 0.0 ? wall / c->wall_per_sim_s : NAN;
    snprintf(c->cause, sizeof c->cause, "%s", TEXT("cause"));
    const cJSON *pass = cJSON_GetObjectItemCaseSensitive(e, "pass");
    snprintf(c->verdict, sizeof c->verdict, "%s",
             cJSON_IsTrue(pass) ? "pass" : !strcmp(TEXT("outcome"), "not judged") ? "not judged" : "fail");
#undef NUM
#undef TEXT
  }
  cJSON_Delete(root);
  return status;
}

/* the compare at the cell's settings with its targets as the engine's limits:
 * its report in the league's folder, its numbers into the cell */
static int backing_compare(const dv_league_pair *pair, const dv_search *s, const dv_probe *p,
                           dv_league_cell *c, int *slips, dv_error *err) {
  const char *engine = pair->engine->name;
  char over[4][192], dir[1024], rel[256], path[1200];
  const char *ptrs[4];
  size_t n = 0;
  if (strcmp(p->choice, "default"))
    snprintf(over[n], sizeof over[n], "%s=%s", s->choice_key, p->choice), n++;
  snprintf(over[n], sizeof over[n], "%s=%.9g", s->step_key, p->step), n++;
  snprintf(over[n], sizeof over[n], "tolerance.%s.theta_max_err=%.17g", engine, c->target), n++;
  if (!isnan(c->path_target))
    snprintf(over[n], sizeof over[n], "tolerance.%s.path_max_err=%.17g", engine, c->path_target),
        n++;
  for (size_t i = 0; i < n; i++) ptrs[i] = over[i];
  dv_scenario *sc = malloc(sizeof *sc);
  if (!sc) return dv_fail(err, DV_ESYSTEM, "out of memory");
  dv_league_report_dir(c->object, engine, c->target, rel, sizeof rel);
  const dv_engine_type *type = dv_engine_find(engine);
  const dv_engine_type *const engines[2] = {type, NULL};
  int status = dv_scenario_with(pair->sc, ptrs, n, sc, err);
  if (!status) status = dv_io_path(dir, sizeof dir, err, "%s/%s", pair->out_dir, rel);
  if (!status) status = dv_io_make_dirs(dir, err);
  if (!status) {
    const int code = dv_report_suite_run_one(sc, engines, dir, 0, pair->explain, 1, err);
    status = code == DV_SUITE_ERROR ? DV_ESYSTEM : DV_OK;
  }
  if (!status) status = dv_io_path(path, sizeof path, err, "%s/%s/report.json", dir, sc->name);
  if (!status) status = read_report(path, engine, c, slips, err);
  if (!status) snprintf(c->report, sizeof c->report, "%.150s/%.60s", rel, sc->name);
  free(sc);
  return status;
}

void dv_league_cell_run(const dv_league_pair *pair, size_t k, dv_league_cell *c) {
  const double began = dv_clock_now();
  c->target = pair->targets[k];
  c->path_target = c->theta_max_err = c->path_max_err = c->wall_per_sim_s = c->sim_s = NAN;
  c->order = c->step = NAN;
  c->steps = -1;
  c->outcome = DV_LEAGUE_NOT_REACHED;
  c->why[0] = c->cause[0] = c->report[0] = c->verdict[0] = '\0';
  c->npoints = 0;
  const dv_engine_type *type = dv_engine_find(pair->engine->name);
  if (type && dv_run_cannot_model(type, pair->sc, c->why, sizeof c->why)) { /* compare's rule */
    c->outcome = DV_LEAGUE_CANNOT_MODEL;
    c->wall_s = dv_clock_now() - began;
    return;
  }
  dv_search *s = calloc(1, sizeof *s);
  dv_error err = {{0}};
  const dv_search_bounds bounds = {1, pair->cost_cap, 1, pair->refs};
  if (!s || dv_search_best_bounded(pair->sc, pair->engine->name, c->target, &bounds, s, &err)) {
    snprintf(c->why, sizeof c->why, "error: %.220s", s ? err.msg : "out of memory");
    c->wall_s = dv_clock_now() - began;
    free(s);
    return;
  }
  c->path_target = s->path_tolerance;
  const int at = chosen_probe(s);
  if (at < 0) {
    snprintf(c->why, sizeof c->why, "error: the search ran no probe");
    free(s);
    return;
  }
  const dv_probe *p = &s->probes[at];
  snprintf(c->choice_key, sizeof c->choice_key, "%s", s->choice_key);
  snprintf(c->choice, sizeof c->choice, "%s", p->choice);
  snprintf(c->step_key, sizeof c->step_key, "%s", s->step_key);
  c->step = p->step;
  keep_points(s, p->choice, c);
  if (s->probes[0].point.thinner) {
    c->outcome = DV_LEAGUE_CANNOT_MODEL;
    snprintf(c->why, sizeof c->why, "cannot model: %.200s", s->probes[0].point.detail);
    free(s);
    return;
  }
  c->order = observed_order(s, p->choice);
  if (s->best < 0) why_not(s, at, c);
  int slips = 0;
  if (backing_compare(pair, s, p, c, &slips, &err)) {
    snprintf(c->why, sizeof c->why, "error: the compare at these settings: %.180s", err.msg);
    c->outcome = DV_LEAGUE_NOT_REACHED;
  } else if (slips) { /* the target is not reached by a disk that slides */
    if (s->best >= 0 || !c->why[0])
      snprintf(c->why, sizeof c->why, "slips: its slip is over its limit at theta %.3g rad, path %.3g m",
               c->theta_max_err, c->path_max_err);
  } else if (c->theta_max_err <= c->target &&
             (isnan(c->path_target) || c->path_max_err <= c->path_target)) {
    c->outcome = DV_LEAGUE_REACHED;
    if (s->best < 0) /* the nearest run is within the targets, not within half of them */
      snprintf(c->why, sizeof c->why, "marginal: no run within half the targets (best's margin)");
  }
  else if (s->best >= 0) /* the search's winner, not met again by its compare */
    snprintf(c->why, sizeof c->why, "the compare at the search's settings: theta %.3g rad, path %.3g m",
             c->theta_max_err, c->path_max_err);
  c->wall_s = dv_clock_now() - began;
  free(s);
}
