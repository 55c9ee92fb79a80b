/* dv_testlib: trajectories in memory for the reduced-solver tests. */
#include "dv_testlib.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "red_formulations.h"
#include "red_reference.h"

red_disk tl_disk(double a_ratio, double c_ratio) {
  const double r = 0.1, m = 1.0;
  red_disk d = {r, m, a_ratio * m * r * r, c_ratio * m * r * r, 9.81};
  return d;
}

typedef struct sink {
  tl_traj *tr;
  const red_disk *disk;
  int form;
} sink;

static int keep(double t, const double *y, void *ctx) {
  sink *s = ctx;
  tl_traj *tr = s->tr;
  if (tr->n >= TL_MAX_SAMPLES) return -1;
  tr->t[tr->n] = t;
  if (s->form == 1)
    red_state_from_momentum(s->disk, y, tr->y[tr->n]);
  else if (s->form == 2)
    red_state_from_lagrange(y, tr->y[tr->n]);
  else
    memcpy(tr->y[tr->n], y, sizeof tr->y[0]);
  tr->n++;
  return 0;
}

static tl_traj alloc_traj(double duration, double dt) {
  tl_traj tr = {0};
  long cap = (long)(duration / dt) + 3;
  if (cap > TL_MAX_SAMPLES) cap = TL_MAX_SAMPLES;
  tr.t = malloc((size_t)cap * sizeof *tr.t);
  tr.y = malloc((size_t)cap * sizeof *tr.y);
  return tr;
}

tl_traj tl_run(const red_disk *disk, const red_stepper_type *stepper, double tol,
               const double y0[RED_NSTATE], double duration, double dt, double theta_limit) {
  return tl_run_tols(disk, stepper, tol, tol * 1e-2, y0, duration, dt, theta_limit);
}

tl_traj tl_run_tols(const red_disk *disk, const red_stepper_type *stepper, double rtol, double atol,
                    const double y0[RED_NSTATE], double duration, double dt, double theta_limit) {
  red_reference ref;
  red_reference_init(&ref, disk, theta_limit);
  tl_traj tr = alloc_traj(duration, dt);
  sink s = {&tr, disk, 0};
  red_run run = {stepper, rtol, atol, 0.0, duration, dt, keep, &s};
  double y[RED_NSTATE];
  memcpy(y, y0, sizeof y);
  tr.status = red_solve(&ref.sys, &run, y, &tr.result, NULL);
  return tr;
}

static int disk_rhs(double t, const double *y, double *f, void *p) {
  return red_rhs(p, y, f);
}

tl_traj tl_run_form(const red_disk *disk, int form, const red_stepper_type *stepper, double tol,
                    const double y0[RED_NSTATE], double duration, double dt) {
  red_disk dk = *disk;
  double y[RED_LAGRANGE_DIM];
  red_system sys = {RED_NSTATE, disk_rhs, &dk, NULL, 0, {0}, {0}};
  if (form == 1) {
    sys.rhs = red_momentum_rhs;
    red_momentum_from_state(disk, y0, y);
  } else if (form == 2) {
    sys.dim = RED_LAGRANGE_DIM;
    sys.rhs = red_lagrange_rhs;
    red_lagrange_from_state(disk, y0, y);
  } else {
    memcpy(y, y0, RED_NSTATE * sizeof(double));
  }
  tl_traj tr = alloc_traj(duration, dt);
  sink s = {&tr, disk, form};
  red_run run = {stepper, tol, tol * 1e-2, 0.0, duration, dt, keep, &s};
  tr.status = red_solve(&sys, &run, y, &tr.result, NULL);
  return tr;
}

void tl_free(tl_traj *tr) {
  free(tr->t);
  free(tr->y);
  tr->t = NULL;
  tr->y = NULL;
}

void tl_compare(const red_disk *disk, const tl_traj *a, const tl_traj *b, double *theta_err,
                double *path_err) {
  const long n = a->n < b->n ? a->n : b->n;
  *theta_err = *path_err = 0.0;
  for (long i = 0; i < n; i++) {
    double pa[2], pb[2];
    red_contact_point(disk, a->y[i], pa);
    red_contact_point(disk, b->y[i], pb);
    *theta_err = fmax(*theta_err, fabs(a->y[i][RED_TH] - b->y[i][RED_TH]));
    *path_err = fmax(*path_err, hypot(pa[0] - pb[0], pa[1] - pb[1]));
  }
}
