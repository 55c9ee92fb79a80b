/* red_step_gsl: GSL odeiv2 steppers with Hermite dense output.
 *
 * GSL's evolve takes free steps; dense output is the Hermite interpolant
 * (gsl_poly_dd_hermite_init) through y and y' at the last four step ends,
 * degree 7, so its error (~h^8) matches the 8th-order method. That needs
 * steps bounded by the motion's frequency (KAPPA below). Where the outputs are
 * further apart than that bound makes worth it, the steps are free instead,
 * and an output inside a step the interpolant does not cover is one step of
 * the method from the step's start: no interpolation error there either. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "red_gsl_words.h"
#include "red_hermite.h"

#define NODES RED_HERMITE_NODES

/* The interpolation error is about 2e-5 (w h)^8 for the fastest frequency w
 * of the motion, so h <= KAPPA rtol^(1/8) / w keeps it near rtol. KAPPA is
 * measured: the theta error of the dense output against a 1e-14 run stepped
 * onto the samples stays below rtol for rtol 1e-10 ... 1e-13 (bench_reduced). */
#define KAPPA 4.7

typedef struct gsl_stepper {
  const red_system *sys;
  gsl_odeiv2_system gsys;
  gsl_odeiv2_driver *driver; /* owns step, control and evolve; msadams needs it */
  gsl_odeiv2_step *step;
  gsl_odeiv2_control *control;
  gsl_odeiv2_evolve *evolve;
  double t, h;
  double step_fraction; /* h <= step_fraction / frequency */
  double y[RED_MAX_DIM];
  long rhs_evals;
  gsl_odeiv2_step *onto; /* the method again, for one step onto an uncovered output */
  double last_query;     /* the last output asked inside a step, s */
  double query_gap;      /* the spacing of the outputs asked, s (0: none yet) */
  int uncovered;         /* steps longer than the bound among the interpolant's last NODES - 1 */
  int nodes;             /* history length, <= NODES */
  int oldest;            /* ring index of the oldest node */
  red_node ring[NODES];  /* the history, a ring: a step writes one node, moves none */
  red_hermite hermite;   /* through the nodes, when valid */
  int hermite_valid;
} gsl_stepper;

static int gsl_rhs(double t, const double y[], double f[], void *p) {
  gsl_stepper *s = p;
  s->rhs_evals++;
  /* not GSL_EBADFUNC: any other failure makes evolve retry a shorter step, which
   * keeps a fall that crosses theta = 0 inside the domain until its event */
  return s->sys->rhs(t, y, f, s->sys->params) ? GSL_EDOM : GSL_SUCCESS;
}

/* the k-th node of the history, oldest first */
static red_node *node(gsl_stepper *s, int k) {
  return &s->ring[(s->oldest + k) % NODES];
}

/* append (t, y, y') to the history; the interpolant is rebuilt when needed.
 * f is y' at the new node (evolve's dydt_out after a step), or NULL */
static int push_node(gsl_stepper *s, const double *f_node, dv_error *err) {
  const size_t n = s->sys->dim;
  if (s->nodes == NODES) {
    s->oldest = (s->oldest + 1) % NODES;
    s->nodes--;
  }
  red_node *q = node(s, s->nodes);
  q->t = s->t;
  memcpy(q->y, s->y, n * sizeof(double));
  if (f_node)
    memcpy(q->f, f_node, n * sizeof(double));
  else if (gsl_rhs(s->t, s->y, q->f, s))
    return dv_fail(err, DV_ENUMERIC, "state left the domain");
  s->nodes++;
  s->hermite_valid = 0;
  return DV_OK;
}

static void gsl_free_stepper(void *p) {
  gsl_stepper *s = p;
  if (!s) return;
  if (s->driver) gsl_odeiv2_driver_free(s->driver);
  if (s->onto) gsl_odeiv2_step_free(s->onto);
  free(s);
}

static void *alloc_with(const gsl_odeiv2_step_type *type, const red_system *sys, double rtol,
                        double atol, dv_error *err) {
  gsl_stepper *s = calloc(1, sizeof *s);
  if (!s) return dv_fail(err, DV_ESYSTEM, "out of memory: a GSL stepper"), NULL;
  s->sys = sys;
  s->step_fraction = fmin(0.5, KAPPA * pow(rtol, 0.125));
  s->gsys = (gsl_odeiv2_system){gsl_rhs, NULL, sys->dim, s};
  s->driver = gsl_odeiv2_driver_alloc_y_new(&s->gsys, type, 1e-4, atol, rtol);
  s->onto = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, sys->dim);
  if (!s->driver || !s->onto) {
    gsl_free_stepper(s);
    dv_fail(err, DV_ESYSTEM, "GSL could not allocate the %s stepper", type->name);
    return NULL;
  }
  s->step = s->driver->s;
  s->control = s->driver->c;
  s->evolve = s->driver->e;
  return s;
}

