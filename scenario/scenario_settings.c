/* dv_settings: every engine setting with its default and range. The
 * defaults are the most accurate affordable settings measured (README,
 * "Engine settings"), not the libraries' own defaults. */
#include <stddef.h>
#include <stdio.h>

#include "scenario.h"
#include "red_solver.h"

static const char *const MJ_INTEGRATORS[] = {"euler", "rk4", "implicit", NULL};
static const char *const MJ_CONES[] = {"pyramidal", "elliptic", NULL};
static const char *const MJ_SOLVERS[] = {"pgs", "cg", "newton", NULL};
static const char *const MJ_GEOMS[] = {"cylinder", "ellipsoid", NULL};
static const char *const ODE_STEPPERS[] = {"step", "quickstep", NULL};
static const char *const ODE_FRICTION[] = {"coefficient", "force_limit", NULL};

#define MJ(field) offsetof(dv_scenario, mujoco.field)
#define ODE(field) offsetof(dv_scenario, ode.field)
#define MATCHED(field) offsetof(dv_scenario, matched.field)

const dv_setting_spec dv_setting_specs[] = {
    {"engines.matched", "half_thickness", MATCHED(half_thickness), 0, 0.002, 0.0, 1.0, NULL,
     "m, half-thickness of the cylinder to match (0: the thin disk)"},
    {"engines.matched", "friction", MATCHED(friction), 0, 2.0, 0.0, 1e6, NULL,
     "friction coefficient that ends the validity window"},

    {"engines.mujoco", "timestep", MJ(timestep), 0, 2e-4, 1e-7, 0.1, NULL, "s"},
    {"engines.mujoco", "integrator", MJ(integrator), 1, 1, 0, 2, MJ_INTEGRATORS, ""},
    {"engines.mujoco", "cone", MJ(cone), 1, 1, 0, 1, MJ_CONES, "friction cone"},
    {"engines.mujoco", "impratio", MJ(impratio), 0, 10.0, 1e-6, 1e6, NULL, ""},
    {"engines.mujoco", "solver", MJ(solver), 1, 2, 0, 2, MJ_SOLVERS, ""},
    {"engines.mujoco", "tolerance", MJ(tolerance), 0, 1e-10, 0.0, 1.0, NULL, "solver tolerance"},
    {"engines.mujoco", "iterations", MJ(iterations), 1, 100, 1, 100000, NULL, "solver"},
    {"engines.mujoco", "noslip_iterations", MJ(noslip_iterations), 1, 0, 0, 100000, NULL, ""},
    {"engines.mujoco", "solref_timeconst", MJ(solref_timeconst), 0, 4e-4, 1e-7, 10.0, NULL,
     "s (raised by MuJoCo to >= 2 timestep)"},
    {"engines.mujoco", "solref_dampratio", MJ(solref_dampratio), 0, 1.0, 0.0, 100.0, NULL, ""},
    {"engines.mujoco", "solimp_dmin", MJ(solimp_dmin), 0, 0.9, 0.0001, 0.9999, NULL, ""},
    {"engines.mujoco", "solimp_dmax", MJ(solimp_dmax), 0, 0.95, 0.0001, 0.9999, NULL, ""},
    {"engines.mujoco", "solimp_width", MJ(solimp_width), 0, 0.001, 0.0, 1.0, NULL, "m"},
    {"engines.mujoco", "friction", MJ(friction), 0, 2.0, 0.0, 1e6, NULL, "sliding coefficient"},
    {"engines.mujoco", "geom", MJ(geom), 1, 1, 0, 1, MJ_GEOMS, "stand-in for the thin disk"},
    {"engines.mujoco", "half_thickness", MJ(half_thickness), 0, 5e-4, 1e-6, 1.0, NULL,
     "m, cylinder half-length or ellipsoid semi-axis"},

    {"engines.ode", "timestep", ODE(timestep), 0, 1e-5, 1e-7, 0.1, NULL, "s"},
    {"engines.ode", "stepper", ODE(stepper), 1, 0, 0, 1, ODE_STEPPERS, ""},
    {"engines.ode", "iterations", ODE(iterations), 1, 50, 1, 100000, NULL, "QuickStep"},
    {"engines.ode", "erp", ODE(erp), 0, 0.2, 0.0, 1.0, NULL,
     "world ERP (inert: only contact joints)"},
    {"engines.ode", "cfm", ODE(cfm), 0, 1e-10, 0.0, 1.0, NULL,
     "world CFM (inert: only contact joints)"},
    {"engines.ode", "friction_model", ODE(friction_model), 1, 0, 0, 1, ODE_FRICTION,
     "coefficient: dContactApprox1"},
    {"engines.ode", "friction", ODE(friction), 0, 5.0, 0.0, 1e9, NULL, "coefficient, or N"},
    {"engines.ode", "soft_erp", ODE(soft_erp), 0, 0.2, 0.0, 1.0, NULL, "contact"},
    {"engines.ode", "soft_cfm", ODE(soft_cfm), 0, 1e-8, 0.0, 1.0, NULL, "contact"},
    {"engines.ode", "half_thickness", ODE(half_thickness), 0, 0.002, 1e-6, 1.0, NULL,
     "m, cylinder half-length"},
};

const size_t dv_nsetting_specs = sizeof dv_setting_specs / sizeof dv_setting_specs[0];

void dv_scenario_defaults(dv_scenario *sc) {
  for (size_t i = 0; i < dv_nsetting_specs; i++) {
    char *field = (char *)sc + dv_setting_specs[i].offset;
    if (dv_setting_specs[i].is_int)
      *(int *)field = (int)dv_setting_specs[i].def;
    else
      *(double *)field = dv_setting_specs[i].def;
  }
  snprintf(sc->reduced.integrator, sizeof sc->reduced.integrator, "%s",
           red_stepper_default()->name);
  sc->reduced.rtol = 1e-12;
  sc->reduced.atol = 1e-14;
  sc->reduced.theta_limit = 0.01;
}
