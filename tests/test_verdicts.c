/* test_verdicts: verdicts follow from a measurement and a limit, on scenes
 * with no [tolerance] section (run_limits.h, run_horizon.h).
 *
 * Clearly wrong runs fail and name the metric: a coarse ODE step, a very
 * soft MuJoCo contact, a thick ODE cylinder that stays up where the thin
 * disk falls. A right engine on a sensitive fall (a US quarter tilted 0.03
 * rad at 0.3x the critical spin) passes, although its pointwise theta error
 * over the whole window is far above the limit: that part measures timing.
 * f1, f2 along MuJoCo's own states are conserved on a steady circle and
 * drift when the contact slips. A window the reference does not fill is not
 * judged. The numbers in comments are this test's own printout.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_test.h"
#include "run_limits.h"
#include "run_scenario.h"

static const char QUARTER[] = /* tilted 0.03 rad, spin 0.3 x sqrt(g / (3 r)) = 4.93 rad/s */
    "[scenario]\nname = quarter\ndescription = d\nduration = 1.5\noutput_dt = 0.005\n"
    "[disk]\nradius = 0.01213\nmass = 0.00567\n"
    "[initial]\ntheta = 1.5407963267948966\npsi_dot = 4.926\n";
static const char CIRCLE[] =
    "[scenario]\nname = circle\ndescription = d\nduration = 2\noutput_dt = 0.01\n"
    "[disk]\nradius = 0.1\nmass = 1\n[initial]\ntheta = 1.0\nsteady_circle_radius = 0.5\n";
static const char TILTED[] = /* r 0.06 m, 0.02 rad from upright, 0.3x critical spin */
    "[scenario]\nname = tilted\ndescription = d\nduration = 2\noutput_dt = 0.01\n"
    "[disk]\nradius = 0.06\nmass = 1\n[initial]\ntheta = 1.5507963267948966\npsi_dot = 2.215\n";

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
  CHECK(!r->pass && r->verdict == DV_VERDICT_EXCEEDS, "%s: %s", what, dv_run_verdict_name(r->verdict));
  CHECK(names(r, metric), "%s: no failure names %s", what, metric);
  dv_run_comparison_free(&c);
}

int main(void) {
  /* wrong runs, no [tolerance]: each must fail on the metric that shows it */
  const char *coarse[] = {"engines.ode.timestep=0.005"};
  check_wrong(CIRCLE, "ode", coarse, 1, "theta_max_err", "coarse ODE step");
  const char *soft[] = {"engines.mujoco.solref_timeconst=0.2"};
  check_wrong(CIRCLE, "mujoco", soft, 1, "path_", "very soft MuJoCo contact");
  const char *thick[] = {"engines.ode.geom=cylinder", "engines.ode.half_thickness=0.002"};
  check_wrong(TILTED, "ode", thick, 2, "theta_", "ODE cylinder that stays up");

  /* a right engine on a sensitive fall passes; pointwise over the whole
   * window it would not (theta error about 1 rad: the fall comes later) */
  dv_scenario sc;
  dv_comparison c;
  if (!compare(QUARTER, "mujoco", NULL, 0, &sc, &c)) {
    const dv_engine_result *r = &c.r[0];
    dv_metrics whole;
    dv_run_compare(&r->traj, &c.thin, c.thin_valid_end, &whole);
    printf("quarter: %s; horizon %g s; theta_max_err %.3g to the horizon, %.3g over the window; "
           "extrema %.3g; %s\n",
           dv_run_verdict_name(r->verdict), c.horizon, r->vs_ref.value[DV_THETA_MAX_ERR],
           whole.value[DV_THETA_MAX_ERR], r->vs_ref.value[DV_THETA_EXTREMA_ERR], r->decided);
    CHECK(r->pass, "a right MuJoCo on a sensitive fall: %s", r->nfailures ? r->failures[0] : "");
    CHECK(c.horizon < r->vs_ref.t_window, "the fall has a horizon inside the window");
    CHECK(whole.value[DV_THETA_MAX_ERR] > r->tolerance[DV_THETA_MAX_ERR],
          "pointwise over the whole window (%g) would have failed", whole.value[DV_THETA_MAX_ERR]);
    /* past the horizon the drift of E, f1, f2 along MuJoCo's own states judges it */
    CHECK(r->tolerance[DV_ENERGY_DRIFT] > 0 && r->tolerance[DV_INVARIANT_DRIFT] > 0,
          "energy and f1, f2 are judged");
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
  CHECK(drift[0] < DV_LIMIT_INVARIANTS, "rolling: f1, f2 drift %g", drift[0]);
  CHECK(drift[1] > 10 * drift[0] && drift[1] > DV_LIMIT_INVARIANTS,
        "slipping: f1, f2 drift %g, rolling %g", drift[1], drift[0]);

  /* no window: rolling needs more friction than the reference allows from t = 0 */
  const char *frictionless[] = {"engines.matched.friction=0"};
  if (!compare(CIRCLE, "mujoco", frictionless, 1, &sc, &c)) {
    const dv_engine_result *r = &c.r[0];
    printf("friction 0: %s: %s\n", dv_run_verdict_name(r->verdict), r->nfailures ? r->failures[0] : "");
    CHECK(!r->pass && r->verdict == DV_VERDICT_OUTSIDE_VALIDITY, "empty window: %s",
          dv_run_verdict_name(r->verdict));
    dv_run_comparison_free(&c);
  }
  return TEST_RESULT();
}
