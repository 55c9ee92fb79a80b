/* engine_dart: the disk as one body on a plane in DART 6.12 (Dynamic Animation
 * and Robotics Toolkit). C++ behind the extern "C" table dv_engine_dart
 * (dv_engine.h); the rest of diskval sees nothing of DART.
 *
 * The body is a Skeleton of one BodyNode on a FreeJoint: the disk's mass, its
 * principal inertia (A, A, C) about the centre, no damping; its collision
 * shape the scene's body (the geom key): the thin disk, a CylinderShape of
 * radius r along the body's z axis and of height THIN_HEIGHT r (a cylinder of
 * height 0 is refused), or for a [disk] thickness (geom cylinder,
 * engine_shape.h) a CylinderShape of height 2 half_thickness, compared with
 * the matched reference of that half-thickness. The ground is a
 * PlaneShape z = 0 on a welded Skeleton; gravity -z; friction the
 * coefficient of [engines.dart] friction on both shapes (DART takes the
 * smaller), a pyramid of two directions solved by DART's boxed LCP
 * (BoxedLcpConstraintSolver: Dantzig, with DART's PGS as its fallback, or PGS
 * alone); restitution 0.
 *
 * The collision detector (the detector key): DART's own refuses a cylinder on
 * a plane, and FCL tessellates the cylinder (16 sides even in primitive mode:
 * the disk lost contact within milliseconds), so the two that collide the
 * exact cylinder:
 *   ode     (default) ODE's dCollideCylinderPlane, double precision: two
 *           contacts, the lowest points of both caps, whose mean is the rim's
 *           lowest point P = G + r d to within THIN_HEIGHT r / 2; for a
 *           cylinder one contact, the lower rim corner exactly (the upper
 *           cap's is off the ground), as the matched reference rolls on it
 *           (test_engine_dart);
 *   bullet  Bullet's convex-plane collider: one contact, the lower cap's
 *           lowest point, off P by THIN_HEIGHT r / 2 plus Bullet's single
 *           precision (Debian's DART links the float build): 2.5e-8 m at 0.2 m
 *           from the origin, growing with the distance. DART's Bullet
 *           detector is opened at run time in a scope of its own (dlopen
 *           RTLD_LOCAL | RTLD_DEEPBIND): its float Bullet and the float64
 *           Bullet engines/bullet/ links have the same symbol names, and one
 *           process linking both corrupts its heap (measured). AddressSanitizer
 *           refuses RTLD_DEEPBIND: a sanitizer build has no bullet detector.
 *           A cylinder is refused: DART gives Bullet's btCylinderShapeZ its
 *           default collision margin, which rounds the rim corner the
 *           contact is at (test_engine_dart measures it).
 * THIN_HEIGHT (1e-7 r) keeps the cap offset far below 1e-6 m for any r a
 * scenario accepts, without a degenerate cylinder.
 *
 * Contact stiffness: DART's contacts are hard constraints whose penetration is
 * corrected by an error-reduction velocity, erp times the depth beyond the
 * error allowance per step, capped at erv; its defaults (erp 0.01, erv 1e-3
 * m/s) let the steady circle's disk sink 0.15 mm at a 1e-3 s step, erp 0.2
 * and erv 1 m/s (the defaults here) 5.5 um, and 0.05 um at 1e-4 s
 * (test_engine_dart). The keys erp, erv, cfm; DART keeps them as process-wide
 * statics of ContactConstraint, so every run sets them before it steps.
 *
 * Faults end the run, never the process: DART reports none but through its
 * asserts (compiled out) and exceptions, so a non-finite state, a runaway
 * energy, a disk sunk deeper than r/20 are diverged and the lowest point more
 * than r/100 above the ground for 0.05 s is lost_contact, as in the other
 * contact engines; checked every DART_CHECK_STEPS steps and before every
 * sample, lying down (and a NaN in n.z) every step. A C++ exception is caught
 * at each entry point and ends the run as an error.
 */
