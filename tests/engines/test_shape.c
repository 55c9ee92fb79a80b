/* test_shape: [disk] thickness is the disk's. A coin written once in [disk]
 * gives the contact engines and the matched reference the same body as their
 * stand-in keys written out; the keys, where given, still win; a thin disk
 * stays thin. Usage: test_shape SCENARIO (a steady circle). */
#include <math.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_test.h"
#include "dv_test_traj.h"

#define H 0.002 /* m, half of the coin's 4 mm */

static int load(const char *path, const char *const *sets, size_t n, dv_scenario *sc) {
  dv_error err = {{0}};
  const int status = dv_engine_load_scenario(path, sets, n, sc, &err);
  CHECK(status == DV_OK, "%s", err.msg);
  return status;
}

/* the same trajectory, bit for bit: the same model, the same settings */
static void check_same_run(const dv_engine_type *e, const dv_scenario *a, const dv_scenario *b) {
  static traj ta, tb;
  dv_test_run(e, a, &ta);
  dv_test_run(e, b, &tb);
  CHECK(ta.status >= 0 && tb.status >= 0, "%s: %s %s", e->name, ta.msg, tb.msg);
  CHECK(ta.n == tb.n && ta.n > 10, "%s: %ld and %ld samples", e->name, ta.n, tb.n);
  for (long i = 0; i < ta.n && i < tb.n; i++)
    CHECK(!memcmp(ta.s[i].y, tb.s[i].y, sizeof ta.s[i].y), "%s: sample %ld differs", e->name, i);
}

