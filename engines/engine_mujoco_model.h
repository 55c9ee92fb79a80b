/* engine_mujoco_model: the MJCF model the mujoco engine compiles for a
 * scenario, for programs that drive MuJoCo themselves (bench/bare_mujoco.c). */
#ifndef ENGINE_MUJOCO_MODEL_H
#define ENGINE_MUJOCO_MODEL_H

#include <stddef.h>

#include "scenario.h"

/* the model text (settings the scenario leaves to the scene derived, as a run
 * derives them); its length, or -1 when it does not fit size. A thin disk
 * also needs dv_mujoco_thin_install (engine_mujoco_thin.h) */
int dv_mujoco_model_xml(const dv_scenario *sc, char *xml, size_t size);

#endif
