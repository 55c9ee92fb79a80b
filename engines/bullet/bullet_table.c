/* bullet_table: the table dv_engine_bullet, linked in: its settings, what searches and
 * attribution turn, and its calls, which go to its module engine_bullet.so
 * (engine_bullet.cc, opened when it first runs: engine_module.h). C, so that no
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
#include "bullet_settings.h"
/* The error model of engine_scene.h per body: the theta error is first order
 * in the timestep (x10 steps give x10 errors: test_engine_bullet). c is the
 * largest err T^2 / (dt D) measured with diskval compare at dt = 2.5e-5 s on
 * the shipped scenarios ODE's model is fitted on (thin disk, whole validity
 * window, T the shortest time scale, D the duration), btMultiBody /
 * btRigidBody: nonuniform 0.83 / 1.29 (its wobble's phase), euler_disk 0.20,
 * steady_steep 0.16 / 0.45, steady_circle 0.107 / 0.29, fast_spin 0.034,
 * falling 0.011 / 0.011, upright_stable 7.5e-5 / 1.4e-3, with the sequential
 * impulse solver (solver si). The default solver dantzig gives the same theta
 * errors to three digits on each of these scenes (btMultiBody, 2.5e-5 s) and
 * at the same cost per step; where C is small the error was the solver's, not
 * the step's: 10 sequential impulse iterations do not converge on a friction
 * row of tiny effective mass C / r^2 (small_c 4.1e-3 rad with si, 9.6e-5 with
 * dantzig; tiny_c, C = 1e-6 m r^2, diverged with si, 9.6e-5 with dantzig).
 * dantzig slips where the friction demand is near the coefficient: euler_disk
 * (ratio 4.08) errs 0.049 rad at friction 5 and 6, si 2.4e-4; at the
 * scene's friction 10, both 2.4e-4. Cost of a step (compare's
 * wall_per_sim_s over the steps, every scenario above): btMultiBody 1.8 us,
 * btRigidBody 2.4 us. */
#define BULLET_C_MULTI 0.83
#define BULLET_C_RIGID 1.3
#define BULLET_COST_MULTI 1.8e-6
#define BULLET_COST_RIGID 2.4e-6



static const char *const BODIES[] = {"multibody", "rigidbody", NULL};
static const char *const GYROSCOPIC[] = {"implicit_body", "explicit", "off", NULL};
static const char *const GEOMS[] = {"thin", "cylinder", NULL};
static const char *const SOLVERS[] = {"si", "dantzig", "pgs", NULL};

#define AT(field) offsetof(bullet_settings, field)

static const dv_setting_spec KEYS[] = {
    {"timestep", DV_SETTING_REAL, AT(timestep), 0, 0, NAN, 1e-7, 0.1, NULL, NULL, "s",
     "default: from the scene's time scales"},
    {"body", DV_SETTING_CHOICE, AT(body), 0, 0, BODY_MULTI, 0, 1, BODIES, NULL, "",
     "multibody: btMultiBody (Featherstone) floating base; rigidbody: btRigidBody"},
    {"solver_iterations", DV_SETTING_INT, AT(solver_iterations), 0, 0, 10, 1, 100000, NULL, NULL,
     "", "iterations of the si and pgs solvers (dantzig solves the LCP exactly)"},
    {"friction", DV_SETTING_REAL, AT(friction), 0, 0, NAN, 0.0, 1e9, NULL, NULL, "",
     "coefficient, in each of two directions"},
    {"cfm", DV_SETTING_REAL, AT(cfm), 0, 0, 0.0, 0.0, 1.0, NULL, NULL, "",
     "the solver's global constraint force mixing: contact softness"},
    {"gyroscopic", DV_SETTING_CHOICE, AT(gyroscopic), 0, 0, GYRO_IMPLICIT_BODY, 0, 2, GYROSCOPIC,
     NULL, "", "rigidbody: Bullet's gyroscopic flag; multibody: its gyroscopic term, on unless off"},
    {"geom", DV_SETTING_CHOICE, AT(geom), 0, 0, 0, 0, 1, GEOMS, NULL, "",
     "thin: the exact disk; cylinder: btCylinderShapeZ of margin 0"},
    {"half_thickness", DV_SETTING_REAL, AT(half_thickness), 0, 0, 0.002, 1e-6, 1.0, NULL, NULL,
     "m", "cylinder half-length (default: [disk] thickness / 2 if > 0)"},
    {"solver", DV_SETTING_CHOICE, AT(solver), 0, 0, SOLVER_DANTZIG, 0, 2, SOLVERS, NULL, "",
     "dantzig: the contact's LCP solved exactly (btMLCPSolver); si: sequential impulse; pgs"},
};