#include <dart/config.hpp>
#include <dart/collision/CollisionDetector.hpp>
#include <dart/collision/CollisionResult.hpp>
#include <dart/collision/ode/OdeCollisionDetector.hpp>
#include <dart/constraint/BoxedLcpConstraintSolver.hpp>
#include <dart/constraint/ContactConstraint.hpp>
#include <dart/constraint/DantzigBoxedLcpSolver.hpp>
#include <dart/constraint/PgsBoxedLcpSolver.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/CylinderShape.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/PlaneShape.hpp>
#include <dart/dynamics/ShapeNode.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/simulation/World.hpp>

#include <dlfcn.h>

#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <new>

extern "C" {
#include "dv_engine.h"
#include "dv_pose.h"
#include "dv_reference.h"
#include "engine_module.h"
#include "dart_settings.h"
#include "engine_scene.h"
#include "engine_shape.h"
#include "engine_watch.h"
}
#include "dv_dart.h"

#if defined(__SANITIZE_ADDRESS__)
#define DART_NO_DEEPBIND 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DART_NO_DEEPBIND 1
#endif
#endif

#define DART_CHECK_STEPS 16
#define THIN_HEIGHT 1e-7 /* the thin disk's cylinder height, in radii */
#define BULLET_LIBRARY "libdart-collision-bullet.so.6.12"
#define BULLET_CREATE "_ZN4dart9collision23BulletCollisionDetector6createEv"

namespace {


using dart::collision::CollisionDetectorPtr;
using dart::dynamics::BodyNode;
using dart::dynamics::SkeletonPtr;

struct dart_engine {
  dart_settings set;
  red_disk disk;
  dv_geometry geom; /* a cylinder of half-thickness 0 (the thin disk) or h */
  dart::simulation::WorldPtr world;
  SkeletonPtr skel, ground;
  BodyNode *body;
  long k;                        /* steps since reset: time = k timestep */
  dv_engine_watch watch;         /* its faults (engine_watch.h) */
  double prev_y[RED_NSTATE];     /* last canonical state, for unwrapping */
  double theta_limit, cos_limit; /* lying down outside (limit, pi - limit) */
  int status;                    /* < 0 once the run failed; DV_EVENT once it ended */
  dv_engine_stats st;
};

/* "DART 6.12.1" */
const char *dart_version(void) {
  return "DART " DART_VERSION;
}

/* mark the run failed: stats outcome and detail, err, and the status kept */
__attribute__((format(printf, 4, 5))) int failed(dart_engine *e, dv_failure failure, dv_error *err,
                                                 const char *fmt, ...) {
  const dv_outcome outcome = dv_failure_outcome(failure);
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(e->st.detail, sizeof e->st.detail, fmt, ap);
  va_end(ap);
  e->st.outcome = outcome;
  e->st.failure = failure;
  e->status = outcome == DV_OUTCOME_ERROR ? DV_ESYSTEM : DV_ENUMERIC;
  return dv_fail(err, e->status, "%s: %s", dv_outcome_name(outcome), e->st.detail);
}

void read_pose(const dart_engine *e, dv_pose *p) {
  const Eigen::Isometry3d &T = e->body->getWorldTransform();
  const Eigen::Vector3d v = e->body->getLinearVelocity();
  const Eigen::Vector3d w = e->body->getAngularVelocity();
  for (int i = 0; i < 3; i++) {
    p->pos[i] = T.translation()[i];
    p->vel[i] = v[i];
    p->omega[i] = w[i];
    for (int j = 0; j < 3; j++) p->R[3 * i + j] = T.linear()(i, j);
  }
}

void write_pose(dart_engine *e, const dv_pose *p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d R;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) R(i, j) = p->R[3 * i + j];
  /* re-orthonormalised: DART's exponential coordinates take a rotation */
  T.linear() = Eigen::Quaterniond(R).normalized().toRotationMatrix();
  T.translation() = Eigen::Vector3d(p->pos[0], p->pos[1], p->pos[2]);
  auto *joint = static_cast<dart::dynamics::FreeJoint *>(e->body->getParentJoint());
  joint->setPositions(dart::dynamics::FreeJoint::convertToPositions(T));
  joint->setLinearVelocity(Eigen::Vector3d(p->vel[0], p->vel[1], p->vel[2]));
  joint->setAngularVelocity(Eigen::Vector3d(p->omega[0], p->omega[1], p->omega[2]));
  e->skel->clearExternalForces();
  e->skel->clearInternalForces();
}

