/* mujoco_table: MuJoCo's table dv_engine_mujoco, linked in: its settings, what
 * searches and attribution turn, and its calls, which go to its module
 * engine_mujoco.so (engine_mujoco.c, opened when it first runs: engine_module.h). */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "dv_engine.h"
#include "engine_choose.h"
#include "engine_friction.h"
#include "engine_module.h"
#include "mujoco_settings.h"

static const char *const INTEGRATORS[] = {"euler", "rk4", "implicit", NULL};
const char *const dv_mujoco_cones[] = {"pyramidal", "elliptic", NULL};
static const char *const SOLVERS[] = {"pgs", "cg", "newton", NULL};
static const char *const GEOMS[] = {"thin", "cylinder", "ellipsoid", NULL};

#define AT(field) offsetof(mujoco_settings, field)
#define NUM DV_SETTING_REAL, AT
#define WHOLE DV_SETTING_INT, AT
#define PICK DV_SETTING_CHOICE, AT

static const dv_setting_spec KEYS[] = {
    {"timestep", NUM(timestep), 0, 0, NAN, 1e-7, 0.1, NULL, NULL, "s",
     "default: from the scene's time scales"},
    {"integrator", PICK(integrator), 0, 0, 1, 0, 2, INTEGRATORS, NULL, "", ""},
    {"cone", PICK(cone), 0, 0, 1, 0, 1, dv_mujoco_cones, NULL, "", "friction cone"},
    {"impratio", NUM(impratio), 0, 0, 10.0, 1e-6, 1e6, NULL, NULL, "", ""},
    {"solver", PICK(solver), 0, 0, 2, 0, 2, SOLVERS, NULL, "", ""},
    {"tolerance", NUM(tolerance), 0, 0, 1e-10, 0.0, 1.0, NULL, NULL, "", "solver tolerance"},
    {"iterations", WHOLE(iterations), 0, 0, 100, 1, 100000, NULL, NULL, "", "solver"},
    {"noslip_iterations", WHOLE(noslip_iterations), 0, 0, 0, 0, 100000, NULL, NULL, "", ""},
    {"solref_timeconst", NUM(solref_timeconst), 0, 0, NAN, 1e-7, 10.0, NULL, NULL, "s",
     "raised by MuJoCo to >= 2 timestep; default: from the scene's time scales"},
    {"solref_dampratio", NUM(solref_dampratio), 0, 0, 1.0, 0.0, 100.0, NULL, NULL, "", ""},
    {"solimp_dmin", NUM(solimp_dmin), 0, 0, 0.9, 0.0001, 0.9999, NULL, NULL, "", ""},
    {"solimp_dmax", NUM(solimp_dmax), 0, 0, 0.95, 0.0001, 0.9999, NULL, NULL, "", ""},
    {"solimp_width", NUM(solimp_width), 0, 0, 0.001, 0.0, 1.0, NULL, NULL, "m", ""},
    {"friction", NUM(friction), 0, 0, NAN, 0.0, 1e6, NULL, NULL, "",
     "sliding coefficient (default: [disk] friction)"},
    {"geom", PICK(geom), 0, 0, GEOM_THIN, 0, 2, GEOMS, NULL, "",
     "default: thin, or cylinder for a [disk] thickness > 0; else a stand-in"},
    {"half_thickness", NUM(half_thickness), 0, 0, 5e-4, 1e-6, 1.0, NULL, NULL, "m",
     "cylinder half-length or ellipsoid semi-axis (default: [disk] thickness / 2 if > 0)"},
};

/* The error model of engine_scene.h per integrator, h the contact time
 * constant at 2 timesteps: the theta error is first order in it (RK4's own
 * step error is far below), and MuJoCo raises a shorter one to 2 timesteps.
 * c is the largest err T^2 / (h D) measured on the shipped scenarios (thin
 * disk, whole validity window, T the shortest time scale, D the duration):
 * RK4 at h = 1.25e-4 s (x4 steps give x4 errors: first order): nonuniform
 * 0.0265 (its wobble's phase), euler_disk 0.018, falling 0.0030, steady_steep
 * 0.0018, fast_spin 0.0017, steady_circle 9.0e-4, small_c 6.3e-4,
 * critical_above 4.9e-6, upright_stable 1.0e-6; Euler and implicit 15-60x
 * more (nonuniform 0.41, 0.38; steady_circle 0.054, 0.052). Cost of a step
 * (./run.sh bench): Euler 3 us, RK4 9 us, implicit 4 us. */
const dv_step_model dv_mujoco_models[] = {
    {"mujoco", 0.41, 2.0, "solref_timeconst", 3e-6},
    {"mujoco", 0.027, 2.0, "solref_timeconst", 9e-6},
    {"mujoco", 0.41, 2.0, "solref_timeconst", 4e-6},
};

