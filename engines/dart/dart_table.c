/* dart_table: the table dv_engine_dart, linked in: its settings, what searches and
 * attribution turn, and its calls, which go to its module engine_dart.so
 * (engine_dart.cc, opened when it first runs: engine_module.h). C, so that no
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
#include "dart_settings.h"
/* The error model of engine_scene.h per LCP solver: the theta error is first
 * order in the timestep (half the step, half the error: test_engine_dart). At
 * the same step DART's error is Bullet's btMultiBody's to 3 digits on most
 * shipped scenarios (diskval compare, both at 1e-4 s over the whole window;
 * the same semi-implicit Euler step of one rigid body on a hard contact), so
 * c (the largest err T^2 / (dt D), T the scene's shortest time scale, D the
 * duration) is Bullet's scaled by the measured ratio of their errors. PGS:
 * nonuniform 0.83 (ratio 1.00), euler_disk 0.20 (1.00), steady_steep 0.16
 * (1.00), steady_circle 0.107 (1.00), fast_spin 0.028 (0.81), falling 0.0098
 * (0.89), upright_stable 8.1e-5 (1.08), small_c 0.37 (0.11); tiny_c (C = 1e-6
 * m r^2) is the solver's: PGS does not converge on a friction row of
 * effective mass C / r^2 (0.30 rad, slip 2.7 m/s). Dantzig: the same but
 * small_c 0.082 and tiny_c right (2.0e-3 rad at 1e-4 s), while on the Euler
 * disk it lets the contact slip (1.5 m/s, 0.055 rad at 1e-4 s and 0.052 at
 * 5e-5 s: the solver, not the step). Cost of a step, in the units of the
 * other engines' constants: the user time of diskval simulate on the steady
 * circle at 1e-5 s over 2.2 s less over 0.2 s (200000 steps) is 6.4 us for
 * PGS and 6.6 us for Dantzig (either detector within 10 %), where Bullet's
 * btMultiBody, calibrated at 1.8 us, measured 3.3 us the same way on the same
 * busy cores: scaled by 1.8 / 3.3, PGS 3.5 us, Dantzig 3.6 us. */
#define DART_C_PGS 0.83
#define DART_C_DANTZIG 0.83
#define DART_COST_PGS 3.5e-6
#define DART_COST_DANTZIG 3.6e-6



static const char *const LCPS[] = {"pgs", "dantzig", NULL};
static const char *const DETECTORS[] = {"ode", "bullet", NULL};
static const char *const GEOMS[] = {"thin", "cylinder", NULL};

#define AT(field) offsetof(dart_settings, field)

static const dv_setting_spec KEYS[] = {
    {"timestep", DV_SETTING_REAL, AT(timestep), 0, 0, NAN, 1e-7, 0.1, NULL, NULL, "s",
     "default: from the scene's time scales"},
    {"lcp", DV_SETTING_CHOICE, AT(lcp), 0, 0, LCP_PGS, 0, 1, LCPS, NULL, "",
     "boxed LCP solver: pgs, or dantzig (with PGS as its fallback)"},
    {"detector", DV_SETTING_CHOICE, AT(detector), 0, 0, DETECTOR_ODE, 0, 1, DETECTORS, NULL, "",
     "collision detector: ode (two contacts, double) or bullet (one, single precision)"},
    {"friction", DV_SETTING_REAL, AT(friction), 0, 0, NAN, 0.0, 1e9, NULL, NULL, "",
     "coefficient of the friction pyramid (default: [disk] friction)"},
    {"erp", DV_SETTING_REAL, AT(erp), 0, 0, 0.2, 0.0, 1.0, NULL, NULL, "",
     "error reduction: the share of the penetration corrected per step"},
    {"erv", DV_SETTING_REAL, AT(erv), 0, 0, 1.0, 0.0, 1e3, NULL, NULL, "m/s",
     "the error reduction's largest velocity"},
    {"cfm", DV_SETTING_REAL, AT(cfm), 0, 0, 1e-5, 0.0, 1.0, NULL, NULL, "",
     "constraint force mixing: contact softness"},
    {"geom", DV_SETTING_CHOICE, AT(geom), 0, 0, GEOM_THIN, 0, 1, GEOMS, NULL, "",
     "thin: the exact disk (a cylinder of height 1e-7 r); cylinder: of half_thickness"},
    {"half_thickness", DV_SETTING_REAL, AT(half_thickness), 0, 0, 0.002, 1e-6, 1.0, NULL, NULL, "m",
     "cylinder half-length (default: [disk] thickness / 2 if > 0)"},
};

