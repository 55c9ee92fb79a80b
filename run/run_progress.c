/* run_progress: the progress line and the long-run warning (run_progress.h). */
#include "run_progress.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_clock.h"
#include "dv_phase.h"
#include "engine_scene.h"
#include "run_trajectory.h"

/* the process's progress: one command, one run or one pool at a time */
static struct {
  int line, warn;   /* what is on */
  char command[24]; /* "compare" */
  size_t shown;     /* characters of the line now on the terminal */
  double last;      /* s: when the line was last drawn (or the run began) */
  char drawn_phase[80]; /* the innermost phase of the line drawn last: "settings probe 5" */
  /* the run under way */
  int running, calibrated;
  int probing, planned; /* a probe runs; a plan was announced */
  double estimate;      /* s: an estimate probed for the next plan to use (NAN: none) */
  char scenario[32], engine[24];
  double duration, began;
  const char *role;     /* what the runs that follow are (dv_run_progress_role), or NULL */
  const char *run_role; /* what the run under way is */
  /* the pool under way */
  int depth; /* pools begun and not ended: 1 in the pool's parent */
  char noun[24];
  size_t n, ended;
  double tasks_began;
  int tasks_warned;
} P;

/* seconds as "45s", "3m12s", "2h05m" */
static void say_time(double s, char *buf, size_t size) {
  const long whole = s < 0.0 ? 0 : s > 1e8 ? 100000000 : (long)(s + 0.5);
  if (whole < 60)
    snprintf(buf, size, "%lds", whole);
  else if (whole < 3600)
    snprintf(buf, size, "%ldm%02lds", whole / 60, whole % 60);
  else
    snprintf(buf, size, "%ldh%02ldm", whole / 3600, whole % 3600 / 60);
}

/* rewrite the line with text, blanking what the last one left over */
static void draw(const char *text) {
  const size_t len = strlen(text) < 200 ? strlen(text) : 200; /* the %.200s drawn */
  char buf[256];
  const int pad = P.shown > len ? (int)((P.shown - len) % sizeof buf) : 0; /* P.shown < sizeof buf */
  snprintf(buf, sizeof buf, "\r%.200s%*s", text, pad, "");
  fputs(buf, stderr); /* one write: stderr is unbuffered */
  P.shown = len;
}

static void clear(void) {
  if (!P.shown) return;
  char buf[256];
  snprintf(buf, sizeof buf, "\r%*s\r", (int)P.shown, "");
  fputs(buf, stderr);
  P.shown = 0;
}

/* the phases now: "attribution 2/11 (integrator), settings probe 3/8 (rk4 5e-05 s)" */
static size_t say_phases(char *buf, size_t size) {
  const dv_phase *s;
  const size_t d = dv_phase_stack(&s);
  size_t n = 0;
  buf[0] = '\0';
  for (size_t i = 0; i < d && n < size; i++) {
    int m = snprintf(buf + n, size - n, "%s%s", i ? ", " : "", s[i].name);
    if (m > 0 && s[i].n > 0 && n + (size_t)m < size)
      m += snprintf(buf + n + (size_t)m, size - n - (size_t)m, " %zu/%zu", s[i].k, s[i].n);
    if (m > 0 && s[i].subject[0] && n + (size_t)m < size)
      m += snprintf(buf + n + (size_t)m, size - n - (size_t)m, " (%.40s)", s[i].subject);
    if (m > 0) n += (size_t)m;
  }
  return n < size ? n : size - 1;
}

/* s left of the outermost counted phase, from its items done so far (its
 * first item: as long as the run under way, whose run_left is given; NAN
 * where nothing says) and at least run_left; no counted phase: run_left */
static double phases_left(double now, double run_left) {
  const dv_phase *s;
  const size_t d = dv_phase_stack(&s);
  for (size_t i = 0; i < d; i++) {
    if (s[i].n == 0 || s[i].k == 0 || s[i].k > s[i].n) continue;
    const double in_item = now - s[i].item_began;
    const double item = s[i].k > 1 ? (s[i].item_began - s[i].began) / (double)(s[i].k - 1)
                                   : in_item + run_left;
    if (isnan(item)) return NAN;
    const double rest = item * (double)(s[i].n - s[i].k);
    return rest + fmax(item - in_item, isnan(run_left) ? 0.0 : run_left);
  }
  return run_left;
}

/* a phase's item began, or a phase ended, outside a run (a settings probe):
 * its line; none once the last phase has ended */
