/* red_period: record step ends, find a closed period of the reduced motion,
 * and answer any later time by the disk's symmetries (red_period.h). */
#include "red_period.h"

#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "red_hermite.h"
#include "red_root.h"

/* the reduced state; theta' is 0 at both maxima only where they are located
 * right, which is what shows an error in the period */
static const int reduced[] = {RED_TH, RED_VTH, RED_VPH, RED_VPS};
#define NREDUCED (sizeof reduced / sizeof reduced[0])

struct red_period {
  red_disk disk;
  double rtol, atol;
  red_period_status status;
  gsl_odeiv2_system sys; /* the reduced equations, for ... */
  gsl_odeiv2_step *onto; /* ... one step of the method onto a maximum */
  red_node *nodes;       /* step ends, times increasing */
  size_t n, cap;
  red_hermite hermite; /* over the step ending at node `cached` */
  size_t cached;       /* 0: none */
  int maxima;          /* maxima of theta found: 0, 1 or 2 */
  double t_a, y_a[RED_NSTATE], t_b, y_b[RED_NSTATE];
  double theta_lo, theta_hi; /* theta's range since t_a */
  double size[RED_NSTATE];   /* the largest |y| since t_a, per component */
  double T, dphi, dpsi;      /* the period, and what it adds to phi and psi */
  double turn_k;             /* the periods the turn below is for (NAN: none yet) */
  double turn[5];            /* cos, sin of k a and of (k - 1) a / 2, and |S_k| */
  char note[240];
};

static int gsl_rhs(double t, const double y[], double f[], void *disk) {
  (void)t;
  return red_rhs(disk, y, f) ? GSL_EDOM : GSL_SUCCESS;
}

red_period *red_period_alloc(const red_disk *disk, double rtol, double atol, dv_error *err) {
  red_period *p = calloc(1, sizeof *p);
  if (!p) return dv_fail(err, DV_ESYSTEM, "out of memory: the period fold's state"), NULL;
  p->disk = *disk;
  p->rtol = rtol;
  p->atol = atol;
  p->sys = (gsl_odeiv2_system){gsl_rhs, NULL, RED_NSTATE, &p->disk};
  p->onto = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, RED_NSTATE);
  if (!p->onto)
    return red_period_free(p),
           dv_fail(err, DV_ESYSTEM, "out of memory: the period fold's GSL stepper"), NULL;
  return p;
}

void red_period_free(red_period *p) {
  if (!p) return;
  if (p->onto) gsl_odeiv2_step_free(p->onto);
  free(p->nodes);
  free(p);
}

