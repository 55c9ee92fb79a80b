/* run_parallel: a comparison's runs in the exec pool, judged here (run_parallel.h). */
#include "run_parallel.h"

#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "exec_pool.h"
#include "run_progress.h"

/* what a task hands back ahead of its samples (and the thin task's amplification) */
typedef struct slot {
  int status; /* the thin task's: < 0 fails the comparison, err saying why */
  dv_error err;
  size_t nsamples;    /* samples after the head */
  dv_engine_result r; /* an engine's task: its run (the trajectories' pointers are not valid) */
  dv_matched_run m;   /* a matched reference's task */
  dv_engine_stats thin_stats;
  double thin_wall_s, horizon_wall_s, thin_valid_end, horizon;
  dv_amplification amp; /* its arrays after the samples */
  double spread[DV_NMETRICS];
} slot;

#define HEAD ((sizeof(slot) + 63) / 64 * 64)
/* t, gain, gain_of[], shadow_of[].env[] */
#define AMP_ARRAYS (2 + DV_NUDGE_DIRS + DV_NUDGE_DIRS * DV_SHADOW_N)

/* the comparison's tasks: 0 the thin reference, then a matched reference per
 * half-thickness, then each engine */
typedef struct plan {
  const dv_scenario *sc, *ref_sc;
  const dv_engine_type *const *engines;
  size_t n, nh;
  double h[DV_MAX_ENGINES]; /* the engines' half-thicknesses > 0, each once */
  size_t cap;               /* samples a slot holds */
} plan;

static dv_sample *samples_of(void *slot_bytes) {
  return (dv_sample *)((char *)slot_bytes + HEAD);
}

static double *amp_of(void *slot_bytes, size_t cap) {
  return (double *)((char *)slot_bytes + HEAD + cap * sizeof(dv_sample));
}

/* tr into the slot's samples: 0, or -1 when it has more than cap (the first cap kept) */
static int pack(const dv_traj *tr, void *slot_bytes, size_t cap) {
  slot *s = slot_bytes;
  s->nsamples = tr->n < cap ? tr->n : cap;
  if (s->nsamples) memcpy(samples_of(slot_bytes), tr->s, s->nsamples * sizeof(dv_sample));
  return tr->n > cap ? -1 : 0;
}

/* the slot's samples into a trajectory of this process: 0, or -1 out of memory */
static int unpack(void *slot_bytes, dv_traj *tr) {
  const slot *s = slot_bytes;
  const dv_sample *from = samples_of(slot_bytes);
  memset(tr, 0, sizeof *tr);
  for (size_t i = 0; i < s->nsamples; i++)
    if (dv_run_traj_push(tr, &from[i])) return -1;
  return 0;
}

static void thin_task(const plan *p, void *bytes) {
  slot *s = bytes;
  dv_comparison *c = malloc(sizeof *c);
  if (!c) {
    s->status = dv_fail(&s->err, DV_ESYSTEM, "out of memory");
    return;
  }
  dv_run_comparison_begin(p->sc, c);
  s->status = dv_run_thin_reference(p->ref_sc, c, &s->err);
  s->thin_stats = c->thin_stats;
  s->thin_wall_s = c->thin_wall_s;
  s->horizon_wall_s = c->horizon_wall_s;
  s->thin_valid_end = c->thin_valid_end;
  s->horizon = c->horizon;
  s->amp = c->amp;
  memcpy(s->spread, c->spread, sizeof s->spread);
  if (!s->status && (pack(&c->thin, bytes, p->cap) || c->amp.n > p->cap))
    s->status = dv_fail(&s->err, DV_ESYSTEM,
                        "the reference gave %zu samples, more than the %zu of the output grid",
                        c->thin.n, p->cap);
  double *to = amp_of(bytes, p->cap);
  const double *arrays[AMP_ARRAYS] = {c->amp.t, c->amp.gain};
  for (int j = 0; j < DV_NUDGE_DIRS; j++) arrays[2 + j] = c->amp.gain_of[j];
  for (int j = 0; j < DV_NUDGE_DIRS; j++)
    for (int k = 0; k < DV_SHADOW_N; k++)
      arrays[2 + DV_NUDGE_DIRS + j * DV_SHADOW_N + k] = c->amp.shadow_of[j].env[k];
  for (int j = 0; j < AMP_ARRAYS && !s->status; j++)
    memcpy(to + (size_t)j * p->cap, arrays[j], c->amp.n * sizeof(double));
  dv_run_comparison_free(c);
  free(c);
}

