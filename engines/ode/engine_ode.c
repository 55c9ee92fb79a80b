/* engine_ode: the disk as one rigid body on a plane in ODE 0.16 (double
 * precision, DESIGN section 4). Its geom (the geom key) is the thin disk by
 * default: a user geom class with one contact at the lowest point of the rim
 * circle (engine_ode_thin.h), compared with the thin reference; or a cylinder
 * of half_thickness, ODE's own collider (at most 4 points), compared with the
 * reference of that thickness.
 *
 * Each step collides the geom with the plane directly (dCollide), makes
 * contact joints (Coulomb friction; no rolling or pivot friction), steps
 * (dWorldStep or dWorldQuickStep; ODE's implicit gyroscopic term stays on)
 * and empties the joint group. The world's ERP/CFM are set
 * but only matter to non-contact joints: the contacts use soft_erp/soft_cfm.
 *
 * Faults end the run, never the process. ODE's error and debug handlers must
 * not return (ODE calls exit or abort after them), so every entry point runs
 * its ODE calls under setjmp and the handlers longjmp back with the message
 * in a static buffer. The handlers, the jump target and that buffer are
 * process-wide: one engine calls into ODE at a time (each run is
 * single-threaded). After such a jump the world is only destroyed, not
 * stepped again. Run-time checks, every 16 steps and before every sample (each
 * step: lying down, and a NaN in the rotation): a non-finite body state, a
 * runaway energy, E > E0 + |E0|/2 + m g r, or the lowest point sunk deeper
 * than r/20 (a few 1e-5 m is normal) is diverged; the lowest point more than
 * r/100 above the ground for longer than 0.05 s is lost_contact.
 */
#include <math.h>
#include <ode/ode.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_pose.h"
#include "dv_reference.h"
#include "engine_module.h"
#include "engine_ode_body.h"
#include "engine_ode_thin.h"
#include "engine_scene.h"
#include "engine_friction.h"
#include "engine_shape.h"
#include "engine_watch.h"

#define ODE_MAX_CONTACTS 4
/* the full checks' share of a 1 us step falls from 4% (every step) to 0.3% */
#define ODE_CHECK_STEPS 16

#include "ode_settings.h"

typedef struct ode_engine {
  ode_settings set;
  red_disk disk;
  dv_geometry geom;
  dWorldID world;
  dBodyID body;
  dGeomID shape, plane; /* the thin disk or the cylinder; the ground */
  dJointGroupID group;
  long k;                    /* steps since reset: time = k timestep */
  dv_engine_watch watch;         /* its faults (engine_watch.h) */
  double prev_y[RED_NSTATE]; /* last canonical state, for unwrapping */
  double theta_limit;        /* rad: the run ends at an event outside (limit, pi - limit) */
  double cos_limit;          /* cos(theta_limit), the per-step test of n.z */
  dContact contact;          /* every contact's surface, made once */
  int ncontacts;             /* contacts of the last collision */
  int status;                /* < 0 once the run failed */
  int broken;                /* an ODE error jumped out: the world is only destroyed */
  dv_engine_stats st;
} ode_engine;

typedef int (*ode_call)(ode_engine *e, void *arg, dv_error *err);

static jmp_buf *ode_jump;       /* where the error handlers return to */
static ode_engine *ode_current; /* the engine inside a guarded call */
static char ode_message[200];   /* the last message from ODE */

/* error and debug handler: keep the message, jump back to the guard */
/* set once ODE was left by a longjmp: its internal state may be half-torn */
static int ode_poisoned;

/* at exit: free ODE's global state, unless an error left it inconsistent */
static void ode_close(void) {
  if (!ode_poisoned) dCloseODE();
}

static void ode_on_error(int num, const char *msg, va_list ap) {
  vsnprintf(ode_message, sizeof ode_message, msg, ap);
  ode_poisoned = 1;
  if (ode_jump) longjmp(*ode_jump, num ? num : 1);
  /* unreachable: every ODE call that can fail runs guarded; ODE aborts now */
  fprintf(stderr, "ODE error outside a guarded call: %s\n", ode_message);
}

