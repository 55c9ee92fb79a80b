/* simbody_table: the table dv_engine_simbody, linked in: its settings, what searches and
 * attribution turn, and its calls, which go to its module engine_simbody.so
 * (engine_simbody.cc, opened when it first runs: engine_module.h). C, so that no
 * C++ is linked above the module. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_reference.h"
#include "engine_choose.h"
#include "engine_friction.h"
#include "engine_module.h"
#include "simbody_settings.h"

/* The error model of engine_scene.h per integrator. engine_scene.h's model
 * is first order (theta error ~ c (h / T) (D / T)) and has no order field;
 * rk3 is third order and rkmerson fourth (test_engine_simbody: halving the
 * step divides theta's error by 8.0 and 15.9; on nonuniform at h = 2e-3 and
 * 1e-3 s, rk3 6.1e-6 and 7.7e-7 rad), so c is measured at the step the
 * model then gives on every shipped scene, T / 100 (the steps-per-scale
 * floor: the fall time 0.101 s / 101 = 1e-3 s on the output grid): the
 * largest err T^2 / (h D) with diskval compare SCENARIO --engines simbody
 * --set engines.simbody.integrator=I --set engines.simbody.timestep=H on
 * the shipped thin-disk scenarios (whole validity window, T the shortest
 * time scale, D the duration compared). rk3 at 1e-3 s: small_c 3.0e-5,
 * tiny_c 3.1e-5, falling 2.2e-6, nonuniform 1.6e-6, upright_unstable
 * 1.1e-6, upright_stable 4e-9, the steady circles 1e-14 (theta held to
 * rounding); rkmerson at 2e-3 s: small_c 9.1e-7, tiny_c 9.2e-7, nonuniform
 * 3.9e-10. A c this small gives a step far longer than T / 100 from the
 * first-order formula, so the floor decides the step; the probe then
 * confirms it. Cost of a step (compare's wall_per_sim_s over the steps per
 * simulated second, nonuniform and steady_steep, every step checking the
 * events and the energy): rk3 8e-5 s (3 stages and a projection), rkmerson
 * 1.7e-4 s (5 stages). */
#define SIMBODY_C_RK3 3.1e-5
#define SIMBODY_C_MERSON 9.2e-7
#define SIMBODY_COST_RK3 8e-5
#define SIMBODY_COST_MERSON 1.7e-4


static const char *const INTEGRATORS[] = {"rk3", "rkmerson", NULL};
static const char *const GEOMS[] = {"thin", "cylinder", NULL};

#define AT(field) offsetof(simbody_settings, field)

static const dv_setting_spec KEYS[] = {
    {"timestep", DV_SETTING_REAL, AT(timestep), 0, 0, NAN, 1e-7, 0.1, NULL, NULL, "s",
     "the fixed step (unused where accuracy > 0); default: from the scene's time scales"},
    {"integrator", DV_SETTING_CHOICE, AT(integrator), 0, 0, INTEG_RK3, 0, 1, INTEGRATORS, NULL, "",
     "explicit Runge-Kutta: rk3 (third order) or rkmerson (Merson, fourth order)"},
    {"accuracy", DV_SETTING_REAL, AT(accuracy), 0, 0, 0.0, 0.0, 0.1, NULL, NULL, "",
     "0: the fixed timestep; > 0: the integrator's own steps, error-controlled to this accuracy"},
    {"constraint_tolerance", DV_SETTING_REAL, AT(tolerance), 0, DV_SETTING_OPEN_LO, 1e-10, 0.0, 0.1,
     NULL, NULL, "",
     "after a step whose no-slip error exceeds it, the integrator projects onto the constraints"},
    {"friction", DV_SETTING_REAL, AT(friction), 0, 0, NAN, 0.0, 1e9, NULL, NULL, "",
     "mu of the validity window (the run ends where |F_h| > mu F_z); default: the window's "
     "([engines.matched], else [disk] friction)"},
    {"geom", DV_SETTING_CHOICE, AT(geom), 0, 0, GEOM_THIN, 0, 1, GEOMS, NULL, "",
     "thin: the constraints hold the rim point P = G + r d; cylinder: the rim corner "
     "G + r d - h sign(n.z) n"},
    {"half_thickness", DV_SETTING_REAL, AT(half_thickness), 0, 0, 0.002, 1e-6, 1.0, NULL, NULL, "m",
     "cylinder half-length h (default: [disk] thickness / 2 if > 0)"},
};

