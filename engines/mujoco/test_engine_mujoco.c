/* test_engine_mujoco: the MuJoCo engine's own contract.
 *
 * 1. Mapping: reset to a state (theta on both sides of pi/2, angles beyond
 *    pi), advance(0) without a step: the same state (1e-12), the energy of its
 *    pose (1e-12), a rim point at rest, for each geom (thin, cylinder,
 *    ellipsoid); a flat ellipsoid has the thin disk's energy.
 * 2. Samples land on the step grid.
 * 3. Physics: a steady circle drifts less with a smaller step and stiffer contact.
 * 4. Faults end the run, not the process: NaN state, blow-up, lost contact,
 *    a model MuJoCo refuses; lying down is an event.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_pose.h"
#include "dv_test.h"

static const dv_engine_type *const E = &dv_engine_mujoco;
static const char *const GEOMS[] = {"thin", "cylinder", "ellipsoid"};

/* a uniform disk (r 0.1 m, m 1 kg) with every engine setting at its default */
static dv_scenario base(void) {
  dv_scenario sc;
  dv_engine_init_scenario(&sc);
  sc.duration = 1.0;
  sc.output_dt = 0.01;
  sc.disk = red_disk_uniform(0.1, 1.0, 9.81);
  return sc;
}

/* run sc from y to t_end; the last status, sample and stats */
static int run(const dv_scenario *sc, const double y[RED_NSTATE], double t_end, dv_sample *last,
               dv_engine_stats *st) {
  dv_error err = {{0}};
  void *e = E->alloc(sc, &err);
  if (!e) return DV_ESYSTEM;
  int status = E->reset(e, y, &err);
  for (long k = 0; status == DV_OK && k * sc->output_dt <= t_end + 1e-12; k++)
    status = E->advance(e, k * sc->output_dt, last, &err);
  E->stats(e, st);
  if (status < 0) CHECK(err.msg[0], "a failed run without a message");
  E->free(e);
  return status;
}

static void check_round_trip(void) {
  const double states[][RED_NSTATE] = {{1.2, 0.3, 2.0, -8.0, 0.1, 0.4, 0.5, -0.2},
                                       {M_PI / 2 + 0.3, -0.5, -3.0, 12.0, -2.0, 3.0, 0.2, -0.1},
                                       {2.8, 1.0, 4.0, -2.0, 7.0, -9.0, -1.0, 2.0},
                                       {0.4, -2.0, 1.0, 5.0, 3.1, -3.1, 0.0, 0.0}};
  for (int geom = 0; geom < 3; geom++)
    for (size_t k = 0; k < sizeof states / sizeof states[0]; k++) {
      dv_scenario sc = base();
      CHECK(!dv_scenario_set(&sc, "mujoco", "geom", GEOMS[geom], NULL), "geom %s", GEOMS[geom]);
      dv_error err = {{0}};
      dv_sample s;
      dv_engine_stats st;
      void *e = E->alloc(&sc, &err);
      CHECK(e, "alloc: %s", err.msg);
      if (!e) return;
      CHECK(E->reset(e, states[k], &err) == DV_OK, "reset: %s", err.msg);
      CHECK(E->advance(e, 0.0, &s, &err) == DV_OK, "advance(0): %s", err.msg);
      E->stats(e, &st);
      CHECK(st.steps == 0 && s.t == 0.0, "geom %s state %zu: %ld steps before t = 0", GEOMS[geom],
            k, st.steps);
      /* rounding: measured (DV_TEST_MEASURE=1) state 1.1e-14, energy 2.2e-16 J,
       * the rim point's speed 1.4e-15 m/s, depth 6.9e-17 m */
      for (int i = 0; i < RED_NSTATE; i++)
        CHECK_NEAR(s.y[i], states[k][i], 1e-12 * (1 + fabs(states[k][i])), "state component");
      /* the thin disk is a cylinder of half-thickness 0 */
      const dv_geometry g = {geom == 2 ? DV_SHAPE_ELLIPSOID : DV_SHAPE_CYLINDER, sc.disk.r,
                             geom ? dv_scenario_get(&sc, "mujoco", "half_thickness") : 0.0};
      dv_pose pose;
      dv_pose_from_state(&g, states[k], &pose);
      const double energy = dv_pose_energy(&sc.disk, &pose);
      CHECK_NEAR(s.energy, energy, 1e-12 * fabs(energy), "energy of the pose");
      CHECK_NEAR(s.slip, 0.0, 1e-12, "rim point's speed");
      CHECK_NEAR(s.penetration, 0.0, 1e-15, "depth");
      E->free(e);
    }
  /* a flat ellipsoid (e = 1e-6 m) is the thin disk to O(e^2 / r^2) */
  dv_scenario sc = base();
  dv_scenario_set(&sc, "mujoco", "geom", "ellipsoid", NULL);
  dv_scenario_set_number(&sc, "mujoco", "half_thickness", 1e-6, NULL);
  dv_sample s;
  dv_engine_stats st;
  sc.duration = 0.0;
  run(&sc, states[1], 0.0, &s, &st);
  const double thin = red_energy(&sc.disk, states[1]);
  /* measured 1.5e-11 J (7e-12 relative) at h = 1e-6 m */
  CHECK_NEAR(s.energy, thin, 1e-9 * thin, "flat ellipsoid energy vs the thin disk's");
}

