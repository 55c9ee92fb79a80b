/* test_lying_down: a thick disk lies down at [engines.reduced] theta_limit in
 * every engine, as the same event in the same words.
 *
 * A cylinder of radius r and half-thickness h leaning at theta in (0, pi/2)
 * has one lowest point, the lower face's rim corner: the lower face's other
 * points are up to 2 r sin(theta) higher, the upper face's corner 2 h
 * cos(theta) higher. Its face reaches the ground only at theta = 0, where
 * engines read n.z = 1. So the rim-corner model (red_rolling.h) holds all
 * the way down and a falling cylinder lies down at theta_limit like the thin
 * disk; atan(h/r) is the tilt from upright inside which it rocks back, and
 * the elevation of its contact vector lying flat, not a floor on theta.
 * Checked on a US quarter (h/r 0.072) and a hockey puck (h/r 1/3, atan 0.32
 * rad): ODE's, MuJoCo's and Bullet's cylinders and the matched reference each end at
 * the lower limit, below atan(h/r), at the same time within their steps, and
 * every engine's outcome names the limit and the time in the same words.
 * Usage: test_lying_down SCENARIO (tests/data/coin_falls_flat.ini). */
#include <math.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_reference.h"
#include "dv_test.h"
#include "dv_test_traj.h"

static traj runs[5];

/* one body falling flat: every engine against the matched reference */
static void check_body(const char *what, const dv_scenario *sc) {
  const double limit = dv_reference_settings(sc)->theta_limit;
  const double h = 0.5 * sc->thickness, corner = atan(h / sc->disk.r);
  const dv_engine_type *engines[] = {&dv_engine_matched, &dv_engine_ode, &dv_engine_mujoco,
                                     &dv_engine_bullet, &dv_engine_reduced};
  double t_matched = NAN;
  CHECK(corner > 5.0 * limit, "%s: atan(h/r) %g is not far above the limit %g", what, corner,
        limit);
  for (int i = 0; i < 5; i++) {
    const dv_engine_type *e = engines[i];
    traj *tr = &runs[i];
    dv_test_run(e, sc, tr);
    CHECK(
        tr->status == DV_EVENT && tr->stats.outcome == DV_OUTCOME_EVENT && tr->stats.lay_down == -1,
        "%s: %s: status %d, outcome %d, lay_down %d: %s %s", what, e->name, tr->status,
        tr->stats.outcome, tr->stats.lay_down, tr->stats.detail, tr->msg);
    if (tr->n < 2) continue;
    const dv_sample *last = &tr->s[tr->n - 1];
    /* the same event in the same words: the limit and the time it was reached */
    char want[sizeof tr->stats.detail];
    dv_engine_limit_detail(1, limit, last->t, want, sizeof want);
    CHECK(strcmp(tr->stats.detail, want) == 0, "%s: %s: detail '%s', want '%s'", what, e->name,
          tr->stats.detail, want);
    if (e == &dv_engine_reduced) continue; /* the thin disk: a different body, words only */
    const double th = last->y[RED_TH];
    if (e == &dv_engine_matched) { /* the event itself, found by root finding */
      CHECK_NEAR(th, limit, 1e-12, "matched: theta at its event");
      t_matched = last->t;
      continue;
    }
    /* below atan(h/r): at the limit, less what theta falls in one step at most (measured
     * 0.73 to 0.94 of such a step: ODE's 2.7 and 8.3 us, MuJoCo's 100 and 250 us) */
    const double step = dv_scenario_get(sc, e->name, "timestep");
    const double one_step = fabs(last->y[RED_VTH]) * step;
    printf(
        "%s: %s lies down at t = %.9g s, matched %.9g s (%.2f steps), theta %.6g "
        "(%.3f of a step below the limit)\n",
        what, e->name, last->t, t_matched, (last->t - t_matched) / step, th,
        (limit - th) / one_step);
    CHECK(th <= limit && th >= limit - one_step, "%s: %s: lay down at theta %.6g (a step %.3g)",
          what, e->name, th, one_step);
    /* the engine finds the event at the first step past it: |dt| within two steps
     * (measured: ODE 0.37 and 0.35 of its step, MuJoCo 0.77 and 1.28) */
    CHECK(fabs(last->t - t_matched) <= 2.0 * step, "%s: %s at %.9g s, matched at %.9g s", what,
          e->name, last->t, t_matched);
  }
}

int main(int argc, char **argv) {
  if (argc != 2) return fprintf(stderr, "usage: test_lying_down SCENARIO\n"), 2;
  static dv_scenario quarter, puck;
  dv_error err = {{0}};
  CHECK(dv_engine_load_scenario(argv[1], NULL, 0, &quarter, &err) == DV_OK, "%s", err.msg);
  /* a hockey puck: 76.2 mm across, 25.4 mm thick, 170 g, let go at 0.6 rad */
  const char *puck_sets[] = {"disk.radius=0.0381", "disk.mass=0.17", "disk.thickness=0.0254",
                             "initial.theta=0.6"};
  CHECK(dv_engine_load_scenario(argv[1], puck_sets, 4, &puck, &err) == DV_OK, "%s", err.msg);
  if (dv_test_failures) return TEST_RESULT();
  check_body("quarter", &quarter);
  check_body("puck", &puck);
  return TEST_RESULT();
}