int main(int argc, char **argv) {
  if (argc != 2) return fprintf(stderr, "usage: test_shape SCENARIO\n"), 2;
  const char *path = argv[1];
  /* a uniform solid cylinder: A = m (3 r^2 + L^2) / 12 (r = 0.1 m, m = 1 kg, L = 4 mm) */
  const double A = (3.0 * 0.01 + 0.004 * 0.004) / 12.0;
  static dv_scenario coin, keys, thin, standin;

  /* the settings a scene chooses are probed against its own reference (the
   * matched one for the coin, none for the keys' stand-in): give them */
#define SAME_SETTINGS \
  "engines.mujoco.integrator=implicit", "engines.mujoco.timestep=2e-5", "engines.ode.timestep=2e-5"
  const char *coin_sets[] = {"scenario.duration=0.2", "disk.thickness=0.004", SAME_SETTINGS};
  if (load(path, coin_sets, 5, &coin)) return TEST_RESULT();
  CHECK_NEAR(coin.disk.A, A, 1e-18, "A of a solid cylinder");
  char given_a[64];
  snprintf(given_a, sizeof given_a, "disk.A=%.17g", coin.disk.A);
  const char *key_sets[] = {"scenario.duration=0.2",
                            given_a,
                            "engines.mujoco.geom=cylinder",
                            "engines.mujoco.half_thickness=0.002",
                            "engines.ode.geom=cylinder",
                            "engines.ode.half_thickness=0.002",
                            "engines.matched.half_thickness=0.002",
                            SAME_SETTINGS};
  if (load(path, key_sets, 10, &keys)) return TEST_RESULT();
  CHECK(coin.disk.A == keys.disk.A, "A %.17g and %.17g", coin.disk.A, keys.disk.A);
  /* the same start: a coin's steady circle is its cylinder's (red_steady_thick.h),
   * the keys' scene only models the cylinder, its disk is thin */
  memcpy(keys.initial, coin.initial, sizeof keys.initial);
  const char *engines[] = {"mujoco", "ode"};
  for (int i = 0; i < 2; i++) {
    const char *e = engines[i];
    CHECK(dv_scenario_get(&coin, e, "geom") == 1.0, "%s: coin geom %g", e,
          dv_scenario_get(&coin, e, "geom"));
    CHECK(dv_scenario_get(&coin, e, "half_thickness") == H, "%s: coin half_thickness %g", e,
          dv_scenario_get(&coin, e, "half_thickness"));
    CHECK(strstr(dv_scenario_derived(&coin, e), "[disk] thickness 0.004 m"), "%s: derived '%s'", e,
          dv_scenario_derived(&coin, e));
    CHECK(dv_engine_half_thickness(dv_engine_find(e), &coin) == H, "%s: compared at h", e);
    check_same_run(dv_engine_find(e), &coin, &keys);
  }
  /* a reason too long for its buffer is cut before a whole character, with an ellipsis */
  static char why[3 * DV_DERIVED_BYTES];
  why[0] = 'x'; /* then thetas, two bytes each: the buffer's last byte falls inside one */
  for (size_t k = 1; k + 2 < sizeof why; k += 2) memcpy(why + k, "\xce\xb8", 2);
  const char *const none[] = {NULL};
  dv_scenario_set_derived(&keys, "ode", none, why);
  const char *cut = dv_scenario_derived(&keys, "ode");
  const size_t len = strlen(cut);
  CHECK(len < DV_DERIVED_BYTES && len + 6 >= DV_DERIVED_BYTES && !strncmp(cut, why, len - 3) &&
            !strcmp(cut + len - 3, "\xe2\x80\xa6") && (len - 3) % 2 == 1,
        "a long reason kept %zu bytes, not cut at a character with an ellipsis", len);
  dv_scenario_set_derived(&keys, "ode", none, "short");
  CHECK(!strcmp(dv_scenario_derived(&keys, "ode"), "short"), "a short reason changed");
  CHECK(dv_scenario_get(&coin, "matched", "half_thickness") == H, "matched: %g",
        dv_scenario_get(&coin, "matched", "half_thickness"));
  check_same_run(&dv_engine_matched, &coin, &keys);

  /* no thickness: the thin disk in every engine, the matched reference is the thin one */
  if (load(path, NULL, 0, &thin)) return TEST_RESULT();
  CHECK(thin.disk.A == 0.25 * (0.1 * 0.1), "thin A %.17g", thin.disk.A);
  for (int i = 0; i < 2; i++) {
    CHECK(dv_scenario_get(&thin, engines[i], "geom") == 0.0, "%s: thin geom", engines[i]);
    CHECK(dv_engine_half_thickness(dv_engine_find(engines[i]), &thin) == 0.0, "%s", engines[i]);
  }
  CHECK(dv_scenario_get(&thin, "matched", "half_thickness") == 0.0, "matched of a thin disk");

  /* the engine keys are stand-ins and win: MuJoCo's flat ellipsoid of the coin's
   * half-thickness, ODE's thin disk, a matched reference of 1 mm */
  const char *standin_sets[] = {"disk.thickness=0.004", "engines.mujoco.geom=ellipsoid",
                                "engines.ode.geom=thin", "engines.matched.half_thickness=0.001"};
  if (load(path, standin_sets, 4, &standin)) return TEST_RESULT();
  CHECK(dv_scenario_get(&standin, "mujoco", "geom") == 2.0, "mujoco: the ellipsoid given");
  CHECK(dv_scenario_get(&standin, "mujoco", "half_thickness") == H, "mujoco: semi-axis");
  CHECK(dv_engine_half_thickness(&dv_engine_mujoco, &standin) == 0.0, "ellipsoid: thin reference");
  CHECK(dv_scenario_get(&standin, "ode", "geom") == 0.0, "ode: the thin disk given");
  CHECK(dv_engine_half_thickness(&dv_engine_ode, &standin) == 0.0, "ode: thin reference");
  CHECK(dv_scenario_get(&standin, "matched", "half_thickness") == 0.001, "matched: given");

  /* the coin's settings are probed against the matched reference; given the
   * thin disk's keys at their default values, the engine's body is the thin
   * disk, probed against the thin reference (one process remembers a scene's
   * choice: the keys given are part of the scene, not only their values) */
  static dv_scenario probed, given;
  const char *probed_sets[] = {"scenario.duration=0.2", "disk.thickness=0.004"};
  const char *given_sets[] = {"scenario.duration=0.2", "disk.thickness=0.004",
                              "engines.mujoco.geom=thin", "engines.mujoco.half_thickness=0.0005"};
  if (load(path, probed_sets, 2, &probed) || load(path, given_sets, 4, &given))
    return TEST_RESULT();
  CHECK(strstr(dv_scenario_derived(&probed, "mujoco"), "from a probe of"), "the coin: '%s'",
        dv_scenario_derived(&probed, "mujoco"));
  CHECK(strcmp(dv_scenario_derived(&probed, "mujoco"), dv_scenario_derived(&given, "mujoco")),
        "the thin disk given took the coin's choice: '%s'", dv_scenario_derived(&given, "mujoco"));
  /* nor is a choice remembered for another start: the same theta on a tighter circle (the
   * rates differ) is probed for itself, its distance rolled in its words */
  static dv_scenario tighter;
  const char *tighter_sets[] = {"scenario.duration=0.2", "disk.thickness=0.004",
                                "initial.steady_circle_radius=0.3"};
  if (load(path, tighter_sets, 3, &tighter)) return TEST_RESULT();
  CHECK(tighter.initial[RED_TH] == probed.initial[RED_TH] &&
            strcmp(dv_scenario_derived(&probed, "mujoco"), dv_scenario_derived(&tighter, "mujoco")),
        "another start took the coin's choice: '%s'", dv_scenario_derived(&tighter, "mujoco"));

  /* a scenario built in code takes the disk's thickness at run time too */
  dv_scenario code = thin;
  code.thickness = 0.004;
  CHECK(dv_engine_half_thickness(&dv_engine_ode, &code) == H, "built in code: ode");
  CHECK(dv_engine_half_thickness(&dv_engine_mujoco, &code) == H, "built in code: mujoco");
  return TEST_RESULT();
}
