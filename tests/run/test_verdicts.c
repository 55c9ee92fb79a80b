/* test_verdicts: verdicts follow from a measurement and a limit, on scenes
 * with no [tolerance] section (run_limits.h, run_horizon.h).
 *
 * Clearly wrong runs fail and name the metric: a coarse ODE step, a very
 * soft MuJoCo contact; a thick ODE cylinder stand-in that stays up where the
 * thin disk falls is judged on its own body up to upright, and the thin
 * disk's error shows. The horizon follows the dynamics: a fall amplifies a nudge
 * exponentially, at the upright disk's unstable rate, and a right MuJoCo
 * passes it; issue 24's hoop amplifies it linearly, and MuJoCo's error
 * there is timing (its turns within 1e-3 rad, lagging 0.004 s by 3.5 s):
 * pointwise judging ends where the lag moves theta by the limit and it
 * passes (issue 35, item 6), as does an engine that converges to the
 * reference; a coarse step's early error ends
 * pointwise judging inside the window. f1, f2 along MuJoCo's own states are
 * conserved on a steady circle and drift when the contact slips. A window
 * the reference does not fill is not judged. Every comparison's one-line
 * "decided" starts with its verdict's word and names the metric furthest over
 * (a pass: nearest) its limit, with its value and limit. The numbers in comments are
 * this test's own printout.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_test.h"
#include "run_limits.h"
#include "run_scenario.h"

static const char FALLING[] = /* scenarios/falling.ini: 0.1 rad off upright, no spin */
    "[scenario]\nname = falling\ndescription = d\nduration = 3\noutput_dt = 0.01\n"
    "[disk]\nradius = 0.1\nmass = 1.0\n[initial]\ntheta = 1.4707963267948966\n"
    "[engines.reduced]\ntheta_limit = 0.05\n";
static const char CIRCLE[] =
    "[scenario]\nname = circle\ndescription = d\nduration = 2\noutput_dt = 0.01\n"
    "[disk]\nradius = 0.1\nmass = 1\n[initial]\ntheta = 1.0\nsteady_circle_radius = 0.5\n";
/* issue 24's hoop: it wobbles between theta 0.35 and 1.5 for ever (integrable) */
static const char HOOP[] =
    "[scenario]\nname = wheel_wobble\nduration = 8\noutput_dt = 0.005\n"
    "[disk]\nradius = 0.3\nmass = 0.8\nA = 0.036\nC = 0.072\n[initial]\ntheta = 1.50\npsi_dot = "
    "1.3\n";
static const char TILTED[] = /* r 0.06 m, 0.02 rad from upright, 0.3x critical spin */
    "[scenario]\nname = tilted\ndescription = d\nduration = 2\noutput_dt = 0.01\n"
    "[disk]\nradius = 0.06\nmass = 1\n[initial]\ntheta = 1.5507963267948966\npsi_dot = 2.215\n";

/* metric m of r against its limit: value / limit, a value not measured the
 * furthest over, NAN where m has no limit */
static double margin_of(const dv_engine_result *r, int m) {
  const double v = r->vs_ref.value[m], l = r->tolerance[m];
  if (isnan(l)) return NAN;
  if (isnan(v)) return INFINITY;
  return l > 0 ? v / l : v > 0 ? INFINITY : 0.0;
}

/* printed (two significant digits at least) is value */
static int near(double printed, double value) {
  return isinf(value) ? printed == value : fabs(printed - value) <= 0.05 * fabs(value);
}

/* r's decided (issue 39): one line of at most DV_DECIDED_MAX characters,
 * starting with its verdict's word; a named metric's value and limit are r's,
 * over its limit and the furthest over on a fail, nearest it on a pass */
