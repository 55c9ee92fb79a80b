/* test_probe_only: a load probes the settings of the engines a command runs
 * (dv_engine_choose_only) and of those the scenario names ([scenario]
 * engines), no other: those keep their error model's step and say so.
 * Usage: test_probe_only SCENARIO (a thin disk's scene every engine probes). */
#include <stdio.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_test.h"
#include "engine_choose.h"

static const char *const NOT_RUN = "not probed (the engine is not among those run)";

static void load(const char *path, const char *const *sets, size_t n, dv_scenario *sc) {
  dv_error err = {{0}};
  CHECK(dv_engine_load_scenario(path, sets, n, sc, &err) == DV_OK, "%s", err.msg);
}

int main(int argc, char **argv) {
  if (argc != 2) return fprintf(stderr, "usage: test_probe_only SCENARIO\n"), 2;
  static dv_scenario all, ode, named;
  load(argv[1], NULL, 0, &all); /* nothing chosen: every engine probed */
  const dv_engine_type *const only_ode[] = {dv_engine_find("ode"), NULL};
  dv_engine_choose_only(only_ode);
  load(argv[1], NULL, 0, &ode);
  const char *const sets[] = {"scenario.engines=mujoco"};
  load(argv[1], sets, 1, &named);
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++) {
    if ((*e)->role != DV_ENGINE_CONTACT) continue;
    const char *name = (*e)->name;
    if ((*e)->outside) { /* an adapter runs, and is probed, only where named */
      CHECK(!strstr(dv_scenario_derived(&all, name), "from a probe"), "%s probed unnamed: %s", name,
            dv_scenario_derived(&all, name));
      continue;
    }
    const int is_ode = strcmp(name, "ode") == 0, is_mujoco = strcmp(name, "mujoco") == 0;
    CHECK(strstr(dv_scenario_derived(&all, name), "from a probe"), "every engine: %s: %s", name,
          dv_scenario_derived(&all, name));
    const int probed_ode = strstr(dv_scenario_derived(&ode, name), NOT_RUN) == NULL;
    const int probed_named = strstr(dv_scenario_derived(&named, name), NOT_RUN) == NULL;
    CHECK(probed_ode == is_ode, "ode runs: %s: %s", name, dv_scenario_derived(&ode, name));
    CHECK(probed_named == (is_ode || is_mujoco),
          "ode runs, the scene names mujoco: %s: %s", name, dv_scenario_derived(&named, name));
    /* the engines run choose as they would with every engine probed */
    if (is_ode || is_mujoco)
      CHECK(!strcmp(dv_scenario_derived(&named, name), dv_scenario_derived(&all, name)),
            "%s: the same choice", name);
  }
  dv_engine_choose_only(NULL);
  return TEST_RESULT();
}
