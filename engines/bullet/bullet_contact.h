/* bullet_contact: Bullet's own collider on the engine's shape, one pose at a
 * time, for the engine's test (test_collider_bullet): what Bullet's narrow
 * phase reports against the closed form of dv_pose.h. */
#ifndef DV_BULLET_CONTACT_H
#define DV_BULLET_CONTACT_H

#ifdef __cplusplus
extern "C" {
#endif

/* The contacts Bullet finds between the plane z = 0 and the engine's shape
 * (btCylinderShapeZ(r, r, h), margin 0; h = 0 the thin disk) at centre G and
 * orientation R (row-major, body axes as columns): the number of points (-1
 * on a library error), the deepest point on the body (m) and its signed
 * distance (m, < 0 inside the ground). */
int dv_bullet_contact(double r, double h, const double R[9], const double G[3], double point[3],
                      double *distance);

#ifdef __cplusplus
}

class btCylinderShapeZ;

/* the engine's body shape: btCylinderShapeZ(r, r, h) of collision margin 0, so
 * its support point is the exact rim point (h = 0) or rim corner (new'd) */
btCylinderShapeZ *dv_bullet_disk_shape(double r, double h);
#endif

#endif