/* message handler (warnings, e.g. from dMassCheck): count and keep */
static void ode_on_message(int num, const char *msg, va_list ap) {
  vsnprintf(ode_message, sizeof ode_message, msg, ap);
  if (ode_current) ode_current->st.warnings++;
}

/* initialise ODE and install the handlers, once per process (not thread-safe) */
static void ode_init_once(void) {
  static int done = 0;
  if (done) return;
  dInitODE2(0);
  atexit(ode_close); /* ODE keeps per-thread state until it is closed */
  dSetErrorHandler(ode_on_error);
  dSetDebugHandler(ode_on_error);
  dSetMessageHandler(ode_on_message);
  done = 1;
}

/* "ODE 0.16.2 double precision": the header's version, dGetConfiguration()'s precision */
static const char *ode_version(void) {
  static char text[64];
  if (!text[0]) {
    const char *conf = dGetConfiguration();
    snprintf(text, sizeof text, "ODE %s %s precision", dODE_VERSION,
             strstr(conf, "ODE_double_precision") ? "double" : "single");
  }
  return text;
}

/* mark the run failed: stats outcome and detail, err, and the status kept */
static int ode_failed(ode_engine *e, dv_failure failure, dv_error *err, const char *fmt, ...) {
  const dv_outcome outcome = dv_failure_outcome(failure);
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(e->st.detail, sizeof e->st.detail, fmt, ap);
  va_end(ap);
  e->st.outcome = outcome;
  e->st.failure = failure;
  e->status = DV_ENUMERIC;
  return dv_fail(err, DV_ENUMERIC, "%s: %s", dv_outcome_name(outcome), e->st.detail);
}

/* run fn under the error guard; an ODE error or debug message fails the run */
static int ode_guarded(ode_engine *e, ode_call fn, void *arg, dv_error *err) {
  jmp_buf here;
  jmp_buf *volatile outer = ode_jump;
  ode_engine *volatile outer_engine = ode_current;
  ode_jump = &here;
  ode_current = e;
  int status;
  if (setjmp(here) == 0) {
    status = fn(e, arg, err);
  } else {
    e->broken = 1;
    dv_pose p;
    dv_ode_read_pose(e->body, &p);
    status = dv_pose_finite(&p)
                 ? ode_failed(e, DV_FAILURE_LIBRARY, err, "ODE error: %s", ode_message)
                 : ode_failed(e, DV_FAILURE_NAN, err, "non-finite state (ODE: %s)", ode_message);
  }
  ode_jump = outer;
  ode_current = outer_engine;
  return status;
}

/* destroy the ODE objects (NULL-safe) */
static int ode_destroy(ode_engine *e, void *arg, dv_error *err) {
  if (e->group) dJointGroupDestroy(e->group);
  if (e->shape) dGeomDestroy(e->shape);
  if (e->plane) dGeomDestroy(e->plane);
  if (e->world) dWorldDestroy(e->world); /* destroys the body too */
  e->group = NULL, e->shape = e->plane = NULL, e->world = NULL, e->body = NULL;
  return DV_OK;
}

/* NULL-safe free */
static void ode_free(void *p) {
  ode_engine *e = p;
  if (!e) return;
  ode_guarded(e, ode_destroy, NULL, NULL);
  free(e);
}

