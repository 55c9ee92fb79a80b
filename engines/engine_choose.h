/* engine_choose: a contact engine's settings for a scene, chosen from a probe
 * against the reference (DESIGN section 4: from evidence, per scene).
 *
 * Each contact engine declares its knobs (dv_engine_knobs): a choice key (MuJoCo's
 * integrator, ODE's stepper), each value with the error model of engine_scene.h
 * and the counted cost of a step, and the step ladder. The candidates are every
 * value free to choose at its model's step h and at h/2, ..., h/2^halvings (the
 * contact time constant, where the engine has one, at soft_steps timesteps), and
 * their cost is counted: steps over the duration times the cost of a step, never
 * wall time. In order of cost, each candidate runs a probe: the scene's first
 * `window` seconds against the reduced reference, at up to DV_CHOOSE_SAMPLES
 * samples on output_dt's grid (every candidate's step divides output_dt), up
 * to the reference's event or the end of its validity window (where compare
 * stops judging; the run is then projected to there, not to the duration),
 *
 *   window = min(duration, max(DV_CHOOSE_SCALES T, min(duration / DV_CHOOSE_SHARE,
 *                                                       DV_CHOOSE_MAX_WINDOW))),
 *
 * T the shortest of the scene's time scales. Each error (the running max of
 * theta's and of the contact point's distance from the reference's) is
 * projected over the duration D as e(D) = D^p max e(t) / t^p over the window's
 * second half: p = 1 for theta, whose error drifts in proportion to the time
 * (a phase, or the offset a steady energy loss makes), p = 2 for the path,
 * whose heading error integrates theta's (saucer, implicit at 8e-6 s: path
 * 1.2e-5, 1.6e-5, 1.2e-4, 4.9e-4, 2.0e-3 m at 0.19, 0.38, 0.75, 1.5, 3 s;
 * projected from a probe of 0.75 s: 2.0e-3 m; of 0.375 s, 3.0e-3 m: the early
 * error, a settling of the contact, hides the drift). The first candidate whose projected theta
 * error and path error are both within DV_CHOOSE_MARGIN of the target (theta
 * DV_SCENE_ACCURACY rad, the path DV_SCENE_ACCURACY of the distance the
 * reference rolls, projected the same way) is chosen. Candidates over the cost
 * cap (DV_SCENE_WALL_PER_SIM counted seconds per simulated second and
 * DV_SCENE_WALL_PER_RUN a run, the model's own step always allowed) are not
 * run; where none meets the target, the one with the smallest margin runs and
 * the reason says so. A cylinder (of [disk] thickness or given) is probed
 * against the matched reference of its half-thickness, as compare judges it;
 * its event's sample, off the grid, is not compared. A scene the probe cannot
 * judge (a stand-in no reference models; a reference or engine that cannot
 * run, or leaves the friction cone before 8 samples; a
 * duration over DV_CHOOSE_SHARE longest windows, too far to project)
 * keeps the model's step and the choice key's default. The probe is
 * deterministic (the same input gives the same choice) and remembered per
 * process: a scenario derived again (a sweep's points, attribution) probes once.
 */
#ifndef DV_ENGINE_CHOOSE_H
#define DV_ENGINE_CHOOSE_H

#include "engine_scene.h"

#define DV_CHOOSE_MARGIN 0.5       /* a candidate meets the target at half of it, projected */
#define DV_CHOOSE_SCALES 3.0       /* the probe covers at least this many shortest time scales */
#define DV_CHOOSE_SHARE 4.0        /* and at least this share of the duration */
#define DV_CHOOSE_MAX_WINDOW 2.0   /* s: but no longer than this where the scales allow */
#define DV_CHOOSE_SAMPLES 64       /* samples compared over the probe window */
#define DV_CHOOSE_THETA_GROWTH 1.0 /* theta's error projected as t^1 */
#define DV_CHOOSE_PATH_GROWTH 2.0  /* the path's as t^2 */

/* what a contact engine may choose for a scene (declared in its own file) */
typedef struct dv_engine_knobs {
  const char *engine;          /* [engines.NAME] */
  const char *choice_key;      /* e.g. "integrator", "stepper" */
  const dv_step_model *models; /* per value of the choice key, by its index */
  int nchoices;                /* values of the choice key */
  unsigned choosable;          /* bit v: value v is a candidate when the key is free */
  int halvings;                /* step candidates: h, h/2, ..., h/2^halvings */
} dv_engine_knobs;

/* the chosen settings */
typedef struct dv_knob_choice {
  int choice;      /* index of the choice key's value */
  double timestep; /* s */
  double softness; /* s: the contact time constant (models with soft_steps > 0), else NAN */
} dv_knob_choice;

struct dv_engine_type;

/* choose sc's settings for engine. default_choice is the choice key's value
 * where the probe cannot judge the scene; given holds the values given (choice < 0,
 * NAN: free; a given value is never replaced, except a timestep longer than
 * output_dt, as dv_engine_derive_step); out the values to run; why one line
 * (may be NULL) naming what was chosen and why; keys (room for 4, may be NULL)
 * the keys chosen, NULL-terminated. Never fails: a scene the probe cannot
 * judge falls back to the model, and why says so. */
void dv_engine_choose(const dv_scenario *sc, const struct dv_engine_type *engine,
                      const dv_engine_knobs *knobs, int default_choice, const dv_knob_choice *given,
                      dv_knob_choice *out, char *why, size_t size, const char **keys);

/* the engines this process will run (NULL-terminated; NULL: every engine): a
 * scene's settings are probed only for these and for those its [scenario]
 * engines names; any other keeps its error model's step, "not probed (the
 * engine is not among those run)". Commands set it before they load. */
void dv_engine_choose_only(const struct dv_engine_type *const *engines);

/* on 0: no scene's settings are probed from now on, whatever the engines
 * run or a scenario names ("not probed"), as for a load that only checks a
 * file and names it (suite before its scenarios run); 1: probed again (the default) */
void dv_engine_choose_probing(int on);

/* the probes' memory of this process (their choices, per scene and engine),
 * to carry into another: a process that probes under a time limit (a timed
 * task, run_within.h) hands it back, and the caller's own derivation then
 * probes no more. DV_CHOOSE_MEMO_BYTES of buf; restore replaces the memory. */
#define DV_CHOOSE_MEMO_BYTES (32u * (DV_DERIVED_BYTES + 48u) + 16u)
void dv_engine_choose_memo_save(void *buf);
void dv_engine_choose_memo_restore(const void *buf);

#endif
