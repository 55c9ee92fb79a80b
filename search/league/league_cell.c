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
#include "io_owned.h"
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

/* the first of the report's failures for the engine, without its "SCENARIO: ENGINE: "
 * and its "; cause: ..." (the cell says its cause apart) */
static void first_failure(const cJSON *e, const char *scenario, const char *engine, char *buf,
                          size_t size) {
  const cJSON *f = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(e, "failures"), 0);
  const char *text = cJSON_IsString(f) ? f->valuestring : "";
  char prefix[200];
  snprintf(prefix, sizeof prefix, "%s: %s: ", scenario, engine);
  if (!strncmp(text, prefix, strlen(prefix))) text += strlen(prefix);
  const char *cause = strstr(text, "; cause:");
  snprintf(buf, size, "%.*s", (int)(cause ? (size_t)(cause - text) : strlen(text)), text);
}

/* the limit a report judged metric name with (its spread included), NAN when none */
static double limit_of(const cJSON *e, const char *name) {
  const cJSON *l = cJSON_GetObjectItemCaseSensitive(
      cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(e, "limits"), name),
      "limit");
  return cJSON_IsNumber(l) ? l->valuedouble : NAN;
}

/* the limit a report was given for metric name, before the shadow's spread it grew
 * by: limit - spread (NAN when none) */
static double given_limit(const cJSON *e, const char *name) {
  const cJSON *l = cJSON_GetObjectItemCaseSensitive(cJSON_GetObjectItemCaseSensitive(e, "limits"), name);
  const cJSON *spread = cJSON_GetObjectItemCaseSensitive(l, "spread");
  return limit_of(e, name) - (cJSON_IsNumber(spread) ? spread->valuedouble : 0.0);
}

/* the engine's entry of the report.json at path: its numbers into b */
static int read_report(const char *path, const char *engine, const char *step_word,
                       const char *choice_word, dv_league_backing *b, dv_error *err) {
  char why[256];
  memset(b, 0, sizeof *b);
  b->step = NAN;
  cJSON *root = dv_io_json_read(path, 64L << 20, why, sizeof why);
  if (!root) return dv_fail(err, DV_ESYSTEM, "%.250s", why);
  const cJSON *error = cJSON_GetObjectItemCaseSensitive(root, "error");
  const cJSON *scenario = cJSON_GetObjectItemCaseSensitive(root, "scenario");
  const cJSON *e = cJSON_GetObjectItemCaseSensitive(
      cJSON_GetObjectItemCaseSensitive(root, "engines"), engine);
  int status = DV_OK;
  if (cJSON_IsString(error))
    status = dv_fail(err, DV_ESYSTEM, "%.400s", error->valuestring);
  else if (!cJSON_IsObject(e))
    status = dv_fail(err, DV_ESYSTEM, "%s: no entry for %s", path, engine);
  else {
    const cJSON *v;
#define NUM(o, name) (cJSON_IsNumber(v = cJSON_GetObjectItemCaseSensitive(o, name)) ? v->valuedouble : NAN)
#define TEXT(o, name) (cJSON_IsString(v = cJSON_GetObjectItemCaseSensitive(o, name)) ? v->valuestring : "")
    b->theta_max_err = NUM(e, "theta_max_err");
    b->path_max_err = NUM(e, "path_max_err");
    b->theta_limit = given_limit(e, "theta_max_err");
    b->path_limit = given_limit(e, "path_max_err");
    const double slip_limit = limit_of(e, "slip_max");
    b->slips = !isnan(slip_limit) && NUM(e, "slip_max") > slip_limit;
    b->wall_per_sim_s = NUM(e, "wall_per_sim_s");
    const double steps = NUM(e, "steps"), wall = NUM(e, "wall_s");
    b->steps = isfinite(steps) ? (long)steps : -1;
    b->sim_s = b->wall_per_sim_s > 0.0 ? wall / b->wall_per_sim_s : NAN;
    snprintf(b->cause, sizeof b->cause, "%s", TEXT(e, "cause"));
    snprintf(b->version, sizeof b->version, "%s", TEXT(e, "version"));
    const cJSON *pass = cJSON_GetObjectItemCaseSensitive(e, "pass");
    snprintf(b->verdict, sizeof b->verdict, "%s",
             cJSON_IsTrue(pass) ? "pass" : !strcmp(TEXT(e, "outcome"), "not judged") ? "not judged" : "fail");
    first_failure(e, cJSON_IsString(scenario) ? scenario->valuestring : "", engine, b->failure,
                  sizeof b->failure);
    const cJSON *settings = cJSON_GetObjectItemCaseSensitive(e, "settings");
    const cJSON *f;
    for (int k = 0; k < 2; k++) { /* the step and the choice it ran at, by their keys' last words */
      const char *key = k ? choice_word : step_word;
      if (!key || !(f = cJSON_GetObjectItemCaseSensitive(settings, key))) continue;
      if (k) snprintf(b->choice, sizeof b->choice, "%s", cJSON_IsString(f) ? f->valuestring : "");
      else b->step = cJSON_IsNumber(f) ? f->valuedouble : NAN;
    }
#undef NUM
#undef TEXT
  }
  cJSON_Delete(root);
  return status;
}