/* world, body, disk geom and plane */
static int ode_build(ode_engine *e, void *arg, dv_error *err) {
  dRandSetSeed(0); /* QuickStep permutes rows with it: every run from the same state */
  e->world = dWorldCreate();
  dWorldSetGravity(e->world, 0.0, 0.0, -e->disk.g);
  dWorldSetERP(e->world, e->set.erp);
  dWorldSetCFM(e->world, e->set.cfm);
  dWorldSetQuickStepNumIterations(e->world, e->set.iterations);
  e->body = dBodyCreate(e->world);
  dMass mass;
  dMassSetParameters(&mass, e->disk.m, 0.0, 0.0, 0.0, e->disk.A, e->disk.A, e->disk.C, 0.0, 0.0,
                     0.0);
  dBodySetMass(e->body, &mass);
  /* both about the body's z axis; ODE's cylinder length is the full thickness */
  if (e->set.geom == 1)
    e->shape = dCreateCylinder(NULL, e->geom.radius, 2.0 * e->geom.half_thickness);
  else
    e->shape = dv_ode_thin_create(e->geom.radius);
  dGeomSetBody(e->shape, e->body);
  e->plane = dCreatePlane(NULL, 0.0, 0.0, 1.0, 0.0);
  e->group = dJointGroupCreate(0);
  return DV_OK;
}

/* an engine for the scenario's disk and [engines.ode] settings (the timestep,
 * when it is NAN, derived here) */
static void *ode_alloc(const dv_scenario *sc, dv_error *err) {
  if (!(sc->disk.A > 0.0 && sc->disk.C > 0.0))
    return dv_fail(err, DV_EINPUT, "ODE needs a positive definite inertia (A = %g, C = %g)",
                   sc->disk.A, sc->disk.C),
           NULL;
  ode_engine *e = calloc(1, sizeof *e);
  if (!e) return dv_fail(err, DV_ESYSTEM, "out of memory: the ODE engine's state"), NULL;
  ode_init_once();
  e->set = *(const ode_settings *)dv_scenario_settings(sc, "ode");
  /* a scenario built in code leaves the step to the scene */
  dv_engine_derive_step(sc, &dv_ode_models[e->set.stepper], &e->set.timestep, NULL, NULL, 0, NULL);
  dv_engine_derive_shape(sc, &dv_ode_shape, &e->set.geom, &e->set.half_thickness, NULL, 0, NULL);
  dv_ode_derive_friction(sc, &e->set, NULL, 0, NULL);
  e->disk = sc->disk;
  /* a cylinder with h = 0 is the thin disk: rho = r d */
  e->geom =
      (dv_geometry){DV_SHAPE_CYLINDER, sc->disk.r, e->set.geom == 1 ? e->set.half_thickness : 0.0};
  e->theta_limit = dv_reference_settings(sc)->theta_limit;
  e->cos_limit = cos(e->theta_limit);
  e->contact.surface.mode = dContactSoftERP | dContactSoftCFM;
  if (e->set.friction_model == 0) e->contact.surface.mode |= dContactApprox1;
  e->contact.surface.mu = e->set.friction;
  e->contact.surface.soft_erp = e->set.soft_erp;
  e->contact.surface.soft_cfm = e->set.soft_cfm;
  if (ode_guarded(e, ode_build, NULL, err) < 0) return ode_free(e), NULL;
  return e;
}

/* collide the disk geom with the plane; with joints, add contact joints */
static int ode_collide(ode_engine *e, int joints) {
  dContactGeom cg[ODE_MAX_CONTACTS];
  const int n = dCollide(e->shape, e->plane, ODE_MAX_CONTACTS, cg, sizeof cg[0]);
  for (int i = 0; joints && i < n; i++) {
    e->contact.geom = cg[i];
    dJointAttach(dJointCreateContact(e->world, e->group, &e->contact), e->body, NULL);
  }
  return e->ncontacts = n;
}

/* place the body in the state (guarded part of reset) */
static int ode_place(ode_engine *e, void *arg, dv_error *err) {
  const double *state = arg;
  dv_pose p;
  dv_pose_from_state(&e->geom, state, &p);
  dJointGroupEmpty(e->group);
  dv_ode_write_pose(e->body, &p);
  dBodySetForce(e->body, 0.0, 0.0, 0.0);
  dBodySetTorque(e->body, 0.0, 0.0, 0.0);
  dv_ode_read_pose(e->body, &p);
  ode_collide(e, 0);
  char why[160];
  const dv_failure fault = dv_engine_watch_start(&e->watch, &e->disk, &p, why, sizeof why);
  if (fault) return ode_failed(e, fault, err, "%s", why);
  return DV_OK;
}