static void check_decided(const dv_engine_result *r) {
  const char *d = r->decided;
  CHECK(strlen(d) <= DV_DECIDED_MAX && !strchr(d, '\n') && r->decided_why[0],
        "decided is no line of at most %d characters with a why: '%s'", DV_DECIDED_MAX, d);
  const int judged =
      r->verdict != DV_VERDICT_NOT_JUDGED && r->verdict != DV_VERDICT_OUTSIDE_VALIDITY;
  const char *word = !judged ? "not judged: " : r->pass ? "passes: " : "fails: ";
  CHECK(!strncmp(d, word, strlen(word)), "decided does not start with '%s': '%s'", word, d);
  char metric[40], op[3];
  double v, l, furthest = -INFINITY;
  for (int m = 0; m < DV_NMETRICS; m++)
    if (!isnan(margin_of(r, m))) furthest = fmax(furthest, margin_of(r, m));
  char unit[40];
  if (sscanf(d + strlen(word), "%39[a-z_] %lf %39[^<=>]%2[<=>] %lf", metric, &v, unit, op, &l) != 5) {
    CHECK(!r->pass && !(r->verdict == DV_VERDICT_EXCEEDS && furthest > 1 && !r->event.why[0]),
          "decided names no metric, value and limit: '%s'", d);
    return;
  }
  int m = 0;
  while (m < DV_NMETRICS && strcmp(dv_metric_names[m], metric)) m++;
  if (m == DV_NMETRICS) {
    CHECK(0, "decided names no metric: '%s'", d);
    return;
  }
  CHECK(!strncmp(unit, dv_metric_units[m], strlen(dv_metric_units[m])),
        "decided gives %s no unit %s: '%s'", metric, dv_metric_units[m], d);
  CHECK(near(v, r->vs_ref.value[m]) && near(l, r->tolerance[m]),
        "decided prints %g and %g, the metric is %g, its limit %g: '%s'", v, l,
        r->vs_ref.value[m], r->tolerance[m], d);
  CHECK(margin_of(r, m) == furthest && (r->pass ? margin_of(r, m) <= 1 : margin_of(r, m) > 1),
        "decided's %s (%g of its limit) is not the metric %s its limit (%g): '%s'", metric,
        margin_of(r, m), r->pass ? "nearest" : "furthest over", furthest, d);
}

/* compare scene (INI text) with overrides in one engine; the result in c */
static int compare(const char *scene, const char *engine, const char *const *sets, size_t nsets,
                   dv_scenario *sc, dv_comparison *c) {
  char path[] = "/tmp/diskval_verdicts_XXXXXX";
  const int fd = mkstemp(path);
  if (fd < 0 || write(fd, scene, strlen(scene)) != (ssize_t)strlen(scene)) return -1;
  close(fd);
  dv_error err = {{0}};
  int status = dv_engine_load_scenario(path, sets, nsets, sc, &err);
  unlink(path);
  const dv_engine_type *engines[] = {dv_engine_find(engine)};
  if (!status) status = dv_run_scenario(sc, NULL, engines, 1, c, &err);
  CHECK(status == 0, "%s: %s", engine, err.msg);
  if (!status) check_decided(&c->r[0]);
  return status;
}

/* does some failure line name metric */
static int names(const dv_engine_result *r, const char *metric) {
  for (size_t i = 0; i < r->nfailures; i++)
    if (strstr(r->failures[i], metric)) return 1;
  return 0;
}

/* a wrong run fails, and its failures name metric */
static void check_wrong(const char *scene, const char *engine, const char *const *sets,
                        size_t nsets, const char *metric, const char *what) {
  dv_scenario sc;
  dv_comparison c;
  if (compare(scene, engine, sets, nsets, &sc, &c)) return;
  const dv_engine_result *r = &c.r[0];
  printf("%s: %s, %s\n", what, dv_run_verdict_name(r->verdict), r->nfailures ? r->failures[0] : "");
  CHECK(!r->pass && r->verdict == DV_VERDICT_EXCEEDS, "%s: %s", what,
        dv_run_verdict_name(r->verdict));
  CHECK(names(r, metric), "%s: no failure names %s", what, metric);
  dv_run_comparison_free(&c);
}

