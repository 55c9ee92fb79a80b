/* bullet_settings: [engines.bullet], shared by its table (bullet_table.c, linked in) and its
 * module (engine_bullet.cc, opened when it runs): the settings, the error models and
 * the shape keys. */
#ifndef DV_BULLET_SETTINGS_H
#define DV_BULLET_SETTINGS_H

#include "engine_scene.h"
#include "engine_shape.h"

/* [engines.bullet] */
typedef struct bullet_settings {
  double timestep;       /* s */
  int body;              /* 0 btMultiBody, 1 btRigidBody */
  int solver_iterations; /* sequential impulse iterations */
  double friction;       /* coefficient */
  double cfm;            /* the solver's global constraint force mixing */
  int gyroscopic;        /* 0 implicit_body, 1 explicit, 2 off */
  int geom;              /* 0 thin, 1 cylinder */
  double half_thickness; /* m, the cylinder's half-length */
  int solver;            /* 0 sequential impulse, 1 MLCP Dantzig, 2 MLCP projected Gauss-Seidel */
} bullet_settings;
enum { BODY_MULTI = 0, BODY_RIGID = 1 };
enum { GYRO_IMPLICIT_BODY = 0, GYRO_EXPLICIT = 1, GYRO_OFF = 2 };
enum { SOLVER_SI = 0, SOLVER_DANTZIG = 1, SOLVER_PGS = 2 };

extern const dv_step_model dv_bullet_models[];
extern const dv_shape_keys dv_bullet_shape;

#endif
