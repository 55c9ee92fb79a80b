/* ode_table: ODE's table dv_engine_ode, linked in: its settings, what searches
 * and attribution turn, and its calls, which go to its module engine_ode.so
 * (engine_ode.c, opened when it first runs: engine_module.h). */
#include <math.h>
#include <stddef.h>

#include "dv_engine.h"
#include "engine_choose.h"
#include "engine_friction.h"
#include "engine_module.h"
#include "ode_settings.h"

static const char *const STEPPERS[] = {"step", "quickstep", NULL};
static const char *const FRICTION_MODELS[] = {"coefficient", "force_limit", NULL};
static const char *const GEOMS[] = {"thin", "cylinder", NULL};

#define AT(field) offsetof(ode_settings, field)
#define NUM DV_SETTING_REAL, AT
#define WHOLE DV_SETTING_INT, AT
#define PICK DV_SETTING_CHOICE, AT

static const dv_setting_spec KEYS[] = {
    {"timestep", NUM(timestep), 0, 0, NAN, 1e-7, 0.1, NULL, NULL, "s",
     "default: from the scene's time scales"},
    {"stepper", PICK(stepper), 0, 0, 0, 0, 1, STEPPERS, NULL, "", ""},
    {"iterations", WHOLE(iterations), 0, 0, 50, 1, 100000, NULL, NULL, "", "QuickStep"},
    {"erp", NUM(erp), 0, 0, 0.2, 0.0, 1.0, NULL, NULL, "",
     "world ERP (inert: only contact joints)"},
    {"cfm", NUM(cfm), 0, 0, 1e-10, 0.0, 1.0, NULL, NULL, "",
     "world CFM: the contact's friction rows (soft_cfm sets its normal row)"},
    {"friction_model", PICK(friction_model), 0, 0, 0, 0, 1, FRICTION_MODELS, NULL, "",
     "coefficient: dContactApprox1"},
    {"friction", NUM(friction), 0, 0, NAN, 0.0, 1e9, NULL, NULL, "",
     "coefficient, or N (default: [disk] friction, times m g for a force limit)"},
    {"soft_erp", NUM(soft_erp), 0, 0, 0.2, 0.0, 1.0, NULL, NULL, "", "contact"},
    {"soft_cfm", NUM(soft_cfm), 0, 0, 1e-8, 0.0, 1.0, NULL, NULL, "", "contact"},
    {"geom", PICK(geom), 0, 0, 0, 0, 1, GEOMS, NULL, "",
     "thin: the exact disk, one contact (default, or cylinder for a [disk] thickness > 0)"},
    {"half_thickness", NUM(half_thickness), 0, 0, 0.002, 1e-6, 1.0, NULL, NULL, "m",
     "cylinder half-length (default: [disk] thickness / 2 if > 0)"},
};

/* The error model of engine_scene.h per stepper: the theta error is first
 * order in the timestep (x4 steps give x4 errors); contact softness changes
 * nothing measurable (docs/engines.md), so only the step is derived. c is the largest
 * err T^2 / (dt D) measured on the shipped scenarios (thin disk, whole
 * validity window, T the shortest time scale, D the duration) at dt =
 * 6.25e-6 s: nonuniform 2.27 (its wobble's phase), steady_steep 0.74,
 * euler_disk 0.68, steady_circle 0.49, fast_spin 0.25, tiny_c 0.015, falling
 * 0.0094, upright_stable 0.0016; QuickStep the same. Cost of a step
 * (./run.sh bench): dWorldStep 0.85 us, QuickStep 2.5 us. */
const dv_step_model dv_ode_models[] = {
    {"ode", 2.3, 0.0, NULL, 0.85e-6},
    {"ode", 2.3, 0.0, NULL, 2.5e-6},
};

/* The knobs chosen per scene (engine_choose.h): the step, from the model's
 * down to half of it, with dWorldStep; QuickStep is declared (attribution turns
 * it) but not a candidate: its errors equal dWorldStep's at 3x the cost. The
 * contact's softness (soft_erp, soft_cfm) is no knob: it changes nothing
 * measurable (the models above). */
static const dv_engine_knobs KNOBS = {"ode", "stepper", dv_ode_models, 2, 0x1, 1};

const dv_shape_keys dv_ode_shape = {"ode", "geom", 1, 0, "half_thickness"};

/* the friction: a coefficient, or a force limit of that coefficient's weight */
void dv_ode_derive_friction(const dv_scenario *sc, ode_settings *s, char *why, size_t size,
                            const char **keys) {
  const int force = s->friction_model == 1;
  dv_engine_derive_friction(sc, "ode", "friction", force ? sc->disk.m * sc->disk.g : 1.0,
                            force ? "N" : "", &s->friction, why, size, keys);
}

static int ode_check(dv_scenario *sc, void *block, dv_setting_issue *issue) {
  ode_settings *s = block;
  char why[DV_DERIVED_BYTES];
  const char *keys[8];
  (void)issue;
  const int given = dv_scenario_is_given(sc, "ode", "stepper");
  const dv_knob_choice in = {given ? s->stepper : -1, s->timestep, NAN};
  dv_knob_choice out;
  dv_engine_choose(sc, &dv_engine_ode, &KNOBS, s->stepper, &in, &out, why, sizeof why, keys);
  s->stepper = out.choice;
  s->timestep = out.timestep;
  dv_engine_derive_shape(sc, &dv_ode_shape, &s->geom, &s->half_thickness, why, sizeof why, keys);
  dv_ode_derive_friction(sc, s, why, sizeof why, keys);
  dv_scenario_set_derived(sc, "ode", keys, why);
  return 0;
}

static const dv_settings_section SETTINGS = {"ode", KEYS, sizeof KEYS / sizeof KEYS[0],
                                             sizeof(ode_settings), ode_check};

/* the thin disk is compared with the thin reference; the cylinder with its match */
static double ode_half_thickness(const dv_scenario *sc) {
  ode_settings s = *(const ode_settings *)dv_scenario_settings(sc, SETTINGS.name);
  dv_engine_derive_shape(sc, &dv_ode_shape, &s.geom, &s.half_thickness, NULL, 0, NULL);
  return s.geom == 1 ? s.half_thickness : 0.0;
}

static const dv_engine_search SEARCH = {"ode", "stepper", "timestep", 1e-7, 0.02, NULL};

/* a stiffer contact: a 100x smaller constraint force mixing (compliance) */
static const dv_engine_contact CONTACT = {"geom", "thin", "soft_cfm", 0.01, 0.0, "friction", NULL, 0};
DV_ENGINE_MODULE_PROXY(ode)

const dv_engine_type dv_engine_ode = {
    .name = "ode",
    .description = "ODE 0.16 contact simulation: a thin disk (or a cylinder) on a plane",
    .role = DV_ENGINE_CONTACT,
    .settings = &SETTINGS,
    .search = &SEARCH,
    .contact = &CONTACT,
    .half_thickness = ode_half_thickness,
    DV_ENGINE_MODULE_CALLS(ode),
};