/* the error models (constants above) */
const dv_step_model dv_dart_models[] = {
    {"dart", DART_C_PGS, 0.0, NULL, DART_COST_PGS},
    {"dart", DART_C_DANTZIG, 0.0, NULL, DART_COST_DANTZIG},
};

/* The knobs chosen per scene (engine_choose.h): the solver and the step, from
 * each solver's model down to half of it. Both are probed: PGS fails a tiny C,
 * Dantzig lets the Euler disk slip (above); PGS where the probe cannot judge. */
static const dv_engine_knobs KNOBS = {"dart", "lcp", dv_dart_models, 2, 0x3, 1};

static int dart_check(dv_scenario *sc, void *block, dv_setting_issue *issue);

const dv_shape_keys dv_dart_shape = {"dart", "geom", GEOM_CYLINDER, GEOM_THIN, "half_thickness"};

static const dv_settings_section SETTINGS = {"dart", KEYS, sizeof KEYS / sizeof KEYS[0],
                                      sizeof(dart_settings), dart_check};

static int dart_check(dv_scenario *sc, void *block, dv_setting_issue *issue) {
  dart_settings *s = (dart_settings *)(block);
  char why[DV_DERIVED_BYTES];
  const char *keys[8];
  const int given = dv_scenario_is_given(sc, "dart", "lcp");
  const dv_knob_choice in = {given ? s->lcp : -1, s->timestep, NAN};
  dv_knob_choice out;
  dv_engine_choose(sc, &dv_engine_dart, &KNOBS, s->lcp, &in, &out, why, sizeof why, keys);
  s->lcp = out.choice;
  s->timestep = out.timestep;
  dv_engine_derive_shape(sc, &dv_dart_shape, &s->geom, &s->half_thickness, why, sizeof why, keys);
  dv_engine_derive_friction(sc, "dart", "friction", 1.0, "", &s->friction, why, sizeof why, keys);
  dv_scenario_set_derived(sc, "dart", keys, why);
  if (s->geom == GEOM_CYLINDER && s->detector == DETECTOR_BULLET) {
    issue->key = "detector";
    snprintf(issue->what, sizeof issue->what,
             "bullet rounds the cylinder's rim corner by its collision margin; a cylinder "
             "(geom cylinder or a [disk] thickness) needs detector ode");
    return -1;
  }
  return 0;
}

static const dv_engine_search SEARCH = {"dart", "lcp", "timestep", 1e-7, 0.02, NULL};

/* a stiffer contact: a 100x smaller CFM */
static const dv_engine_contact CONTACT = {"geom", "thin", "cfm", 0.01, 0.0, "friction", NULL, 0};

/* the half-thickness of the cylinder DART models in sc (0: the thin disk) */
static double dart_half_thickness(const dv_scenario *sc) {
  dart_settings s = *(const dart_settings *)(dv_scenario_settings(sc, "dart"));
  dv_engine_derive_shape(sc, &dv_dart_shape, &s.geom, &s.half_thickness, NULL, 0, NULL);
  return s.geom == GEOM_CYLINDER ? s.half_thickness : 0.0;
}

DV_ENGINE_MODULE_PROXY(dart)

const dv_engine_type dv_engine_dart = {
    .name = "dart",
    .description = "DART 6.12 contact simulation: the thin disk or the scene's cylinder on a plane (FreeJoint, "
    "boxed LCP)",
    .role = DV_ENGINE_CONTACT,
    .settings = &SETTINGS,
    .search = &SEARCH,
    .contact = &CONTACT,
    .half_thickness = dart_half_thickness,
    DV_ENGINE_MODULE_CALLS(dart),
};