/* the backing report's numbers into c */
static void take_backing(const dv_league_backing *b, dv_league_cell *c) {
  c->theta_max_err = b->theta_max_err;
  c->path_max_err = b->path_max_err;
  c->wall_per_sim_s = b->wall_per_sim_s;
  c->steps = b->steps;
  c->sim_s = b->sim_s;
  snprintf(c->cause, sizeof c->cause, "%s", b->cause);
  snprintf(c->verdict, sizeof c->verdict, "%s", b->verdict);
}

int dv_league_backed(const dv_league_cell *c, int slips) {
  return !slips && !strcmp(c->verdict, "pass") && c->theta_max_err <= c->target &&
         (isnan(c->path_target) || c->path_max_err <= c->path_target);
}

/* the compare at the cell's settings with its targets as the engine's limits:
 * its report in the league's folder, its numbers into the cell */
static int backing_compare(const dv_league_pair *pair, const dv_search *s, const dv_probe *p,
                           dv_league_cell *c, dv_league_backing *b, dv_error *err) {
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
  dv_league_report_dir(c->object, engine, c->target, rel, sizeof rel); /* its parent */
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
  if (!status) status = read_report(path, engine, NULL, NULL, b, err);
  if (!status) take_backing(b, c), dv_league_backing_dir(c, c->report, sizeof c->report);
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
  dv_league_backing b;
  if (backing_compare(pair, s, p, c, &b, &err)) {
    snprintf(c->why, sizeof c->why, "error: the compare at these settings: %.180s", err.msg);
    c->outcome = DV_LEAGUE_NOT_REACHED;
  } else if (b.slips) { /* the target is not reached by a disk that slides */
    if (s->best >= 0 || !c->why[0])
      snprintf(c->why, sizeof c->why, "slips: its slip is over its limit at theta %.3g rad, path %.3g m",
               c->theta_max_err, c->path_max_err);
  } else if (dv_league_backed(c, 0)) {
    c->outcome = DV_LEAGUE_REACHED;
    if (s->best < 0) /* the nearest run is within the targets, not within half of them */
      snprintf(c->why, sizeof c->why, "marginal: no run within half the targets (best's margin)");
  } else if (c->theta_max_err <= c->target &&
             (isnan(c->path_target) || c->path_max_err <= c->path_target)) {
    /* within the targets, yet its compare did not pass: its verdict stops it (a window too
     * short to judge, another metric over its limit) */
    if (b.failure[0])
      snprintf(c->why, sizeof c->why, "%s%.200s", strcmp(c->verdict, "not judged") ? "fails: " : "",
               b.failure);
    else
      snprintf(c->why, sizeof c->why, "%s: its compare says so, within the targets", c->verdict);
  } else if (s->best >= 0) /* the search's winner, not met again by its compare */
    snprintf(c->why, sizeof c->why, "the compare at the search's settings: theta %.3g rad, path %.3g m",
             c->theta_max_err, c->path_max_err);
  c->wall_s = dv_clock_now() - began;
  free(s);
}

void dv_league_backing_dir(const dv_league_cell *c, char *out, size_t size) {
  char rel[256];
  dv_league_report_dir(c->object, c->engine, c->target, rel, sizeof rel);
  snprintf(out, size, "%.150s/%.60s", rel, c->object);
}