static void matched_task(const plan *p, size_t k, void *bytes) {
  slot *s = bytes;
  dv_run_matched_reference(p->ref_sc, p->h[k], &s->m);
  if (pack(&s->m.traj, bytes, p->cap) && s->m.status >= 0)
    s->m.status = dv_fail(&s->m.err, DV_ESYSTEM, "%zu samples, more than the %zu of the output grid",
                          s->m.traj.n, p->cap);
  dv_run_traj_free(&s->m.traj);
}

static void engine_task(const plan *p, size_t i, void *bytes) {
  slot *s = bytes;
  dv_engine_result *r = &s->r;
  memset(r, 0, sizeof *r);
  dv_run_engine_only(p->engines[i], p->sc, r);
  if (pack(&r->traj, bytes, p->cap) && r->status >= 0) {
    r->status = DV_ESYSTEM;
    r->stats.outcome = DV_OUTCOME_ERROR;
    snprintf(r->stats.detail, sizeof r->stats.detail,
             "it gave %zu samples, more than the %zu of the output grid", r->traj.n, p->cap);
  }
  dv_run_traj_free(&r->traj);
}

/* dv_exec_pool's task k */
static void task(size_t k, void *result, void *ctx) {
  const plan *p = ctx;
  if (k == 0)
    thin_task(p, result);
  else if (k <= p->nh)
    matched_task(p, k - 1, result);
  else
    engine_task(p, k - 1 - p->nh, result);
}

static const char LOST[] = "its process ended without a result (crashed or killed)";

/* the thin task's result into c: DV_OK, or < 0 with err */
static int take_thin(const plan *p, void *bytes, int arrived, dv_comparison *c, dv_error *err) {
  slot *s = bytes;
  if (!arrived)
    return dv_fail(err, DV_ESYSTEM, "the %s reference: %s",
                   dv_engine_of_role(DV_ENGINE_THIN_REFERENCE)->name, LOST);
  if (s->status < 0) return *err = s->err, s->status;
  c->thin_stats = s->thin_stats;
  c->thin_wall_s = s->thin_wall_s;
  c->horizon_wall_s = s->horizon_wall_s;
  c->thin_valid_end = s->thin_valid_end;
  c->horizon = s->horizon;
  memcpy(c->spread, s->spread, sizeof c->spread);
  c->amp = s->amp;
  c->amp.t = c->amp.gain = NULL;
  for (int j = 0; j < DV_NUDGE_DIRS; j++) c->amp.gain_of[j] = NULL;
  for (int j = 0; j < DV_NUDGE_DIRS; j++) memset(c->amp.shadow_of[j].env, 0, sizeof c->amp.shadow_of[j].env);
  double **arrays[AMP_ARRAYS] = {&c->amp.t, &c->amp.gain};
  for (int j = 0; j < DV_NUDGE_DIRS; j++) arrays[2 + j] = &c->amp.gain_of[j];
  for (int j = 0; j < DV_NUDGE_DIRS; j++)
    for (int k = 0; k < DV_SHADOW_N; k++)
      arrays[2 + DV_NUDGE_DIRS + j * DV_SHADOW_N + k] = &c->amp.shadow_of[j].env[k];
  const double *from = amp_of(bytes, p->cap);
  for (int j = 0; j < AMP_ARRAYS; j++) {
    *arrays[j] = malloc((c->amp.n ? c->amp.n : 1) * sizeof(double));
    if (!*arrays[j]) return dv_fail(err, DV_ESYSTEM, "out of memory");
    memcpy(*arrays[j], from + (size_t)j * p->cap, c->amp.n * sizeof(double));
  }
  if (unpack(bytes, &c->thin)) return dv_fail(err, DV_ESYSTEM, "out of memory");
  return DV_OK;
}

/* engine i's run into r: its task's, or an error where its process died */
static int take_engine(const plan *p, size_t i, void *bytes, int arrived, dv_engine_result *r) {
  slot *s = bytes;
  if (!arrived) {
    memset(r, 0, sizeof *r);
    dv_run_engine_body(p->engines[i], p->sc, r);
    r->status = DV_ESYSTEM;
    r->stats.outcome = DV_OUTCOME_ERROR;
    snprintf(r->stats.detail, sizeof r->stats.detail, "%s", LOST);
    return 0;
  }
  *r = s->r;
  memset(&r->matched, 0, sizeof r->matched);
  return unpack(bytes, &r->traj);
}

/* the distinct half-thicknesses > 0 of the engines' bodies */
static void half_thicknesses(plan *p) {
  for (size_t i = 0; i < p->n; i++) {
    const double h = dv_engine_half_thickness(p->engines[i], p->sc);
    size_t k = 0;
    while (k < p->nh && p->h[k] != h) k++;
    if (h > 0.0 && k == p->nh) p->h[p->nh++] = h;
  }
}