/* The knobs chosen per scene (engine_choose.h): the integrator, and the step
 * from each integrator's model down to a quarter of it; the cost of a step is
 * the bench's. MuJoCo 2.2's rk4 loses energy on rolling contact steadily, first
 * order in the step but far more than its theta error shows (the saucer of
 * tests/data: 0.33 % a second and path 1.98e-2 m over 3 s at 5e-5 s, 0.16 % and
 * 9.9e-3 m at 2.5e-5 s, theta 4.5e-4 rad), which only a probe sees. */
static const dv_engine_knobs KNOBS = {"mujoco", "integrator", dv_mujoco_models, 3, 0x7, 2};

const dv_shape_keys dv_mujoco_shape = {"mujoco", "geom", GEOM_CYLINDER, GEOM_THIN, "half_thickness"};

/* fill the timestep, time constant and shape s leaves to the scene (the model's
 * step, for a scenario built in code); why as dv_engine_derive_step and
 * dv_engine_derive_shape */
void dv_mujoco_derive(const dv_scenario *sc, mujoco_settings *s, char *why, size_t size,
                      const char **keys) {
  dv_engine_derive_step(sc, &dv_mujoco_models[s->integrator], &s->timestep, &s->solref_timeconst, why, size,
                        keys);
  dv_engine_derive_shape(sc, &dv_mujoco_shape, &s->geom, &s->half_thickness, why, size, keys);
  dv_engine_derive_friction(sc, "mujoco", "friction", 1.0, "", &s->friction, why, size, keys);
}

static int mujoco_check(dv_scenario *sc, void *block, dv_setting_issue *issue) {
  mujoco_settings *s = block;
  char why[DV_DERIVED_BYTES];
  const char *keys[8];
  (void)issue;
  const int given = dv_scenario_is_given(sc, "mujoco", "integrator");
  const dv_knob_choice in = {given ? s->integrator : -1, s->timestep, s->solref_timeconst};
  dv_knob_choice out;
  dv_engine_choose(sc, &dv_engine_mujoco, &KNOBS, s->integrator, &in, &out, why, sizeof why, keys);
  s->integrator = out.choice;
  s->timestep = out.timestep;
  s->solref_timeconst = out.softness;
  if (s->solref_timeconst < 2.0 * s->timestep) { /* what MuJoCo would do unnoticed */
    s->solref_timeconst = 2.0 * s->timestep;
    const size_t used = strlen(why);
    snprintf(why + used, sizeof why - used, "%ssolref_timeconst 2 timesteps, MuJoCo's least",
             used ? "; " : "");
  }
  size_t n = 0;
  while (keys[n]) n++;
  dv_engine_derive_shape(sc, &dv_mujoco_shape, &s->geom, &s->half_thickness, why, sizeof why, keys + n);
  dv_engine_derive_friction(sc, "mujoco", "friction", 1.0, "", &s->friction, why, sizeof why,
                            keys + n);
  dv_scenario_set_derived(sc, "mujoco", keys, why);
  return 0;
}

static const dv_settings_section SETTINGS = {"mujoco", KEYS, sizeof KEYS / sizeof KEYS[0],
                                             sizeof(mujoco_settings), mujoco_check};

static const mujoco_settings *settings_of(const dv_scenario *sc) {
  return dv_scenario_settings(sc, SETTINGS.name);
}

/* the thin disk and the smooth ellipsoid are compared with the thin disk; the cylinder with
 * its match */
static double mujoco_half_thickness(const dv_scenario *sc) {
  mujoco_settings s = *settings_of(sc);
  dv_engine_derive_shape(sc, &dv_mujoco_shape, &s.geom, &s.half_thickness, NULL, 0, NULL);
  return s.geom == GEOM_CYLINDER ? s.half_thickness : 0.0;
}

static const dv_engine_search SEARCH = {"mujoco", "integrator", "timestep", 1e-6, 0.02, NULL};

/* MuJoCo raises the solref time constant to 2 timesteps */
static const dv_engine_contact CONTACT = {"geom", "thin", "solref_timeconst",
                                          0.25,   2.0,    "friction", NULL, 0};
DV_ENGINE_MODULE_PROXY(mujoco)

const dv_engine_type dv_engine_mujoco = {
    .name = "mujoco",
    .description = "MuJoCo 2.2 contact simulation (free body on a plane)",
    .role = DV_ENGINE_CONTACT,
    .settings = &SETTINGS,
    .search = &SEARCH,
    .contact = &CONTACT,
    .half_thickness = mujoco_half_thickness,
    DV_ENGINE_MODULE_CALLS(mujoco),
};