/* DART's Bullet collision detector, from its library opened in a scope of its
 * own (the header's comment); NULL and why when it cannot be */
CollisionDetectorPtr bullet_detector(char *why, size_t size) {
#ifdef DART_NO_DEEPBIND
  snprintf(why, size,
           "detector bullet: not in a sanitizer build (AddressSanitizer refuses the "
           "RTLD_DEEPBIND that keeps DART's float Bullet apart)");
  return nullptr;
#else
  static void *lib = NULL;
  if (!lib) lib = dlopen(BULLET_LIBRARY, RTLD_NOW | RTLD_LOCAL | RTLD_DEEPBIND);
  if (!lib) {
    snprintf(why, size, "detector bullet: %s", dlerror());
    return nullptr;
  }
  /* BulletCollisionDetector::create(): a shared_ptr to a class whose first and
   * only base is CollisionDetector, so the same pointer */
  typedef std::shared_ptr<dart::collision::CollisionDetector> (*create_fn)();
  void *sym = dlsym(lib, BULLET_CREATE);
  if (!sym) {
    snprintf(why, size, "detector bullet: %s", dlerror());
    return nullptr;
  }
  create_fn create;
  memcpy(&create, &sym, sizeof create);
  return create();
#endif
}

double dart_half_thickness(const dv_scenario *sc);

/* DART's contact parameters are statics of ContactConstraint: this run's */
void apply_contact_parameters(const dart_engine *e) {
  using dart::constraint::ContactConstraint;
  ContactConstraint::setErrorReductionParameter(e->set.erp);
  ContactConstraint::setMaxErrorReductionVelocity(e->set.erv);
  ContactConstraint::setConstraintForceMixing(e->set.cfm);
  ContactConstraint::setErrorAllowance(0.0);
}

/* world, ground and body; 0, or -1 and why */
int build(dart_engine *e, char *why, size_t size) {
  using namespace dart::dynamics;
  e->world = dart::simulation::World::create("diskval");
  e->world->setGravity(Eigen::Vector3d(0.0, 0.0, -e->disk.g));
  e->world->setTimeStep(e->set.timestep);
  std::shared_ptr<dart::constraint::BoxedLcpSolver> primary, secondary;
  if (e->set.lcp == LCP_PGS) {
    primary = std::make_shared<dart::constraint::PgsBoxedLcpSolver>();
  } else {
    primary = std::make_shared<dart::constraint::DantzigBoxedLcpSolver>();
    secondary = std::make_shared<dart::constraint::PgsBoxedLcpSolver>();
  }
  e->world->setConstraintSolver(
      std::make_unique<dart::constraint::BoxedLcpConstraintSolver>(primary, secondary));
  CollisionDetectorPtr detector = e->set.detector == DETECTOR_BULLET
                                      ? bullet_detector(why, size)
                                      : dart::collision::OdeCollisionDetector::create();
  if (!detector) return -1;
  e->world->getConstraintSolver()->setCollisionDetector(detector);

  e->ground = Skeleton::create("ground");
  BodyNode *g = e->ground->createJointAndBodyNodePair<WeldJoint>().second;
  ShapeNode *gs = g->createShapeNodeWith<CollisionAspect, DynamicsAspect>(
      std::make_shared<PlaneShape>(Eigen::Vector3d::UnitZ(), 0.0));
  gs->getDynamicsAspect()->setFrictionCoeff(e->set.friction);
  gs->getDynamicsAspect()->setRestitutionCoeff(0.0);
  e->ground->setMobile(false);
  e->world->addSkeleton(e->ground);

  e->skel = Skeleton::create("disk");
  e->body = e->skel->createJointAndBodyNodePair<FreeJoint>().second;
  e->body->setMass(e->disk.m);
  e->body->setMomentOfInertia(e->disk.A, e->disk.A, e->disk.C, 0.0, 0.0, 0.0);
  e->body->setLocalCOM(Eigen::Vector3d::Zero());
  ShapeNode *ds =
      e->body->createShapeNodeWith<CollisionAspect, DynamicsAspect>(std::make_shared<CylinderShape>(
          e->disk.r,
          e->geom.half_thickness > 0.0 ? 2.0 * e->geom.half_thickness : THIN_HEIGHT * e->disk.r));
  ds->getDynamicsAspect()->setFrictionCoeff(e->set.friction);
  ds->getDynamicsAspect()->setRestitutionCoeff(0.0);
  e->skel->setGravity(Eigen::Vector3d(0.0, 0.0, -e->disk.g));
  e->world->addSkeleton(e->skel);
  return 0;
}