/* a and b are the same number (NaN is NaN) */
static int same(double a, double b) { return a == b || (isnan(a) && isnan(b)); }

/* a limit the report gives as limit - spread, against the one the cell was given: the
 * subtraction may leave a few ulps (measured: none on the quarter's cells, limit
 * 1.34e-3 less spread 3.4e-4 is 1e-3 exactly), 1e-12 is far below any edit */
static int same_limit(double given, double got) {
  return same(given, got) || fabs(given - got) <= 1e-12 * fabs(given);
}

/* the last word of key ("timestep" of engines.mujoco.timestep) when its section is
 * engine's own (the settings a report lists), else NULL */
static const char *own_word(const char *key, const char *engine) {
  char prefix[64];
  snprintf(prefix, sizeof prefix, "engines.%s.", engine);
  return key[0] && !strncmp(key, prefix, strlen(prefix)) ? key + strlen(prefix) : NULL;
}

/* the claims of a cached cell that ran against its backing report: why not, or 0 */
static int check_backed(const char *out_dir, const dv_league_cell *c, char *why, size_t size) {
  char expected[256], compare[4096], path[4096];
  dv_error err = {{0}};
  dv_league_backing b;
  dv_league_backing_dir(c, expected, sizeof expected);
  if (strcmp(c->report, expected))
    return snprintf(why, size, "its report is not %s", expected), -1;
  /* resolved: a link out of --out (its compare/ or a folder in it) is not followed */
  if (dv_io_path(compare, sizeof compare, &err, "%s/compare", out_dir) ||
      dv_io_path(path, sizeof path, &err, "%s/%s/report.json", out_dir, c->report) ||
      !dv_io_within(path, compare) || !dv_io_within(path, out_dir))
    return snprintf(why, size, "its report lies outside %s", compare), -1;
  const char *step_word = own_word(c->step_key, c->engine);
  const char *choice_word = strcmp(c->choice, "default") ? own_word(c->choice_key, c->engine) : NULL;
  if (read_report(path, c->engine, step_word, choice_word, &b, &err))
    return snprintf(why, size, "its report: %.200s", err.msg), -1;
  dv_league_cell as_said = *c;
  take_backing(&b, &as_said);
  char step[2][32];
  snprintf(step[0], sizeof step[0], "%.9g", c->step), snprintf(step[1], sizeof step[1], "%.9g", b.step);
  const int agrees =
      same(c->theta_max_err, b.theta_max_err) && same(c->path_max_err, b.path_max_err) &&
      same(c->wall_per_sim_s, b.wall_per_sim_s) && same(c->sim_s, b.sim_s) &&
      c->steps == b.steps && !strcmp(c->verdict, b.verdict) && !strcmp(c->cause, b.cause) &&
      !strcmp(c->engine_version, b.version) && same_limit(c->target, b.theta_limit) &&
      (isnan(c->path_target) || same_limit(c->path_target, b.path_limit)) &&
      (!step_word || !strcmp(step[0], step[1])) && (!choice_word || !strcmp(c->choice, b.choice)) &&
      (c->outcome == DV_LEAGUE_REACHED) == dv_league_backed(&as_said, b.slips);
  return agrees ? 0 : (snprintf(why, size, "it says other than its report %s", c->report), -1);
}

int dv_league_cell_check(const char *out_dir, const dv_league_cell *c, const dv_scenario *sc,
                         char *why, size_t size) {
  const dv_engine_type *type = dv_engine_find(c->engine);
  char word[240];
  if (!type) return snprintf(why, size, "no engine %s", c->engine), -1;
  switch (c->outcome) {
    case DV_LEAGUE_CANNOT_MODEL: /* compare's rule, asked again; a search's verdict runs again */
      return !c->report[0] && dv_run_cannot_model(type, sc, word, sizeof word) &&
                     !strcmp(word, c->why)
                 ? 0
                 : (snprintf(why, size, "a cannot-model cell not so by compare's rule"), -1);
    case DV_LEAGUE_REACHED:
    case DV_LEAGUE_NOT_REACHED:
      if (!strncmp(c->why, "error:", 6)) return snprintf(why, size, "it ended in an error"), -1;
      return check_backed(out_dir, c, why, size);
    default:
      return snprintf(why, size, "it did not run"), -1;
  }
}
