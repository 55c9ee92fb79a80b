/* engine_generate: real objects and how they are set going, drawn at random
 * from a seed, reproducibly, as scenarios (diskval generate; the property
 * tests of props/).
 *
 * A scene is drawn from (seed, index) alone, so scene 17 of seed 3 is the
 * same whatever else is drawn: radii from a coin (8 mm) to a wheel (0.35 m);
 * thin (two in five) or a cylinder with thickness / (2 r) up to 0.6; moments
 * from an axle-heavy wheel (C 0.02 of 2A) to a hoop (C = 2A), never past the
 * rim (C <= m r^2); friction from 0.3 to 2 ([engines.matched] friction);
 * started on a steady circle of radius 2 r to 100 r (either lean), as a fall
 * from near upright with a slow spin, nutating (spin 1 to 12 sqrt(g/r), a
 * tilt rate), or spinning fast near upright; a start (x, y, phi) anywhere;
 * a duration of 2 to 6 fall periods 2 pi sqrt(r/g) (at most 2.5 s) with 150
 * to 300 samples. Every scene is checked as a load checks a file (the core
 * sections' checks, then every engine's): a draw the checks refuse (a steady
 * circle that cannot exist at that lean) is drawn again, so every scene
 * returned is valid input and its .ini text loads to the same scene.
 */
#ifndef DV_ENGINE_GENERATE_H
#define DV_ENGINE_GENERATE_H

#include <stddef.h>
#include <stdint.h>

#include "dv_error.h"
#include "scenario.h"

/* how a generated scene starts */
typedef enum dv_gen_kind {
  DV_GEN_STEADY = 0,
  DV_GEN_FALL,
  DV_GEN_NUTATION,
  DV_GEN_SPIN
} dv_gen_kind;

extern const char *const dv_gen_kind_names[4]; /* "steady", "fall", "nutation", "spin" */

/* one drawn scene, the values its .ini file gives */
typedef struct dv_gen_scene {
  char name[64]; /* gen-SEED-INDEX */
  dv_gen_kind kind;
  double radius, mass, thickness, A, C, gravity, friction;
  double theta, theta_dot, phi_dot, psi_dot, phi, x, y; /* rates unused for a steady circle */
  double steady_circle_radius;                          /* m, NAN unless kind is steady */
  double duration, output_dt;
} dv_gen_scene;

/* scene index of seed into g and, checked as a load would, into sc (NULL:
 * not wanted); gravity as given (m/s^2, > 0). DV_OK, or DV_EINPUT when no
 * valid scene came of 200 draws (a generator bug) */
int dv_engine_generate(uint64_t seed, size_t index, double gravity, dv_gen_scene *g,
                       dv_scenario *sc, dv_error *err);

/* g into sc, checked as a load checks its file (a steady start without its
 * rates, any other without a circle); DV_OK, or < 0 with err */
int dv_engine_generate_build(const dv_gen_scene *g, dv_scenario *sc, dv_error *err);

/* g as a scenario file's text; the length written (snprintf's) */
int dv_engine_generate_ini(const dv_gen_scene *g, char *buf, size_t size);

#endif
