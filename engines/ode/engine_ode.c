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
#include "engine_choose.h"
#include "engine_ode_body.h"
#include "engine_ode_thin.h"
#include "engine_scene.h"
#include "engine_friction.h"
#include "engine_shape.h"
#include "engine_watch.h"

#define ODE_MAX_CONTACTS 4
/* the full checks' share of a 1 us step falls from 4% (every step) to 0.3% */
#define ODE_CHECK_STEPS 16

/* [engines.ode] */
typedef struct ode_settings {
  double timestep;           /* s */
  int stepper;               /* 0 dWorldStep, 1 dWorldQuickStep */
  int iterations;            /* QuickStep iterations */
  double erp, cfm;           /* world error reduction, constraint force mixing */
  int friction_model;        /* 0 coefficient (dContactApprox1), 1 force limit (N) */
  double friction;           /* coefficient, or force limit in N */
  double soft_erp, soft_cfm; /* contact softness */
  int geom;                  /* 0 thin disk (user geom), 1 cylinder */
  double half_thickness;     /* m, cylinder half-length */
} ode_settings;

static const char *const STEPPERS[] = {"step", "quickstep", NULL};
static const char *const FRICTION_MODELS[] = {"coefficient", "force_limit", NULL};
static const char *const GEOMS[] = {"thin", "cylinder", NULL};

#define AT(field) offsetof(ode_settings, field)
#define NUM DV_SETTING_REAL, AT
#define WHOLE DV_SETTING_INT, AT
#define PICK DV_SETTING_CHOICE, AT

static const dv_setting_spec KEYS[] = {
    {"timestep", NUM(timestep), 0, 0, NAN, 1e-7, 0.1, NULL, NULL, "s",
     "default: from the scene's time scales"},
    {"stepper", PICK(stepper), 0, 0, 0, 0, 1, STEPPERS, NULL, "", ""},
    {"iterations", WHOLE(iterations), 0, 0, 50, 1, 100000, NULL, NULL, "", "QuickStep"},
    {"erp", NUM(erp), 0, 0, 0.2, 0.0, 1.0, NULL, NULL, "",
     "world ERP (inert: only contact joints)"},
    {"cfm", NUM(cfm), 0, 0, 1e-10, 0.0, 1.0, NULL, NULL, "",
     "world CFM: the contact's friction rows (soft_cfm sets its normal row)"},
    {"friction_model", PICK(friction_model), 0, 0, 0, 0, 1, FRICTION_MODELS, NULL, "",
     "coefficient: dContactApprox1"},
    {"friction", NUM(friction), 0, 0, NAN, 0.0, 1e9, NULL, NULL, "",
     "coefficient, or N (default: [disk] friction, times m g for a force limit)"},
    {"soft_erp", NUM(soft_erp), 0, 0, 0.2, 0.0, 1.0, NULL, NULL, "", "contact"},
    {"soft_cfm", NUM(soft_cfm), 0, 0, 1e-8, 0.0, 1.0, NULL, NULL, "", "contact"},
    {"geom", PICK(geom), 0, 0, 0, 0, 1, GEOMS, NULL, "",
     "thin: the exact disk, one contact (default, or cylinder for a [disk] thickness > 0)"},
    {"half_thickness", NUM(half_thickness), 0, 0, 0.002, 1e-6, 1.0, NULL, NULL, "m",
     "cylinder half-length (default: [disk] thickness / 2 if > 0)"},
};

/* The error model of engine_scene.h per stepper: the theta error is first
 * order in the timestep (x4 steps give x4 errors); contact softness changes
 * nothing measurable (README), so only the step is derived. c is the largest
 * err T^2 / (dt D) measured on the shipped scenarios (thin disk, whole
 * validity window, T the shortest time scale, D the duration) at dt =
 * 6.25e-6 s: nonuniform 2.27 (its wobble's phase), steady_steep 0.74,
 * euler_disk 0.68, steady_circle 0.49, fast_spin 0.25, tiny_c 0.015, falling
 * 0.0094, upright_stable 0.0016; QuickStep the same. Cost of a step
 * (./run.sh bench): dWorldStep 0.85 us, QuickStep 2.5 us. */
