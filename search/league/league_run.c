/* league_run: the cells of every object and engine: those the cache holds
 * with the same key are kept, the others run a pair (object, engine) per
 * task of the exec pool, each writing its cells into the cache as they end. */
#include "league_run.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/utsname.h>
#include <time.h>
#include <unistd.h>

#include "engine_choose.h"
#include "exec_mpi.h"
#include "exec_pool.h"
#include "io_file.h"
#include "io_json.h"
#include "io_owned.h"
#include "io_temp.h"
#include "league_cell.h"
#include "run_progress.h"

#define CACHE_DIR "cells"

void dv_league_cache_name(const dv_league_cell *c, char *out, size_t size) {
  snprintf(out, size, "%s/%.60s--%.30s--%g.json", CACHE_DIR, c->object, c->engine, c->target);
}

/* FNV-1a, 64 bits: the key of a cell */
static uint64_t fnv(uint64_t h, const void *data, size_t n) {
  const unsigned char *p = data;
  for (size_t i = 0; i < n; i++) h = (h ^ p[i]) * 1099511628211ULL;
  return h;
}

static uint64_t fnv_text(uint64_t h, const char *text) { return fnv(h, text, strlen(text) + 1); }

/* a hash of the object file's bytes; 0 when it cannot be read */
static uint64_t file_hash(const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) return 0;
  uint64_t h = 14695981039346656037ULL;
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof buf, f)) > 0;) h = fnv(h, buf, n);
  fclose(f);
  return h;
}

static void cell_key(const dv_league_request *rq, uint64_t file, dv_league_cell *c) {
  char number[64];
  uint64_t h = fnv_text(14695981039346656037ULL, DV_LEAGUE_FORMAT);
  h = fnv(h, &file, sizeof file);
  h = fnv_text(fnv_text(h, c->engine), c->engine_version);
  snprintf(number, sizeof number, "%.17g %.17g", c->target, rq->cost_cap);
  h = fnv_text(fnv_text(h, number), DV_PROJECT_VERSION);
  for (size_t i = 0; i < rq->noverrides; i++) h = fnv_text(h, rq->overrides[i]);
  snprintf(c->key, sizeof c->key, "%016llx", (unsigned long long)h);
}

/* the cached cell of c's name with c's key, into c, when what it claims is what its
 * backing report says (league_cell.h); 0 when there is one */
static int from_cache(const char *dir, const dv_scenario *sc, dv_league_cell *c) {
  char name[256], path[4096], why[256];
  dv_error err = {{0}};
  dv_league_cache_name(c, name, sizeof name);
  if (dv_io_path(path, sizeof path, &err, "%s/%s", dir, name)) return -1;
  if (access(path, F_OK)) return -1;
  cJSON *j = dv_io_json_read(path, 16L << 20, why, sizeof why);
  dv_league_cell *got = malloc(sizeof *got);
  int ok = j && got && !dv_league_cell_from_json(j, got, &err) && !strcmp(got->key, c->key) &&
           !strcmp(got->object, c->object) && !strcmp(got->engine, c->engine) &&
           got->target == c->target;
  /* its key matches, yet its claims are not its report's (edited, or its report gone):
   * run again, and say why */
  if (ok && dv_league_cell_check(dir, got, sc, why, sizeof why)) {
    if (got->outcome != DV_LEAGUE_NOT_RUN) dv_run_progress_say("%s: run again: %s", name, why);
    ok = 0;
  }
  if (ok) *c = *got;
  cJSON_Delete(j);
  free(got);
  return ok ? 0 : -1;
}

static int to_cache(const char *dir, const dv_league_cell *c, dv_error *err) {
  char name[256];
  dv_league_cache_name(c, name, sizeof name);
  cJSON *j = dv_league_cell_to_json(c);
  char *text = j ? cJSON_Print(j) : NULL;
  cJSON_Delete(j);
  if (!text) return dv_fail(err, DV_ESYSTEM, "%s: out of memory", name);
  const int status = dv_io_write_text(dir, name, text, err);
  free(text);
  return status;
}

typedef struct league_ctx {
  const dv_league_request *rq;
  dv_league *lg;
  size_t npairs, nengines; /* available engines */
  const dv_league_engine **engines;
  size_t *todo, ntodo;     /* the pairs with a cell to run: the pool's tasks */
  dv_league_cell *slots;   /* ntodo x ntargets, the pool's results */
} league_ctx;

static dv_league_cell *cell_at(dv_league *lg, size_t pair, size_t t) {
  return &lg->cells[pair * lg->ntargets + t];
}

