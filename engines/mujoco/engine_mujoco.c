/* engine_mujoco: the disk as a free body on a plane in MuJoCo 2.2 (DESIGN section 4).
 *
 * The model (one plane, one body with a free joint, one disk geom, sliding
 * friction only) is written as MJCF in memory and loaded through a VFS. The
 * disk geom is the thin disk by default: a cylinder geom whose contact is the
 * one rim point of engine_mujoco_thin.c, installed in MuJoCo's collision
 * table from alloc to free; a cylinder of half-thickness h (MuJoCo's own
 * collider, up to four contacts) and a flat ellipsoid are stand-ins. The
 * free joint's qpos is (centre, quaternion w x y z); its qvel is (centre
 * velocity in the world frame, angular velocity in the body frame). MuJoCo's
 * error handler must not return: every MuJoCo call runs inside trapped(),
 * which turns mju_error into a longjmp and a failed run. MuJoCo silently
 * resets the state on a bad qpos/qvel/qacc and only counts a warning: the
 * counters are checked after every step, so a reset ends the run as
 * diverged. Each step also tests lying down (and a NaN) on the quaternion;
 * the rest of the checks (energy, off the ground) run every MJ_CHECK_STEPS
 * steps and before every sample. Like the reference, a run ends at an event where theta leaves
 * (theta_limit, pi - theta_limit) ([engines.reduced] theta_limit): the
 * canonical state is singular at a disk lying flat. Not thread-safe: MuJoCo's
 * handler pointers and collision table are process-global.
 */
#include <math.h>
#include <mujoco/mujoco.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_pose.h"
#include "dv_reference.h"
#include "engine_module.h"
#include "engine_mujoco_model.h"
#include "engine_mujoco_thin.h"
#include "engine_scene.h"
#include "engine_friction.h"
#include "engine_shape.h"

#include "mujoco_settings.h"

static const mujoco_settings *settings_of(const dv_scenario *sc) {
  return dv_scenario_settings(sc, "mujoco");
}

#define LOST_CONTACT_TIME 0.05 /* s the lowest point may stay above the gap before lost_contact */
/* the full state checks every this many steps (each step: counters and lying down) */
#define MJ_CHECK_STEPS 16

typedef struct mujoco_engine {
  red_disk disk;
  dv_geometry geom;
  mjModel *m;
  mjData *d;
  int thin;                /* the thin collider is installed for this run */
  double prev[RED_NSTATE]; /* last canonical state, for angle unwrapping */
  double e0;               /* energy at reset, J */
  double e_max;            /* energy above which the run has diverged, J */
  double gap;              /* lowest-point height that counts as off the ground, m */
  double off_since;        /* time the lowest point went above gap, or -1 */
  double theta_limit;      /* rad: the run ends at an event outside (limit, pi - limit) */
  double cos_limit;        /* cos(theta_limit), the per-step test of n.z */
  long checked;            /* the step of the last full check */
  int status;              /* DV_OK, or the event or failure every later call returns */
  dv_engine_stats stats;
} mujoco_engine;

/* end the run: outcome, detail and the status every later call returns */
__attribute__((format(printf, 4, 5))) static int end_run(mujoco_engine *e, dv_outcome outcome,
                                                         dv_failure failure, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(e->stats.detail, sizeof e->stats.detail, fmt, ap);
  va_end(ap);
  e->stats.outcome = outcome;
  e->stats.failure = failure;
  e->status = outcome == DV_OUTCOME_EVENT   ? DV_EVENT
              : outcome == DV_OUTCOME_ERROR ? DV_ESYSTEM
                                            : DV_ENUMERIC;
  return e->status;
}

/* the active trap of this thread: where mju_error jumps, and its message */
typedef struct trap {
  jmp_buf env;
  char msg[200];
} trap;
static _Thread_local trap *active_trap;

/* mju_user_error: keep the message and leave MuJoCo (it must not return) */
static void on_error(const char *msg) {
  snprintf(active_trap->msg, sizeof active_trap->msg, "%s", msg);
  longjmp(active_trap->env, 1);
}

