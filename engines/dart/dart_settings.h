/* dart_settings: [engines.dart], shared by its table (dart_table.c, linked in) and its
 * module (engine_dart.cc, opened when it runs): the settings, the error models and
 * the shape keys. */
#ifndef DV_DART_SETTINGS_H
#define DV_DART_SETTINGS_H

#include "engine_scene.h"
#include "engine_shape.h"

/* [engines.dart] */
typedef struct dart_settings {
  double timestep;       /* s */
  int lcp;               /* 0 pgs, 1 dantzig */
  int detector;          /* 0 ode, 1 bullet */
  double friction;       /* coefficient */
  double erp;            /* error reduction parameter */
  double erv;            /* maximum error reduction velocity, m/s */
  double cfm;            /* constraint force mixing */
  int geom;              /* 0 thin, 1 cylinder */
  double half_thickness; /* m, the cylinder's half-length */
} dart_settings;
enum { GEOM_THIN = 0, GEOM_CYLINDER = 1 };
enum { LCP_PGS = 0, LCP_DANTZIG = 1 };
enum { DETECTOR_ODE = 0, DETECTOR_BULLET = 1 };

extern const dv_step_model dv_dart_models[];
extern const dv_shape_keys dv_dart_shape;

#endif
