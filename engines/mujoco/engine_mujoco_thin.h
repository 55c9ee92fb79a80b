/* engine_mujoco_thin: the thin disk's contact in MuJoCo 2.2 (DESIGN section 4).
 *
 * The disk is a cylinder geom marked as thin by its user data (the model has
 * nuser_geom >= 1 and the geom's first user value is DV_MUJOCO_THIN_MARK).
 * Its half-length (dv_mujoco_thin_half_length) only sizes the bounding
 * volume; mass and inertia come from an explicit inertial element. The
 * plane-cylinder entry of MuJoCo's collision table is replaced by
 * dv_mujoco_thin_collide, which gives a marked geom exactly one contact, at
 * the lowest point of its rim circle, and passes every other cylinder on to
 * the entry it replaced.
 *
 * Threads: mjCOLLISIONFUNC is process-global, so install and restore change
 * collision for every MuJoCo model in the process. They are counted (nested
 * runs keep the collider until the last one restores it) but not locked: one
 * MuJoCo run at a time per process, as engine_mujoco.c already requires for
 * its error handlers.
 */
#ifndef ENGINE_MUJOCO_THIN_H
#define ENGINE_MUJOCO_THIN_H

#include <mujoco/mujoco.h>

/* first geom user value of a thin disk */
#define DV_MUJOCO_THIN_MARK 1.0

/* half-length (m) of the cylinder geom that stands for a thin disk of radius r (m) */
double dv_mujoco_thin_half_length(double r);

/* MuJoCo's mjfCollision for (plane g1, cylinder g2): a thin disk touches the
 * plane at the lowest point of its rim, one contact within margin; con->pos
 * is the midpoint between the surfaces (rim point - dist/2 normal), dist the
 * rim point's height above the plane (negative: penetration), frame[0..2]
 * the plane's normal. A disk lying flat (axis along the normal) touches at
 * the rim point on its x axis, as MuJoCo's own plane-cylinder collider does.
 * A cylinder without the mark goes to the collider this one replaced. */
int dv_mujoco_thin_collide(const mjModel *m, const mjData *d, mjContact *con, int g1, int g2,
                           mjtNum margin);

/* put dv_mujoco_thin_collide in MuJoCo's plane-cylinder table entry, keeping the old one */
void dv_mujoco_thin_install(void);

/* undo one install; the last one puts the old table entry back */
void dv_mujoco_thin_restore(void);

#endif
