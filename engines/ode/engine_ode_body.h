/* engine_ode_body: an ODE body's pose and velocities <-> dv_pose (dv_pose.h),
 * the one place ODE's 3x4 rotation layout is converted; shared by the ODE
 * engine and the bare ODE baseline of bench/. */
#ifndef ENGINE_ODE_BODY_H
#define ENGINE_ODE_BODY_H

#include <ode/ode.h>

#include "dv_pose.h"

/* the body's pose and velocities (world frame) */
void dv_ode_read_pose(dBodyID body, dv_pose *p);

/* place the body at p, with its velocities */
void dv_ode_write_pose(dBodyID body, const dv_pose *p);

#endif