static void phase_changed(void) {
  if (!P.line || P.depth > 0 || P.running) return;
  const dv_phase *stack;
  if (!dv_phase_stack(&stack)) return clear();
  const double now = dv_clock_now();
  /* a phase begun is drawn at once: its items may all pass within the throttle */
  const size_t depth = dv_phase_stack(&stack);
  char phase[sizeof P.drawn_phase];
  snprintf(phase, sizeof phase, "%.60s %zu", stack[depth - 1].name, stack[depth - 1].n);
  if (now - P.last < 1.0 / DV_PROGRESS_HZ && !strcmp(phase, P.drawn_phase)) return;
  P.last = now;
  memcpy(P.drawn_phase, phase, sizeof phase);
  char text[192], t_left[32];
  const size_t n = say_phases(text, 120);
  const double left = phases_left(now, NAN);
  if (isnan(left))
    snprintf(text + n, sizeof text - n, "  estimating the time left");
  else
    say_time(left, t_left, sizeof t_left), snprintf(text + n, sizeof text - n, "  %s left", t_left);
  draw(text);
}

void dv_run_progress_start(const char *command, int quiet, int stdout_busy) {
  memset(&P, 0, sizeof P);
  snprintf(P.command, sizeof P.command, "%s", command);
  P.warn = !quiet;
  P.estimate = NAN;
  P.line = !quiet && isatty(STDERR_FILENO) && !(stdout_busy && isatty(STDOUT_FILENO));
  dv_phase_listen(P.line ? phase_changed : NULL);
}

/* the warning, on a line of its own: what will take about seconds (more) */
static void announce(const char *what, double seconds, int more, const char *basis) {
  char t[32];
  say_time(seconds, t, sizeof t);
  clear();
  fprintf(stderr, "diskval %s: %s will take about %s%s (%s); --quiet hides this\n", P.command, what,
          t, more ? " more" : "", basis);
}

/* a probe: the wall time from the first sample, up to the budget */
typedef struct probe {
  double first, spent, t; /* s of wall time at the first sample, since then; simulated s */
  double duration;        /* s simulated by the whole run */
  int stopped;            /* the budget ended it */
} probe;

static int probe_sample(void *ctx, const dv_sample *s) {
  probe *p = ctx;
  const double now = dv_clock_now();
  if (p->first < 0.0) return p->first = now, 0;
  p->spent = now - p->first, p->t = s->t;
  const int short_run =
      p->spent >= DV_PROGRESS_PROBE_MIN_S &&
      p->spent * p->duration < p->t * DV_PROGRESS_WARN_S / DV_PROGRESS_PROBE_SHARE;
  return p->stopped = p->spent >= DV_PROGRESS_PROBE_S || short_run; /* non-zero ends the run */
}

/* wall seconds a whole run of engine over sc will take, from a probe that
 * samples DV_PROGRESS_PROBE_PER_SCALE times a shortest time scale of the
 * scene: one output_dt of a fast scene may take minutes, and the probe
 * looks at its clock only at a sample */
static double estimate(const dv_engine_type *engine, const dv_scenario *sc) {
  dv_scenario *fine = malloc(sizeof *fine);
  if (!fine) return NAN;
  dv_scene_scales scales;
  dv_engine_scene_scales(sc, &scales);
  *fine = *sc;
  fine->output_dt = fmin(sc->output_dt, scales.t[scales.shortest] / DV_PROGRESS_PROBE_PER_SCALE);
  probe p = {-1.0, 0.0, 0.0, sc->duration, 0};
  dv_engine_stats st;
  P.probing = 1;
  dv_run_collect(engine, fine, probe_sample, &p, &st, NULL);
  P.probing = 0;
  free(fine);
  return p.stopped && p.t > 0.0 ? p.spent * sc->duration / p.t : p.spent;
}

/* wall seconds of a comparison's runs: the thin reference three times (the
 * run and the horizon's two), each engine, a thick one's matched reference
 * (as long as the thin one); *runs: how many */
static double comparison_estimate(const dv_scenario *sc, const dv_scenario *ref_sc,
                                  const dv_engine_type *const *engines, size_t n, int probing,
                                  size_t *runs) {
  const double thin =
      probing ? estimate(dv_engine_of_role(DV_ENGINE_THIN_REFERENCE), ref_sc ? ref_sc : sc) : NAN;
  double total = 3.0 * thin;
  *runs = 3 + n;
  for (size_t i = 0; i < n; i++) {
    const int thick = dv_engine_half_thickness(engines[i], sc) > 0.0;
    total += (probing ? estimate(engines[i], sc) : NAN) + (thick ? thin : 0.0);
    *runs += (size_t)thick;
  }
  return total;
}