int main(void) {
  /* wrong runs, no [tolerance]: each must fail on the metric that shows it */
  const char *coarse[] = {"engines.ode.timestep=0.005"};
  check_wrong(CIRCLE, "ode", coarse, 1, "theta_max_err", "coarse ODE step");
  const char *soft[] = {"engines.mujoco.solref_timeconst=0.2"};
  check_wrong(CIRCLE, "mujoco", soft, 1, "path_", "very soft MuJoCo contact");
  /* a 2 mm cylinder stand-in stays up where the thin disk falls: judged on its
   * own body only up to where that body reaches upright (its rim corners
   * switch), said, never against the thin disk; the thin disk's error shows */
  {
    const char *thick[] = {"engines.ode.geom=cylinder", "engines.ode.half_thickness=0.002"};
    dv_scenario sc;
    dv_comparison c;
    if (!compare(TILTED, "ode", thick, 2, &sc, &c)) {
      const dv_engine_result *r = &c.r[0];
      printf("ODE cylinder that stays up: %s, vs thin %.3g rad; %s\n",
             dv_run_verdict_name(r->verdict), r->vs_thin.value[DV_THETA_MAX_ERR], r->reference_note);
      CHECK(r->half_thickness == 0.002 && strstr(r->reference_note, "upright") &&
                r->vs_ref.t_window < r->traj.s[r->traj.n - 1].t,
            "the cylinder's window does not end where its body reaches upright: '%s'",
            r->reference_note);
      CHECK(!(r->vs_thin.value[DV_THETA_MAX_ERR] <= DV_LIMIT_THETA),
            "the thin disk's error does not show: %g", r->vs_thin.value[DV_THETA_MAX_ERR]);
      dv_run_comparison_free(&c);
    }
  }

  /* a right engine on a sensitive fall passes: the fall amplifies a nudge
   * exponentially, e-folding in 0.123 s (measured here) where the upright
   * disk's unstable rate sqrt(m g r / (A + m r^2)) = 8.86 /s gives 0.113 s
   * (the measurement runs into the nonlinear fall: within 15%) */
  dv_scenario sc;
  dv_comparison c;
  if (!compare(FALLING, "mujoco", NULL, 0, &sc, &c)) {
    const dv_engine_result *r = &c.r[0];
    const double efold = 1.0 / sqrt(9.81 * 0.1 / (0.25 * 0.01 + 0.01));
    printf(
        "falling: %s; amplification %s, e-folding %.3g s (linearised %.3g s); horizon %g s; "
        "%s\n",
        dv_run_verdict_name(r->verdict), c.amp.growth, c.amp.efold, efold, r->horizon, r->decided);
    CHECK(r->pass, "a right MuJoCo on a fall: %s", r->nfailures ? r->failures[0] : "");
    CHECK(!strcmp(c.amp.growth, "exponential"), "a fall's amplification: %s", c.amp.growth);
    CHECK(fabs(c.amp.efold / efold - 1.0) < 0.15, "e-folding %g s, linearised %g s", c.amp.efold,
          efold);
    /* past the horizon the drift of E, f1, f2 along MuJoCo's own states judges it */
    CHECK(r->tolerance[DV_ENERGY_DRIFT] > 0 && r->tolerance[DV_INVARIANT_DRIFT] > 0,
          "energy and f1, f2 are judged");
    dv_run_comparison_free(&c);
  }

  /* the hoop: the reference amplifies a nudge linearly (x99 in 8 s, measured
   * here). MuJoCo's early error (1.1e-6 rad) spreads the reference by 1.8e-4
   * rad by 8 s; its own error grows to 0.043 rad, its turns lagging more each
   * period: a drift of its own, judged over the whole window, which it fails
   * (issue 48: the turning lag that once ended its pointwise judging at 3.48
   * s no longer does). Its turning values stay within 2e-3 rad */
  if (!compare(HOOP, "mujoco", NULL, 0, &sc, &c)) {
    const dv_engine_result *r = &c.r[0];
    printf(
        "hoop: %s; amplification %s x%.3g (exponent %.2f); early error %.3g; spread %.3g rad; "
        "theta_max_err %.3g, turning_lag %.3g s, theta_turning_err %.3g\n",
        dv_run_verdict_name(r->verdict), c.amp.growth, c.amp.factor, c.amp.exponent, r->early_err,
        r->excused[DV_THETA_MAX_ERR], r->vs_ref.value[DV_THETA_MAX_ERR],
        r->vs_ref.value[DV_TURNING_LAG], r->vs_ref.value[DV_THETA_TURNING_ERR]);
    CHECK(!strcmp(c.amp.growth, "linear"), "the hoop's amplification: %s", c.amp.growth);
    CHECK(c.amp.factor > 10 && c.amp.factor < 1e3, "x%g in 8 s", c.amp.factor);
    CHECK(isinf(r->horizon) && r->pointwise_end >= r->vs_ref.t_window - 1e-9,
          "pointwise to %g of %g: %s", r->pointwise_end, r->vs_ref.t_window, r->horizon_why);
    CHECK(!r->pass && r->verdict == DV_VERDICT_EXCEEDS, "MuJoCo at defaults: %s",
          r->nfailures ? r->failures[0] : "passes");
    CHECK(r->vs_ref.value[DV_THETA_MAX_ERR] > 0.03 && r->excused[DV_THETA_MAX_ERR] > 0.0 &&
              r->excused[DV_THETA_MAX_ERR] < 1e-3,
          "its whole-window error %g, the spread's excuse %g", r->vs_ref.value[DV_THETA_MAX_ERR],
          r->excused[DV_THETA_MAX_ERR]);
    CHECK(r->vs_ref.value[DV_THETA_TURNING_ERR] < 2e-3, "its turns: %g rad",
          r->vs_ref.value[DV_THETA_TURNING_ERR]);
    dv_run_comparison_free(&c);
  }
  /* an engine shown to converge to the reference (matched at h = 0: 2e-13
   * against reduced, test_formulations) passes the hoop over the whole window */
  if (!compare(HOOP, "matched", NULL, 0, &sc, &c)) {
    const dv_engine_result *r = &c.r[0];
    printf("hoop, matched: %s, theta_max_err %.3g\n", dv_run_verdict_name(r->verdict),
           r->vs_ref.value[DV_THETA_MAX_ERR]);
    CHECK(r->pass && isinf(r->horizon), "matched on the hoop: %s",
          r->nfailures ? r->failures[0] : "");
    dv_run_comparison_free(&c);
  }
  /* a coarse ODE step on the fall: its early error (capped at the limit) is
   * excused only as the scene spreads it; the rest is its own, judged to the
   * window's end unless the spread reaches the motion's size first */
  const char *coarse_fall[] = {"engines.ode.timestep=0.005"};
  if (!compare(FALLING, "ode", coarse_fall, 1, &sc, &c)) {
    const dv_engine_result *r = &c.r[0];
    printf("falling, coarse ODE: early error %.3g, pointwise to %g s, window %g s, spread %.3g, "
           "theta_max_err %.3g: %s\n",
           r->early_err, r->pointwise_end, r->vs_ref.t_window, r->excused[DV_THETA_MAX_ERR],
           r->vs_ref.value[DV_THETA_MAX_ERR], r->decided);
    CHECK(r->pointwise_end >= r->early_until &&
              (isinf(r->horizon) ? r->pointwise_end >= r->vs_ref.t_window - 1e-9
                                 : r->unpredictable_by == 2 ||
                                       r->shadow_at_end[0] >= r->motion_size[0] ||
                                       r->shadow_at_end[1] >= r->motion_size[1]),
          "pointwise to %g, window %g: %s", r->pointwise_end, r->vs_ref.t_window, r->horizon_why);
    dv_run_comparison_free(&c);
  }

  /* f1, f2 along MuJoCo's states: conserved while rolling, drifting when it slips */
  double drift[2];
  const char *slips[] = {"engines.mujoco.friction=0.05"};
  for (int k = 0; k < 2; k++) {
    if (compare(CIRCLE, "mujoco", slips, (size_t)k, &sc, &c)) return TEST_RESULT();
    drift[k] = c.r[0].vs_ref.value[DV_INVARIANT_DRIFT];
    dv_run_comparison_free(&c);
  }
  printf("invariant drift on a steady circle: %.3g rolling, %.3g with friction 0.05\n", drift[0],
         drift[1]);
  /* measured 2.5e-4 rolling and 0.98 slipping (3900x): a slip is 100x at least */
  CHECK(drift[0] < DV_LIMIT_INVARIANTS, "rolling: f1, f2 drift %g", drift[0]);
  CHECK(drift[1] > 100 * drift[0] && drift[1] > DV_LIMIT_INVARIANTS,
        "slipping: f1, f2 drift %g, rolling %g", drift[1], drift[0]);

  /* no window: rolling needs more friction than the reference allows from t = 0 */
  const char *frictionless[] = {"engines.matched.friction=0"};
  if (!compare(CIRCLE, "mujoco", frictionless, 1, &sc, &c)) {
    const dv_engine_result *r = &c.r[0];
    printf("friction 0: %s: %s\n", dv_run_verdict_name(r->verdict),
           r->nfailures ? r->failures[0] : "");
    CHECK(!r->pass && r->verdict == DV_VERDICT_OUTSIDE_VALIDITY, "empty window: %s",
          dv_run_verdict_name(r->verdict));
    dv_run_comparison_free(&c);
  }
  return TEST_RESULT();
}