static const dv_step_model MODELS[] = {
    {"ode", 2.3, 0.0, NULL, 0.85e-6},
    {"ode", 2.3, 0.0, NULL, 2.5e-6},
};

/* The knobs chosen per scene (engine_choose.h): the step, from the model's
 * down to half of it, with dWorldStep; QuickStep is declared (attribution turns
 * it) but not a candidate: its errors equal dWorldStep's at 3x the cost. The
 * contact's softness (soft_erp, soft_cfm) is no knob: it changes nothing
 * measurable (the models above). */
static const dv_engine_knobs KNOBS = {"ode", "stepper", MODELS, 2, 0x1, 1};

static const dv_shape_keys SHAPE = {"ode", "geom", 1, 0, "half_thickness"};

/* the friction: a coefficient, or a force limit of that coefficient's weight */
static void derive_friction(const dv_scenario *sc, ode_settings *s, char *why, size_t size,
                            const char **keys) {
  const int force = s->friction_model == 1;
  dv_engine_derive_friction(sc, "ode", "friction", force ? sc->disk.m * sc->disk.g : 1.0,
                            force ? "N" : "", &s->friction, why, size, keys);
}

static int ode_check(dv_scenario *sc, void *block, dv_setting_issue *issue) {
  ode_settings *s = block;
  char why[DV_DERIVED_BYTES];
  const char *keys[8];
  (void)issue;
  const int given = dv_scenario_is_given(sc, "ode", "stepper");
  const dv_knob_choice in = {given ? s->stepper : -1, s->timestep, NAN};
  dv_knob_choice out;
  dv_engine_choose(sc, &dv_engine_ode, &KNOBS, s->stepper, &in, &out, why, sizeof why, keys);
  s->stepper = out.choice;
  s->timestep = out.timestep;
  dv_engine_derive_shape(sc, &SHAPE, &s->geom, &s->half_thickness, why, sizeof why, keys);
  derive_friction(sc, s, why, sizeof why, keys);
  dv_scenario_set_derived(sc, "ode", keys, why);
  return 0;
}

static const dv_settings_section SETTINGS = {"ode", KEYS, sizeof KEYS / sizeof KEYS[0],
                                             sizeof(ode_settings), ode_check};

/* the thin disk is compared with the thin reference; the cylinder with its match */
static double ode_half_thickness(const dv_scenario *sc) {
  ode_settings s = *(const ode_settings *)dv_scenario_settings(sc, SETTINGS.name);
  dv_engine_derive_shape(sc, &SHAPE, &s.geom, &s.half_thickness, NULL, 0, NULL);
  return s.geom == 1 ? s.half_thickness : 0.0;
}

static const dv_engine_search SEARCH = {"ode", "stepper", "timestep", 1e-7, 0.02, NULL};

/* a stiffer contact: a 100x smaller constraint force mixing (compliance) */
static const dv_engine_contact CONTACT = {"geom", "thin", "soft_cfm", 0.01, 0.0, "friction", NULL, 0};

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
  e->set = *(const ode_settings *)dv_scenario_settings(sc, SETTINGS.name);
  /* a scenario built in code leaves the step to the scene */
  dv_engine_derive_step(sc, &MODELS[e->set.stepper], &e->set.timestep, NULL, NULL, 0, NULL);
  dv_engine_derive_shape(sc, &SHAPE, &e->set.geom, &e->set.half_thickness, NULL, 0, NULL);
  derive_friction(sc, &e->set, NULL, 0, NULL);
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

const dv_engine_type dv_engine_ode = {
    .name = "ode",
    .description = "ODE 0.16 contact simulation: a thin disk (or a cylinder) on a plane",
    .role = DV_ENGINE_CONTACT,
    .settings = &SETTINGS,
    .search = &SEARCH,
    .contact = &CONTACT,
    .half_thickness = ode_half_thickness,
    .version = ode_version,
    .alloc = ode_alloc,
    .reset = ode_reset,
    .advance = ode_advance,
    .stats = ode_stats,
    .free = ode_free,
};
