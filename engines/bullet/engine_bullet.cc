/* engine_bullet: the disk as one body on a plane in Bullet 3.24, double
 * precision (the float64 build: BT_USE_DOUBLE_PRECISION). The only C++ file
 * of the engines layer: the rest of diskval sees the extern "C" table
 * dv_engine_bullet (dv_engine.h) and nothing of Bullet.
 *
 * The body (the body key) is a btMultiBody without links, a floating base
 * (default), or a btRigidBody; its shape is the exact thin disk: a Z-axis
 * cylinder of radius r and half-height 0, whose collision margin Bullet
 * itself drops to 0 (setSafeMargin: a tenth of the smallest half-extent), so
 * its support point is the rim's lowest point P = G + r d, and the convex-plane
 * collider gives that one point. For a [disk] thickness the shape is
 * btCylinderShapeZ(r, r, h) with its margin set to 0 (geom cylinder, as ODE's
 * and MuJoCo's): its support point is the exact rim corner (the contact
 * distance 3.5e-18 m at the exact height), compared with the matched
 * reference (quarter_circle: theta 4.3e-4 rad; with the default margin 0.04 m
 * a 2 mm disk sank 1.6 cm). The ground is a static plane z = 0; gravity -z;
 * friction the coefficient of [engines.bullet] friction (the plane's is 1,
 * Bullet multiplies them), in two directions per contact
 * (SOLVER_USE_2_FRICTION_DIRECTIONS: with one, a btRigidBody on the steady
 * circle lost 1.3 % of its energy a second at 1e-3 s and 0.13 % at 1e-4 s;
 * btMultiBody's contacts are the same either way); restitution 0, no
 * damping, no sleeping.
 *
 * Faults end the run, never the process: Bullet reports none (no error
 * callback; its asserts are compiled out), so a non-finite state, a runaway
 * energy, a disk sunk deeper than r/20 are diverged and the lowest point more
 * than r/100 above the ground for 0.05 s is lost_contact, as in ODE
 * (engines/ode/engine_ode.c): checked every BT_CHECK_STEPS steps and before every sample,
 * lying down (and a NaN in n.z) every step. A C++ exception (out of memory)
 * is caught at each entry point and ends the run as an error.
 */
#include <btBulletDynamicsCommon.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <BulletDynamics/Featherstone/btMultiBodyMLCPConstraintSolver.h>
#include <BulletDynamics/MLCPSolvers/btDantzigSolver.h>
#include <BulletDynamics/MLCPSolvers/btMLCPSolver.h>
#include <BulletDynamics/MLCPSolvers/btSolveProjectedGaussSeidel.h>

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
#include "bullet_settings.h"
#include "engine_scene.h"
#include "engine_friction.h"
#include "engine_shape.h"
#include "engine_watch.h"
}
#include "bullet_contact.h"

#define BT_CHECK_STEPS 16
#define TOUCH 1e-6 /* m: a manifold point this close counts as a contact */

