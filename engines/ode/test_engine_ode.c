/* test_engine_ode: the ODE engine's state mapping and its fault handling.
 * (a) reset then advance(0) reads back the state and the energy it was given
 *     (several states, theta on both sides of pi/2); (b) absurd settings end
 *     the run as diverged or lost_contact with a message, and later advance
 *     calls repeat the failure; an ODE assertion comes back as a failed run;
 *     (c) C = 0 and non-finite states are refused. */
#include <math.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_pose.h"
#include "dv_test.h"

/* a uniform disk (r 0.1 m, m 1 kg) with every setting at its default */
static void scenario(dv_scenario *sc) {
  dv_engine_init_scenario(sc);
  sc->disk = red_disk_uniform(0.1, 1.0, 9.81);
  sc->duration = 1.0;
  sc->output_dt = 0.01;
}

/* (a) the mapping round trip through ODE's body state */
static void test_round_trip(void) {
  static const double states[][RED_NSTATE] = {
      {1.0, 0.3, 2.0, -5.0, 0.4, 1.2, 0.1, -0.2},  {M_PI / 2, 0.01, 0.0, 8.5, 0.0, 0.0, 0.0, 0.0},
      {2.2, -0.5, 1.0, 3.0, -2.0, 3.0, 0.5, 0.25}, {0.3, 0.0, 7.0, -1.0, 3.0, -3.0, -1.0, 2.0},
      {2.9, 1.5, -4.0, 0.5, -3.1, 2.5, 0.0, 0.0},
  };
  dv_scenario sc;
  scenario(&sc);
  /* the settings left to the scene derived from the first state, as a load does */
  memcpy(sc.initial, states[0], sizeof sc.initial);
  CHECK(dv_engine_derive_settings(&sc, NULL) == DV_OK, "derive settings");
  /* the body's geometry: the thin disk by default, a cylinder with h = 0 */
  const dv_geometry geom = {DV_SHAPE_CYLINDER, sc.disk.r,
                            dv_engine_half_thickness(&dv_engine_ode, &sc)};
  dv_error err = {{0}};
  void *e = dv_engine_ode.alloc(&sc, &err);
  CHECK(e != NULL, "alloc: %s", err.msg);
  if (!e) return;
  for (size_t k = 0; k < sizeof states / sizeof states[0]; k++) {
    const double *y = states[k];
    dv_sample s;
    CHECK(dv_engine_ode.reset(e, y, &err) == DV_OK, "reset %zu: %s", k, err.msg);
    CHECK(dv_engine_ode.advance(e, 0.0, &s, &err) == DV_OK, "advance(0) %zu: %s", k, err.msg);
    for (int i = 0; i < RED_NSTATE; i++) CHECK_NEAR(s.y[i], y[i], 1e-12, "state component");
    dv_pose p;
    dv_pose_from_state(&geom, y, &p);
    CHECK_NEAR(s.energy, dv_pose_energy(&sc.disk, &p), 1e-12, "energy");
    CHECK(s.t == 0.0, "t %g", s.t);
    CHECK(s.penetration < 1e-12, "penetration %g", s.penetration);
    dv_engine_stats st;
    dv_engine_ode.stats(e, &st);
    CHECK(st.steps == 0 && st.outcome == DV_OUTCOME_COMPLETED, "steps %ld", st.steps);
  }
  /* a short normal run keeps rolling */
  dv_sample s;
  CHECK(dv_engine_ode.reset(e, states[0], &err) == DV_OK, "%s", err.msg);
  CHECK(dv_engine_ode.advance(e, 0.05, &s, &err) == DV_OK, "%s", err.msg);
  CHECK(fabs(s.y[RED_TH] - 1.0) < 0.05 && s.contacts >= 1, "theta %g contacts %d", s.y[RED_TH],
        s.contacts);
  dv_engine_stats st;
  dv_engine_ode.stats(e, &st);
  CHECK(st.steps == lround(0.05 / dv_scenario_get(&sc, "ode", "timestep")), "steps %ld", st.steps);
  dv_engine_ode.free(e);
}

