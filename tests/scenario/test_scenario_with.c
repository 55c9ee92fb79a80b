/* test_scenario_with: a loaded scenario with overrides (dv_scenario_with) is,
 * byte for byte, the scenario a load of its file with those overrides gives:
 * over every shipped scenario and overrides that change what the checks
 * derive (the moments, a steady start's rates, an engine's step and shape).
 * Every file without overrides, and two of the overrides in turn (file k: cases
 * 1 + k mod 10 and 1 + (k + 5) mod 10), so each case meets about 9 files of every
 * kind: all cases on all files took 235 s of a loaded machine's suite for the same code. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_test.h"
#include "engine_choose.h"

#define MAX_OVER 3

static const char *const OVERRIDES[][MAX_OVER] = {
    {NULL}, /* nothing changed: every derived value derived again, the same */
    {"engines.mujoco.timestep=0.0005"},
    {"engines.ode.timestep=1e-4", "engines.mujoco.integrator=euler"},
    {"disk.radius=0.15"},
    {"disk.mass=2", "disk.thickness=0.01"},
    {"initial.theta=1.2"},
    {"engines.reduced.integrator=cvode-bdf", "engines.reduced.rtol=1e-9"},
    {"engines.reduced.max_steps=2000000", "disk.gravity=3"},
    {"tolerance.theta_max_err=0.5", "tolerance.mujoco.path_max_err=2"},
    {"engines.matched.half_thickness=0.002"},
    {"scenario.duration=0.5", "scenario.output_dt=0.05"},
};
#define NCASES (sizeof OVERRIDES / sizeof OVERRIDES[0])

static void check_file(const char *path, size_t k) {
  static dv_scenario base, loaded, with;
  dv_error err = {{0}};
  if (dv_engine_load_scenario(path, NULL, 0, &base, &err)) {
    CHECK(0, "%s", err.msg);
    return;
  }
  for (size_t c = 0; c < NCASES; c++) {
    if (c && c != 1 + k % (NCASES - 1) && c != 1 + (k + (NCASES - 1) / 2) % (NCASES - 1)) continue;
    size_t n = 0;
    while (n < MAX_OVER && OVERRIDES[c][n]) n++;
    dv_error e1 = {{0}}, e2 = {{0}};
    memset(&loaded, 0xa5, sizeof loaded); /* any byte either leaves unset differs */
    memset(&with, 0x5a, sizeof with);
    const int s1 = dv_engine_load_scenario(path, OVERRIDES[c], n, &loaded, &e1);
    const int s2 = dv_scenario_with(&base, OVERRIDES[c], n, &with, &e2);
    CHECK(s1 == s2, "%s, case %zu: load %d (%s), with %d (%s)", path, c, s1, e1.msg, s2, e2.msg);
    if (s1 || s2) continue;
    CHECK(!memcmp(&loaded, &with, sizeof with), "%s, case %zu (%s): not the loaded scenario", path,
          c, n ? OVERRIDES[c][0] : "none");
  }
}

static void check_dir(const char *dir) {
  static size_t files; /* over every directory: the cases turn across them */
  DIR *d = opendir(dir);
  CHECK(d, "cannot read %s", dir);
  for (struct dirent *e; d && (e = readdir(d));) {
    const size_t len = strlen(e->d_name);
    if (len < 5 || strcmp(e->d_name + len - 4, ".ini")) continue;
    char path[2048];
    snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    check_file(path, files++);
  }
  if (d) closedir(d);
}

int main(int argc, char **argv) {
  /* the probe is one code for every engine (engine_choose.c): ODE's, whose step
   * the overrides change, is probed; the others keep their models' steps, derived
   * again as well (two busy cores: every engine probed 484 s, MuJoCo and ODE 169 s) */
  const dv_engine_type *const probed[] = {dv_engine_find("ode"), NULL};
  dv_engine_choose_only(probed);
  for (int i = 1; i < argc; i++) check_dir(argv[i]);
  /* a value the checks refuse is refused, naming the key */
  static dv_scenario base, out;
  dv_error err = {{0}};
  char path[2048];
  snprintf(path, sizeof path, "%s/steady_circle.ini", argc > 1 ? argv[1] : ".");
  if (!dv_engine_load_scenario(path, NULL, 0, &base, &err)) {
    const char *bad[] = {"disk.C=1"};
    CHECK(dv_scenario_with(&base, bad, 1, &out, &err) == DV_EINPUT && strstr(err.msg, "disk.C"),
          "C > 2A: %s", err.msg);
    const char *unknown[] = {"engines.mujoco.warp=1"};
    CHECK(dv_scenario_with(&base, unknown, 1, &out, &err) == DV_EINPUT, "an unknown key accepted");
  }
  return TEST_RESULT();
}
