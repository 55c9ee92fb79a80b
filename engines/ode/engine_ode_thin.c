/* engine_ode_thin: the thin disk as an ODE user geom class; checked against
 * the closed form P = G + r d by test_ode_thin (both argument orders,
 * contacts below and none above the plane). */
#include "engine_ode_thin.h"

#include <math.h>

#define NUMC_MASK 0xffff /* the contact count in dCollide's flags (ODE's collision_kernel.h) */

static int thin_class = -1; /* class number once registered */

/* the disk's data: its radius */
typedef struct thin_data {
  double radius; /* m */
} thin_data;

/* one contact between the disk and the plane, or none (see the header) */
static int collide_plane(dGeomID o1, dGeomID o2, int flags, dContactGeom *contact, int skip) {
  (void)skip;
  if ((flags & NUMC_MASK) < 1) return 0;
  /* dCollide hands a user class its own geom first; the other order is kept
   * for direct calls: the normal then points into the plane, o1 */
  const int flip = dGeomGetClass(o1) == dPlaneClass;
  const dGeomID disk = flip ? o2 : o1, plane = flip ? o1 : o2;
  const double r = ((const thin_data *)dGeomGetClassData(disk))->radius;
  const dReal *G = dGeomGetPosition(disk), *R = dGeomGetRotation(disk);
  dVector4 p;
  dGeomPlaneGetParams(plane, p);
  const double n[3] = {R[2], R[6], R[10]};
  const double Nn = p[0] * n[0] + p[1] * n[1] + p[2] * n[2];
  double u[3], norm = 0.0;
  for (int i = 0; i < 3; i++) {
    u[i] = p[i] - Nn * n[i];
    norm += u[i] * u[i];
  }
  norm = sqrt(norm);
  if (!(norm > 1e-300)) { /* lying flat on the plane: every rim point is lowest; take x1 */
    const double x1[3] = {R[0], R[4], R[8]};
    for (int i = 0; i < 3; i++) u[i] = x1[i];
    norm = 1.0;
  }
  double low[3], height = 0.0;
  for (int i = 0; i < 3; i++) {
    low[i] = G[i] - r * u[i] / norm;
    height += p[i] * low[i];
  }
  const double depth = p[3] - height;
  if (!(depth >= 0.0)) return 0;
  for (int i = 0; i < 3; i++) {
    contact->pos[i] = low[i];
    contact->normal[i] = flip ? -p[i] : p[i];
  }
  contact->pos[3] = contact->normal[3] = 0.0;
  contact->depth = depth;
  contact->g1 = o1;
  contact->g2 = o2;
  contact->side1 = contact->side2 = -1;
  return 1;
}

/* the collider for another class: the plane only */
static dColliderFn *collider_for(int num) {
  return num == dPlaneClass ? collide_plane : NULL;
}

/* the rim circle's bounding box: extent r sqrt(1 - n_i^2) along world axis i */
static void thin_aabb(dGeomID disk, dReal aabb[6]) {
  const double r = ((const thin_data *)dGeomGetClassData(disk))->radius;
  const dReal *G = dGeomGetPosition(disk), *R = dGeomGetRotation(disk);
  const double n[3] = {R[2], R[6], R[10]};
  for (int i = 0; i < 3; i++) {
    const double half = r * sqrt(fmax(0.0, 1.0 - n[i] * n[i]));
    aabb[2 * i] = G[i] - half;
    aabb[2 * i + 1] = G[i] + half;
  }
}

int dv_ode_thin_class(void) {
  if (thin_class < 0) {
    dGeomClass c = {sizeof(thin_data), collider_for, thin_aabb, NULL, NULL};
    thin_class = dCreateGeomClass(&c);
  }
  return thin_class;
}

dGeomID dv_ode_thin_create(double radius) {
  dGeomID g = dCreateGeom(dv_ode_thin_class());
  ((thin_data *)dGeomGetClassData(g))->radius = radius;
  return g;
}

double dv_ode_thin_radius(dGeomID disk) {
  return ((const thin_data *)dGeomGetClassData(disk))->radius;
}