/* mju_user_warning: warnings are counted in mjData, not printed */
static void on_warning(const char *msg) {
  (void)msg;
}

/* run fn(arg) with MuJoCo's handlers trapped; 0, or -1 with the error in msg */
static int trapped(void (*fn)(void *), void *arg, char *msg, size_t size) {
  void (*prev_error)(const char *) = mju_user_error;
  void (*prev_warning)(const char *) = mju_user_warning;
  trap *outer = active_trap, here;
  volatile int failed = 0;
  active_trap = &here;
  mju_user_error = on_error;
  mju_user_warning = on_warning;
  if (setjmp(here.env) == 0)
    fn(arg);
  else
    failed = 1;
  mju_user_error = prev_error;
  mju_user_warning = prev_warning;
  active_trap = outer;
  if (failed) snprintf(msg, size, "MuJoCo error: %s", here.msg);
  return failed ? -1 : 0;
}

/* "MuJoCo 2.2.2" from mj_version() (222) */
static const char *mujoco_version(void) {
  static char text[32];
  const int v = mj_version();
  snprintf(text, sizeof text, "MuJoCo %d.%d.%d", v / 100, v / 10 % 10, v % 10);
  return text;
}

/* the MJCF model of the scene; returns its length, or -1 if it did not fit. The disk geom's
 * user value marks the thin disk for engine_mujoco_thin.c */
static int write_model(const dv_scenario *sc, const mujoco_settings *s, char *xml, size_t size) {
  static const char *const MJ_INTEGRATORS[] = {"Euler", "RK4", "implicit"};
  static const char *const MJ_SOLVERS[] = {"PGS", "CG", "Newton"};
  const red_disk *k = &sc->disk;
  char size_attr[96];
  if (s->geom == GEOM_ELLIPSOID)
    snprintf(size_attr, sizeof size_attr, "%.17g %.17g %.17g", k->r, k->r, s->half_thickness);
  else
    snprintf(size_attr, sizeof size_attr, "%.17g %.17g", k->r,
             s->geom == GEOM_THIN ? dv_mujoco_thin_half_length(k->r) : s->half_thickness);
  const int n = snprintf(
      xml, size,
      "<mujoco model=\"diskval\">\n"
      "  <option timestep=\"%.17g\" gravity=\"0 0 %.17g\" integrator=\"%s\" cone=\"%s\"\n"
      "          impratio=\"%.17g\" solver=\"%s\" tolerance=\"%.17g\" iterations=\"%d\"\n"
      "          noslip_iterations=\"%d\"/>\n"
      "  <size nuser_geom=\"1\"/>\n"
      "  <default>\n"
      "    <geom condim=\"3\" friction=\"%.17g 0 0\" solref=\"%.17g %.17g\"\n"
      "          solimp=\"%.17g %.17g %.17g 0.5 2\"/>\n"
      "  </default>\n"
      "  <worldbody>\n"
      "    <geom name=\"ground\" type=\"plane\" size=\"0 0 1\" contype=\"0\" conaffinity=\"1\"/>\n"
      "    <body name=\"disk\">\n"
      "      <freejoint/>\n"
      "      <inertial pos=\"0 0 0\" mass=\"%.17g\" diaginertia=\"%.17g %.17g %.17g\"/>\n"
      "      <geom name=\"disk\" type=\"%s\" size=\"%s\" user=\"%g\" contype=\"1\"\n"
      "            conaffinity=\"0\"/>\n"
      "    </body>\n"
      "  </worldbody>\n"
      "</mujoco>\n",
      s->timestep, -k->g, MJ_INTEGRATORS[s->integrator], dv_mujoco_cones[s->cone], s->impratio,
      MJ_SOLVERS[s->solver], s->tolerance, s->iterations, s->noslip_iterations, s->friction,
      s->solref_timeconst, s->solref_dampratio, s->solimp_dmin, s->solimp_dmax, s->solimp_width,
      k->m, k->A, k->A, k->C, s->geom == GEOM_ELLIPSOID ? "ellipsoid" : "cylinder", size_attr,
      s->geom == GEOM_THIN ? DV_MUJOCO_THIN_MARK : 0.0);
  return n > 0 && (size_t)n < size ? n : -1;
}

