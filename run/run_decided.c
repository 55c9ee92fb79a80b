/* run_decided: the one line that decided a verdict, and the sentences why (run_decided.h). */
#include "run_decided.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "dv_reference.h"
#include "run_turning.h"

/* append to out (size) at *len, never past its end */
static void put(char *out, size_t size, size_t *len, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

static void put(char *out, size_t size, size_t *len, const char *fmt, ...) {
  if (*len >= size - 1) return;
  va_list ap;
  va_start(ap, fmt);
  const int n = vsnprintf(out + *len, size - *len, fmt, ap);
  va_end(ap);
  if (n > 0) *len = *len + (size_t)n < size - 1 ? *len + (size_t)n : size - 1;
}

/* value and limit in as few digits as tell them apart (2 at least) */
static void two_numbers(double v, double l, const char *unit, char *vs, char *ls, size_t size) {
  for (int p = 2; p <= 6; p++) {
    snprintf(vs, size, "%.*g %s", p, v, unit);
    snprintf(ls, size, "%.*g %s", p, l, unit);
    if (strcmp(vs, ls) || v == l) return;
  }
}

/* how far over (or under) its limit metric m is; a value not measured is
 * furthest over; NAN where the metric has no limit */
static double ratio(const dv_engine_result *r, int m) {
  if (isnan(r->tolerance[m])) return NAN;
  if (isnan(r->vs_ref.value[m])) return INFINITY;
  return r->tolerance[m] > 0.0 ? r->vs_ref.value[m] / r->tolerance[m]
         : r->vs_ref.value[m] > 0.0 ? INFINITY
                                    : 0.0;
}

static int not_judged(const dv_engine_result *r) {
  return r->verdict == DV_VERDICT_NOT_JUDGED || r->verdict == DV_VERDICT_OUTSIDE_VALIDITY;
}

int dv_run_deciding_metric(const dv_engine_result *r) {
  if (not_judged(r) || dv_run_verdict_failed(r->verdict)) return -1;
  if (r->event.judged && !r->event.agrees) return -1;
  int best = -1;
  for (int m = 0; m < DV_NMETRICS; m++) {
    const double q = ratio(r, m);
    if (isnan(q) || (r->pass && isinf(q))) continue;
    if (!r->pass && dv_run_limit_check(r->vs_ref.value[m], r->tolerance[m]) != DV_LIMIT_OVER)
      continue;
    if (best < 0 || q > ratio(r, best)) best = m;
  }
  return best;
}

static const char *ordinal_suffix(size_t k) {
  if (k % 100 >= 11 && k % 100 <= 13) return "th";
  return k % 10 == 1 ? "st" : k % 10 == 2 ? "nd" : k % 10 == 3 ? "rd" : "th";
}

/* which turning point made theta_turning_err, and how early or late */
static void turning_words(const dv_traj *eng, const dv_traj *ref, double t_end, char *out,
                          size_t size) {
  dv_turning_worst w;
  dv_run_turning_worst(eng, ref, t_end, &w);
  out[0] = '\0';
  if (!w.kind) return;
  const char *kind = w.kind > 0 ? "maximum" : "minimum";
  const char *sfx = ordinal_suffix(w.ordinal);
  if (w.only > 0)
    snprintf(out, size, "its %zu%s %s, which the reference does not make", w.ordinal, sfx, kind);
  else if (w.only < 0)
    snprintf(out, size, "the reference's %zu%s %s, which it does not make", w.ordinal, sfx, kind);
  else if (fabs(w.lag) < 5e-4)
    snprintf(out, size, "%zu%s %s, on time", w.ordinal, sfx, kind);
  else
    snprintf(out, size, "%zu%s %s %.3g ms %s", w.ordinal, sfx, kind, 1e3 * fabs(w.lag),
             w.lag < 0 ? "early" : "late");
}

/* the turn of eng that lags or leads ref's most, in words: "3rd maximum 280 ms late" */
static void lag_words(const dv_traj *eng, const dv_traj *ref, double t_end, char *out,
                      size_t size) {
  dv_turn_id w;
  double lag;
  out[0] = '\0';
  if (isnan(dv_run_turning_lag_worst(eng, ref, t_end, &w, &lag))) return;
  const char *kind = w.kind > 0 ? "maximum" : "minimum", *sfx = ordinal_suffix(w.ordinal);
  if (w.only > 0)
    snprintf(out, size, "its %zu%s %s, the reference's past the window", w.ordinal, sfx, kind);
  else if (w.only < 0)
    snprintf(out, size, "the reference's %zu%s %s, its own past the window", w.ordinal, sfx, kind);
  else
    snprintf(out, size, "%zu%s %s %.3g ms %s", w.ordinal, sfx, kind, 1e3 * fabs(lag),
             lag < 0 ? "early" : "late");
}

/* why the compared window ends where it does: a few words into brief, a
 * sentence's worth into full */
static void window_end_words(const dv_comparison *c, const dv_traj *ref,
                             const dv_engine_stats *ref_st, double ref_end,
                             const dv_engine_result *r, char *brief, char *full, size_t size) {
  const dv_scenario *sc = c->sc;
  const double half = 0.5 * sc->output_dt, t_w = r->vs_ref.t_window;
  const double t_run = ref->n ? ref->s[ref->n - 1].t : 0.0;
  const double t_eng = r->traj.n ? r->traj.s[r->traj.n - 1].t : 0.0;
  const char *cross = strstr(r->reference_note, "upright");
  if (ref_end < t_run - half && ref_end <= t_w + half && !cross) {
    size_t i = 0; /* the first sample past the validity window: its force says why */
    while (i < ref->n && ref->s[i].t <= ref_end + 1e-12) i++;
    const double *F = i < ref->n ? ref->s[i].force : NULL;
    const double mu = dv_matched_friction(sc);
    if (F && !(F[2] > 0.0)) {
      snprintf(brief, size, "rolling needs the ground to pull from t = %g s", ref_end);
      snprintf(full, size,
               "at t = %g s the contact force rolling needs turns away from the ground (normal "
               "force %.3g N): the disk would leave it, which the reduced equations do not "
               "describe",
               ref_end, F[2]);
    } else {
      double need = 0.0; /* the most friction rolling needs from there on */
      for (size_t k = i; k < ref->n; k++)
        if (ref->s[k].force[2] > 0.0)
          need = fmax(need, hypot(ref->s[k].force[0], ref->s[k].force[1]) / ref->s[k].force[2]);
      snprintf(brief, size, "rolling needs more friction than mu = %g from t = %g s", mu, ref_end);
      snprintf(full, size,
               "from t = %g s rolling needs more friction than mu = %g (up to %.3g times the "
               "normal force by the reference's end): the disk slips there, which the reduced "
               "equations of rolling do not describe",
               ref_end, mu, need);
    }
  } else if (cross && r->half_thickness > 0.0 && ref_end <= t_w + half) {
    snprintf(brief, size, "the scene's body reaches upright at t = %g s", ref_end);
    snprintf(full, size, "%s", r->reference_note);
  } else if (t_eng < t_run - half && t_eng <= t_w + half) {
    snprintf(brief, size, "its run ended at t = %g s", t_eng);
    snprintf(full, size, "the engine's run ended there (%s%s%.200s)",
             dv_outcome_name(r->stats.outcome), r->stats.detail[0] ? ": " : "", r->stats.detail);
  } else if (ref_st->outcome != DV_OUTCOME_COMPLETED) {
    snprintf(brief, size, "the reference ended at t = %g s", t_run);
    snprintf(full, size, "the reference ended there (%s%s%.200s)", dv_outcome_name(ref_st->outcome),
             ref_st->detail[0] ? ": " : "", ref_st->detail);
  } else {
    snprintf(brief, size, "the scenario's end");
    snprintf(full, size, "the scenario's duration ends there");
  }
}

/* the first clause of text (to a ':', ';' or '('), clipped to room characters */
static void first_clause(const char *text, char *out, size_t room) {
  size_t n = strcspn(text, ":;(");
  while (n > 0 && text[n - 1] == ' ') n--;
  if (n > room) n = room;
  snprintf(out, room + 1, "%.*s", (int)n, text);
}

/* the one line: the verdict's word and what decided it */
static void one_line(const dv_comparison *c, const dv_traj *ref, const char *brief,
                     dv_engine_result *r) {
  char line[512], detail[160] = "", body[48] = "";
  const double t_eng = r->traj.n ? r->traj.s[r->traj.n - 1].t : 0.0;
  const double t0 = ref->n ? ref->s[0].t : 0.0;
  if (r->half_thickness > 0.0) {
    body[0] = ',', body[1] = ' ';
    dv_run_body_words(r->half_thickness, body + 2, sizeof body - 2);
  }
  const int m = dv_run_deciding_metric(r);
  if (not_judged(r)) {
    char clause[100];
    const char *first = r->nfailures ? r->failures[0] : "";
    first_clause(r->not_judged, clause, 80);
    if (r->not_judged[0])
      snprintf(line, sizeof line, "not judged: %s", clause);
    else if (strstr(first, "compared window"))
      snprintf(line, sizeof line, "not judged: compared window %.3g s (%.80s)",
               fmax(0.0, r->vs_ref.t_window - t0), brief);
    else if (strstr(first, "is the reference it would be compared with"))
      snprintf(line, sizeof line, "not judged: it is the reference it would be compared with");
    else
      snprintf(line, sizeof line, "not judged: its samples are its reference's own");
  } else if (dv_run_verdict_failed(r->verdict)) {
    char what[64];
    first_clause(r->stats.detail, what, 60);
    snprintf(line, sizeof line, "fails: the run %s at t = %.3g s%s%s%s",
             r->verdict == DV_VERDICT_ERROR ? "stopped with an error"
                                            : dv_run_verdict_name(r->verdict),
             t_eng, what[0] ? ": " : "", what, body);
  } else if (m < 0 && !r->pass) {
    snprintf(line, sizeof line, "fails: it %s%s", r->event.why[0] ? r->event.why : "fails", body);
  } else if (m < 0) {
    snprintf(line, sizeof line, "passes: no metric has a limit here%s", body);
  } else {
    const double v = r->vs_ref.value[m], l = r->tolerance[m];
    char vs[48], ls[48];
    two_numbers(v, l, dv_metric_units[m], vs, ls, sizeof vs);
    if (m == DV_THETA_TURNING_ERR)
      turning_words(&r->traj, ref, r->vs_ref.t_window, detail, sizeof detail);
    else if (m == DV_TURNING_LAG)
      lag_words(&r->traj, ref, r->vs_ref.t_window, detail, sizeof detail);
    else if (dv_run_metric_pointwise((dv_metric_id)m) &&
             r->pointwise_end < r->vs_ref.t_window - 0.5 * c->sc->output_dt)
      snprintf(detail, sizeof detail, "judged to t = %.3g s, where the spread reaches the motion",
               r->pointwise_end);
    else if (r->excused[m] > 0.0)
      snprintf(detail, sizeof detail, "the limit plus the spread %.2g %s", r->excused[m],
               dv_metric_units[m]);
    else if (isinf(v) && m == DV_NUTATION_PERIOD_ERR)
      snprintf(detail, sizeof detail, "it completes no nutation period");
    if (r->pass)
      snprintf(line, sizeof line, "passes: %s %s <= %s (%.2g of its limit%s%s)%s",
               dv_metric_names[m], vs, ls, v / l, detail[0] ? "; " : "", detail, body);
    else if (isnan(v))
      snprintf(line, sizeof line, "fails: %s not measured (limit %s)%s", dv_metric_names[m], ls,
               body);
    else
      snprintf(line, sizeof line, "fails: %s %s > %s%s%s%s%s", dv_metric_names[m], vs, ls,
               detail[0] ? " (" : "", detail, detail[0] ? ")" : "", body);
    if (strlen(line) > DV_DECIDED_MAX && detail[0]) { /* the detail goes first */
      detail[0] = '\0';
      snprintf(line, sizeof line, "%s: %s %s %s %s%s", r->pass ? "passes" : "fails",
               dv_metric_names[m], vs, r->pass ? "<=" : ">", ls, body);
    }
  }
  for (char *p = line; *p; p++) /* one line, whatever a detail holds */
    if (*p == '\n' || *p == '\r') *p = ' ';
  snprintf(r->decided, sizeof r->decided, "%s", line);
}

void dv_run_excused_words(const dv_engine_result *r, int m, char *buf, size_t size) {
  buf[0] = '\0';
  if (r->excused[m] > 0.0)
    snprintf(buf, size, ", plus %.3g %s the spread of its early error excuses", r->excused[m],
             dv_metric_units[m]);
}

/* the sentences: the window, the shadow, the deciding limit, the lying down */
static void sentences(const dv_comparison *c, const dv_traj *ref, const char *full,
                      dv_engine_result *r) {
  char *w = r->decided_why;
  const size_t size = sizeof r->decided_why;
  size_t len = 0;
  const double t0 = ref->n ? ref->s[0].t : 0.0;
  const double t_run = ref->n ? ref->s[ref->n - 1].t : 0.0;
  char body[48];
  dv_run_body_words(r->half_thickness, body, sizeof body);
  w[0] = '\0';
  put(w, size, &len, "Judged %s%s%s. ", body, r->reference_note[0] ? ": " : "",
      r->reference_note);
  put(w, size, &len,
      "The compared window runs to t = %g s (%.0f%% of the reference's %g s): %s. ",
      r->vs_ref.t_window, 100 * r->window_fraction, t_run - t0, full);
  if (r->vs_ref.n_window >= 2 && r->pointwise_end >= r->vs_ref.t_window - 0.5 * c->sc->output_dt)
    put(w, size, &len,
        "The pointwise metrics (theta, contact point and phase at equal times) and the turning "
        "lag judge it all: %s. ",
        r->horizon_why);
  else if (r->vs_ref.n_window >= 2)
    put(w, size, &len,
        "The pointwise metrics (theta, contact point and phase at equal times) judge it to t = "
        "%g s, where the spread of its early error reaches the motion's size, and the turning "
        "lag and timing-insensitive ones (turning points, periods, path shape, drifts) all of "
        "it: %s. ",
        r->pointwise_end, r->horizon_why);
  const int m = dv_run_deciding_metric(r);
  char plus[120];
  if (m >= 0) dv_run_excused_words(r, m, plus, sizeof plus);
  if (m >= 0)
    put(w, size, &len, "The limit of %s (%.3g %s): %s%s. ", dv_metric_names[m], r->tolerance[m],
        dv_metric_units[m], r->limit_why[m], plus);
  else if (r->nfailures)
    put(w, size, &len, "%s. ", r->failures[0]);
  if (r->event.judged)
    put(w, size, &len, "Lying down: %s: %s.",
        r->event.agrees ? "as the reference does" : r->event.why, r->event.note);
  while (len > 0 && w[len - 1] == ' ') w[--len] = '\0';
  for (char *p = w; *p; p++)
    if (*p == '\n' || *p == '\r') *p = ' ';
}

void dv_run_say_decided(const dv_comparison *c, const dv_traj *ref, const dv_engine_stats *ref_st,
                        double ref_end, dv_engine_result *r) {
  char brief[400], full[400];
  window_end_words(c, ref, ref_st, ref_end, r, brief, full, sizeof full);
  one_line(c, ref, brief, r);
  sentences(c, ref, full, r);
}
