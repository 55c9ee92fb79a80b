/* engine_adapter: an adapter's run, as an engine (adapter.h; docs/adapters.md).
 *
 * reset starts the adapter and sends the scene; advance asks for each sample
 * and checks the row it gets as a linked engine's state is checked
 * (engine_watch.h) and against the rows before it as a trajectory file's
 * columns are (the steps against the time, the row at t = 0 against the state
 * sent, each angle's step against its rate, the centre's against its
 * velocity: a pose replayed with made-up velocities fails), plus what only a
 * pipe can get wrong: an answer that never
 * comes (the manifest's timeout), a line that is not 16 numbers, a time that
 * is not the one asked, a quaternion off the unit sphere, the adapter's own
 * "error" line, its exit. Every one ends the run as failed with the reason
 * and the adapter's last line on standard error; the adapter is then killed.
 * The lying down is seen at the samples (the rows are all diskval sees).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adapter.h"
#include "adapter_child.h"
#include "dv_pose.h"
#include "dv_reference.h"
#include "engine_watch.h"

#define ROW_FIELDS 16
#define QUAT_TOL 1e-6  /* a row's quaternion norm off 1 (float32 engines: ~1e-7) */
#define STOP_GRACE 2.0 /* s an adapter has to exit once its input is closed */
#define SCENE_BYTES 8192

typedef struct adapter_run {
  const dv_adapter *a;
  dv_geometry geom;
  double timestep, theta_limit, time_tol;
  char scene[SCENE_BYTES]; /* the settings' lines, then start */
  dv_scenario sc;          /* a copy: reset may come after the caller's scenario is gone */
  dv_child child;
  dv_engine_watch watch;
  dv_engine_stats st;
  double prev_y[RED_NSTATE];
  double sent[RED_NSTATE]; /* the state the run starts from */
  double rate_scale;       /* rad/s: the rows' checks (engine_watch.h) */
  size_t rows;             /* rows answered */
  dv_sample last[1];       /* the row before */
  dv_rows_centre_track centre;
  dv_rows_drift drift[3]; /* theta, phi, psi */
  int status; /* DV_OK, DV_EVENT, or the failure's code */
} adapter_run;

static int failed(adapter_run *r, dv_failure why, dv_error *err, const char *fmt,
                  const char *what) {
  char tail[200] = "";
  if (r->child.pid) dv_child_stop(&r->child, 0.0);
  if (r->child.err_tail[0]) snprintf(tail, sizeof tail, " (its stderr: %.160s)", r->child.err_tail);
  r->st.failure = why;
  r->st.outcome = dv_failure_outcome(why);
  snprintf(r->st.detail, sizeof r->st.detail, "%s: %s%.150s%s", r->a->name, fmt, what, tail);
  r->status = why == DV_FAILURE_NAN ? DV_ENUMERIC : DV_ESYSTEM;
  return dv_fail(err, r->status, "%s", r->st.detail);
}

/* the adapter ended its output: how, and what it said */
static int ended(adapter_run *r, dv_error *err) {
  char how[64];
  dv_child_stop(&r->child, STOP_GRACE);
  dv_child_end_text(&r->child, how, sizeof how);
  return failed(r, DV_FAILURE_LIBRARY, err, "the adapter stopped answering: ", how);
}

/* the manifest's command split into argv (in buf), at most 30 words; their count */
static size_t command_words(const char *command, char *buf, size_t size, char *argv[32]) {
  size_t n = 0;
  snprintf(buf, size, "%s", command);
  for (char *save = NULL, *w = strtok_r(buf, " ", &save); w && n < 30;
       w = strtok_r(NULL, " ", &save))
    argv[n++] = w;
  return n;
}

static void *adapter_alloc(const dv_adapter *a, const dv_scenario *sc, dv_error *err) {
  adapter_run *r = calloc(1, sizeof *r);
  if (!r) return dv_fail(err, DV_ESYSTEM, "out of memory"), NULL;
  r->a = a;
  r->sc = *sc;
  r->timestep = dv_scenario_get(sc, a->name, a->step_key);
  r->geom = (dv_geometry){DV_SHAPE_CYLINDER, sc->disk.r,
                          dv_scenario_get(sc, a->name, DV_ADAPTER_HALF_KEY)};
  r->theta_limit = dv_reference_settings(sc)->theta_limit;
  r->time_tol = 1e-6 * r->timestep;
  r->child.in = r->child.out = r->child.err = -1;
  if (a->missing[0]) {
    dv_fail(err, DV_EINPUT, "%s is not available: %s", a->name, a->missing);
    free(r);
    return NULL;
  }
  return r;
}