double dv_run_progress_estimate(const dv_scenario *sc, const dv_scenario *ref_sc,
                                const dv_engine_type *const *engines, size_t n) {
  size_t runs;
  if (isnan(P.estimate)) P.estimate = comparison_estimate(sc, ref_sc, engines, n, 1, &runs);
  return P.estimate;
}

double dv_run_progress_estimate_run(const dv_scenario *sc, const dv_engine_type *engine) {
  if (isnan(P.estimate)) P.estimate = estimate(engine, sc);
  return P.estimate;
}

void dv_run_progress_keep_estimate(double seconds) {
  P.estimate = seconds;
}

void dv_run_progress_plan(const dv_scenario *sc, const dv_scenario *ref_sc,
                          const dv_engine_type *const *engines, size_t n) {
  if (!P.warn || P.depth > 0 || P.planned || !(sc->duration > 0.0)) return;
  size_t runs;
  const double probed = comparison_estimate(sc, ref_sc, engines, n, isnan(P.estimate), &runs);
  const double total = isnan(P.estimate) ? probed : P.estimate;
  P.estimate = NAN; /* used: the next comparison (verify runs several) is probed afresh */
  if (!(total > DV_PROGRESS_WARN_S)) return;
  P.planned = 1;
  char what[160], basis[96];
  snprintf(what, sizeof what, "%.60s: the comparison to t = %g s (%zu runs)", sc->name,
           sc->duration, runs);
  snprintf(basis, sizeof basis, "each engine's rate timed for %g s", DV_PROGRESS_PROBE_S);
  announce(what, total, 0, basis);
}

void dv_run_progress_plan_run(const dv_scenario *sc, const dv_engine_type *engine) {
  if (!P.warn || P.depth > 0 || P.planned || !(sc->duration > 0.0)) return;
  const double total = dv_run_progress_estimate_run(sc, engine);
  P.estimate = NAN;
  if (!(total > DV_PROGRESS_WARN_S)) return;
  P.planned = 1;
  char what[80], basis[96];
  snprintf(what, sizeof what, "%.40s: %s to t = %g s", sc->name, engine->name, sc->duration);
  snprintf(basis, sizeof basis, "its rate timed for %g s", DV_PROGRESS_PROBE_S);
  announce(what, total, 0, basis);
}

void dv_run_progress_plan_levels(const dv_scenario *sc, const dv_engine_type *const *engines,
                                  size_t n, int levels) {
  if (!P.warn || P.depth > 0 || P.planned || !(sc->duration > 0.0)) return;
  const double thin = estimate(dv_engine_of_role(DV_ENGINE_THIN_REFERENCE), sc);
  double total = 0.0;
  size_t runs = 0;
  for (size_t i = 0; i < n; i++) {
    const int thick = dv_engine_half_thickness(engines[i], sc) > 0.0;
    const double one = estimate(engines[i], sc);
    for (int k = 0; k < levels; k++) total += (3.0 + thick) * thin + one * (double)(1 << k);
    runs += (size_t)levels * (4 + (size_t)thick);
  }
  if (!(total > DV_PROGRESS_WARN_S)) return;
  P.planned = 1;
  char what[160], basis[128];
  snprintf(what, sizeof what, "%.60s: the verification to t = %g s (%d levels x %zu engine%s, %zu runs)",
           sc->name, sc->duration, levels, n, n == 1 ? "" : "s", runs);
  snprintf(basis, sizeof basis,
           "each engine's rate timed for %g s, level k's step 2^k times finer", DV_PROGRESS_PROBE_S);
  announce(what, total, 0, basis);
}

void dv_run_progress_plan_total(const char *what, double seconds, const char *basis) {
  if (!P.warn || P.depth > 0 || P.planned || !(seconds > DV_PROGRESS_WARN_S)) return;
  P.planned = 1;
  announce(what, seconds, 0, basis);
}

void dv_run_progress_announce(const char *what, double seconds, const char *basis) {
  if (P.warn && P.depth == 0 && seconds > DV_PROGRESS_WARN_S) announce(what, seconds, 0, basis);
}

