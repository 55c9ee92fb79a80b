/* bullet_contact: Bullet's collider alone, on the engine's shape (bullet_contact.h). */
#include "bullet_contact.h"

#include <btBulletCollisionCommon.h>

#include <cmath>
#include <memory>
#include <new>

namespace {

/* the deepest of the points Bullet reports */
struct deepest : btCollisionWorld::ContactResultCallback {
  int n = 0;
  double point[3] = {NAN, NAN, NAN};
  double distance = INFINITY;
  btScalar addSingleResult(btManifoldPoint &cp, const btCollisionObjectWrapper *a, int, int,
                           const btCollisionObjectWrapper *, int, int) override {
    const btVector3 p = a->getCollisionObject()->getCollisionShape()->getShapeType() ==
                                STATIC_PLANE_PROXYTYPE
                            ? cp.getPositionWorldOnB()
                            : cp.getPositionWorldOnA();
    n++;
    if (cp.getDistance() < distance) {
      distance = cp.getDistance();
      for (int i = 0; i < 3; i++) point[i] = p[i];
    }
    return 0;
  }
};

} // namespace

btCylinderShapeZ *dv_bullet_disk_shape(double r, double h) {
  btCylinderShapeZ *shape = new btCylinderShapeZ(btVector3(r, r, h));
  shape->setMargin(0.0);
  return shape;
}

extern "C" int dv_bullet_contact(double r, double h, const double R[9], const double G[3],
                                 double point[3], double *distance) {
  try {
    const std::unique_ptr<btCylinderShapeZ> shape(dv_bullet_disk_shape(r, h));
    btStaticPlaneShape plane(btVector3(0, 0, 1), 0);
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher(&config);
    btDbvtBroadphase broadphase;
    btCollisionWorld world(&dispatcher, &broadphase, &config);
    btCollisionObject disk, ground;
    disk.setCollisionShape(shape.get());
    ground.setCollisionShape(&plane);
    btTransform pose;
    pose.setBasis(btMatrix3x3(R[0], R[1], R[2], R[3], R[4], R[5], R[6], R[7], R[8]));
    pose.setOrigin(btVector3(G[0], G[1], G[2]));
    disk.setWorldTransform(pose);
    deepest found;
    world.contactPairTest(&disk, &ground, found);
    for (int i = 0; i < 3; i++) point[i] = found.point[i];
    *distance = found.distance;
    return found.n;
  } catch (const std::exception &) {
    return -1;
  }
}
