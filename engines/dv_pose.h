/* dv_pose: the canonical disk state <-> a rigid body's pose and velocities.
 *
 * World frame, SI units. The body frame: z1 = n (the disk's axis),
 * x1 = cos(psi) t + sin(psi) d, y1 = -sin(psi) t + cos(psi) d, with
 * a = (cos phi, sin phi, 0), t = (sin phi, -cos phi, 0), d = cos(theta) a - sin(theta) ez,
 * n = sin(theta) a + cos(theta) ez. R is row-major with the body axes as its
 * columns (world = R body). omega = phi' ez - theta' t + psi' n; rolling
 * without slip on the contact vector rho gives v_G = -omega x rho.
 *
 * Geometry: a cylinder of radius r and half-thickness h touches the ground at
 * its rim corner, rho = r d - h sign(n.z) n, centre height r sin + h |cos|;
 * a flat ellipsoid (r, r, e) at its support point.
 */
#ifndef DV_POSE_H
#define DV_POSE_H

#include "red_disk.h"

typedef enum dv_shape { DV_SHAPE_CYLINDER = 0, DV_SHAPE_ELLIPSOID = 1 } dv_shape;

typedef struct dv_geometry {
  dv_shape shape;
  double radius;         /* m */
  double half_thickness; /* m: cylinder half-length, or ellipsoid semi-axis e along n */
} dv_geometry;

typedef struct dv_pose {
  double pos[3];   /* centre of mass, m */
  double R[9];     /* orientation, row-major, body axes as columns */
  double vel[3];   /* centre velocity, world, m/s */
  double omega[3]; /* angular velocity, world, rad/s */
} dv_pose;

/* contact vector from the centre to the lowest point of the body (m) */
void dv_geometry_contact_vector(const dv_geometry *geom, const double R[9], double rho[3]);

/* the z component of that vector: the lowest point's height over the centre's (m) */
double dv_geometry_contact_height(const dv_geometry *geom, const double R[9]);

/* pose and velocities of a body rolling without slip in state y */
void dv_pose_from_state(const dv_geometry *geom, const double y[RED_NSTATE], dv_pose *pose);

/* state from a pose; angles are unwrapped to lie nearest prev (NULL: none) */
void dv_state_from_pose(const dv_pose *pose, const double *prev, double y[RED_NSTATE]);

/* mechanical energy m v^2/2 + omega.I.omega/2 + m g z (J) */
double dv_pose_energy(const red_disk *disk, const dv_pose *pose);

/* lowest point of the body (world, m) and its material speed (m/s) */
void dv_pose_lowest_point(const dv_geometry *geom, const dv_pose *pose, double p[3],
                          double *slip_speed);

/* the body-to-world rotation (row-major, body axes as columns) of the unit
 * quaternion q = (w, x, y, z) */
void dv_quat_to_matrix(const double q[4], double R[9]);

/* the unit quaternion (w, x, y, z), w >= 0, of the rotation R (Shepperd's
 * method: from the largest of its four squared components) */
void dv_matrix_to_quat(const double R[9], double q[4]);

#endif