int dv_mujoco_model_xml(const dv_scenario *sc, char *xml, size_t size) {
  mujoco_settings set = *settings_of(sc);
  dv_mujoco_derive(sc, &set, NULL, 0, NULL);
  return write_model(sc, &set, xml, size);
}

/* mj_loadXML's arguments and result, for trapped() */
typedef struct load_call {
  mjVFS *vfs;
  mjModel *m;
  char err[300];
} load_call;

/* trapped: compile the model in the VFS */
static void load_model(void *p) {
  load_call *c = p;
  c->m = mj_loadXML("disk.xml", c->vfs, c->err, (int)sizeof c->err);
}

/* NULL-safe */
static void mujoco_free(void *p) {
  mujoco_engine *e = p;
  if (!e) return;
  if (e->d) mj_deleteData(e->d);
  if (e->m) mj_deleteModel(e->m);
  if (e->thin) dv_mujoco_thin_restore();
  free(e);
}

/* the model compiled from the scenario (settings it leaves to the scene, as in
 * a scenario built in code, derived here) */
static void *mujoco_alloc(const dv_scenario *sc, dv_error *err) {
  mujoco_engine *e = calloc(1, sizeof *e), *result = NULL;
  mjVFS *vfs = calloc(1, sizeof *vfs); /* ~2 MB: not on the stack; empty when zeroed */
  load_call call = {vfs, NULL, ""};
  char xml[2048], msg[300];
  mujoco_settings set = *settings_of(sc);
  const mujoco_settings *s = &set;
  dv_mujoco_derive(sc, &set, NULL, 0, NULL);
  const int len = write_model(sc, s, xml, sizeof xml);
  int idx = -1;
  if (!e || !vfs) {
    dv_fail(err, DV_ESYSTEM, "out of memory: MuJoCo's engine state and model file system");
    goto cleanup;
  }
  mj_defaultVFS(vfs);
  if (len < 0 || mj_makeEmptyFileVFS(vfs, "disk.xml", len) ||
      (idx = mj_findFileVFS(vfs, "disk.xml")) < 0) {
    dv_fail(err, DV_ESYSTEM, "cannot write the MuJoCo model into a VFS");
    goto cleanup;
  }
  memcpy(vfs->filedata[idx], xml, (size_t)len);
  if (trapped(load_model, &call, msg, sizeof msg) || !call.m) {
    for (char *c = call.err; *c; c++)
      if (*c == '\n') *c = ' ';
    dv_fail(err, DV_EINPUT, "MuJoCo cannot load the disk model: %s", call.m ? msg : call.err);
    goto cleanup;
  }
  e->m = call.m;
  call.m = NULL;
  if (!(e->d = mj_makeData(e->m))) {
    dv_fail(err, DV_ESYSTEM, "MuJoCo cannot allocate its data");
    goto cleanup;
  }
  e->disk = sc->disk;
  /* a cylinder with h = 0 has rho = r d: the thin disk */
  e->geom = (dv_geometry){s->geom == GEOM_ELLIPSOID ? DV_SHAPE_ELLIPSOID : DV_SHAPE_CYLINDER,
                          sc->disk.r, s->geom == GEOM_THIN ? 0.0 : s->half_thickness};
  if (s->geom == GEOM_THIN) {
    dv_mujoco_thin_install();
    e->thin = 1;
  }
  e->gap = fmax(0.01 * sc->disk.r, 5.0 * s->solimp_width);
  e->theta_limit = dv_reference_settings(sc)->theta_limit;
  e->cos_limit = cos(e->theta_limit);
  end_run(e, DV_OUTCOME_ERROR, DV_FAILURE_SETUP, "advance before reset");
  result = e;
  e = NULL;
cleanup:
  if (call.m) mj_deleteModel(call.m);
  if (vfs) mj_deleteVFS(vfs);
  free(vfs);
  mujoco_free(e);
  return result;
}