static void check_grid(void) {
  dv_scenario sc = base();
  dv_scenario_set_number(&sc, "mujoco", "timestep", 1e-3, NULL);
  const double y[RED_NSTATE] = {1.0, 0, 3.038043841609511, -15.190219208047555, 0, 0, 0, 0};
  dv_sample s;
  dv_engine_stats st;
  CHECK(run(&sc, y, 0.05, &s, &st) == DV_OK, "%s", st.detail);
  CHECK(st.steps == 50 && s.t == 0.05, "%ld steps to t = %g, want 50", st.steps, s.t);
  CHECK(st.contacts_max == 1 && st.warnings == 0, "%d contacts, %ld warnings", st.contacts_max,
        st.warnings);
}

/* largest |theta - 1| over 1 s of a steady circle at theta = 1 (thin ellipsoid) */
static double circle_drift(double dt, double timeconst) {
  dv_scenario sc = base();
  dv_scenario_set(&sc, "mujoco", "geom", "ellipsoid", NULL);
  dv_scenario_set_number(&sc, "mujoco", "timestep", dt, NULL);
  dv_scenario_set_number(&sc, "mujoco", "solref_timeconst", timeconst, NULL);
  const double y[RED_NSTATE] = {1.0, 0, 3.038043841609511, -15.190219208047555, 0, 0, 0, 0};
  dv_error err = {{0}};
  dv_sample s;
  double drift = 0.0;
  void *e = E->alloc(&sc, &err);
  int status = e ? E->reset(e, y, &err) : DV_ESYSTEM;
  for (int k = 0; status == DV_OK && k <= 100; k++) {
    status = E->advance(e, 0.01 * k, &s, &err);
    drift = fmax(drift, fabs(s.y[RED_TH] - 1.0));
  }
  CHECK(status == DV_OK, "steady circle: %s", err.msg);
  E->free(e);
  return drift;
}

static void check_convergence(void) {
  const double coarse = circle_drift(1e-3, 2e-3), fine = circle_drift(2e-4, 4e-4);
  printf("steady circle, 1 s: theta drift %.2e (dt 1e-3) -> %.2e (dt 2e-4)\n", coarse, fine);
  /* measured 4.1e-4 -> 7.6e-5 (0.18; a first-order step 5x smaller: 0.2) */
  CHECK(fine < 0.5 * coarse, "drift %g does not shrink (%g)", fine, coarse);
  CHECK(coarse < 1e-3, "drift %g at dt 1e-3", coarse);
}

static void check_faults(void) {
  dv_sample s;
  dv_engine_stats st;
  dv_error err = {{0}};
  /* a NaN state: reset fails, and so does every later call */
  dv_scenario sc = base();
  const double bad[RED_NSTATE] = {1.0, NAN, 0, 0, 0, 0, 0, 0};
  void *e = E->alloc(&sc, &err);
  CHECK(e && E->reset(e, bad, &err) < 0, "NaN state accepted");
  CHECK(e && E->advance(e, 0.01, &s, &err) < 0, "advance after a failed reset");
  if (e) E->stats(e, &st);
  CHECK(e && st.outcome == DV_OUTCOME_DIVERGED && st.detail[0], "NaN: %s", st.detail);
  E->free(e);
  /* a 50 ms step under a huge spin blows up */
  dv_scenario_set_number(&sc, "mujoco", "timestep", 0.05, NULL);
  sc.output_dt = 0.05;
  const double spin[RED_NSTATE] = {M_PI / 2, 0.01, 0, 1e4, 0, 0, 0, 0};
  CHECK(run(&sc, spin, 1.0, &s, &st) < 0 && st.outcome == DV_OUTCOME_DIVERGED, "blow-up: %s: %s",
        dv_outcome_name(st.outcome), st.detail);
  /* tipping over at 20 rad/s needs r theta_dot^2 = 40 m/s^2 > g of pull:
   * the disk leaves the ground (faster, it lies down before 0.05 s in the air) */
  sc = base();
  const double jump[RED_NSTATE] = {M_PI / 2, 20.0, 0, 0, 0, 0, 0, 0};
  CHECK(run(&sc, jump, 1.0, &s, &st) < 0 && st.outcome == DV_OUTCOME_LOST_CONTACT, "jump: %s: %s",
        dv_outcome_name(st.outcome), st.detail);
  /* C = 0: MuJoCo refuses the model; alloc fails with a message */
  sc = base();
  sc.disk.C = 0.0;
  err.msg[0] = 0;
  e = E->alloc(&sc, &err);
  CHECK(!e && strstr(err.msg, "MuJoCo"), "C = 0: %s", err.msg);
  E->free(e);
  /* falling: lying down ends the run at an event, before the sample time */
  sc = base();
  dv_scenario_set_number(&sc, "reduced", "theta_limit", 0.05, NULL);
  const double fall[RED_NSTATE] = {M_PI / 2 - 0.1, 0, 0, 0, 0, 0, 0, 0};
  CHECK(run(&sc, fall, 3.0, &s, &st) == DV_EVENT && st.outcome == DV_OUTCOME_EVENT, "fall: %s: %s",
        dv_outcome_name(st.outcome), st.detail);
  CHECK(s.y[RED_TH] < 0.05 && s.t < 1.0 && isfinite(s.y[RED_VPH]), "fall: theta %g at t = %g",
        s.y[RED_TH], s.t);
}

int main(void) {
  CHECK(!strncmp(E->version(), "MuJoCo 2.", 9), "version %s", E->version());
  check_round_trip();
  check_grid();
  check_convergence();
  check_faults();
  return TEST_RESULT();
}
