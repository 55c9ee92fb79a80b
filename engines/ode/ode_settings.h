/* ode_settings: [engines.ode], shared by its table (ode_table.c, linked in) and its
 * module (engine_ode, opened when it runs): the settings, the error models and
 * the shape keys. */
#ifndef DV_ODE_SETTINGS_H
#define DV_ODE_SETTINGS_H

#include "engine_scene.h"
#include "engine_shape.h"

/* [engines.ode] */
typedef struct ode_settings {
  double timestep;           /* s */
  int stepper;               /* 0 dWorldStep, 1 dWorldQuickStep */
  int iterations;            /* QuickStep iterations */
  double erp, cfm;           /* world error reduction, constraint force mixing */
  int friction_model;        /* 0 coefficient (dContactApprox1), 1 force limit (N) */
  double friction;           /* coefficient, or force limit in N */
  double soft_erp, soft_cfm; /* contact softness */
  int geom;                  /* 0 thin disk (user geom), 1 cylinder */
  double half_thickness;     /* m, cylinder half-length */
} ode_settings;


extern const dv_step_model dv_ode_models[];
extern const dv_shape_keys dv_ode_shape;

/* the friction: a coefficient, or a force limit of that coefficient's weight */
void dv_ode_derive_friction(const dv_scenario *sc, ode_settings *s, char *why, size_t size,
                            const char **keys);

#endif
