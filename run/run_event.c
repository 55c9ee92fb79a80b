/* run_event: the lying-down rule (run_event.h). */
#include "run_event.h"

#include <math.h>
#include <stdio.h>

#include "dv_reference.h"

/* a run's end in words: where it lay down, or how far it ran */
static void say_end(const dv_scenario *sc, const dv_run_end *e, char *buf, size_t size) {
  if (e->lay_down)
    dv_engine_limit_detail(e->lay_down < 0, dv_reference_settings(sc)->theta_limit, e->t, buf,
                           size);
  else
    snprintf(buf, size, "did not lie down (ran to t = %g s)", e->t);
}

/* append "; WHO: END" to out */
static void append(const dv_scenario *sc, const char *who, const dv_run_end *e, char *out,
                   size_t size, size_t *len) {
  char end[160];
  say_end(sc, e, end, sizeof end);
  const int n = snprintf(out + *len, size - *len, "%s%s: %s", *len ? "; " : "", who, end);
  if (n > 0) *len += (size_t)n < size - *len ? (size_t)n : size - 1 - *len;
}

void dv_run_event_judge(const dv_scenario *sc, const char *engine_name, const dv_run_end *engine,
                        const dv_run_end *ref, const dv_run_end nudged[2], double valid_end,
                        dv_event_verdict *out) {
  const double dt = sc->output_dt;
  const double ref_stop = fmin(ref->t, valid_end);
  const int engine_in = engine->lay_down && engine->t < ref_stop - 0.5 * dt;
  const int ref_in = ref->lay_down && ref->t <= valid_end + 0.5 * dt;
  *out = (dv_event_verdict){.judged = engine_in || ref_in, .agrees = 1, .from = NAN, .to = NAN};
  if (!out->judged) return;
  const int side = engine_in ? engine->lay_down : ref->lay_down;
  /* the times the reference and its nudged runs lie down on that side */
  const dv_run_end *runs[3] = {ref, &nudged[0], &nudged[1]};
  double lo = INFINITY, hi = -INFINITY;
  int all = 1;
  for (int k = 0; k < 3; k++) {
    if (!runs[k]->ran) continue;
    if (runs[k]->lay_down != side) {
      all = 0;
      continue;
    }
    lo = fmin(lo, runs[k]->t);
    hi = fmax(hi, runs[k]->t);
  }
  if (isfinite(lo)) {
    out->from = lo - dt;
    out->to = all ? hi + dt : INFINITY;
  }
  if (engine_in && !isfinite(lo))
    snprintf(out->why, sizeof out->why, "lies down where the reference does not, nudged or not");
  else if (engine_in && engine->t < out->from)
    snprintf(out->why, sizeof out->why, "lies down before the nudged reference allows (t >= %g s)",
             out->from);
  else if (!engine_in && !(engine->t <= out->to))
    snprintf(out->why, sizeof out->why,
             "does not lie down by t = %g s, where the reference does, nudged or not", out->to);
  out->agrees = !out->why[0];
  size_t len = 0;
  char who[64];
  append(sc, engine_name, engine, out->note, sizeof out->note, &len);
  append(sc, "the reference", ref, out->note, sizeof out->note, &len);
  for (int k = 0; k < 2; k++) {
    if (!nudged[k].ran) continue;
    snprintf(who, sizeof who, "nudged by %+g rad", nudged[k].nudge);
    append(sc, who, &nudged[k], out->note, sizeof out->note, &len);
  }
}