static int adapter_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  adapter_run *r = p;
  char what[256], line[DV_CHILD_LINE];
  char *argv[32];
  char words[sizeof r->a->command];
  size_t n = 0;
  dv_child_stop(&r->child, 0.0);
  memset(&r->st, 0, sizeof r->st);
  r->status = DV_OK;
  if (dv_adapter_scene_text(r->a, &r->sc, state, r->scene, sizeof r->scene, err))
    return failed(r, DV_FAILURE_SETUP, err, "", err->msg);
  memcpy(r->prev_y, state, sizeof r->prev_y);
  memcpy(r->sent, state, sizeof r->sent);
  r->rate_scale = dv_rows_rate_scale(&r->sc.disk, state);
  r->rows = 0;
  memset(&r->centre, 0, sizeof r->centre);
  memset(r->drift, 0, sizeof r->drift);
  dv_pose start; /* watched from the state sent, whatever times are asked for */
  dv_pose_from_state(&r->geom, state, &start);
  const dv_failure f = dv_engine_watch_start(&r->watch, &r->sc.disk, &start, what, sizeof what);
  if (f) return failed(r, f, err, "", what);
  n = command_words(r->a->command, words, sizeof words, argv);
  argv[n] = NULL;
  if (dv_child_start(&r->child, r->a->dir, argv, what, sizeof what))
    return failed(r, DV_FAILURE_SETUP, err, "", what);
  if (dv_child_write(&r->child, r->scene, what, sizeof what)) return ended(r, err);
  const int got =
      dv_child_read_line(&r->child, r->a->timeout, line, sizeof line, what, sizeof what);
  if (got > 0) return ended(r, err);
  if (got < 0) return failed(r, DV_FAILURE_SETUP, err, "while it built the model: ", what);
  if (strncmp(line, "error", 5) == 0) return failed(r, DV_FAILURE_SETUP, err, "", line);
  if (strcmp(line, "ready") != 0)
    return failed(r, DV_FAILURE_SETUP, err, "expected 'ready', got: ", line);
  return DV_OK;
}

/* the row's 16 numbers; 0, or -1 with what set */
static int parse_row(const char *line, double v[ROW_FIELDS], char *what, size_t size) {
  const char *s = line;
  for (int k = 0; k < ROW_FIELDS; k++) {
    char *end;
    v[k] = strtod(s, &end);
    if (end == s || (*end && *end != ' ' && *end != '\t'))
      return snprintf(what, size, "field %d is not a number in: %.80s", k + 1, line), -1;
    s = end;
  }
  while (*s == ' ' || *s == '\t') s++;
  if (*s) return snprintf(what, size, "more than %d fields in: %.80s", ROW_FIELDS, line), -1;
  return 0;
}

/* the row's own consistency, as a trajectory file's (engine_watch.h): its
 * step count against its time, the row at t = 0 against the state sent, each
 * angle's step against its rate and the centre's against its velocity: 0, or
 * 1 with what set */
static int rows_disagree(adapter_run *r, const dv_sample *s, const dv_pose *pose,
                         const double v[ROW_FIELDS], char *what, size_t size) {
  const double steps = round(v[0] / r->timestep);
  if (v[15] != steps)
    return snprintf(what, size, "%.0f steps at t = %.9g s, where the step %g s makes %.0f", v[15],
                    v[0], r->timestep, steps), 1;
  const int k = s->t == 0.0 ? dv_rows_start_off(s->y, r->sent, r->sc.disk.r, r->rate_scale) : -1;
  if (k >= 0)
    return snprintf(what, size, "its state at t = 0 is not the one sent: %s = %.10g, sent %.10g",
                    red_state_name(k), s->y[k], r->sent[k]), 1;
  const dv_sample *a = r->rows ? &r->last[0] : NULL;
  static const char *const angle[3] = {"theta", "phi", "psi"};
  double d, miss;
  int summed;
  const int q = a ? dv_rows_angles(a, s, 1, r->rate_scale, r->drift, &d, &miss, &summed) : -1;
  if (q >= 0 && summed)
    return snprintf(what, size,
                    "%s's steps to t = %.9g s add up to %.3g rad off the trapezoids of its rate "
                    "over %.3g rad of them, %.3g times what they allow",
                    angle[q], s->t, r->drift[q].miss, r->drift[q].travel, d), 1;
  if (q >= 0)
    return snprintf(what, size,
                    "%s misses the trapezoid of its rate by %.3g rad from t = %.9g to %.9g s, "
                    "%.3g times what the step and the rates allow",
                    angle[q], fabs(miss), a->t, s->t, d), 1;
  int c;
  d = dv_rows_centre(&r->centre, a, s, pose->pos, pose->vel, r->sc.disk.r * r->rate_scale, &c);
  if (d > 1.0)
    return snprintf(what, size,
                    "the centre's %s step to t = %.9g s misses the trapezoid of its velocity, %.3g "
                    "times what the step and the speed allow",
                    c ? "y" : "x", s->t, d), 1;
  r->last[0] = *s;
  r->rows++;
  return 0;
}