/* the pool's task: the pair's cells not in the cache, each cached as it ends */
static void run_pair(size_t task, void *result, void *vctx) {
  const league_ctx *x = vctx;
  const size_t k = x->todo[task];
  const dv_league_request *rq = x->rq;
  dv_league_cell *cells = result;
  const size_t o = k / x->nengines, e = k % x->nengines;
  dv_league_pair pair = {&rq->objects[o], &x->lg->objects[o], x->engines[e], rq->targets,
                         rq->ntargets, rq->cost_cap, rq->out_dir, rq->explain, NULL};
  /* a probe derives its scene again: the settings of this engine alone are chosen (its own process) */
  const dv_engine_type *const only[] = {dv_engine_find(x->engines[e]->name), NULL};
  dv_engine_choose_only(only);
  pair.refs = dv_league_pair_references(&pair); /* a task is a pair with a cell to run */
  for (size_t t = 0; t < rq->ntargets; t++) {
    cells[t] = *cell_at(x->lg, k, t);
    if (cells[t].outcome != DV_LEAGUE_NOT_RUN) continue;
    dv_league_cell_run(&pair, t, &cells[t]);
    dv_error err = {{0}};
    if (to_cache(rq->out_dir, &cells[t], &err)) fprintf(stderr, "diskval league: %s\n", err.msg);
  }
  dv_league_pair_references_free((struct dv_comparison *)pair.refs);
}

/* as each pair ends: its cells into the league, and a progress note */
static void pair_ended(size_t task, int ran, void *vctx) {
  league_ctx *x = vctx;
  const size_t k = x->todo[task];
  char note[160] = "";
  if (ran) {
    for (size_t t = 0; t < x->lg->ntargets; t++) *cell_at(x->lg, k, t) = x->slots[task * x->lg->ntargets + t];
    const dv_league_cell *c = cell_at(x->lg, k, 0);
    snprintf(note, sizeof note, "%s %s: %s", c->object, c->engine, dv_league_outcome_name(c->outcome));
  }
  dv_run_progress_task_ended(note);
}

/* a pair whose process did not end with its cells (stopped by a signal, killed at
 * the time limit or crashed): the cells it finished are in the cache, as they
 * were; the others are not run, or, at the limit, an error that says so */
static void not_ended(const dv_league_request *rq, const league_ctx *x, size_t k,
                      unsigned char end) {
  const size_t o = k / x->nengines;
  int said = 0;
  for (size_t t = 0; t < x->lg->ntargets; t++) {
    dv_league_cell *c = cell_at(x->lg, k, t);
    char rel[256], dir[4096];
    dv_error err = {{0}};
    dv_league_report_dir(c->object, c->engine, c->target, rel, sizeof rel);
    /* the report its killed process was building */
    if (!dv_io_path(dir, sizeof dir, &err, "%s/%s", rq->out_dir, rel)) dv_io_temp_remove_stale(dir);
    if (c->outcome != DV_LEAGUE_NOT_RUN || !from_cache(rq->out_dir, &rq->objects[o], c)) continue;
    if (end == DV_EXEC_TIMED_OUT) {
      if (!said++) fprintf(stderr, "diskval league: %s %s: timed out after %g s\n", c->object, c->engine,
                      rq->timeout);
      c->outcome = DV_LEAGUE_NOT_REACHED;
      snprintf(c->why, sizeof c->why,
               "error: timed out after %g s (--timeout: the time its object and engine may take)",
               rq->timeout);
    }
  }
}