/* the body's pose from qpos/qvel (xpos/xmat lag one step behind after mj_step) */
void dv_mujoco_read_pose(const mjData *d, dv_pose *p) {
  double q[4] = {d->qpos[3], d->qpos[4], d->qpos[5], d->qpos[6]};
  mju_normalize4(q);
  mju_quat2Mat(p->R, q);
  mju_copy3(p->pos, d->qpos);
  mju_copy3(p->vel, d->qvel);
  mju_mulMatVec(p->omega, p->R, d->qvel + 3, 3, 3); /* world = R body */
}

/* sum of MuJoCo's warning counters, and of its bad-state ones */
static long warning_count(const mjData *d, long *bad) {
  long n = 0;
  for (int i = 0; i < mjNWARNING; i++) n += d->warning[i].number;
  *bad = d->warning[mjWARN_BADQPOS].number + d->warning[mjWARN_BADQVEL].number +
         d->warning[mjWARN_BADQACC].number;
  return n;
}

/* the state after a step or a reset: non-finite, reset by MuJoCo, runaway, lying down
 * (an event), off the ground */
static int check_state(mujoco_engine *e) {
  e->checked = e->stats.steps;
  const mjData *d = e->d;
  long bad;
  e->stats.warnings = warning_count(d, &bad);
  if (bad)
    return end_run(e, DV_OUTCOME_DIVERGED, DV_FAILURE_RESET,
                   "MuJoCo reset a bad qpos/qvel/qacc at step %ld (t = %g s)", e->stats.steps,
                   e->stats.steps * e->m->opt.timestep);
  for (int i = 0; i < 7; i++)
    if (!isfinite(d->qpos[i]) || (i < 6 && !isfinite(d->qvel[i])))
      return end_run(e, DV_OUTCOME_DIVERGED, DV_FAILURE_NAN, "non-finite state at t = %g s",
                     d->time);
  dv_pose p;
  double low[3], slip;
  dv_mujoco_read_pose(d, &p);
  /* runaway: E > E0 + |E0|/2 + m g r cannot come from a passive contact */
  const double energy = dv_pose_energy(&e->disk, &p);
  if (energy > e->e_max)
    return end_run(e, DV_OUTCOME_DIVERGED, DV_FAILURE_ENERGY, "energy %g J ran away (limit %g J)",
                   energy, e->e_max);
  /* n.z = cos(theta), n = R ez */
  if (fabs(p.R[8]) > e->cos_limit) {
    char detail[sizeof e->stats.detail];
    dv_engine_limit_detail(p.R[8] > 0.0, e->theta_limit, d->time, detail, sizeof detail);
    e->stats.lay_down = p.R[8] > 0.0 ? -1 : 1;
    return end_run(e, DV_OUTCOME_EVENT, DV_FAILURE_NONE, "%s", detail);
  }
  dv_pose_lowest_point(&e->geom, &p, low, &slip);
  if (low[2] <= e->gap)
    e->off_since = -1.0;
  else if (e->off_since < 0.0)
    e->off_since = d->time;
  else if (d->time - e->off_since > LOST_CONTACT_TIME)
    return end_run(e, DV_OUTCOME_LOST_CONTACT, DV_FAILURE_LOST_CONTACT,
                   "the lowest point was %g m above the ground, off it since t = %g s", low[2],
                   e->off_since);
  return DV_OK;
}

/* trapped: recompute the derived quantities of the state set by reset */
static void forward(void *p) {
  mujoco_engine *e = p;
  mj_forward(e->m, e->d);
}

