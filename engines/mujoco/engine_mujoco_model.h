/* engine_mujoco_model: the MJCF model the mujoco engine compiles for a
 * scenario, for programs that drive MuJoCo themselves (bench/bare_mujoco.c). */
#ifndef ENGINE_MUJOCO_MODEL_H
#define ENGINE_MUJOCO_MODEL_H

#include <mujoco/mujoco.h>
#include <stddef.h>

#include "dv_pose.h"
#include "scenario.h"

/* the model text (settings the scenario leaves to the scene derived, as a run
 * derives them); its length, or -1 when it does not fit size. A thin disk
 * also needs dv_mujoco_thin_install (engine_mujoco_thin.h) */
int dv_mujoco_model_xml(const dv_scenario *sc, char *xml, size_t size);

/* the disk's pose and velocities (world frame) from its free joint in d */
void dv_mujoco_read_pose(const mjData *d, dv_pose *p);

#endif
