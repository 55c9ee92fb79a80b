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
#include "engine_choose.h"
#include "engine_scene.h"
#include "engine_friction.h"
#include "engine_shape.h"
#include "engine_watch.h"
}
#include "bullet_contact.h"

#define BT_CHECK_STEPS 16
#define TOUCH 1e-6 /* m: a manifold point this close counts as a contact */

/* The error model of engine_scene.h per body: the theta error is first order
 * in the timestep (x10 steps give x10 errors: test_engine_bullet). c is the
 * largest err T^2 / (dt D) measured with diskval compare at dt = 2.5e-5 s on
 * the shipped scenarios ODE's model is fitted on (thin disk, whole validity
 * window, T the shortest time scale, D the duration), btMultiBody /
 * btRigidBody: nonuniform 0.83 / 1.29 (its wobble's phase), euler_disk 0.20,
 * steady_steep 0.16 / 0.45, steady_circle 0.107 / 0.29, fast_spin 0.034,
 * falling 0.011 / 0.011, upright_stable 7.5e-5 / 1.4e-3, with the sequential
 * impulse solver (solver si). The default solver dantzig gives the same theta
 * errors to three digits on each of these scenes (btMultiBody, 2.5e-5 s) and
 * at the same cost per step; where C is small the error was the solver's, not
 * the step's: 10 sequential impulse iterations do not converge on a friction
 * row of tiny effective mass C / r^2 (small_c 4.1e-3 rad with si, 9.6e-5 with
 * dantzig; tiny_c, C = 1e-6 m r^2, diverged with si, 9.6e-5 with dantzig).
 * dantzig slips where the friction demand is near the coefficient: euler_disk
 * (ratio 4.08) errs 0.049 rad at friction 5 and 6, si 2.4e-4; at the
 * scene's friction 10, both 2.4e-4. Cost of a step (compare's
 * wall_per_sim_s over the steps, every scenario above): btMultiBody 1.8 us,
 * btRigidBody 2.4 us. */
#define BULLET_C_MULTI 0.83
#define BULLET_C_RIGID 1.3
#define BULLET_COST_MULTI 1.8e-6
#define BULLET_COST_RIGID 2.4e-6