/* (b) a huge spin with a 0.05 s step fails inside the run, not the process */
static void test_absurd(void) {
  dv_scenario sc;
  scenario(&sc);
  dv_scenario_set_number(&sc, "ode", "timestep", 0.05, NULL);
  const double y[RED_NSTATE] = {1.0, 5.0, 300.0, -3000.0, 0, 0, 0, 0};
  dv_error err = {{0}};
  void *e = dv_engine_ode.alloc(&sc, &err);
  CHECK(e != NULL, "alloc: %s", err.msg);
  if (!e) return;
  int status = dv_engine_ode.reset(e, y, &err);
  dv_sample s;
  for (int k = 0; status == DV_OK && k <= 1000; k++)
    status = dv_engine_ode.advance(e, 0.01 * k, &s, &err);
  CHECK(status == DV_ENUMERIC, "status %d", status);
  dv_engine_stats st;
  dv_engine_ode.stats(e, &st);
  CHECK(st.outcome == DV_OUTCOME_DIVERGED || st.outcome == DV_OUTCOME_LOST_CONTACT, "outcome %s",
        dv_outcome_name(st.outcome));
  CHECK(st.detail[0] != '\0' && err.msg[0] != '\0', "no message");
  fprintf(stderr, "absurd run: %s (%s)\n", dv_outcome_name(st.outcome), st.detail);
  dv_error again = {{0}};
  CHECK(dv_engine_ode.advance(e, 20.0, &s, &again) == status, "later advance");
  CHECK(again.msg[0] != '\0', "later advance: no message");
  dv_engine_ode.free(e);
}

/* (b') an ODE assertion (a NaN quaternion from a 1e150 rad/s spin) comes back
 * through the error handler as a failed run; the engine refuses further use */
static void test_library_error(void) {
  dv_scenario sc;
  scenario(&sc);
  const double y[RED_NSTATE] = {1.0, 0.0, 1e150, 1e150, 0, 0, 0, 0};
  dv_error err = {{0}};
  void *e = dv_engine_ode.alloc(&sc, &err);
  CHECK(e != NULL, "alloc: %s", err.msg);
  if (!e) return;
  dv_sample s;
  int status = dv_engine_ode.reset(e, y, &err);
  for (int k = 0; status == DV_OK && k <= 100; k++)
    status = dv_engine_ode.advance(e, 0.01 * k, &s, &err);
  dv_engine_stats st;
  dv_engine_ode.stats(e, &st);
  CHECK(status == DV_ENUMERIC && st.outcome == DV_OUTCOME_DIVERGED, "status %d outcome %s", status,
        dv_outcome_name(st.outcome));
  fprintf(stderr, "library error: %s\n", st.detail);
  const double fine[RED_NSTATE] = {1.0, 0, 0, 0, 0, 0, 0, 0};
  if (strstr(st.detail, "ODE")) /* the handler ran (ODE built with its assertions) */
    CHECK(dv_engine_ode.reset(e, fine, &err) < 0, "reset after an ODE error");
  dv_engine_ode.free(e);
}

/* (c) inputs ODE cannot take are refused with a message */
static void test_refused(void) {
  dv_scenario sc;
  scenario(&sc);
  dv_error err = {{0}};
  sc.disk.C = 0.0;
  CHECK(dv_engine_ode.alloc(&sc, &err) == NULL && err.msg[0], "C = 0 accepted");
  scenario(&sc);
  void *e = dv_engine_ode.alloc(&sc, &err);
  CHECK(e != NULL, "alloc: %s", err.msg);
  const double bad[RED_NSTATE] = {1.0, NAN, 0, 0, 0, 0, 0, 0};
  const double huge[RED_NSTATE] = {1.0, 0, 0, 1e200, 0, 0, 0, 0};
  err.msg[0] = '\0';
  CHECK(e && dv_engine_ode.reset(e, bad, &err) < 0 && err.msg[0], "NaN state accepted");
  err.msg[0] = '\0';
  CHECK(e && dv_engine_ode.reset(e, huge, &err) < 0 && err.msg[0], "infinite energy accepted");
  dv_engine_ode.free(e);
  dv_engine_ode.free(NULL);
}

int main(void) {
  test_round_trip();
  test_absurd();
  test_library_error();
  test_refused();
  return TEST_RESULT();
}