static void *alloc_rk8pd(const red_system *sys, double rtol, double atol, dv_error *err) {
  return alloc_with(gsl_odeiv2_step_rk8pd, sys, rtol, atol, err);
}

static void *alloc_msadams(const red_system *sys, double rtol, double atol, dv_error *err) {
  return alloc_with(gsl_odeiv2_step_msadams, sys, rtol, atol, err);
}

static int gsl_reset(void *p, double t0, const double *y0, dv_error *err) {
  gsl_stepper *s = p;
  gsl_odeiv2_step_reset(s->step);
  gsl_odeiv2_evolve_reset(s->evolve);
  s->t = t0;
  s->h = 1e-4; /* small first steps keep the low-degree start of the interpolant accurate */
  memcpy(s->y, y0, s->sys->dim * sizeof(double));
  s->nodes = s->oldest = 0;
  s->last_query = t0;
  s->query_gap = 0.0;
  s->uncovered = 0;
  return push_node(s, NULL, err);
}

/* Free steps of the proposed length s->h, plus one step onto each output,
 * cost less than bounded ones: 1/h + 1/gap < 1/h_max (steps per second) */
static int free_step_pays(const gsl_stepper *s, double h_max) {
  return s->query_gap > 0.0 && s->query_gap * (s->h - h_max) > s->h * h_max;
}

static int gsl_step(void *p, double t_max, double *t, dv_error *err) {
  gsl_stepper *s = p;
  double h_max = INFINITY;
  if (s->sys->frequency) {
    h_max = s->step_fraction / s->sys->frequency(s->y, s->sys->params);
    if (s->h > h_max && !free_step_pays(s, h_max)) s->h = h_max;
  }
  int status =
      gsl_odeiv2_evolve_apply(s->evolve, s->control, s->step, &s->gsys, &s->t, t_max, &s->h, s->y);
  if (status != GSL_SUCCESS)
    return dv_fail(err, DV_ENUMERIC, "GSL %s failed at t = %.17g: %s", s->step->type->name, s->t,
                   red_gsl_words(status));
  *t = s->t;
  if (s->evolve->last_step > h_max)
    s->uncovered = NODES - 1;
  else if (s->uncovered > 0)
    s->uncovered--;
  /* rk8pd and msadams leave y' at the step's end in dydt_out */
  return push_node(s, s->evolve->dydt_out, err);
}

/* y at t inside the last step: one step of the method from the step's start
 * (shorter than the step it took, so within its tolerance) */
static int step_onto(gsl_stepper *s, double t, double *y, dv_error *err) {
  if (red_node_step(s->onto, &s->gsys, node(s, s->nodes - 2), t, y))
    return dv_fail(err, DV_ENUMERIC, "state left the domain at t = %.17g", t);
  return DV_OK;
}

static int gsl_dense(void *p, double t, double *y, dv_error *err) {
  gsl_stepper *s = p;
  if (t == s->t) {
    memcpy(y, s->y, s->sys->dim * sizeof(double));
    return DV_OK;
  }
  s->query_gap = fabs(t - s->last_query);
  s->last_query = t;
  if (s->uncovered) return step_onto(s, t, y, err);
  if (!s->hermite_valid) {
    const red_node *nodes[NODES];
    for (int k = 0; k < s->nodes; k++) nodes[k] = node(s, k);
    red_hermite_init(&s->hermite, s->sys->dim, nodes, (size_t)s->nodes);
    s->hermite_valid = 1;
  }
  red_hermite_eval(&s->hermite, t, y);
  return DV_OK;
}

static void gsl_stats(const void *p, red_stats *out) {
  const gsl_stepper *s = p;
  out->steps = (long)s->evolve->count;
  out->failed_steps = (long)s->evolve->failed_steps;
  out->rhs_evals = s->rhs_evals;
}

const red_stepper_type red_gsl_rk8pd = {
    "gsl-rk8pd",     "GSL Prince-Dormand 8(9), free steps, degree-7 Hermite output",
    RED_CAP_DENSE,   alloc_rk8pd,
    gsl_reset,       gsl_step,
    gsl_dense,       gsl_stats,
    gsl_free_stepper};
const red_stepper_type red_gsl_rk8pd_stepped = {
    "gsl-rk8pd-stepped",
    "GSL Prince-Dormand 8(9) stepping onto every output time",
    0,
    alloc_rk8pd,
    gsl_reset,
    gsl_step,
    gsl_dense,
    gsl_stats,
    gsl_free_stepper};
const red_stepper_type red_gsl_msadams = {
    "gsl-msadams",
    "GSL variable-order Adams (orders 1-12) stepping onto every output time",
    0,
    alloc_msadams,
    gsl_reset,
    gsl_step,
    gsl_dense,
    gsl_stats,
    gsl_free_stepper};