namespace {

/* [engines.bullet] */
struct bullet_settings {
  double timestep;       /* s */
  int body;              /* 0 btMultiBody, 1 btRigidBody */
  int solver_iterations; /* sequential impulse iterations */
  double friction;       /* coefficient */
  double cfm;            /* the solver's global constraint force mixing */
  int gyroscopic;        /* 0 implicit_body, 1 explicit, 2 off */
  int geom;              /* 0 thin, 1 cylinder */
  double half_thickness; /* m, the cylinder's half-length */
  int solver;            /* 0 sequential impulse, 1 MLCP Dantzig, 2 MLCP projected Gauss-Seidel */
};

const char *const BODIES[] = {"multibody", "rigidbody", NULL};
const char *const GYROSCOPIC[] = {"implicit_body", "explicit", "off", NULL};
const char *const GEOMS[] = {"thin", "cylinder", NULL};
const char *const SOLVERS[] = {"si", "dantzig", "pgs", NULL};
enum { BODY_MULTI = 0, BODY_RIGID = 1 };
enum { GYRO_IMPLICIT_BODY = 0, GYRO_EXPLICIT = 1, GYRO_OFF = 2 };
enum { SOLVER_SI = 0, SOLVER_DANTZIG = 1, SOLVER_PGS = 2 };

#define AT(field) offsetof(bullet_settings, field)

const dv_setting_spec KEYS[] = {
    {"timestep", DV_SETTING_REAL, AT(timestep), 0, 0, NAN, 1e-7, 0.1, NULL, NULL, "s",
     "default: from the scene's time scales"},
    {"body", DV_SETTING_CHOICE, AT(body), 0, 0, BODY_MULTI, 0, 1, BODIES, NULL, "",
     "multibody: btMultiBody (Featherstone) floating base; rigidbody: btRigidBody"},
    {"solver_iterations", DV_SETTING_INT, AT(solver_iterations), 0, 0, 10, 1, 100000, NULL, NULL,
     "", "iterations of the si and pgs solvers (dantzig solves the LCP exactly)"},
    {"friction", DV_SETTING_REAL, AT(friction), 0, 0, NAN, 0.0, 1e9, NULL, NULL, "",
     "coefficient, in each of two directions"},
    {"cfm", DV_SETTING_REAL, AT(cfm), 0, 0, 0.0, 0.0, 1.0, NULL, NULL, "",
     "the solver's global constraint force mixing: contact softness"},
    {"gyroscopic", DV_SETTING_CHOICE, AT(gyroscopic), 0, 0, GYRO_IMPLICIT_BODY, 0, 2, GYROSCOPIC,
     NULL, "", "rigidbody: Bullet's gyroscopic flag; multibody: its gyroscopic term, on unless off"},
    {"geom", DV_SETTING_CHOICE, AT(geom), 0, 0, 0, 0, 1, GEOMS, NULL, "",
     "thin: the exact disk; cylinder: btCylinderShapeZ of margin 0"},
    {"half_thickness", DV_SETTING_REAL, AT(half_thickness), 0, 0, 0.002, 1e-6, 1.0, NULL, NULL,
     "m", "cylinder half-length (default: [disk] thickness / 2 if > 0)"},
    {"solver", DV_SETTING_CHOICE, AT(solver), 0, 0, SOLVER_DANTZIG, 0, 2, SOLVERS, NULL, "",
     "dantzig: the contact's LCP solved exactly (btMLCPSolver); si: sequential impulse; pgs"},
};

/* the error models (constants above) */
const dv_step_model MODELS[] = {
    {"bullet", BULLET_C_MULTI, 0.0, NULL, BULLET_COST_MULTI},
    {"bullet", BULLET_C_RIGID, 0.0, NULL, BULLET_COST_RIGID},
};

/* The knobs chosen per scene (engine_choose.h): the body and the step, from
 * each body's model down to half of it. btMultiBody's theta error is 1/3 of
 * btRigidBody's at the same step on most scenes (the steady circle: 1.1e-2
 * against 2.8e-2 rad over 1 s at 1e-3 s), and its step costs less, so it is
 * probed first; btRigidBody stays a candidate for the scenes where the
 * multibody diverges (a tiny C). */
const dv_engine_knobs KNOBS = {"bullet", "body", MODELS, 2, 0x3, 1};

int bullet_check(dv_scenario *sc, void *block, dv_setting_issue *issue);

const dv_shape_keys SHAPE = {"bullet", "geom", 1, 0, "half_thickness"};

const dv_settings_section SETTINGS = {"bullet", KEYS, sizeof KEYS / sizeof KEYS[0],
                                      sizeof(bullet_settings), bullet_check};

int bullet_check(dv_scenario *sc, void *block, dv_setting_issue *issue) {
  bullet_settings *s = static_cast<bullet_settings *>(block);
  char why[DV_DERIVED_BYTES];
  const char *keys[8];
  (void)issue;
  const int given = dv_scenario_is_given(sc, "bullet", "body");
  const dv_knob_choice in = {given ? s->body : -1, s->timestep, NAN};
  dv_knob_choice out;
  dv_engine_choose(sc, &dv_engine_bullet, &KNOBS, s->body, &in, &out, why, sizeof why, keys);
  s->body = out.choice;
  s->timestep = out.timestep;
  dv_engine_derive_shape(sc, &SHAPE, &s->geom, &s->half_thickness, why, sizeof why, keys);
  dv_engine_derive_friction(sc, "bullet", "friction", 1.0, "", &s->friction, why, sizeof why,
                            keys);
  dv_scenario_set_derived(sc, "bullet", keys, why);
  return 0;
}

const dv_engine_search SEARCH = {"bullet", "body", "timestep", 1e-7, 0.02, NULL};

/* a stiffer contact: a 100x smaller global CFM (0 by default: rigid already) */
const dv_engine_contact CONTACT = {"geom", "thin", "cfm", 0.01, 0.0, "friction", NULL, 0};

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
  e->set = *static_cast<const bullet_settings *>(dv_scenario_settings(sc, SETTINGS.name));
  /* a scenario built in code leaves the step to the scene */
  dv_engine_derive_step(sc, &MODELS[e->set.body], &e->set.timestep, NULL, NULL, 0, NULL);
  e->disk = sc->disk;
  dv_engine_derive_shape(sc, &SHAPE, &e->set.geom, &e->set.half_thickness, NULL, 0, NULL);
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

/* the cylinder's half-length where the scene makes Bullet's body a cylinder, else 0 */
double bullet_half_thickness(const dv_scenario *sc) {
  bullet_settings s = *static_cast<const bullet_settings *>(dv_scenario_settings(sc, SETTINGS.name));
  dv_engine_derive_shape(sc, &SHAPE, &s.geom, &s.half_thickness, NULL, 0, NULL);
  return s.geom == 1 ? s.half_thickness : 0.0;
}

} // namespace

extern "C" const dv_engine_type dv_engine_bullet = {
    "bullet",
    "Bullet 3.24 contact simulation: the thin disk or a cylinder on a plane (btMultiBody or btRigidBody)",
    DV_ENGINE_CONTACT,
    &SETTINGS,
    &SEARCH,
    &CONTACT,
    bullet_half_thickness,
    NULL, /* tighten: a reference's */
    bullet_version,
    bullet_alloc,
    bullet_reset,
    bullet_advance,
    bullet_stats,
    bullet_free,
    NULL, /* alloc_self: a replay's */
    NULL, /* data */
    0,    /* outside: linked */
    NULL, /* missing */
};
