/* engine_scene: the time scales of a scene, from which the contact engines
 * derive the settings a scenario leaves out (their time step, MuJoCo's
 * contact time constant).
 *
 * Every scale is a time in seconds, INFINITY where the scene has none:
 *   spin      2 pi / |psi_dot|            (the initial spin rate)
 *   turning   2 pi / |phi_dot|            (the initial heading rate)
 *   wobble    2 pi / omega: theta's small oscillation about the steady motion
 *             with the scene's integrals f1, f2. A steady start is linearised
 *             where it is (red_linear_stability); any other start about the
 *             minimum of its effective potential U(theta) (red_potential.h)
 *             inside the reachable range of theta, omega^2 = U'' / (A + m r^2).
 *   growth    1 / lambda: the e-folding time of an unstable motion, from the
 *             same linearisation (a steady start with a real eigenvalue; else
 *             the maximum of U when U has no minimum in the range: a fall)
 *   fall      sqrt(r / g)
 *   duration  the scenario's
 * and the shortest of them, with its name. The state is the scenario's
 * initial one; a state the reduced equations cannot take (theta outside
 * (0, pi), a disk built in code before its state is set) has only the
 * scales that need no state (fall, duration).
 */
#ifndef DV_ENGINE_SCENE_H
#define DV_ENGINE_SCENE_H

#include "scenario.h"

typedef enum dv_scale_id {
  DV_SCALE_SPIN = 0,
  DV_SCALE_TURNING,
  DV_SCALE_WOBBLE,
  DV_SCALE_GROWTH,
  DV_SCALE_FALL,
  DV_SCALE_DURATION,
  DV_NSCALES
} dv_scale_id;

/* "spin period", "turning period", "wobble period", "growth time", "fall time", "duration" */
extern const char *const dv_scale_names[DV_NSCALES];

typedef struct dv_scene_scales {
  double t[DV_NSCALES];  /* s, by dv_scale_id; INFINITY: none */
  dv_scale_id shortest;  /* the shortest finite one */
  double theta_range[2]; /* rad, reachable from the start (red_theta_range); NAN when unknown */
  int falls;             /* the range reaches [engines.reduced] theta_limit */
} dv_scene_scales;

/* the time scales of sc's initial state (never fails: a scale that cannot be
 * computed is INFINITY, and the fall time and duration always exist) */
void dv_engine_scene_scales(const dv_scenario *sc, dv_scene_scales *out);

/* Settings derived from the scales. A contact engine's theta error is first
 * order in one step h, its timestep or (MuJoCo) its contact time constant,
 * and grows in proportion to the time simulated (a drift of phase):
 *
 *   theta error ~ c (h / T) (D / T),
 *
 * T the shortest of the scene's own time scales (spin, turning, wobble,
 * growth, fall), D the duration, c each engine's constant, calibrated as the
 * largest over the shipped scenarios (the engine files list the numbers).
 * The step is the h that makes this DV_SCENE_ACCURACY, but
 *  - no shorter than a run can afford: DV_SCENE_WALL_PER_SIM s of wall time
 *    per simulated second and DV_SCENE_WALL_PER_RUN s per run, at the
 *    engine's measured cost of a step, and
 *  - no longer than T / DV_SCENE_STEPS_PER_SCALE: a step that misses the
 *    scene is no use, so this one holds even where it costs more than the cap;
 * then shortened to output_dt / k for a whole k, so every sample falls on a
 * step, and kept inside the key's range. */
#define DV_SCENE_ACCURACY 1e-3       /* rad: theta's distance from the reference over the scene */
#define DV_SCENE_STEPS_PER_SCALE 100 /* steps at least in the shortest time scale */
#define DV_SCENE_WALL_PER_SIM 0.5    /* s of wall time per simulated second at most */
#define DV_SCENE_WALL_PER_RUN 10.0   /* s of wall time per run at most */

/* a contact engine's error model: theta error ~ c (h / T) (D / T) */
typedef struct dv_step_model {
  const char *engine;   /* whose [engines.NAME] keys take the values (kept in their ranges) */
  double c;             /* calibrated constant */
  double soft_steps;    /* > 0: h is the contact time constant, which the library keeps at
                         * soft_steps timesteps or more (MuJoCo: 2); 0: h is the timestep */
  const char *soft_key; /* the time constant's key, when soft_steps > 0 */
  double step_cost;     /* s of wall time one step takes (measured; the cap) */
} dv_step_model;

/* the timestep, and for soft_steps > 0 the contact time constant, of sc under
 * m. A value given (not NAN) is kept, except a timestep longer than
 * output_dt, which becomes output_dt; a NAN one is derived (a time constant:
 * the h above, never under soft_steps timesteps). why (may be NULL): one line
 * naming what was derived or changed and the reason, "" when nothing was;
 * keys (may be NULL, room for 3): the keys derived, NULL-terminated. */
void dv_engine_derive_step(const dv_scenario *sc, const dv_step_model *m, double *timestep,
                           double *softness, char *why, size_t size, const char **keys);

#endif
