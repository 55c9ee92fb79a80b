/* mujoco_settings: [engines.mujoco], shared by its table (mujoco_table.c, linked in) and its
 * module (engine_mujoco, opened when it runs): the settings, the error models and
 * the shape keys. */
#ifndef DV_MUJOCO_SETTINGS_H
#define DV_MUJOCO_SETTINGS_H

#include "engine_scene.h"
#include "engine_shape.h"

/* [engines.mujoco]: the defaults are the most accurate affordable settings
 * measured (docs/engines.md), not MuJoCo's own; the timestep and
 * the contact time constant follow from the scene (MODELS below) */
typedef struct mujoco_settings {
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
  int geom;                                      /* GEOM_THIN, GEOM_CYLINDER, GEOM_ELLIPSOID */
  double half_thickness; /* m: cylinder half-length or ellipsoid semi-axis (not the thin disk's) */
} mujoco_settings;
enum { GEOM_THIN, GEOM_CYLINDER, GEOM_ELLIPSOID }; /* GEOMS' indices */

extern const dv_step_model dv_mujoco_models[];
extern const dv_shape_keys dv_mujoco_shape;
extern const char *const dv_mujoco_cones[]; /* the cone key's choices */

/* fill the timestep, time constant and shape s leaves to the scene (the model's
 * step, for a scenario built in code); why as dv_engine_derive_step and
 * dv_engine_derive_shape */
void dv_mujoco_derive(const dv_scenario *sc, mujoco_settings *s, char *why, size_t size,
                      const char **keys);

#endif
