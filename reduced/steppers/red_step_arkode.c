/* red_step_arkode: SUNDIALS ARKODE ERKStep with the Fehlberg 13-stage
 * 8th-order table; dense output from ARKODE's degree-5 Hermite interpolant. */
#include <arkode/arkode_erkstep.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>

#include "red_solver.h"

typedef struct ark_stepper {
  const red_system *sys;
  SUNContext ctx;
  N_Vector y, ytmp;
  void *mem;
  double rtol, atol;
  char msg[256];
} ark_stepper;

static int ark_rhs(realtype t, N_Vector y, N_Vector f, void *p) {
  const ark_stepper *s = p;
  return s->sys->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(f), s->sys->params) ? 1 : 0;
}

static void ark_error(int code, const char *module, const char *function, char *msg, void *p) {
  ark_stepper *s = p;
  snprintf(s->msg, sizeof s->msg, "%s %s (%d): %s", module, function, code, msg);
}

static void ark_free(void *p) {
  ark_stepper *s = p;
  if (!s) return;
  ERKStepFree(&s->mem);
  if (s->ytmp) N_VDestroy(s->ytmp);
  if (s->y) N_VDestroy(s->y);
  if (s->ctx) SUNContext_Free(&s->ctx);
  free(s);
}

static void *ark_alloc(const red_system *sys, double rtol, double atol, dv_error *err) {
  ark_stepper *s = calloc(1, sizeof *s);
  if (!s) return dv_fail(err, DV_ESYSTEM, "out of memory: an ARKODE stepper"), NULL;
  s->sys = sys;
  s->rtol = rtol;
  s->atol = atol;
  if (SUNContext_Create(NULL, &s->ctx) || !(s->y = N_VNew_Serial((sunindextype)sys->dim, s->ctx)) ||
      !(s->ytmp = N_VClone(s->y))) {
    ark_free(s);
    return dv_fail(err, DV_ESYSTEM, "SUNDIALS could not allocate vectors"), NULL;
  }
  return s;
}

static int ark_flag(ark_stepper *s, int flag, const char *what, dv_error *err) {
  if (flag >= 0) return DV_OK;
  char *name = ERKStepGetReturnFlagName(flag); /* malloc'd by SUNDIALS */
  const int status = dv_fail(err, DV_ENUMERIC, "ARKODE %s: %s%s%s", what,
                             name ? name : "unknown flag", s->msg[0] ? ": " : "", s->msg);
  free(name);
  return status;
}

static int ark_reset(void *p, double t0, const double *y0, dv_error *err) {
  ark_stepper *s = p;
  for (size_t i = 0; i < s->sys->dim; i++) NV_Ith_S(s->y, i) = y0[i];
  if (s->mem) return ark_flag(s, ERKStepReInit(s->mem, ark_rhs, t0, s->y), "reinit", err);
  s->mem = ERKStepCreate(ark_rhs, t0, s->y, s->ctx);
  if (!s->mem) return dv_fail(err, DV_ESYSTEM, "ERKStepCreate failed");
  int flag = ERKStepSetErrHandlerFn(s->mem, ark_error, s);
  if (flag >= 0) flag = ERKStepSetUserData(s->mem, s);
  if (flag >= 0) flag = ERKStepSetTableNum(s->mem, ARKODE_FEHLBERG_13_7_8);
  if (flag >= 0) flag = ERKStepSStolerances(s->mem, s->rtol, s->atol);
  if (flag >= 0) flag = ERKStepSetMaxNumSteps(s->mem, 1000000);
  if (flag >= 0) flag = ERKStepSetInterpolantDegree(s->mem, 5);
  return ark_flag(s, flag, "setup", err);
}

static int ark_step(void *p, double t_max, double *t, dv_error *err) {
  ark_stepper *s = p;
  int flag = ERKStepSetStopTime(s->mem, t_max);
  realtype tr = 0.0;
  if (flag >= 0) flag = ERKStepEvolve(s->mem, t_max, s->y, &tr, ARK_ONE_STEP);
  *t = tr;
  return ark_flag(s, flag, "step", err);
}

static int ark_dense(void *p, double t, double *y, dv_error *err) {
  ark_stepper *s = p;
  int status = ark_flag(s, ERKStepGetDky(s->mem, t, 0, s->ytmp), "dense output", err);
  for (size_t i = 0; i < s->sys->dim; i++) y[i] = NV_Ith_S(s->ytmp, i);
  return status;
}

static void ark_stats(const void *p, red_stats *out) {
  const ark_stepper *s = p;
  long steps = 0, fevals = 0, fails = 0;
  if (s->mem) {
    ERKStepGetNumSteps(s->mem, &steps);
    ERKStepGetNumRhsEvals(s->mem, &fevals);
    ERKStepGetNumErrTestFails(s->mem, &fails);
  }
  *out = (red_stats){steps, fevals, fails};
}

const red_stepper_type red_arkode_fehlberg13 = {
    "arkode-fehlberg13",
    "SUNDIALS ARKODE explicit Fehlberg 13-stage 8(7), Hermite output",
    RED_CAP_DENSE,
    ark_alloc,
    ark_reset,
    ark_step,
    ark_dense,
    ark_stats,
    ark_free};
