/* dv_scenario: a scenario file, parsed (inih) and validated.
 *
 * Sections and keys (radians, SI units), see README "Scenario files":
 *   [scenario]   name, description, duration, output_dt, engines
 *   [disk]       radius, mass, A, C, gravity     (A, C default to a uniform disk)
 *   [initial]    theta and phi, psi, x, y, theta_dot, phi_dot, psi_dot
 *                or theta + steady_circle_radius, or theta + steady_phi_dot
 *   [engines.reduced]   integrator, rtol, atol, theta_limit
 *   [tolerance], [tolerance.ENGINE]   limits on the comparison metrics
 * Unknown sections and keys, duplicates, non-numbers and out-of-range values
 * are errors reported as "FILE:LINE: key: what".
 */
#ifndef DV_SCENARIO_H
#define DV_SCENARIO_H

#include <stddef.h>

#include "dv_error.h"
#include "red_disk.h"

#define DV_MAX_TOLERANCES 32

typedef enum dv_init_mode {
  DV_INIT_STATE = 0,     /* the state is given key by key */
  DV_INIT_STEADY_RADIUS, /* theta + steady_circle_radius */
  DV_INIT_STEADY_PHI_DOT /* theta + steady_phi_dot */
} dv_init_mode;

/* one tolerance: metric <= limit, for one engine or all ("") */
typedef struct dv_tolerance {
  char engine[32];
  char metric[32];
  double limit;
} dv_tolerance;

/* the reference solver's settings, [engines.reduced] */
typedef struct dv_reduced_settings {
  char integrator[32]; /* default: red_stepper_default() */
  double rtol;         /* default 1e-12 */
  double atol;         /* default 1e-14 */
  double theta_limit;  /* rad; the run ends where theta < limit or > pi - limit; default 0.01 */
} dv_reduced_settings;

/* [engines.mujoco]: MuJoCo 2.2 settings (defaults: dv_setting_specs) */
typedef struct dv_mujoco_settings {
  double timestep;                               /* s */
  int integrator;                                /* 0 euler, 1 rk4, 2 implicit */
  int cone;                                      /* 0 pyramidal, 1 elliptic */
  double impratio;                               /* frictional-to-normal impedance ratio */
  int solver;                                    /* 0 pgs, 1 cg, 2 newton */
  double tolerance;                              /* solver tolerance */
  int iterations;                                /* solver iterations */
  int noslip_iterations;                         /* noslip solver iterations */
  double solref_timeconst;                       /* s (MuJoCo raises it to >= 2 timestep) */
  double solref_dampratio;                       /* 1: critical damping */
  double solimp_dmin, solimp_dmax, solimp_width; /* impedance, width in m */
  double friction;                               /* sliding friction coefficient */
  int geom;                                      /* 0 cylinder, 1 ellipsoid */
  double half_thickness; /* m: cylinder half-length or ellipsoid semi-axis */
} dv_mujoco_settings;

/* [engines.ode]: ODE 0.16 settings */
typedef struct dv_ode_settings {
  double timestep;           /* s */
  int stepper;               /* 0 dWorldStep, 1 dWorldQuickStep */
  int iterations;            /* QuickStep iterations */
  double erp, cfm;           /* world error reduction, constraint force mixing */
  int friction_model;        /* 0 coefficient (dContactApprox1), 1 force limit (N) */
  double friction;           /* coefficient, or force limit in N */
  double soft_erp, soft_cfm; /* contact softness */
  double half_thickness;     /* m, cylinder half-length */
} dv_ode_settings;

/* [engines.matched]: the reference for the disk an engine simulates */
typedef struct dv_matched_settings {
  double half_thickness; /* m, cylinder half-length matched to the engine's */
  double friction;       /* the validity window ends where |F_h| > friction F_z */
} dv_matched_settings;

/* one engine setting: section, key, where it lives, default, range, doc */
typedef struct dv_setting_spec {
  const char *section;
  const char *key;
  size_t offset;              /* into dv_scenario */
  int is_int;                 /* stored as int (choices and counts) */
  double def, lo, hi;         /* default and inclusive range */
  const char *const *choices; /* NULL-terminated names; value = index */
  const char *doc;            /* units and meaning */
} dv_setting_spec;

extern const dv_setting_spec dv_setting_specs[];
extern const size_t dv_nsetting_specs;

typedef struct dv_scenario {
  char path[1024];
  char name[64];
  char description[256];
  char engines[64]; /* engines a comparison runs, e.g. "mujoco, ode" ("": the default) */
  double duration;  /* s */
  double output_dt; /* s */
  red_disk disk;
  dv_init_mode init_mode;
  double initial[RED_NSTATE]; /* resolved initial state */
  dv_reduced_settings reduced;
  dv_matched_settings matched;
  dv_mujoco_settings mujoco;
  dv_ode_settings ode;
  size_t ntolerances;
  dv_tolerance tolerances[DV_MAX_TOLERANCES];
} dv_scenario;

/* every engine setting and the reference's solver settings at their
 * defaults (for scenarios built in code) */
void dv_scenario_defaults(dv_scenario *sc);

/* parse and validate path; overrides are "section.key=value" strings applied
 * after the file (as from --set). Returns DV_OK or DV_EINPUT with err set. */
int dv_scenario_load(const char *path, const char *const *overrides, size_t noverrides,
                     dv_scenario *sc, dv_error *err);

#endif