static void stop(red_period *p, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void stop(red_period *p, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  p->status = RED_PERIOD_OFF;
  vsnprintf(p->note, sizeof p->note, fmt, ap);
  va_end(ap);
}

/* append a step end with y' there */
static int push(red_period *p, double t, const double *y) {
  if (p->n == p->cap) {
    const size_t cap = p->cap ? 2 * p->cap : 256;
    if (cap > RED_PERIOD_MAX_NODES) {
      stop(p, "no fold: no closed period within %zu step ends (to t = %.9g s)", p->n, t);
      return -1;
    }
    red_node *nodes = realloc(p->nodes, cap * sizeof *nodes);
    if (!nodes) {
      stop(p, "no fold: no memory to record the period (at t = %.9g s)", t);
      return -1;
    }
    p->nodes = nodes;
    p->cap = cap;
  }
  red_node *q = &p->nodes[p->n];
  q->t = t;
  memcpy(q->y, y, RED_NSTATE * sizeof(double));
  if (red_rhs(&p->disk, q->y, q->f)) {
    stop(p, "no fold: the state left the domain at t = %.9g s", t);
    return -1;
  }
  p->n++;
  return 0;
}

/* the first maximum of theta: the period starts there */
static void first_maximum(red_period *p, double t, const double *y) {
  p->maxima = 1;
  p->t_a = t;
  memcpy(p->y_a, y, sizeof p->y_a);
  p->theta_lo = p->theta_hi = y[RED_TH];
  for (size_t k = 0; k < NREDUCED; k++) p->size[reduced[k]] = fabs(y[reduced[k]]);
}

int red_period_reset(red_period *p, double t0, const double y0[RED_NSTATE], dv_error *err) {
  p->n = 0;
  p->cached = 0;
  p->turn_k = NAN;
  p->maxima = 0;
  p->status = RED_PERIOD_RECORDING;
  snprintf(p->note, sizeof p->note, "no fold: no period within the run");
  if (push(p, t0, y0) && p->n == 0 && !p->nodes)
    return dv_fail(err, DV_ESYSTEM, "out of memory: the period fold's first node");
  if (p->n && y0[RED_VTH] == 0.0 && p->nodes[0].f[RED_VTH] < 0.0) /* it starts at a maximum */
    first_maximum(p, t0, y0);
  return DV_OK;
}

/* the integrator's interpolant on the step ending at node i >= 1 */
static const red_hermite *step_hermite(red_period *p, size_t i) {
  if (p->cached != i) {
    const red_node *nodes[RED_HERMITE_NODES];
    const size_t first = i + 1 > RED_HERMITE_NODES ? i + 1 - RED_HERMITE_NODES : 0;
    for (size_t k = first; k <= i; k++) nodes[k - first] = &p->nodes[k];
    red_hermite_init(&p->hermite, RED_NSTATE, nodes, i + 1 - first);
    p->cached = i;
  }
  return &p->hermite;
}

static double theta_rate(double t, void *ctx) {
  red_period *p = ctx;
  return red_hermite_eval_one(&p->hermite, RED_VTH, t);
}

/* y at t in the step ending at node i, by a step of the method */
static int step_onto(red_period *p, size_t i, double t, double *y) {
  return red_node_step(p->onto, &p->sys, &p->nodes[i - 1], t, y);
}

/* where theta' falls through zero inside the step ending at node i, and y
 * there: Brent's method on the interpolant, then Newton's on steps of the
 * method (the maxima set the period, which every later period repeats) */
static double locate_maximum(red_period *p, size_t i, double *y) {
  const double ta = p->nodes[i - 1].t, tb = p->nodes[i].t;
  double t = tb;
  if (p->nodes[i].y[RED_VTH] != 0.0) {
    step_hermite(p, i);
    gsl_function fn = {theta_rate, p};
    if (red_brent(&fn, ta, tb, 0.0, 4.0 * DBL_EPSILON, &t)) return NAN;
  }
  for (int iter = 0; iter < 3; iter++) {
    double f[RED_NSTATE];
    if (step_onto(p, i, t, y) || red_rhs(&p->disk, y, f) || !(f[RED_VTH] < 0.0)) return NAN;
    t = fmin(tb, fmax(ta, t - y[RED_VTH] / f[RED_VTH]));
  }
  return step_onto(p, i, t, y) ? NAN : t;
}

/* the largest mismatch of the reduced state at t_b against t_a, in
 * tolerances of each component's size over the period */
static double closure(const red_period *p) {
  double worst = 0.0;
  for (size_t k = 0; k < NREDUCED; k++) {
    const int j = reduced[k];
    const double tol = p->rtol * p->size[j] + p->atol;
    worst = fmax(worst, fabs(p->y_b[j] - p->y_a[j]) / tol);
  }
  return worst;
}

/* a second maximum: fold if the reduced state closes over a true nutation */
static void close_period(red_period *p) {
  const double amplitude = p->theta_hi - p->theta_lo;
  const double amplitude_tol = RED_PERIOD_AMPLITUDE * (p->rtol * p->y_a[RED_TH] + p->atol);
  const double mismatch = closure(p);
  if (!(amplitude >= amplitude_tol)) {
    stop(p, "no fold: theta's range over a period, %.3g rad, is below %.3g rad (a steady motion)",
         amplitude, amplitude_tol);
    return;
  }
  if (!(mismatch <= RED_PERIOD_CLOSURE)) {
    stop(p,
         "no fold: the reduced state after one period missed its start by %.3g tolerances at t "
         "= %.9g s",
         mismatch, p->t_b);
    return;
  }
  p->T = p->t_b - p->t_a;
  p->dphi = p->y_b[RED_PH] - p->y_a[RED_PH];
  p->dpsi = p->y_b[RED_PS] - p->y_a[RED_PS];
  p->status = RED_PERIOD_CLOSED;
  snprintf(p->note, sizeof p->note,
           "folded from t = %.9g s: nutation period %.12g s, theta from %.9g rad over a range of "
           "%.3g rad, the reduced state closes within %.2g tolerances",
           p->t_a, p->T, p->theta_lo, amplitude, mismatch);
}

int red_period_record(double t, const double *y, void *ctx) {
  red_period *p = ctx;
  if (p->status != RED_PERIOD_RECORDING) return p->status == RED_PERIOD_CLOSED;
  if (push(p, t, y)) return 0;
  const size_t i = p->n - 1;
  if (p->maxima) {
    p->theta_lo = fmin(p->theta_lo, y[RED_TH]);
    p->theta_hi = fmax(p->theta_hi, y[RED_TH]);
    for (size_t k = 0; k < NREDUCED; k++)
      p->size[reduced[k]] = fmax(p->size[reduced[k]], fabs(y[reduced[k]]));
  }
  if (!(p->nodes[i - 1].y[RED_VTH] > 0.0 && y[RED_VTH] <= 0.0)) return 0;
  double *ym = p->maxima ? p->y_b : p->y_a;
  const double tm = locate_maximum(p, i, ym);
  if (!isfinite(tm)) {
    stop(p, "no fold: a maximum of theta near t = %.9g s was not located", t);
    return 0;
  }
  if (p->maxima == 0) {
    first_maximum(p, tm, ym);
    return 0;
  }
  p->maxima = 2;
  p->t_b = tm;
  close_period(p);
  return p->status == RED_PERIOD_CLOSED;
}

red_period_status red_period_state(const red_period *p) {
  return p->status;
}

int red_period_covers(const red_period *p, double t) {
  return p->status == RED_PERIOD_CLOSED || (p->n > 0 && t <= p->nodes[p->n - 1].t);
}

/* the recorded state at t in [t0, last step end] */
static void recorded(red_period *p, double t, double *y) {
  size_t lo = 0, hi = p->n - 1; /* nodes[lo].t < t <= nodes[hi].t */
  if (t <= p->nodes[0].t) {
    memcpy(y, p->nodes[0].y, RED_NSTATE * sizeof(double));
    return;
  }
  if (p->cached && p->nodes[p->cached - 1].t < t && t <= p->nodes[p->cached].t)
    lo = p->cached - 1, hi = p->cached;
  while (hi - lo > 1) {
    const size_t mid = lo + (hi - lo) / 2;
    if (p->nodes[mid].t < t)
      lo = mid;
    else
      hi = mid;
  }
  if (t == p->nodes[hi].t)
    memcpy(y, p->nodes[hi].y, RED_NSTATE * sizeof(double));
  else
    red_hermite_eval(step_hermite(p, hi), t, y);
}

int red_period_eval(red_period *p, double t, double y[RED_NSTATE]) {
  if (!red_period_covers(p, t)) return DV_EINPUT;
  if (p->status != RED_PERIOD_CLOSED ||
      t <= p->nodes[p->n - 1].t) { /* recorded up to t_b and past */
    recorded(p, t, y);
    return DV_OK;
  }
  double k = floor((t - p->t_a) / p->T);
  double tau = fma(-k, p->T, t);
  if (tau < p->t_a) tau += p->T, k -= 1.0; /* rounding at a period's edge */
  if (tau >= p->t_b) tau -= p->T, k += 1.0;
  recorded(p, tau, y);
  if (!(k == p->turn_k)) { /* the samples of a period share one turn: five sines fewer a sample */
    const double a = remainder(p->dphi, 2.0 * M_PI), half = sin(0.5 * a);
    p->turn[4] = half == 0.0 ? k : sin(0.5 * k * a) / half; /* |S_k| */
    p->turn[0] = cos(k * a), p->turn[1] = sin(k * a);
    p->turn[2] = cos(0.5 * (k - 1.0) * a), p->turn[3] = sin(0.5 * (k - 1.0) * a);
    p->turn_k = k;
  }
  const double sum = p->turn[4];
  const double dx = y[RED_X] - p->y_a[RED_X];
  const double dy = y[RED_Y] - p->y_a[RED_Y];
  const double bx = p->y_b[RED_X] - p->y_a[RED_X], by = p->y_b[RED_Y] - p->y_a[RED_Y];
  const double c = p->turn[0], s = p->turn[1], cs = p->turn[2], ss = p->turn[3];
  y[RED_X] = p->y_a[RED_X] + c * dx - s * dy + sum * (cs * bx - ss * by);
  y[RED_Y] = p->y_a[RED_Y] + s * dx + c * dy + sum * (ss * bx + cs * by);
  y[RED_PH] += k * p->dphi;
  y[RED_PS] += k * p->dpsi;
  return DV_OK;
}

int red_period_orbit(const red_period *p, double *t_a, double *T, double *dphi, double *dpsi) {
  if (p->status != RED_PERIOD_CLOSED) return DV_EINPUT;
  *t_a = p->t_a, *T = p->T, *dphi = p->dphi, *dpsi = p->dpsi;
  return DV_OK;
}

const char *red_period_note(const red_period *p) {
  return p->note;
}