namespace {


struct bullet_engine {
  bullet_settings set;
  red_disk disk;
  dv_geometry geom; /* the thin disk: a cylinder of half-thickness 0 */
  btDefaultCollisionConfiguration *config;
  btCollisionDispatcher *dispatcher;
  btBroadphaseInterface *broadphase;
  btConstraintSolver *solver;
  btMLCPSolverInterface *mlcp;
  btDiscreteDynamicsWorld *world; /* a btMultiBodyDynamicsWorld for BODY_MULTI */
  btCylinderShapeZ *shape;
  btStaticPlaneShape *plane_shape;
  btRigidBody *ground;
  btRigidBody *body;             /* BODY_RIGID */
  btMultiBody *mb;               /* BODY_MULTI */
  btMultiBodyLinkCollider *link; /* its base's collider */
  long k;                        /* steps since reset: time = k timestep */
  dv_engine_watch watch;         /* its faults (engine_watch.h) */
  double prev_y[RED_NSTATE];     /* last canonical state, for unwrapping */
  double theta_limit, cos_limit; /* lying down outside (limit, pi - limit) */
  int status;                    /* < 0 once the run failed; DV_EVENT once it ended */
  dv_engine_stats st;
};

/* "Bullet 3.24 double precision" */
const char *bullet_version(void) {
  static char text[64];
  if (!text[0]) {
    const int v = btGetVersion();
    snprintf(text, sizeof text, "Bullet %d.%02d %s precision", v / 100, v % 100,
             sizeof(btScalar) == sizeof(double) ? "double" : "single");
  }
  return text;
}

/* mark the run failed: stats outcome and detail, err, and the status kept */
__attribute__((format(printf, 4, 5))) int failed(bullet_engine *e, dv_failure failure,
                                                 dv_error *err, const char *fmt, ...) {
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

void read_pose(const bullet_engine *e, dv_pose *p) {
  btVector3 pos, vel, omega;
  btMatrix3x3 R;
  if (e->mb) {
    pos = e->mb->getBasePos();
    R = btMatrix3x3(e->mb->getWorldToBaseRot().inverse());
    vel = e->mb->getBaseVel();
    omega = e->mb->getBaseOmega();
  } else {
    const btTransform &tr = e->body->getWorldTransform();
    pos = tr.getOrigin();
    R = tr.getBasis();
    vel = e->body->getLinearVelocity();
    omega = e->body->getAngularVelocity();
  }
  for (int i = 0; i < 3; i++) {
    p->pos[i] = pos[i];
    p->vel[i] = vel[i];
    p->omega[i] = omega[i];
    for (int j = 0; j < 3; j++) p->R[3 * i + j] = R[i][j];
  }
}

void write_pose(bullet_engine *e, const dv_pose *p) {
  const btMatrix3x3 R(p->R[0], p->R[1], p->R[2], p->R[3], p->R[4], p->R[5], p->R[6], p->R[7],
                      p->R[8]);
  btQuaternion q;
  R.getRotation(q);
  const btTransform tr(q, btVector3(p->pos[0], p->pos[1], p->pos[2]));
  const btVector3 vel(p->vel[0], p->vel[1], p->vel[2]);
  const btVector3 omega(p->omega[0], p->omega[1], p->omega[2]);
  if (e->mb) {
    e->mb->setBaseWorldTransform(tr);
    e->mb->setBaseVel(vel); /* after finalizeMultiDof, which zeroes them */
    e->mb->setBaseOmega(omega);
    e->mb->clearForcesAndTorques();
    e->link->setWorldTransform(tr);
  } else {
    e->body->setWorldTransform(tr);
    e->body->setInterpolationWorldTransform(tr);
    e->body->setLinearVelocity(vel);
    e->body->setAngularVelocity(omega);
    e->body->setInterpolationLinearVelocity(vel);
    e->body->setInterpolationAngularVelocity(omega);
    e->body->clearForces();
  }
}


/* contact points within TOUCH of the ground */
int count_contacts(const bullet_engine *e) {
  int n = 0;
  btDispatcher *d = e->world->getDispatcher();
  for (int m = 0; m < d->getNumManifolds(); m++) {
    const btPersistentManifold *pm = d->getManifoldByIndexInternal(m);
    for (int i = 0; i < pm->getNumContacts(); i++)
      if (pm->getContactPoint(i).getDistance() <= TOUCH) n++;
  }
  return n;
}

void destroy(bullet_engine *e) {
  if (e->world) {
    if (e->mb) static_cast<btMultiBodyDynamicsWorld *>(e->world)->removeMultiBody(e->mb);
    if (e->link) e->world->removeCollisionObject(e->link);
    if (e->body) e->world->removeRigidBody(e->body);
    if (e->ground) e->world->removeRigidBody(e->ground);
  }
  delete e->world;
  delete e->mb;
  delete e->link;
  delete e->body;
  delete e->ground;
  delete e->shape;
  delete e->plane_shape;
  delete e->solver;
  delete e->mlcp;
  delete e->broadphase;
  delete e->dispatcher;
  delete e->config;
}

void bullet_free(void *p) {
  bullet_engine *e = static_cast<bullet_engine *>(p);
  if (!e) return;
  destroy(e);
  delete e;
}

/* world, ground and body */
void build(bullet_engine *e) {
  e->config = new btDefaultCollisionConfiguration();
  e->dispatcher = new btCollisionDispatcher(e->config);
  e->broadphase = new btDbvtBroadphase();
  if (e->set.solver == SOLVER_DANTZIG) e->mlcp = new btDantzigSolver();
  if (e->set.solver == SOLVER_PGS) e->mlcp = new btSolveProjectedGaussSeidel();
  if (e->set.body == BODY_MULTI) {
    btMultiBodyConstraintSolver *solver =
        e->mlcp ? new btMultiBodyMLCPConstraintSolver(e->mlcp) : new btMultiBodyConstraintSolver();
    e->solver = solver;
    e->world = new btMultiBodyDynamicsWorld(e->dispatcher, e->broadphase, solver, e->config);
  } else {
    if (e->mlcp)
      e->solver = new btMLCPSolver(e->mlcp);
    else
      e->solver = new btSequentialImpulseConstraintSolver();
    e->world = new btDiscreteDynamicsWorld(e->dispatcher, e->broadphase, e->solver, e->config);
  }
  e->world->setGravity(btVector3(0.0, 0.0, -e->disk.g));
  btContactSolverInfo &info = e->world->getSolverInfo();
  info.m_numIterations = e->set.solver_iterations;
  info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
  info.m_globalCfm = e->set.cfm;

  e->plane_shape = new btStaticPlaneShape(btVector3(0.0, 0.0, 1.0), 0.0);
  btRigidBody::btRigidBodyConstructionInfo ground(0.0, NULL, e->plane_shape);
  ground.m_friction = 1.0;
  ground.m_restitution = 0.0;
  e->ground = new btRigidBody(ground);
  e->world->addRigidBody(e->ground);

  /* the thin disk: Bullet drops the margin to 0 at half-height 0 */
  e->shape = dv_bullet_disk_shape(e->disk.r, e->geom.half_thickness); /* margin 0 */
  const btVector3 inertia(e->disk.A, e->disk.A, e->disk.C);
  if (e->set.body == BODY_MULTI) {
    e->mb = new btMultiBody(0, e->disk.m, inertia, false, false);
    e->mb->setLinearDamping(0.0);
    e->mb->setAngularDamping(0.0);
    e->mb->setUseGyroTerm(e->set.gyroscopic != GYRO_OFF);
    e->mb->setHasSelfCollision(false);
    e->mb->setCanSleep(false);
    e->mb->finalizeMultiDof();
    e->link = new btMultiBodyLinkCollider(e->mb, -1);
    e->link->setCollisionShape(e->shape);
    e->link->setFriction(e->set.friction);
    e->link->setRestitution(0.0);
    e->link->setActivationState(DISABLE_DEACTIVATION);
    /* a dynamic body's filter: not the static group, which the plane is in */
    e->world->addCollisionObject(e->link, btBroadphaseProxy::DefaultFilter,
                                 btBroadphaseProxy::AllFilter);
    e->mb->setBaseCollider(e->link);
    static_cast<btMultiBodyDynamicsWorld *>(e->world)->addMultiBody(e->mb);
  } else {
    btRigidBody::btRigidBodyConstructionInfo ci(e->disk.m, NULL, e->shape, inertia);
    ci.m_friction = e->set.friction;
    ci.m_restitution = 0.0;
    ci.m_linearDamping = ci.m_angularDamping = 0.0;
    e->body = new btRigidBody(ci);
    static const int flags[] = {BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY,
                                BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT, 0};
    e->body->setFlags(flags[e->set.gyroscopic]);
    e->body->setSleepingThresholds(0.0, 0.0);
    e->body->setActivationState(DISABLE_DEACTIVATION);
    e->world->addRigidBody(e->body);
  }
}

void *bullet_alloc(const dv_scenario *sc, dv_error *err) {
  if (!(sc->disk.A > 0.0 && sc->disk.C > 0.0))
    return dv_fail(err, DV_EINPUT, "Bullet needs a positive definite inertia (A = %g, C = %g)",
                   sc->disk.A, sc->disk.C),
           nullptr;
  bullet_engine *e = new (std::nothrow) bullet_engine();
  if (!e) return dv_fail(err, DV_ESYSTEM, "out of memory: the Bullet engine's state"), nullptr;
  e->set = *static_cast<const bullet_settings *>(dv_scenario_settings(sc, "bullet"));
  /* a scenario built in code leaves the step to the scene */
  dv_engine_derive_step(sc, &dv_bullet_models[e->set.body], &e->set.timestep, NULL, NULL, 0, NULL);
  e->disk = sc->disk;
  dv_engine_derive_shape(sc, &dv_bullet_shape, &e->set.geom, &e->set.half_thickness, NULL, 0, NULL);
  dv_engine_derive_friction(sc, "bullet", "friction", 1.0, "", &e->set.friction, NULL, 0, NULL);
  e->geom = dv_geometry{DV_SHAPE_CYLINDER, sc->disk.r,
                        e->set.geom == 1 ? e->set.half_thickness : 0.0};
  e->theta_limit = dv_reference_settings(sc)->theta_limit;
  e->cos_limit = std::cos(e->theta_limit);
  try {
    build(e);
  } catch (const std::exception &ex) {
    dv_fail(err, DV_ESYSTEM, "Bullet: %s", ex.what());
    bullet_free(e);
    return nullptr;
  }
  return e;
}

int bullet_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  bullet_engine *e = static_cast<bullet_engine *>(p);
  memset(&e->st, 0, sizeof e->st);
  e->k = 0;
  e->status = DV_OK;
  memcpy(e->prev_y, state, sizeof e->prev_y);
  for (int i = 0; i < RED_NSTATE; i++)
    if (!std::isfinite(state[i])) return failed(e, DV_FAILURE_SETUP, err, "non-finite initial state");
  dv_pose pose;
  dv_pose_from_state(&e->geom, state, &pose);
  write_pose(e, &pose);
  /* forget the previous run's contacts (warm starting) */
  btOverlappingPairCache *pairs = e->world->getBroadphase()->getOverlappingPairCache();
  for (btCollisionObject *o : {static_cast<btCollisionObject *>(e->ground),
                               e->mb ? static_cast<btCollisionObject *>(e->link) : e->body})
    pairs->cleanProxyFromPairs(o->getBroadphaseHandle(), e->dispatcher);
  e->world->updateAabbs();
  read_pose(e, &pose);
  char why[160];
  const dv_failure fault = dv_engine_watch_start(&e->watch, &e->disk, &pose, why, sizeof why);
  if (fault) return failed(e, fault, err, "%s", why);
  return DV_OK;
}

/* the divergence and lost-contact checks over the steps since the last */
int check_state(bullet_engine *e, dv_error *err) {
  dv_pose p;
  read_pose(e, &p);
  char why[160];
  const dv_failure fault = dv_engine_watch_check(&e->watch, &e->disk, &e->geom, &p, e->k,
                                                 e->set.timestep, why, sizeof why);
  return fault ? failed(e, fault, err, "%s", why) : DV_OK;
}

/* the body axis' z component: cos theta */
double axis_z(const bullet_engine *e) {
  if (e->mb) return btMatrix3x3(e->mb->getWorldToBaseRot().inverse())[2][2];
  return e->body->getWorldTransform().getBasis()[2][2];
}

/* one step and its lying-down test (n.z = cos theta, as the references' event) */
int step(bullet_engine *e, dv_error *err) {
  const double dt = e->set.timestep;
  e->world->stepSimulation(dt, 0, dt);
  e->k++;
  e->st.steps++;
  const double nz = axis_z(e);
  if (!(std::fabs(nz) <= e->cos_limit)) {
    if (std::isnan(nz)) return check_state(e, err);
    dv_engine_lay_down(&e->st, nz > 0.0, e->theta_limit, e->k * dt);
    e->status = DV_EVENT;
    return DV_EVENT;
  }
  return e->k - e->watch.checked < BT_CHECK_STEPS ? DV_OK : check_state(e, err);
}

int bullet_advance(void *p, double t, dv_sample *out, dv_error *err) {
  bullet_engine *e = static_cast<bullet_engine *>(p);
  if (e->status < 0)
    return dv_fail(err, e->status, "%s: %s", dv_outcome_name(e->st.outcome), e->st.detail);
  if (e->status == DV_EVENT) return DV_EVENT;
  const double dt = e->set.timestep;
  int status = DV_OK;
  try {
    while (status == DV_OK && e->k * dt < t - 0.5 * dt) status = step(e, err);
    if (status == DV_OK && e->k > e->watch.checked) status = check_state(e, err);
  } catch (const std::exception &ex) {
    return failed(e, DV_FAILURE_LIBRARY, err, "Bullet: %s", ex.what());
  }
  if (status < 0) return status;
  dv_pose pose;
  read_pose(e, &pose);
  dv_sample_from_pose(&e->disk, &e->geom, &pose, status == DV_EVENT ? e->k * dt : t, e->prev_y,
                      out);
  out->contacts = count_contacts(e);
  memcpy(e->prev_y, out->y, sizeof e->prev_y);
  dv_stats_add_sample(&e->st, out);
  return status;
}

void bullet_stats(const void *p, dv_engine_stats *out) {
  *out = static_cast<const bullet_engine *>(p)->st;
}


} // namespace

extern "C" {
DV_ENGINE_MODULE_EXPORT(bullet_version, bullet_alloc, bullet_reset, bullet_advance, bullet_stats, bullet_free);
}