/* the error models (constants above) */
const dv_step_model dv_simbody_models[] = {
    {"simbody", SIMBODY_C_RK3, 0.0, NULL, SIMBODY_COST_RK3},
    {"simbody", SIMBODY_C_MERSON, 0.0, NULL, SIMBODY_COST_MERSON},
};

/* the integrator and the step, chosen per scene from each one's model down to
 * half of it (engine_choose.h); rk3 costs less a step and is probed first */
static const dv_engine_knobs KNOBS = {"simbody", "integrator", dv_simbody_models, 2, 0x3, 1};

static int simbody_check(dv_scenario *sc, void *block, dv_setting_issue *issue);

const dv_shape_keys dv_simbody_shape = {"simbody", "geom", GEOM_CYLINDER, GEOM_THIN, "half_thickness"};

static const dv_settings_section SETTINGS = {"simbody", KEYS, sizeof KEYS / sizeof KEYS[0],
                                      sizeof(simbody_settings), simbody_check};

static int simbody_check(dv_scenario *sc, void *block, dv_setting_issue *issue) {
  simbody_settings *s = (simbody_settings *)(block);
  char why[DV_DERIVED_BYTES];
  const char *keys[8];
  (void)issue;
  const int given = dv_scenario_is_given(sc, "simbody", "integrator");
  const dv_knob_choice in = {given ? s->integrator : -1, s->timestep, NAN};
  dv_knob_choice out;
  dv_engine_choose(sc, &dv_engine_simbody, &KNOBS, s->integrator, &in, &out, why, sizeof why, keys);
  s->integrator = out.choice;
  s->timestep = out.timestep;
  dv_reference_derive_friction(sc, "simbody", &s->friction, why, sizeof why, keys);
  dv_engine_derive_shape(sc, &dv_simbody_shape, &s->geom, &s->half_thickness, why, sizeof why, keys);
  dv_scenario_set_derived(sc, "simbody", keys, why);
  return 0;
}

static const dv_engine_search SEARCH = {"simbody", "integrator", "timestep", 1e-6, 0.02, NULL};

/* no contact softness: the constraint's own slack, its projection tolerance */
static const dv_engine_contact CONTACT = {"geom", "thin", "constraint_tolerance", 0.01, 0.0, "friction", NULL, 0};

/* the half-thickness of the cylinder the chain holds in sc (0: the thin disk) */
static double simbody_half_thickness(const dv_scenario *sc) {
  simbody_settings s =
      *(const simbody_settings *)(dv_scenario_settings(sc, "simbody"));
  dv_engine_derive_shape(sc, &dv_simbody_shape, &s.geom, &s.half_thickness, NULL, 0, NULL);
  return s.geom == GEOM_CYLINDER ? s.half_thickness : 0.0;
}

DV_ENGINE_MODULE_PROXY(simbody)

const dv_engine_type dv_engine_simbody = {
    .name = "simbody",
    .description = "Simbody 3.7 exact constraints: the thin disk or the scene's cylinder (its rim corner) as a "
    "joint chain with no-slip speed couplers "
    "(cannot slip or lose contact; ends at the validity window)",
    .role = DV_ENGINE_CONTACT,
    .settings = &SETTINGS,
    .search = &SEARCH,
    .contact = &CONTACT,
    .half_thickness = simbody_half_thickness,
    DV_ENGINE_MODULE_CALLS(simbody),
};