static int adapter_advance(void *p, double t, dv_sample *out, dv_error *err) {
  adapter_run *r = p;
  char what[256], line[DV_CHILD_LINE], ask[64];
  double v[ROW_FIELDS];
  if (r->status < 0) return dv_fail(err, r->status, "%s", r->st.detail);
  if (r->status == DV_EVENT) return DV_EVENT;
  snprintf(ask, sizeof ask, "advance %.17g\n", t);
  if (dv_child_write(&r->child, ask, what, sizeof what)) return ended(r, err);
  const int got =
      dv_child_read_line(&r->child, r->a->timeout, line, sizeof line, what, sizeof what);
  if (got > 0) return ended(r, err);
  if (got < 0) return failed(r, DV_FAILURE_LIBRARY, err, "hung or garbled: ", what);
  if (strncmp(line, "error", 5) == 0) return failed(r, DV_FAILURE_LIBRARY, err, "", line);
  if (parse_row(line, v, what, sizeof what))
    return failed(r, DV_FAILURE_LIBRARY, err, "a row that is not 16 numbers: ", what);
  const double asked = round(t / r->timestep) * r->timestep;
  if (!(fabs(v[0] - asked) <= r->time_tol + 1e-12 * fabs(asked))) {
    snprintf(what, sizeof what, "asked for t = %.17g s, the row is at %.17g s", t, v[0]);
    return failed(r, DV_FAILURE_LIBRARY, err, "", what);
  }
  dv_pose pose = {{v[1], v[2], v[3]}, {0}, {v[8], v[9], v[10]}, {v[11], v[12], v[13]}};
  double q[4] = {v[4], v[5], v[6], v[7]};
  const double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int k = 0; k < 4; k++) q[k] /= norm;
  dv_quat_to_matrix(q, pose.R);
  if (!dv_pose_finite(&pose) || !isfinite(norm)) {
    snprintf(what, sizeof what, "a non-finite state at t = %g s", t);
    return failed(r, DV_FAILURE_NAN, err, "", what);
  }
  if (!(fabs(norm - 1.0) <= QUAT_TOL)) {
    snprintf(what, sizeof what, "the quaternion's norm is %.9g at t = %g s, not 1 within %g", norm,
             t, QUAT_TOL);
    return failed(r, DV_FAILURE_LIBRARY, err, "", what);
  }
  if (!(v[14] == floor(v[14]) && v[14] >= -1 && v[14] < 1e6 && v[15] == floor(v[15]) &&
        v[15] >= 0 && v[15] < 1e15)) {
    snprintf(what, sizeof what, "contacts %g and steps %g at t = %g s: not whole counts", v[14],
             v[15], t);
    return failed(r, DV_FAILURE_LIBRARY, err, "", what);
  }
  const long steps = (long)v[15];
  r->st.steps = steps;
  const dv_failure f = dv_engine_watch_check(&r->watch, &r->sc.disk, &r->geom, &pose, steps,
                                             r->timestep, what, sizeof what);
  if (f) return failed(r, f, err, "", what);
  dv_sample_from_pose(&r->sc.disk, &r->geom, &pose, t, r->prev_y, out);
  if (rows_disagree(r, out, &pose, v, what, sizeof what))
    return failed(r, DV_FAILURE_LIBRARY, err, "its rows disagree: ", what);
  out->contacts = (int)v[14];
  memcpy(r->prev_y, out->y, sizeof r->prev_y);
  dv_stats_add_sample(&r->st, out);
  const double theta = out->y[0];
  if (theta < r->theta_limit || theta > M_PI - r->theta_limit) {
    dv_engine_lay_down(&r->st, theta < r->theta_limit, r->theta_limit, t);
    r->status = DV_EVENT;
    dv_child_stop(&r->child, STOP_GRACE);
    return DV_EVENT;
  }
  return DV_OK;
}

static void adapter_stats(const void *p, dv_engine_stats *out) {
  const adapter_run *r = p;
  *out = r->st;
  if (!r->st.detail[0] && r->a->version[0])
    snprintf(out->method, sizeof out->method, "%s through its adapter", r->a->version);
}

static void adapter_free(void *p) {
  adapter_run *r = p;
  if (!r) return;
  dv_child_stop(&r->child, STOP_GRACE);
  free(r);
}