/* the error models (constants above) */
const dv_step_model dv_bullet_models[] = {
    {"bullet", BULLET_C_MULTI, 0.0, NULL, BULLET_COST_MULTI},
    {"bullet", BULLET_C_RIGID, 0.0, NULL, BULLET_COST_RIGID},
};

/* The knobs chosen per scene (engine_choose.h): the body and the step, from
 * each body's model down to half of it. btMultiBody's theta error is 1/3 of
 * btRigidBody's at the same step on most scenes (the steady circle: 1.1e-2
 * against 2.8e-2 rad over 1 s at 1e-3 s), and its step costs less, so it is
 * probed first; btRigidBody stays a candidate for the scenes where the
 * multibody diverges (a tiny C). */
static const dv_engine_knobs KNOBS = {"bullet", "body", dv_bullet_models, 2, 0x3, 1};

static int bullet_check(dv_scenario *sc, void *block, dv_setting_issue *issue);

const dv_shape_keys dv_bullet_shape = {"bullet", "geom", 1, 0, "half_thickness"};

static const dv_settings_section SETTINGS = {"bullet", KEYS, sizeof KEYS / sizeof KEYS[0],
                                      sizeof(bullet_settings), bullet_check};

static int bullet_check(dv_scenario *sc, void *block, dv_setting_issue *issue) {
  bullet_settings *s = (bullet_settings *)(block);
  char why[DV_DERIVED_BYTES];
  const char *keys[8];
  (void)issue;
  const int given = dv_scenario_is_given(sc, "bullet", "body");
  const dv_knob_choice in = {given ? s->body : -1, s->timestep, NAN};
  dv_knob_choice out;
  dv_engine_choose(sc, &dv_engine_bullet, &KNOBS, s->body, &in, &out, why, sizeof why, keys);
  s->body = out.choice;
  s->timestep = out.timestep;
  dv_engine_derive_shape(sc, &dv_bullet_shape, &s->geom, &s->half_thickness, why, sizeof why, keys);
  dv_engine_derive_friction(sc, "bullet", "friction", 1.0, "", &s->friction, why, sizeof why,
                            keys);
  dv_scenario_set_derived(sc, "bullet", keys, why);
  return 0;
}

static const dv_engine_search SEARCH = {"bullet", "body", "timestep", 1e-7, 0.02, NULL};

/* a stiffer contact: a 100x smaller global CFM (0 by default: rigid already) */
static const dv_engine_contact CONTACT = {"geom", "thin", "cfm", 0.01, 0.0, "friction", NULL, 0};

/* the cylinder's half-length where the scene makes Bullet's body a cylinder, else 0 */
static double bullet_half_thickness(const dv_scenario *sc) {
  bullet_settings s = *(const bullet_settings *)(dv_scenario_settings(sc, "bullet"));
  dv_engine_derive_shape(sc, &dv_bullet_shape, &s.geom, &s.half_thickness, NULL, 0, NULL);
  return s.geom == 1 ? s.half_thickness : 0.0;
}

DV_ENGINE_MODULE_PROXY(bullet)

const dv_engine_type dv_engine_bullet = {
    .name = "bullet",
    .description = "Bullet 3.24 contact simulation: the thin disk or a cylinder on a plane (btMultiBody or btRigidBody)",
    .role = DV_ENGINE_CONTACT,
    .settings = &SETTINGS,
    .search = &SEARCH,
    .contact = &CONTACT,
    .half_thickness = bullet_half_thickness,
    DV_ENGINE_MODULE_CALLS(bullet),
};