void dv_run_progress_say(const char *fmt, ...) {
  if (!P.warn || P.depth > 0) return;
  char text[1024];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(text, sizeof text, fmt, ap);
  va_end(ap);
  clear();
  fprintf(stderr, "diskval %s: %s\n", P.command, text);
}

void dv_run_progress_role(const char *role) { P.role = role; }

void dv_run_progress_run_begin(const char *scenario, const char *engine, int reference,
                               double duration) {
  P.running = (P.line || P.warn) && P.depth == 0 && !P.probing && duration > 0.0;
  if (!P.running) return;
  snprintf(P.scenario, sizeof P.scenario, "%s", scenario);
  snprintf(P.engine, sizeof P.engine, "%s", engine);
  P.duration = duration;
  P.run_role = P.role ? P.role : reference ? "reference" : "engine run";
  P.calibrated = 0;
  P.began = P.last = dv_clock_now();
}

void dv_run_progress_run_at(double t) {
  if (!P.running || !(t > 0.0)) return;
  const double now = dv_clock_now();
  if (now - P.last < 1.0 / DV_PROGRESS_HZ) return; /* the throttle: one clock read a sample */
  P.last = now;
  const double spent = now - P.began, left = spent * (P.duration - t) / t;
  if (P.warn && !P.planned && !P.calibrated && spent >= DV_PROGRESS_CALIBRATE_S) {
    P.calibrated = 1;
    if (left > DV_PROGRESS_WARN_S) {
      char what[80], basis[96];
      snprintf(what, sizeof what, "%s: %s", P.scenario, P.engine);
      snprintf(basis, sizeof basis, "%.3g s of wall time per simulated s, to t = %g s", spent / t,
               P.duration);
      announce(what, left, 1, basis);
    }
  }
  if (!P.line || spent < DV_PROGRESS_DELAY_S) return;
  char text[256], t_left[32];
  size_t n = say_phases(text, 120);
  n += (size_t)snprintf(text + n, sizeof text - n, "%s%s", n ? ": " : "", P.run_role);
  say_time(phases_left(now, left), t_left, sizeof t_left);
  snprintf(text + n, sizeof text - n, "  %.31s %.23s  t %.1f/%g s  %s left", P.scenario, P.engine,
           t, P.duration, t_left);
  draw(text);
}

void dv_run_progress_run_end(void) {
  if (P.running && P.line) clear();
  P.running = 0;
}

void dv_run_progress_tasks_begin(const char *noun, size_t n) {
  if (P.depth++ > 0) return; /* a pool in a task's process, or in a task of an MPI rank */
  snprintf(P.noun, sizeof P.noun, "%s", noun);
  P.n = n;
  P.ended = 0;
  P.tasks_warned = 0;
  P.tasks_began = P.last = dv_clock_now();
}

void dv_run_progress_task_ended(const char *note) {
  if (P.depth != 1 || !(P.line || P.warn)) return;
  P.ended++;
  const double now = dv_clock_now(), spent = now - P.tasks_began;
  const double left = spent * (double)(P.n - P.ended) / (double)P.ended;
  if (P.warn && !P.tasks_warned && spent >= DV_PROGRESS_CALIBRATE_S) {
    P.tasks_warned = 1;
    if (left > DV_PROGRESS_WARN_S) {
      char what[64], basis[64], t[32];
      say_time(spent, t, sizeof t);
      snprintf(what, sizeof what, "%s %zu/%zu: the rest", P.noun, P.ended, P.n);
      snprintf(basis, sizeof basis, "%zu ended in %s", P.ended, t);
      announce(what, left, 1, basis);
    }
  }
  if (!P.line || (now - P.last < 1.0 / DV_PROGRESS_HZ && P.ended < P.n)) return;
  P.last = now;
  char text[160], t_left[32];
  say_time(left, t_left, sizeof t_left);
  snprintf(text, sizeof text, "%s %zu/%zu  %s left%s%.60s%s", P.noun, P.ended, P.n, t_left,
           note ? "  (" : "", note ? note : "", note ? ")" : "");
  draw(text);
}

void dv_run_progress_tasks_end(void) {
  if (P.depth > 0 && --P.depth == 0 && P.line) clear();
}

void dv_run_progress_on_result(size_t k, int ran, void *ctx) {
  (void)k, (void)ran, (void)ctx;
  dv_run_progress_task_ended(NULL);
}