/* the engine's own words: COMMAND --version's first line (asked once) */
static const char *adapter_version(dv_adapter *a) {
  char what[256], line[DV_CHILD_LINE], words[sizeof a->command];
  char *argv[32];
  size_t n;
  dv_child c;
  if (a->version[0]) return a->version;
  if (a->missing[0]) return snprintf(a->version, sizeof a->version, "not available"), a->version;
  n = command_words(a->command, words, sizeof words, argv);
  argv[n++] = "--version";
  argv[n] = NULL;
  snprintf(a->version, sizeof a->version, "version unknown");
  if (dv_child_start(&c, a->dir, argv, what, sizeof what)) return a->version;
  if (dv_child_read_line(&c, a->timeout, line, sizeof line, what, sizeof what) == 0 && line[0])
    snprintf(a->version, sizeof a->version, "%.159s", line);
  dv_child_stop(&c, STOP_GRACE);
  return a->version;
}

/* the slots' methods: the interface has no self argument, so each adapter is
 * served by the functions of its slot in the registry */
static dv_adapter *slots[DV_MAX_ADAPTERS];

#define SLOT(i)                                                                 \
  static void *alloc_##i(const dv_scenario *sc, dv_error *err) {                \
    return adapter_alloc(slots[i], sc, err);                                    \
  }                                                                             \
  static const char *version_##i(void) {                                        \
    return adapter_version(slots[i]);                                           \
  }                                                                             \
  static double half_##i(const dv_scenario *sc) {                               \
    return dv_scenario_get(sc, slots[i]->name, DV_ADAPTER_HALF_KEY);            \
  }                                                                             \
  static int check_##i(dv_scenario *sc, void *block, dv_setting_issue *issue) { \
    return dv_adapter_check(slots[i], sc, block, issue);                        \
  }
SLOT(0)
SLOT(1)
SLOT(2)
SLOT(3)
SLOT(4)
SLOT(5) SLOT(6) SLOT(7) SLOT(8) SLOT(9) SLOT(10) SLOT(11)
#undef SLOT
#define SLOT(i) \
  { alloc_##i, version_##i, half_##i, check_##i }

    static const struct {
  void *(*alloc)(const dv_scenario *, dv_error *);
  const char *(*version)(void);
  double (*half)(const dv_scenario *);
  int (*check)(dv_scenario *, void *, dv_setting_issue *);
} METHODS[DV_MAX_ADAPTERS] = {SLOT(0), SLOT(1), SLOT(2), SLOT(3), SLOT(4),  SLOT(5),
                              SLOT(6), SLOT(7), SLOT(8), SLOT(9), SLOT(10), SLOT(11)};
#undef SLOT

void dv_adapter_make_type(dv_adapter *a, size_t i) {
  slots[i] = a;
  const int choice = a->choice_key[0] != '\0';
  size_t nchoices = 1;
  for (size_t k = 0; choice && k < a->nsettings; k++)
    if (strcmp(a->setting[k].key, a->choice_key) == 0)
      for (nchoices = 0; a->specs[k].choices[nchoices];) nchoices++;
  for (size_t v = 0; v < nchoices; v++) {
    a->models[v].engine = a->name;
    a->models[v].soft_key = a->models[v].soft_steps > 0.0 ? a->softness_key : NULL;
  }
  a->section =
      (dv_settings_section){a->name, a->specs, a->nsettings, 8 * a->nsettings, METHODS[i].check};
  if (!a->search.hi) a->search.lo = 1e-7, a->search.hi = 0.02;
  a->search.section = a->name;
  a->search.choice_key = choice ? a->choice_key : NULL;
  a->search.step_key = a->step_key;
  a->contact.geom_key = NULL;
  a->contact.thin_choice = NULL;
  a->contact.softness_key = a->softness_key[0] ? a->softness_key : NULL;
  a->contact.friction_key = a->friction_key;
  a->contact.extra = a->extra;
  a->contact.nextra = a->nextra;
  a->knobs = (dv_engine_knobs){
      a->name, choice ? a->choice_key : NULL, a->models, (int)nchoices, a->model_given, 2};
  a->type = (dv_engine_type){
      .name = a->name,
      .description = a->description,
      .role = DV_ENGINE_CONTACT,
      .settings = &a->section,
      .search = &a->search,
      .contact = &a->contact,
      .half_thickness = METHODS[i].half,
      .version = METHODS[i].version,
      .alloc = METHODS[i].alloc,
      .reset = adapter_reset,
      .advance = adapter_advance,
      .stats = adapter_stats,
      .free = adapter_free,
      .outside = 1,
      .missing = a->missing,
  };
}