/* start from a canonical state, rolling without slip */
static int mujoco_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  mujoco_engine *e = p;
  dv_pose pose;
  char msg[300];
  memset(&e->stats, 0, sizeof e->stats);
  e->status = DV_OK;
  e->off_since = -1.0;
  e->checked = 0;
  mj_resetData(e->m, e->d);
  memcpy(e->prev, state, sizeof e->prev);
  for (int i = 0; i < RED_NSTATE; i++)
    if (!isfinite(state[i])) {
      end_run(e, DV_OUTCOME_DIVERGED, DV_FAILURE_SETUP, "non-finite initial state (component %d)",
              i);
      return dv_fail(err, e->status, "%s", e->stats.detail);
    }
  dv_pose_from_state(&e->geom, state, &pose);
  mju_copy3(e->d->qpos, pose.pos);
  mju_mat2Quat(e->d->qpos + 3, pose.R);
  mju_copy3(e->d->qvel, pose.vel);
  mju_mulMatTVec(e->d->qvel + 3, pose.R, pose.omega, 3, 3); /* body = R^T world */
  e->e0 = dv_pose_energy(&e->disk, &pose);
  e->e_max = e->e0 + 0.5 * fabs(e->e0) + e->disk.m * e->disk.g * e->disk.r;
  if (trapped(forward, e, msg, sizeof msg))
    end_run(e, DV_OUTCOME_ERROR, DV_FAILURE_LIBRARY, "%s", msg);
  else
    check_state(e);
  return e->status < 0 ? dv_fail(err, e->status, "%s", e->stats.detail) : DV_OK;
}

/* step_to's arguments */
typedef struct step_call {
  mujoco_engine *e;
  double t; /* s */
} step_call;

/* after a step: MuJoCo's bad-state counters and n.z = cos(theta) from the
 * quaternion (w x y z) every step, where a NaN fails too; the full checks
 * every MJ_CHECK_STEPS steps */
static int step_check(mujoco_engine *e) {
  const double *q = e->d->qpos + 3;
  const double nz = (q[0] * q[0] - q[1] * q[1] - q[2] * q[2] + q[3] * q[3]) /
                    (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  long bad;
  warning_count(e->d, &bad);
  if (bad || !(fabs(nz) <= e->cos_limit) || e->stats.steps - e->checked >= MJ_CHECK_STEPS)
    return check_state(e);
  return DV_OK;
}

/* trapped: step to the grid time nearest t, checking each step, then fully */
static void step_to(void *p) {
  step_call *c = p;
  mujoco_engine *e = c->e;
  const double half = 0.5 * e->m->opt.timestep;
  while (e->d->time < c->t - half) {
    mj_step(e->m, e->d);
    e->stats.steps++;
    if (step_check(e)) return;
  }
  if (e->stats.steps > e->checked) check_state(e);
}

/* step to time t and sample the disk there (at an event: where it ended) */
static int mujoco_advance(void *p, double t, dv_sample *out, dv_error *err) {
  mujoco_engine *e = p;
  step_call call = {e, t};
  char msg[300];
  dv_pose pose;
  if (e->status == DV_OK && trapped(step_to, &call, msg, sizeof msg))
    end_run(e, DV_OUTCOME_ERROR, DV_FAILURE_LIBRARY, "%s", msg);
  if (e->status < 0) return dv_fail(err, e->status, "%s", e->stats.detail);
  dv_mujoco_read_pose(e->d, &pose);
  dv_sample_from_pose(&e->disk, &e->geom, &pose, e->status == DV_EVENT ? e->d->time : t, e->prev,
                      out);
  memcpy(e->prev, out->y, sizeof e->prev);
  out->contacts = e->d->ncon;
  dv_stats_add_sample(&e->stats, out);
  return e->status;
}

/* counters and outcome so far */
static void mujoco_stats(const void *p, dv_engine_stats *out) {
  const mujoco_engine *e = p;
  *out = e->stats;
}

DV_ENGINE_MODULE_EXPORT(mujoco_version, mujoco_alloc, mujoco_reset, mujoco_advance, mujoco_stats,
                        mujoco_free);
