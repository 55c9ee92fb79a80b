/* test_events: the lying-down rule (run/run_event.h) on made-up run ends.
 *
 * An engine lying down inside the window agrees only where the reference or
 * a nudged run lies down on the same side, and no earlier than the earliest
 * of them less one output interval; an engine that runs on past where all of
 * them lay down (plus one interval) fails; lying down past the validity
 * limit, or with no one lying down, is not judged.
 */
#include <math.h>
#include <string.h>

#include "dv_test.h"
#include "run_event.h"
#include "dv_engine.h"

static dv_scenario sc;

/* the rule on one case: engine and reference ends, nudged lying down at t (0: not) */
static dv_event_verdict judge(double t_eng, int eng_side, double t_ref, int ref_side,
                              double t_minus, double t_plus, double valid_end) {
  const dv_run_end eng = {0, 1, t_eng, eng_side}, ref = {0, 1, t_ref, ref_side};
  const dv_run_end nudged[2] = {{-1e-3, 1, t_minus > 0 ? t_minus : 5.0, t_minus > 0 ? -1 : 0},
                                {1e-3, 1, t_plus > 0 ? t_plus : 5.0, t_plus > 0 ? -1 : 0}};
  dv_event_verdict v;
  dv_run_event_judge(&sc, "engine", &eng, &ref, nudged, valid_end, &v);
  return v;
}

int main(void) {
  dv_engine_init_scenario(&sc);
  sc.duration = 5.0;
  sc.output_dt = 0.01;
  dv_event_verdict v;

  /* the case: the engine lies down at 0.8 s, nobody else does */
  v = judge(0.806869, -1, 5.0, 0, 0, 0, INFINITY);
  CHECK(v.judged && !v.agrees && strstr(v.why, "where the reference does not"), "%s", v.why);
  CHECK(strstr(v.note, "engine: theta reached the lower limit 0.01 rad at t = 0.806869 s") &&
            strstr(v.note, "the reference: did not lie down (ran to t = 5 s)"),
        "both events in words: %s", v.note);

  /* a nudged run lies down at 0.9 s: from 0.89 s the engine agrees, before it fails */
  v = judge(0.895, -1, 5.0, 0, 0.9, 0, INFINITY);
  CHECK(v.judged && v.agrees && fabs(v.from - 0.89) < 1e-12 && isinf(v.to), "0.895: %s", v.why);
  v = judge(0.88, -1, 5.0, 0, 0.9, 0, INFINITY);
  CHECK(!v.agrees && strstr(v.why, "before the nudged reference allows"), "0.88: %s", v.why);

  /* the other side: the upper limit is not the lower one */
  v = judge(0.95, 1, 5.0, 0, 0.9, 0, INFINITY);
  CHECK(!v.agrees, "upper side against a lower lying down: %s", v.note);

  /* all three lie down near 2 s: the engine must too, by 2.03 + 0.01 s */
  v = judge(5.0, 0, 2.0, -1, 1.98, 2.03, INFINITY);
  CHECK(v.judged && !v.agrees && strstr(v.why, "does not lie down by t = 2.04 s"), "%s", v.why);
  v = judge(2.035, -1, 2.0, -1, 1.98, 2.03, INFINITY);
  CHECK(v.agrees && fabs(v.to - 2.04) < 1e-12, "2.035 after the reference's 2.0: %s", v.why);
  /* one nudged run stays up: running on past them is what the nudge allows */
  v = judge(5.0, 0, 2.0, -1, 1.98, 0, INFINITY);
  CHECK(v.agrees && isinf(v.to), "a nudged run stays up: %s", v.why);

  /* past the reference's validity limit nothing is judged */
  v = judge(0.39, -1, 0.392, -1, 0, 0, 0.33);
  CHECK(!v.judged && v.agrees, "past the validity limit: %s", v.note);
  v = judge(5.0, 0, 5.0, 0, 0, 0, INFINITY);
  CHECK(!v.judged && v.agrees, "no one lies down");
  return TEST_RESULT();
}