/* start a run from a canonical state */
static int ode_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  ode_engine *e = p;
  if (e->broken) return dv_fail(err, DV_ENUMERIC, "ODE failed earlier: %s", e->st.detail);
  memset(&e->st, 0, sizeof e->st);
  e->k = 0;
  e->status = DV_OK;
  memcpy(e->prev_y, state, sizeof e->prev_y);
  for (int i = 0; i < RED_NSTATE; i++)
    if (!isfinite(state[i]))
      return ode_failed(e, DV_FAILURE_SETUP, err, "non-finite initial state");
  return ode_guarded(e, ode_place, (void *)state, err);
}

/* the divergence and lost-contact checks of the body's state, over the steps
 * since the last check */
static int ode_check_state(ode_engine *e, dv_error *err) {
  dv_pose p;
  dv_ode_read_pose(e->body, &p);
  char why[160];
  const dv_failure fault = dv_engine_watch_check(&e->watch, &e->disk, &e->geom, &p, e->k,
                                                 e->set.timestep, why, sizeof why);
  return fault ? ode_failed(e, fault, err, "%s", why) : DV_OK;
}

/* one step and its lying-down test (n.z = cos theta, like the references'
 * event); a NaN fails that test too and goes to the full checks, which
 * otherwise run every ODE_CHECK_STEPS steps and before every sample */
static int ode_step(ode_engine *e, dv_error *err) {
  const double dt = e->set.timestep;
  ode_collide(e, 1);
  if (e->set.stepper == 1)
    dWorldQuickStep(e->world, dt);
  else
    dWorldStep(e->world, dt);
  dJointGroupEmpty(e->group);
  e->k++;
  e->st.steps++;
  const double nz = dBodyGetRotation(e->body)[10];
  if (!(fabs(nz) <= e->cos_limit)) {
    if (isnan(nz)) return ode_check_state(e, err);
    dv_engine_lay_down(&e->st, nz > 0.0, e->theta_limit, e->k * dt);
    e->status = DV_EVENT;
    return DV_EVENT;
  }
  return e->k - e->watch.checked < ODE_CHECK_STEPS ? DV_OK : ode_check_state(e, err);
}

typedef struct ode_target {
  double t;
  dv_sample *out;
} ode_target;

/* step to the target time and read the sample (guarded part of advance) */
static int ode_run_to(ode_engine *e, void *arg, dv_error *err) {
  ode_target *g = arg;
  const double dt = e->set.timestep;
  int status = DV_OK;
  while (status == DV_OK && e->k * dt < g->t - 0.5 * dt) status = ode_step(e, err);
  if (status == DV_OK && e->k > e->watch.checked) status = ode_check_state(e, err);
  if (status < 0) return status;
  dv_pose p;
  dv_ode_read_pose(e->body, &p);
  dv_sample_from_pose(&e->disk, &e->geom, &p, status == DV_EVENT ? e->k * dt : g->t, e->prev_y,
                      g->out);
  g->out->contacts = e->ncontacts;
  memcpy(e->prev_y, g->out->y, sizeof e->prev_y);
  dv_stats_add_sample(&e->st, g->out);
  return status;
}

/* advance to time t; a failed run keeps returning its failure */
static int ode_advance(void *p, double t, dv_sample *out, dv_error *err) {
  ode_engine *e = p;
  if (e->status < 0)
    return dv_fail(err, e->status, "%s: %s", dv_outcome_name(e->st.outcome), e->st.detail);
  if (e->status == DV_EVENT) return DV_EVENT;
  ode_target g = {t, out};
  return ode_guarded(e, ode_run_to, &g, err);
}

/* statistics of the run so far */
static void ode_stats(const void *p, dv_engine_stats *out) {
  const ode_engine *e = p;
  *out = e->st;
}

DV_ENGINE_MODULE_EXPORT(ode_version, ode_alloc, ode_reset, ode_advance, ode_stats, ode_free);