void dart_free(void *p) {
  delete static_cast<dart_engine *>(p);
}

/* the engine of sc, whatever its detector (dv_dart_contacts measures them all) */
dart_engine *make_engine(const dv_scenario *sc, dv_error *err) {
  if (!(sc->disk.A > 0.0 && sc->disk.C > 0.0))
    return dv_fail(err, DV_EINPUT, "DART needs a positive definite inertia (A = %g, C = %g)",
                   sc->disk.A, sc->disk.C),
           nullptr;
  dart_engine *e = new (std::nothrow) dart_engine();
  if (!e) return dv_fail(err, DV_ESYSTEM, "out of memory: the DART engine's state"), nullptr;
  e->set = *static_cast<const dart_settings *>(dv_scenario_settings(sc, "dart"));
  /* a scenario built in code leaves the step to the scene */
  dv_engine_derive_step(sc, &dv_dart_models[e->set.lcp], &e->set.timestep, NULL, NULL, 0, NULL);
  /* a scenario built in code derives its shape here */
  dv_engine_derive_shape(sc, &dv_dart_shape, &e->set.geom, &e->set.half_thickness, NULL, 0, NULL);
  dv_engine_derive_friction(sc, "dart", "friction", 1.0, "", &e->set.friction, NULL, 0, NULL);
  e->disk = sc->disk;
  e->geom = dv_geometry{DV_SHAPE_CYLINDER, sc->disk.r,
                        e->set.geom == GEOM_CYLINDER ? e->set.half_thickness : 0.0};
  e->theta_limit = dv_reference_settings(sc)->theta_limit;
  e->cos_limit = std::cos(e->theta_limit);
  char why[200] = "";
  try {
    if (build(e, why, sizeof why) < 0) {
      dv_fail(err, DV_ESYSTEM, "DART: %s", why);
      dart_free(e);
      return nullptr;
    }
  } catch (const std::exception &ex) {
    dv_fail(err, DV_ESYSTEM, "DART: %s", ex.what());
    dart_free(e);
    return nullptr;
  }
  return e;
}

void *dart_alloc(const dv_scenario *sc, dv_error *err) {
  if (dart_half_thickness(sc) > 0.0 &&
      static_cast<const dart_settings *>(dv_scenario_settings(sc, "dart"))->detector ==
          DETECTOR_BULLET)
    return dv_fail(err, DV_EINPUT,
                   "DART: detector bullet rounds a cylinder's rim corner; a cylinder needs "
                   "detector ode"),
           nullptr;
  return make_engine(sc, err);
}

int dart_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  dart_engine *e = static_cast<dart_engine *>(p);
  memset(&e->st, 0, sizeof e->st);
  e->k = 0;
  e->status = DV_OK;
  memcpy(e->prev_y, state, sizeof e->prev_y);
  for (int i = 0; i < RED_NSTATE; i++)
    if (!std::isfinite(state[i]))
      return failed(e, DV_FAILURE_SETUP, err, "non-finite initial state");
  dv_pose pose;
  try {
    e->world->reset();
    dv_pose_from_state(&e->geom, state, &pose);
    write_pose(e, &pose);
    read_pose(e, &pose);
  } catch (const std::exception &ex) {
    return failed(e, DV_FAILURE_LIBRARY, err, "DART: %s", ex.what());
  }
  char why[160];
  const dv_failure fault = dv_engine_watch_start(&e->watch, &e->disk, &pose, why, sizeof why);
  if (fault) return failed(e, fault, err, "%s", why);
  return DV_OK;
}

/* the divergence and lost-contact checks over the steps since the last */
int check_state(dart_engine *e, dv_error *err) {
  dv_pose p;
  read_pose(e, &p);
  char why[160];
  const dv_failure fault = dv_engine_watch_check(&e->watch, &e->disk, &e->geom, &p, e->k,
                                                 e->set.timestep, why, sizeof why);
  return fault ? failed(e, fault, err, "%s", why) : DV_OK;
}

