/* dv_scenario: a scenario file, parsed (inih) and validated.
 *
 * Sections and keys (radians, SI units), see README "Scenario files":
 *   [scenario]   name, description, duration, output_dt
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

typedef struct dv_scenario {
  char path[1024];
  char name[64];
  char description[256];
  double duration;  /* s */
  double output_dt; /* s */
  red_disk disk;
  dv_init_mode init_mode;
  double initial[RED_NSTATE]; /* resolved initial state */
  dv_reduced_settings reduced;
  size_t ntolerances;
  dv_tolerance tolerances[DV_MAX_TOLERANCES];
} dv_scenario;

/* parse and validate path; overrides are "section.key=value" strings applied
 * after the file (as from --set). Returns DV_OK or DV_EINPUT with err set. */
int dv_scenario_load(const char *path, const char *const *overrides, size_t noverrides,
                     dv_scenario *sc, dv_error *err);

#endif
