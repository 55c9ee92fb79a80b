/* simbody_settings: [engines.simbody], shared by its table (simbody_table.c, linked in) and its
 * module (engine_simbody.cc, opened when it runs): the settings, the error models and
 * the shape keys. */
#ifndef DV_SIMBODY_SETTINGS_H
#define DV_SIMBODY_SETTINGS_H

#include "engine_scene.h"
#include "engine_shape.h"

/* [engines.simbody] */
typedef struct simbody_settings {
  double timestep;  /* s: the fixed step (accuracy 0) */
  int integrator;   /* INTEG_* */
  double accuracy;  /* 0: fixed step; > 0: error-controlled to this accuracy */
  double tolerance; /* constraint tolerance of the projection */
  double
      friction; /* mu of the validity window; NAN: the window's ([engines.matched], else [disk]) */
  int geom;     /* 0 thin, 1 cylinder */
  double half_thickness; /* m, the cylinder's half-length */
} simbody_settings;
enum { GEOM_THIN = 0, GEOM_CYLINDER = 1 };
enum { INTEG_RK3 = 0, INTEG_MERSON = 1 };

extern const dv_step_model dv_simbody_models[];
extern const dv_shape_keys dv_simbody_shape;

#endif