/* one step and its lying-down test (n.z = cos theta, as the references' event) */
int step(dart_engine *e, dv_error *err) {
  const double dt = e->set.timestep;
  e->world->step();
  e->k++;
  e->st.steps++;
  const double nz = e->body->getWorldTransform().linear()(2, 2);
  if (!(std::fabs(nz) <= e->cos_limit)) {
    if (std::isnan(nz)) return check_state(e, err);
    dv_engine_lay_down(&e->st, nz > 0.0, e->theta_limit, e->k * dt);
    e->status = DV_EVENT;
    return DV_EVENT;
  }
  return e->k - e->watch.checked < DART_CHECK_STEPS ? DV_OK : check_state(e, err);
}

int dart_advance(void *p, double t, dv_sample *out, dv_error *err) {
  dart_engine *e = static_cast<dart_engine *>(p);
  if (e->status < 0)
    return dv_fail(err, e->status, "%s: %s", dv_outcome_name(e->st.outcome), e->st.detail);
  if (e->status == DV_EVENT) return DV_EVENT;
  const double dt = e->set.timestep;
  int status = DV_OK;
  dv_pose pose;
  int contacts = 0;
  try {
    apply_contact_parameters(e);
    while (status == DV_OK && e->k * dt < t - 0.5 * dt) status = step(e, err);
    if (status == DV_OK && e->k > e->watch.checked) status = check_state(e, err);
    if (status < 0) return status;
    read_pose(e, &pose);
    contacts = static_cast<int>(e->world->getLastCollisionResult().getNumContacts());
  } catch (const std::exception &ex) {
    return failed(e, DV_FAILURE_LIBRARY, err, "DART: %s", ex.what());
  }
  dv_sample_from_pose(&e->disk, &e->geom, &pose, status == DV_EVENT ? e->k * dt : t, e->prev_y,
                      out);
  out->contacts = contacts;
  memcpy(e->prev_y, out->y, sizeof e->prev_y);
  dv_stats_add_sample(&e->st, out);
  return status;
}

void dart_stats(const void *p, dv_engine_stats *out) {
  *out = static_cast<const dart_engine *>(p)->st;
}

/* the half-thickness of the cylinder DART models in sc (0: the thin disk) */
double dart_half_thickness(const dv_scenario *sc) {
  dart_settings s = *static_cast<const dart_settings *>(dv_scenario_settings(sc, "dart"));
  dv_engine_derive_shape(sc, &dv_dart_shape, &s.geom, &s.half_thickness, NULL, 0, NULL);
  return s.geom == GEOM_CYLINDER ? s.half_thickness : 0.0;
}

}  // namespace

extern "C" __attribute__((visibility("default"))) int dv_dart_contacts(const dv_scenario *sc, const double y[RED_NSTATE], double sink,
                                double mean[3], double *depth, dv_error *err) {
  dart_engine *e = make_engine(sc, err);
  if (!e) return -1;
  int n = -1;
  try {
    dv_pose pose;
    dv_pose_from_state(&e->geom, y, &pose);
    pose.pos[2] -= sink;
    write_pose(e, &pose);
    dart::collision::CollisionOption option;
    option.maxNumContacts = 100;
    dart::collision::CollisionResult result;
    e->world->getConstraintSolver()->getCollisionGroup()->collide(option, &result);
    n = static_cast<int>(result.getNumContacts());
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    *depth = 0.0;
    for (int i = 0; i < n; i++) {
      sum += result.getContact(i).point;
      *depth = std::fmax(*depth, result.getContact(i).penetrationDepth);
    }
    for (int i = 0; i < 3; i++) mean[i] = n > 0 ? sum[i] / n : NAN;
  } catch (const std::exception &ex) {
    dv_fail(err, DV_ESYSTEM, "DART: %s", ex.what());
    n = -1;
  }
  dart_free(e);
  return n;
}

extern "C" {
DV_ENGINE_MODULE_EXPORT(dart_version, dart_alloc, dart_reset, dart_advance, dart_stats, dart_free);
}