static void describe_machine(dv_league *lg) {
  struct utsname u;
  char cpu[128] = "unknown CPU", line[256];
  FILE *f = fopen("/proc/cpuinfo", "r");
  while (f && fgets(line, sizeof line, f))
    if (!strncmp(line, "model name", 10) && strchr(line, ':')) {
      snprintf(cpu, sizeof cpu, "%s", strchr(line, ':') + 2);
      cpu[strcspn(cpu, "\n")] = '\0';
      break;
    }
  if (f) fclose(f);
  if (uname(&u)) snprintf(u.sysname, sizeof u.sysname, "unknown"), u.release[0] = u.machine[0] = '\0';
  snprintf(lg->machine, sizeof lg->machine, "%.40s %.60s %.20s, %.100s, %ld cores", u.sysname,
           u.release, u.machine, cpu, sysconf(_SC_NPROCESSORS_ONLN));
  const time_t now = time(NULL);
  strftime(lg->date, sizeof lg->date, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
  snprintf(lg->diskval_version, sizeof lg->diskval_version, "%s", DV_PROJECT_VERSION);
}

/* the objects, engines and cells (from the cache where it holds them) */
static int fill(const dv_league_request *rq, dv_league *lg, dv_error *err) {
  describe_machine(lg);
  lg->cost_cap = rq->cost_cap;
  lg->overrides = rq->overrides;
  lg->noverrides = rq->noverrides;
  if (rq->ntargets > DV_LEAGUE_MAX_TARGETS || !rq->ntargets)
    return dv_fail(err, DV_EINPUT, "from 1 to %d targets", DV_LEAGUE_MAX_TARGETS);
  if (rq->nobjects > DV_LEAGUE_MAX_OBJECTS)
    return dv_fail(err, DV_EINPUT, "%zu objects: at most %d", rq->nobjects, DV_LEAGUE_MAX_OBJECTS);
  lg->ntargets = rq->ntargets;
  memcpy(lg->targets, rq->targets, rq->ntargets * sizeof *rq->targets);
  for (const dv_engine_type *const *e = rq->engines; *e; e++) {
    if (lg->nengines == DV_LEAGUE_MAX_ENGINES)
      return dv_fail(err, DV_EINPUT, "more than %d engines", DV_LEAGUE_MAX_ENGINES);
    dv_league_engine *g = &lg->engines[lg->nengines++];
    const char *why = dv_engine_unavailable(*e);
    snprintf(g->name, sizeof g->name, "%s", (*e)->name);
    g->available = !why;
    snprintf(g->why, sizeof g->why, "%s", why ? why : "");
    snprintf(g->version, sizeof g->version, "%s", why ? "" : (*e)->version());
  }
  size_t navailable = 0;
  for (size_t e = 0; e < lg->nengines; e++) navailable += lg->engines[e].available;
  lg->nobjects = rq->nobjects;
  lg->ncells = rq->nobjects * navailable * rq->ntargets;
  lg->cells = calloc(lg->ncells ? lg->ncells : 1, sizeof *lg->cells);
  if (!lg->cells) return dv_fail(err, DV_ESYSTEM, "out of memory");
  size_t k = 0;
  for (size_t o = 0; o < rq->nobjects; o++) {
    const dv_scenario *sc = &rq->objects[o];
    dv_league_object *b = &lg->objects[o];
    snprintf(b->name, sizeof b->name, "%s", sc->name);
    snprintf(b->file, sizeof b->file, "%.500s", sc->path);
    snprintf(b->description, sizeof b->description, "%.150s", sc->description);
    b->radius = sc->disk.r;
    b->thickness = sc->thickness;
    b->duration = sc->duration;
    const uint64_t file = file_hash(sc->path);
    for (size_t e = 0; e < lg->nengines; e++)
      for (size_t t = 0; lg->engines[e].available && t < rq->ntargets; t++, k++) {
        dv_league_cell *c = &lg->cells[k];
        snprintf(c->object, sizeof c->object, "%s", b->name);
        snprintf(c->scenario_file, sizeof c->scenario_file, "%s", b->file);
        snprintf(c->engine, sizeof c->engine, "%s", lg->engines[e].name);
        snprintf(c->engine_version, sizeof c->engine_version, "%s", lg->engines[e].version);
        c->target = rq->targets[t];
        c->outcome = DV_LEAGUE_NOT_RUN;
        c->path_target = c->step = c->theta_max_err = c->path_max_err = NAN;
        c->wall_per_sim_s = c->sim_s = c->order = c->wall_s = NAN;
        c->steps = -1;
        snprintf(c->why, sizeof c->why, "not run: the league ended before it");
        cell_key(rq, file, c);
        if (file) from_cache(rq->out_dir, sc, c); /* a cached cell has this key, or is not taken */
      }
  }
  return DV_OK;
}

int dv_league_run(const dv_league_request *rq, dv_league *lg, dv_error *err) {
  memset(lg, 0, sizeof *lg);
  int status = fill(rq, lg, err);
  char cache[4096];
  if (!status) status = dv_io_path(cache, sizeof cache, err, "%s/" CACHE_DIR, rq->out_dir);
  /* rank 0 alone: its check of the --out comes first (a worker's folder would fail it) */
  if (!status && dv_exec_mpi_rank() == 0) status = dv_io_make_dirs(cache, err);
  if (status) return status;
  league_ctx x = {rq, lg, 0, 0, NULL, NULL, 0, NULL};
  x.engines = calloc(lg->nengines + 1, sizeof *x.engines);
  for (size_t e = 0; x.engines && e < lg->nengines; e++)
    if (lg->engines[e].available) x.engines[x.nengines++] = &lg->engines[e];
  x.npairs = lg->nobjects * x.nengines;
  x.todo = calloc(x.npairs + 1, sizeof *x.todo);
  for (size_t k = 0; x.todo && k < x.npairs; k++) {
    int some = 0;
    for (size_t t = 0; t < lg->ntargets; t++) some |= cell_at(lg, k, t)->outcome == DV_LEAGUE_NOT_RUN;
    if (some) x.todo[x.ntodo++] = k;
  }
  x.slots = calloc(x.ntodo ? x.ntodo * lg->ntargets : 1, sizeof *x.slots);
  unsigned char *done = calloc(x.ntodo ? x.ntodo : 1, 1);
  if (!x.engines || !x.slots || !x.todo || !done) {
    free(x.engines), free(x.slots), free(x.todo), free(done);
    return dv_fail(err, DV_ESYSTEM, "out of memory");
  }
  size_t cached = 0;
  for (size_t k = 0; k < lg->ncells; k++) cached += lg->cells[k].outcome != DV_LEAGUE_NOT_RUN;
  if (cached)
    dv_run_progress_say("%zu of %zu cells from the cache (%s/" CACHE_DIR ")", cached, lg->ncells,
                        rq->out_dir);
  dv_run_progress_tasks_begin("pair", x.ntodo);
  const dv_exec_options opt = {
      .jobs = rq->jobs, .on_result = pair_ended, .done = done, .timeout = rq->timeout};
  const int ran = x.ntodo ? dv_exec_pool(x.ntodo, lg->ntargets * sizeof *x.slots, run_pair, &x,
                                         x.slots, &opt)
                          : DV_EXEC_DONE;
  dv_run_progress_tasks_end();
  for (size_t i = 0; (ran == DV_EXEC_DONE || ran == DV_EXEC_INTERRUPTED) && i < x.ntodo; i++)
    if (done[i] != DV_EXEC_ARRIVED) not_ended(rq, &x, x.todo[i], done[i]);
  free(x.engines), free(x.slots), free(x.todo), free(done);
  if (ran == DV_EXEC_NOMEM) return dv_fail(err, DV_ESYSTEM, "out of memory");
  if (ran == DV_EXEC_WORKER) return DV_LEAGUE_WORKER;
  lg->interrupted = ran == DV_EXEC_INTERRUPTED;
  return lg->interrupted ? DV_EVENT : DV_OK;
}

int dv_league_check_inputs(const char *out_dir, const char *const *inputs, size_t n,
                           dv_error *err) {
  static const char *const WRITTEN[] = {CACHE_DIR, "compare"};
  for (size_t d = 0; d < 2; d++) {
    char dir[4096];
    if (dv_io_path(dir, sizeof dir, err, "%s/%s", out_dir, WRITTEN[d])) return DV_EINPUT;
    for (size_t i = 0; i < n; i++)
      if (inputs[i] && dv_io_within(inputs[i], dir))
        return dv_fail(err, DV_EINPUT,
                       "%s: an input of this run lies inside %s, which the league writes; "
                       "nothing was written: move it, or choose another --out",
                       inputs[i], dir);
  }
  return DV_OK;
}

/* the key of a --set override: its text before '=' */
static void key_of(const char *override, char *key, size_t size) {
  snprintf(key, size, "%.*s", (int)strcspn(override, "="), override);
}

int dv_league_check_overrides(const dv_engine_type *const *engines, const char *const *overrides,
                              size_t n, dv_error *err) {
  for (size_t i = 0; i < n; i++) {
    char key[256], own[160];
    key_of(overrides[i], key, sizeof key);
    if (!strcmp(key, "tolerance.theta_max_err"))
      return dv_fail(err, DV_EINPUT,
                     "--set %s: the league's targets set it (--targets): a cell's theta "
                     "limit is its target",
                     key);
    for (const dv_engine_type *const *e = engines; *e; e++) {
      const dv_engine_search *s = (*e)->search;
      snprintf(own, sizeof own, "tolerance.%s.theta_max_err", (*e)->name);
      if (!strcmp(key, own))
        return dv_fail(err, DV_EINPUT,
                       "--set %s: the league's targets set it (--targets): a cell's theta "
                       "limit is its target",
                       key);
      for (int k = 0; s && k < 2; k++) {
        const char *word = k ? s->choice_key : s->step_key;
        snprintf(own, sizeof own, "engines.%s.%s", s->section, word ? word : "");
        if (word && !strcmp(key, own))
          return dv_fail(err, DV_EINPUT,
                         "--set %s: the league's search varies it (%s's %s): each cell runs the "
                         "cheapest settings its search finds; drop it (compare runs fixed "
                         "settings)",
                         key, (*e)->name, k ? "choice" : "step");
      }
    }
  }
  return DV_OK;
}

void dv_league_free(dv_league *lg) {
  if (lg) free(lg->cells), lg->cells = NULL;
}
