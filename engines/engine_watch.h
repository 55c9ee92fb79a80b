/* engine_watch: the faults that end a contact engine's run (never the process).
 *
 * A run diverges where its state is not finite, where its energy runs away
 * (over E0 + |E0| / 2 + m g r), or where the body's lowest point sinks deeper
 * than DV_WATCH_SUNK r into the ground; it loses contact where that point stays
 * higher than DV_WATCH_AIR r above the ground for longer than DV_WATCH_AIR_TIME.
 * The engines check every few steps (the time off the ground adds up the steps
 * between checks) and before every sample.
 */
#ifndef DV_ENGINE_WATCH_H
#define DV_ENGINE_WATCH_H

#include <stddef.h>

#include "dv_engine.h"
#include "dv_pose.h"

#define DV_WATCH_AIR 0.01      /* lost contact: height above the ground, in radii */
#define DV_WATCH_AIR_TIME 0.05 /* and for longer than this, s */
#define DV_WATCH_SUNK 0.05     /* diverged: lowest point this deep below the ground, in radii */

typedef struct dv_engine_watch {
  double e0, e_max; /* energy at the start, runaway above, J */
  double airborne;  /* s the lowest point has been off the ground */
  long checked;     /* the step of the last check */
} dv_engine_watch;

/* all 18 numbers of the pose are finite */
int dv_pose_finite(const dv_pose *p);

/* start watching a run at its first pose: DV_FAILURE_NONE, or DV_FAILURE_SETUP
 * where the pose or its energy is not finite (msg says so) */
dv_failure dv_engine_watch_start(dv_engine_watch *w, const red_disk *disk, const dv_pose *pose,
                                 char *msg, size_t size);

/* the pose at step k of step dt: DV_FAILURE_NONE, or the fault, msg saying what
 * and when ("runaway energy at t = 0.2 s: ...") */
dv_failure dv_engine_watch_check(dv_engine_watch *w, const red_disk *disk, const dv_geometry *geom,
                                 const dv_pose *p, long k, double dt, char *msg, size_t size);

#endif
