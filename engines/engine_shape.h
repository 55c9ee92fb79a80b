/* engine_shape: the body a contact engine models, from the scene's disk.
 *
 * The disk's thickness is [disk] thickness (scenario.h): a real coin is
 * written once. With thickness t > 0, a contact engine whose scenario gives
 * no shape (its geom key) models a cylinder of half-length t / 2, and is
 * compared with the matched reference of that half-thickness; with t = 0, the
 * thin disk. The engine's shape keys, where given (file, --set, code), are a
 * stand-in and win: a geom given keeps its shape, a half_thickness given its
 * size; a stand-in of a thick disk without a half_thickness takes t / 2.
 */
#ifndef DV_ENGINE_SHAPE_H
#define DV_ENGINE_SHAPE_H

#include <stddef.h>

#include "scenario.h"

/* a contact engine's shape keys in [engines.NAME] */
typedef struct dv_shape_keys {
  const char *engine;   /* NAME */
  const char *geom_key; /* its shape, a choice */
  int cylinder;         /* the choice's index of a cylinder */
  int thin;             /* and of the thin disk (which has no half-thickness) */
  const char *half_key; /* the stand-in's half-thickness, m */
} dv_shape_keys;

/* *geom and *half as sc's disk makes them where sc does not give them. why
 * (may be NULL): "; "-appended "geom cylinder, half_thickness 0.002 m: [disk]
 * thickness 0.004 m" when anything was derived; keys (may be NULL): a
 * NULL-terminated list the derived keys are appended to (room for 2 more). */
void dv_engine_derive_shape(const dv_scenario *sc, const dv_shape_keys *k, int *geom, double *half,
                            char *why, size_t size, const char **keys);

#endif
