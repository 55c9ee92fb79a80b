/* red_step_cvode: SUNDIALS CVODE (Adams with fixed-point iteration, or BDF
 * with Newton and a dense LU), one internal step at a time; dense output is
 * CVODE's own interpolant (CVodeGetDky) at the method's order. */
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <stdlib.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "red_solver.h"

typedef struct cv_stepper {
  const red_system *sys;
  SUNContext ctx;
  N_Vector y, ytmp;
  SUNMatrix J;
  SUNLinearSolver ls;
  SUNNonlinearSolver nls;
  void *mem;
  int lmm;
  double rtol, atol;
  char msg[256]; /* last message from CVODE's error handler */
} cv_stepper;

static int cv_rhs(realtype t, N_Vector y, N_Vector f, void *p) {
  const cv_stepper *s = p;
  /* positive: recoverable, CVODE retries with a smaller step */
  return s->sys->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(f), s->sys->params) ? 1 : 0;
}

static void cv_error(int code, const char *module, const char *function, char *msg, void *p) {
  cv_stepper *s = p;
  snprintf(s->msg, sizeof s->msg, "%s %s (%d): %s", module, function, code, msg);
}

static void cv_free(void *p) {
  cv_stepper *s = p;
  if (!s) return;
  CVodeFree(&s->mem);
  if (s->nls) SUNNonlinSolFree(s->nls);
  if (s->ls) SUNLinSolFree(s->ls);
  if (s->J) SUNMatDestroy(s->J);
  if (s->ytmp) N_VDestroy(s->ytmp);
  if (s->y) N_VDestroy(s->y);
  if (s->ctx) SUNContext_Free(&s->ctx);
  free(s);
}

static void *alloc_with(int lmm, const red_system *sys, double rtol, double atol, dv_error *err) {
  cv_stepper *s = calloc(1, sizeof *s);
  if (!s) return dv_fail(err, DV_ESYSTEM, "out of memory: a CVODE stepper"), NULL;
  s->sys = sys;
  s->lmm = lmm;
  s->rtol = rtol;
  s->atol = atol;
  if (SUNContext_Create(NULL, &s->ctx) || !(s->y = N_VNew_Serial((sunindextype)sys->dim, s->ctx)) ||
      !(s->ytmp = N_VClone(s->y))) {
    cv_free(s);
    return dv_fail(err, DV_ESYSTEM, "SUNDIALS could not allocate vectors"), NULL;
  }
  return s;
}

static void *alloc_adams(const red_system *sys, double rtol, double atol, dv_error *err) {
  return alloc_with(CV_ADAMS, sys, rtol, atol, err);
}

static void *alloc_bdf(const red_system *sys, double rtol, double atol, dv_error *err) {
  return alloc_with(CV_BDF, sys, rtol, atol, err);
}

static int cv_flag(cv_stepper *s, int flag, const char *what, dv_error *err) {
  if (flag >= 0) return DV_OK;
  char *name = CVodeGetReturnFlagName(flag); /* malloc'd by SUNDIALS */
  const int status = dv_fail(err, DV_ENUMERIC, "CVODE %s: %s%s%s", what,
                             name ? name : "unknown flag", s->msg[0] ? ": " : "", s->msg);
  free(name);
  return status;
}

static int cv_reset(void *p, double t0, const double *y0, dv_error *err) {
  cv_stepper *s = p;
  for (size_t i = 0; i < s->sys->dim; i++) NV_Ith_S(s->y, i) = y0[i];
  if (s->mem) return cv_flag(s, CVodeReInit(s->mem, t0, s->y), "reinit", err);
  s->mem = CVodeCreate(s->lmm, s->ctx);
  if (!s->mem) return dv_fail(err, DV_ESYSTEM, "CVodeCreate failed");
  int flag = CVodeSetErrHandlerFn(s->mem, cv_error, s);
  if (flag >= 0) flag = CVodeInit(s->mem, cv_rhs, t0, s->y);
  if (flag >= 0) flag = CVodeSetUserData(s->mem, s);
  if (flag >= 0) flag = CVodeSStolerances(s->mem, s->rtol, s->atol);
  if (flag >= 0) flag = CVodeSetMaxNumSteps(s->mem, 1000000);
  if (flag >= 0 && s->lmm == CV_ADAMS) {
    s->nls = SUNNonlinSol_FixedPoint(s->y, 0, s->ctx);
    flag = s->nls ? CVodeSetNonlinearSolver(s->mem, s->nls) : CV_MEM_FAIL;
  } else if (flag >= 0) {
    s->J = SUNDenseMatrix((sunindextype)s->sys->dim, (sunindextype)s->sys->dim, s->ctx);
    s->ls = s->J ? SUNLinSol_Dense(s->y, s->J, s->ctx) : NULL;
    flag = s->ls ? CVodeSetLinearSolver(s->mem, s->ls, s->J) : CV_MEM_FAIL;
  }
  return cv_flag(s, flag, "setup", err);
}

static int cv_step(void *p, double t_max, double *t, dv_error *err) {
  cv_stepper *s = p;
  int flag = CVodeSetStopTime(s->mem, t_max);
  realtype tr = 0.0;
  if (flag >= 0) flag = CVode(s->mem, t_max, s->y, &tr, CV_ONE_STEP);
  *t = tr;
  return cv_flag(s, flag, "step", err);
}

static int cv_dense(void *p, double t, double *y, dv_error *err) {
  cv_stepper *s = p;
  int status = cv_flag(s, CVodeGetDky(s->mem, t, 0, s->ytmp), "dense output", err);
  for (size_t i = 0; i < s->sys->dim; i++) y[i] = NV_Ith_S(s->ytmp, i);
  return status;
}

static void cv_stats(const void *p, red_stats *out) {
  const cv_stepper *s = p;
  long steps = 0, fevals = 0, fails = 0;
  if (s->mem) {
    CVodeGetNumSteps(s->mem, &steps);
    CVodeGetNumRhsEvals(s->mem, &fevals);
    CVodeGetNumErrTestFails(s->mem, &fails);
  }
  *out = (red_stats){steps, fevals, fails};
}

const red_stepper_type red_cvode_adams = {
    "cvode-adams", "SUNDIALS CVODE Adams-Moulton (orders 1-12), fixed-point iteration",
    RED_CAP_DENSE, alloc_adams,
    cv_reset,      cv_step,
    cv_dense,      cv_stats,
    cv_free};
const red_stepper_type red_cvode_bdf = {
    "cvode-bdf",   "SUNDIALS CVODE BDF (orders 1-5), Newton with dense LU",
    RED_CAP_DENSE, alloc_bdf,
    cv_reset,      cv_step,
    cv_dense,      cv_stats,
    cv_free};