/* the runs made: c's references and engines, judged in order */
static int assemble(const plan *p, char *results, size_t size, const unsigned char *done,
                    const dv_run_hook *hook, dv_comparison *c, dv_error *err) {
  int status = take_thin(p, results, done[0] == DV_EXEC_ARRIVED, c, err);
  for (size_t k = 0; k < p->nh && !status; k++) {
    void *bytes = results + (1 + k) * size;
    dv_matched_run *m = &c->matched[c->nmatched++];
    *m = ((slot *)bytes)->m;
    m->half_thickness = p->h[k];
    if (done[1 + k] != DV_EXEC_ARRIVED) {
      memset(&m->traj, 0, sizeof m->traj);
      m->status = dv_fail(&m->err, DV_ESYSTEM, "%s", LOST);
    } else if (unpack(bytes, &m->traj)) {
      status = dv_fail(err, DV_ESYSTEM, "out of memory");
    }
  }
  const dv_scenario *ref_sc = p->ref_sc == p->sc ? NULL : p->ref_sc;
  for (size_t i = 0; i < p->n && !status; i++) {
    const size_t k = 1 + p->nh + i;
    dv_engine_result *r = &c->r[c->n++];
    if (take_engine(p, i, results + k * size, done[k] == DV_EXEC_ARRIVED, r))
      return dv_fail(err, DV_ESYSTEM, "out of memory");
    status = dv_run_engine_judge(c, ref_sc, hook, r, err);
  }
  return status;
}

/* a task has ended: the progress line names its run */
static void task_ended(size_t k, int ran, void *ctx) {
  const plan *p = ctx;
  char note[64] = "the references";
  if (k > 0 && k <= p->nh) snprintf(note, sizeof note, "the reference of h = %g m", p->h[k - 1]);
  if (k > p->nh) snprintf(note, sizeof note, "%s", p->engines[k - 1 - p->nh]->name);
  (void)ran;
  dv_run_progress_task_ended(note);
}

int dv_run_scenario_jobs(const dv_scenario *sc, const dv_scenario *ref_sc,
                         const dv_engine_type *const *engines, size_t n, const dv_run_hook *hook,
                         int jobs, dv_comparison *c, dv_error *err) {
  plan p = {sc, ref_sc ? ref_sc : sc, engines, n, 0, {0}, 0};
  /* a sample at t = 0, one every output_dt, one at an event */
  const double grid = sc->output_dt > 0.0 ? ceil(sc->duration / sc->output_dt) : INFINITY;
  const double bytes = (double)HEAD + (grid + 3.0) * (sizeof(dv_sample) + AMP_ARRAYS * 8.0);
  if (n <= DV_MAX_ENGINES) half_thicknesses(&p);
  const size_t ntasks = 1 + p.nh + n;
  /* the slots twice (the pool's shared ones, the results here) beside what a
   * comparison in one process may take, the budget's figure (scenario.h) */
  const double in_one = (grid + 1.0) * DV_MEMORY_PER_SAMPLE + DV_MEMORY_BASE_MIB * 1048576.0;
  const int fits = in_one + 2.0 * (double)ntasks * bytes <= sc->memory_budget * 1073741824.0;
  /* one job (a suite's scenario): in this process, so that a stop reaches the suite's pool alone */
  if (jobs <= 1 || n > DV_MAX_ENGINES || !(bytes <= DV_RUN_SLOT_MAX) || !fits)
    return dv_run_scenario_hooked(sc, ref_sc, engines, n, hook, c, err);
  p.cap = (size_t)grid + 3;
  const size_t size = HEAD + p.cap * (sizeof(dv_sample) + AMP_ARRAYS * sizeof(double));
  dv_run_comparison_begin(sc, c);
  dv_run_progress_plan(sc, p.ref_sc, engines, n); /* a long comparison says so first */
  char *results = calloc(ntasks, size);
  unsigned char *done = calloc(ntasks, 1);
  int status = DV_OK;
  const dv_exec_options opt = {.jobs = jobs, .on_result = task_ended, .done = done, .local = 1};
  /* the tasks' processes draw nothing: this one counts them (their lines would interleave) */
  dv_run_progress_tasks_begin("comparison run", ntasks);
  const int pool = results && done ? dv_exec_pool(ntasks, size, task, &p, results, &opt)
                                   : DV_EXEC_NOMEM;
  dv_run_progress_tasks_end();
  if (pool == DV_EXEC_NOMEM)
    status = dv_fail(err, DV_ESYSTEM, "out of memory");
  else if (pool == DV_EXEC_INTERRUPTED) /* die of it, as in one process (temporaries removed) */
    status = (raise(dv_exec_stopped_by()),
              dv_fail(err, DV_EVENT, "interrupted (signal %d)", dv_exec_stopped_by()));
  else
    status = assemble(&p, results, size, done, hook, c, err);
  free(results);
  free(done);
  return status;
}
