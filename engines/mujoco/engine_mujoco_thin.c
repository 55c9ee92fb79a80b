/* engine_mujoco_thin: a one-point rim contact for the thin disk in MuJoCo 2.2.
 *
 * MuJoCo 2.2's mj_collideGeoms orders a pair by geom type before it calls
 * mjCOLLISIONFUNC[type1][type2], so the plane (mjGEOM_PLANE = 0) is g1 and
 * the cylinder (mjGEOM_CYLINDER = 5) g2. A collider sets dist, pos and the
 * normal frame[0..2] (frame[3..5] zero); mj_collideGeoms completes the frame
 * (mju_makeFrame) and adds friction, solref, solimp, condim and the gap.
 * The midpoint convention for pos is that of MuJoCo's own plane colliders
 * (mjc_PlaneSphere, mjc_PlaneCylinder). Checked against the closed form
 * P = G + r d (DESIGN section 1) by test_mujoco_thin.
 */
#include "engine_mujoco_thin.h"

/* the cylinder table entry replaced, and how many installs are in force */
static mjfCollision replaced;
static int installs;

/* the half-length is 1e-6 r: no contact depends on it, and the bounding radius stays r */
double dv_mujoco_thin_half_length(double r) {
  return 1e-6 * r;
}

/* geom g carries the thin-disk mark */
static int is_thin(const mjModel *m, int g) {
  return m->nuser_geom > 0 && m->geom_user[g * m->nuser_geom] == DV_MUJOCO_THIN_MARK;
}

int dv_mujoco_thin_collide(const mjModel *m, const mjData *d, mjContact *con, int g1, int g2,
                           mjtNum margin) {
  if (!is_thin(m, g2)) {
    const mjfCollision other = installs ? replaced : mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER];
    return other && other != dv_mujoco_thin_collide ? other(m, d, con, g1, g2, margin) : 0;
  }
  const mjtNum *pos1 = d->geom_xpos + 3 * g1, *mat1 = d->geom_xmat + 9 * g1;
  const mjtNum *pos2 = d->geom_xpos + 3 * g2, *mat2 = d->geom_xmat + 9 * g2;
  const mjtNum r = m->geom_size[3 * g2];
  const mjtNum normal[3] = {mat1[2], mat1[5], mat1[8]}, axis[3] = {mat2[2], mat2[5], mat2[8]};
  /* down the disk's plane: -normal less its part along the axis, |down| = sin(theta) */
  const mjtNum along = mju_dot3(normal, axis);
  mjtNum down[3], rim[3], rel[3];
  for (int i = 0; i < 3; i++) down[i] = along * axis[i] - normal[i];
  const mjtNum len = mju_norm3(down);
  if (len < mjMINVAL) /* lying flat: every rim point is lowest; take the x axis's */
    for (int i = 0; i < 3; i++) down[i] = mat2[3 * i];
  else
    mju_scl3(down, down, 1.0 / len);
  mju_addScl3(rim, pos2, down, r);
  mju_sub3(rel, rim, pos1);
  const mjtNum dist = mju_dot3(rel, normal);
  if (dist > margin) return 0;
  con->dist = dist;
  mju_addScl3(con->pos, rim, normal, -0.5 * dist);
  mju_copy3(con->frame, normal);
  mju_zero3(con->frame + 3);
  return 1;
}

void dv_mujoco_thin_install(void) {
  if (installs++ == 0) {
    replaced = mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER];
    mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER] = dv_mujoco_thin_collide;
  }
}

void dv_mujoco_thin_restore(void) {
  if (installs > 0 && --installs == 0) mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER] = replaced;
}
