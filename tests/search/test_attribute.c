/* test_attribute: attribution of a contact engine's error.
 *
 * The maths on errors of known form: e(h) = e0 + c h^p splits into a time
 * share c dt^p with order p, whatever e0; a plateau (errors that do not fall
 * with the step) has no order and no time share; the shares always add up to
 * the error. Then the whole pipeline on MuJoCo rolling upright: the exact
 * thin disk has no geometry share, the ellipsoid stand-in has one, and a run
 * that cannot start (C = 0) is an error, not a table of zeros.
 */
#include <math.h>
#include <string.h>

#include "dv_test.h"
#include "dv_engine.h"
#include "search_attribute.h"

/* errors e0 + c h^p at dt, dt/2, dt/4, with c dt^p = 2 e0 */
static dv_attribution_errors model(double e0, double p, double dt) {
  const double c = 2.0 * e0 / pow(dt, p);
  dv_attribution_errors e = {e0 + c * pow(dt, p), e0 + c * pow(dt, p), {0}, 0.5 * e0};
  for (int i = 0; i < 3; i++) e.dt[i] = e0 + c * pow(dt / (1 << i), p);
  return e;
}

/* the shares add up to the error they split */
static void check_sum(const dv_attribution *a, const char *what) {
  CHECK_NEAR(a->geometry + a->time + a->contact + a->rest, a->e.stand_in, 1e-15, what);
}

/* the scenario at path with sets, loaded once, attributed */
static int attribute(dv_scenario *sc, const char *path, const char *const *sets, size_t n,
                     const char *engine, dv_attribution *a, dv_error *err) {
  if (dv_engine_load_scenario(path, sets, n, sc, err)) return DV_EINPUT;
  return dv_search_attribute(sc, engine, a, err);
}

int main(int argc, char **argv) {
  dv_attribution a;
  for (double p = 0.5; p <= 4.0; p *= 2) {
    dv_attribution_errors e = model(3e-4, p, 1e-2);
    dv_search_attribute_split(&e, 0, &a);
    CHECK_NEAR(a.order, p, 1e-9, "order of e0 + c h^p");
    CHECK_NEAR(a.time, 6e-4, 1e-15, "time share is c dt^p");
    CHECK(a.geometry == 0.0, "no stand-in, no geometry share");
    check_sum(&a, "shares add up");
  }
  /* a plateau at the contact's floor: flat errors, and ones that fall by 1% */
  dv_attribution_errors flat = {6e-4, 6e-4, {6e-4, 6e-4, 6e-4}, 1e-4};
  dv_search_attribute_split(&flat, 0, &a);
  CHECK(isnan(a.order) && a.time == 0.0, "flat: no order (%g), no time share (%g)", a.order,
        a.time);
  dv_attribution_errors nearly = {6e-4, 6e-4, {6e-4, 5.97e-4, 5.94e-4}, 1e-4};
  dv_search_attribute_split(&nearly, 0, &a);
  CHECK(isnan(a.order), "errors falling 1%% over dt..dt/4: a plateau, no order (%g)", a.order);
  check_sum(&a, "plateau: shares add up");
  /* a stand-in: geometry is its error minus the thin disk's */
  dv_attribution_errors stand = model(1e-4, 1.0, 1e-3);
  stand.stand_in = 9e-3;
  dv_search_attribute_split(&stand, 1, &a);
  CHECK_NEAR(a.geometry, 9e-3 - stand.thin, 1e-15, "stand-in geometry share");
  check_sum(&a, "stand-in: shares add up");

  if (argc > 1) { /* the pipeline on a scenario: upright rolling */
    static dv_scenario sc;
    const char *thin[] = {"engines.mujoco.timestep=1e-3", "engines.mujoco.solref_timeconst=2e-3"};
    dv_error err = {{0}};
    int status = attribute(&sc, argv[1], thin, 2, "mujoco", &a, &err);
    CHECK(status == 0, "attribute mujoco: %s", err.msg);
    CHECK(!a.has_stand_in && a.geometry == 0.0, "thin disk: geometry share %g", a.geometry);
    check_sum(&a, "mujoco thin: shares add up");
    const char *ellipsoid[] = {thin[0], thin[1], "engines.mujoco.geom=ellipsoid",
                               "engines.mujoco.half_thickness=2e-2"};
    status = attribute(&sc, argv[1], ellipsoid, 4, "mujoco", &a, &err);
    CHECK(status == 0, "attribute mujoco ellipsoid: %s", err.msg);
    /* a 2 cm ellipsoid upright: geometry is 100% of 7.3e-4 rad (diskval attribute
     * scenarios/upright_stable.ini --engine mujoco --set engines.mujoco.geom=ellipsoid
     * --set engines.mujoco.half_thickness=2e-2) */
    CHECK(a.has_stand_in && a.geometry > 0.5 * a.e.stand_in, "ellipsoid: geometry share %g of %g",
          a.geometry, a.e.stand_in);
    const char *no_c[] = {"disk.C=0"};
    status = attribute(&sc, argv[1], no_c, 1, "mujoco", &a, &err);
    printf("C = 0 in MuJoCo: %s\n", err.msg);
    CHECK(status < 0 && strstr(err.msg, "cannot be attributed"),
          "C = 0 in MuJoCo: an error, got %d", status);
    /* a contact so soft that ODE sinks (sank 5 mm at t = 0.03 s: diskval simulate
     * tests/data/short_circle.ini --engine ode --set engines.ode.soft_cfm=0.5 --set
     * engines.ode.soft_erp=0): diverged, never a table of zeros */
    const char *sinks[] = {"engines.ode.soft_cfm=0.5", "engines.ode.soft_erp=0"};
    status = attribute(&sc, argv[1], sinks, 2, "ode", &a, &err);
    printf("ODE sinking: %s\n", err.msg);
    CHECK(status < 0 && strstr(err.msg, "cannot be attributed") && strstr(err.msg, "sank"),
          "ODE sinking: an error saying so, got %d: %s", status, err.msg);
    status = attribute(&sc, argv[1], NULL, 0, "reduced", &a, &err);
    CHECK(status < 0, "the reference has nothing to attribute");
  }
  return TEST_RESULT();
}
