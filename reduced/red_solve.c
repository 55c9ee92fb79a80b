/* red_solve: the stepping loop shared by every stepper: output from dense
 * interpolation, and events located by Brent's method (GSL) on it. */
#include <float.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "red_solver.h"
#include "red_gsl_words.h"
#include "red_root.h"

struct red_integrator {
  const red_system *sys;
  const red_stepper_type *type;
  void *stepper;
  double t_step;              /* end of the last internal step */
  double t_end;               /* no step goes beyond */
  double t0, y0[RED_MAX_DIM]; /* the start: answered without asking the stepper */
  double g[RED_MAX_EVENTS];   /* event functions there */
  int event;                  /* event found in the last step, or -1 */
  double t_event;
  int done;        /* an event has been returned */
  int status;      /* error inside the root finder's callback */
  size_t locating; /* event being located */
  dv_error *err;
  long max_steps, steps; /* the budget, and the steps taken since the start */
  int short_steps;       /* steps in a row shorter than min_step */
  double min_step;       /* s */
  char stalled[200];     /* why the progress guard ended the run, or "" */
  red_step_fn observer;  /* told every accepted step's end, or NULL */
  void *observer_ctx;
  int paused; /* the observer asked to stop stepping */
};

red_integrator *red_integrator_alloc(const red_system *sys, const red_stepper_type *type,
                                     double rtol, double atol, dv_error *err) {
  if (sys->dim > RED_MAX_DIM || sys->nevents > RED_MAX_EVENTS)
    return dv_fail(err, DV_EINPUT, "system too large"), NULL;
  red_integrator *in = calloc(1, sizeof *in);
  if (!in) return dv_fail(err, DV_ESYSTEM, "out of memory: an integrator"), NULL;
  in->sys = sys;
  in->type = type;
  in->stepper = type->alloc(sys, rtol, atol, err);
  if (!in->stepper) return free(in), NULL;
  in->max_steps = RED_DEFAULT_MAX_STEPS;
  return in;
}

void red_integrator_set_max_steps(red_integrator *in, long max_steps) {
  in->max_steps = max_steps > 0 ? max_steps : RED_DEFAULT_MAX_STEPS;
}

void red_integrator_observe(red_integrator *in, red_step_fn fn, void *ctx) {
  in->observer = fn;
  in->observer_ctx = ctx;
}

const char *red_integrator_stalled(const red_integrator *in) {
  return in->stalled;
}

void red_integrator_free(red_integrator *in) {
  if (!in) return;
  in->type->free(in->stepper);
  free(in);
}

void red_integrator_stats(const red_integrator *in, red_stats *out) {
  in->type->stats(in->stepper, out);
}

static void eval_events(const red_system *sys, double t, const double *y, double *g) {
  for (size_t i = 0; i < sys->nevents; i++) g[i] = sys->events[i](t, y, sys->params);
}

int red_integrator_reset(red_integrator *in, double t0, double t_end, const double *y0,
                         dv_error *err) {
  in->t_step = t0;
  in->t_end = t_end;
  in->t0 = t0;
  memcpy(in->y0, y0, in->sys->dim * sizeof(double));
  in->event = -1;
  in->done = 0;
  in->steps = 0;
  in->short_steps = 0;
  in->stalled[0] = '\0';
  in->paused = 0;
  const double scale = in->sys->frequency ? 1.0 / in->sys->frequency(y0, in->sys->params) : 0.0;
  in->min_step = RED_MIN_STEP_FRACTION * (scale > 0.0 && isfinite(scale) ? scale : t_end - t0);
  eval_events(in->sys, t0, y0, in->g);
  return in->type->reset(in->stepper, t0, y0, err);
}

static double event_on_dense(double t, void *p) {
  red_integrator *in = p;
  double y[RED_MAX_DIM];
  int status = in->type->dense(in->stepper, t, y, in->err);
  if (status) {
    in->status = status;
    return NAN;
  }
  return in->sys->events[in->locating](t, y, in->sys->params);
}

/* the sign change of event i inside (ta, tb) */
static int locate(red_integrator *in, double ta, double tb, double *t_root) {
  gsl_function fn = {event_on_dense, in};
  in->status = 0;
  const int status = red_brent(&fn, ta, tb, 0.0, 4.0 * DBL_EPSILON, t_root);
  if (in->status) return in->status;
  if (status == GSL_ENOMEM) return dv_fail(in->err, DV_ESYSTEM, "out of memory: GSL's root finder");
  if (status) return dv_fail(in->err, DV_ENUMERIC, "event location: %s", red_gsl_words(status));
  return DV_OK;
}

/* the progress guard (red_solver.h): a stalled run is an error, not a hang */
static int check_progress(red_integrator *in, double t0, double t1, double t_max, dv_error *err) {
  in->steps++;
  if (t1 < t_max) /* a step cut short at an output or at the end says nothing */
    in->short_steps = t1 - t0 < in->min_step ? in->short_steps + 1 : 0;
  if (in->short_steps >= RED_MAX_SHORT_STEPS)
    snprintf(in->stalled, sizeof in->stalled,
             "no progress: %d steps in a row shorter than %.3g s (%g of the scene's time scale) "
             "at t = %.9g s",
             in->short_steps, in->min_step, RED_MIN_STEP_FRACTION, t1);
  else if (in->steps >= in->max_steps && t1 < in->t_end)
    snprintf(in->stalled, sizeof in->stalled,
             "step budget spent: %ld steps reached t = %.9g s of %.9g s", in->steps, t1, in->t_end);
  else
    return DV_OK;
  return dv_fail(err, DV_ENUMERIC, "%s %s", in->type->name, in->stalled);
}

/* one internal step, then the earliest event inside it */
static int step_once(red_integrator *in, double t_max, dv_error *err) {
  double y[RED_MAX_DIM], g[RED_MAX_EVENTS], t1;
  const double t0 = in->t_step;
  int status = in->type->step(in->stepper, t_max, &t1, err);
  if (!status) status = in->type->dense(in->stepper, t1, y, err);
  if (status) return status;
  eval_events(in->sys, t1, y, g);
  in->err = err;
  for (size_t i = 0; i < in->sys->nevents; i++) {
    if (in->g[i] == 0.0 || in->g[i] * g[i] > 0.0) continue;
    double t_root = t1;
    in->locating = i;
    status = locate(in, t0, t1, &t_root);
    if (status) return status;
    if (in->event < 0 || t_root < in->t_event) {
      in->event = (int)i;
      in->t_event = t_root;
    }
  }
  memcpy(in->g, g, sizeof g);
  in->t_step = t1;
  if (in->event >= 0) return DV_OK;
  if (in->observer && in->observer(t1, y, in->observer_ctx)) in->paused = 1;
  return check_progress(in, t0, t1, t_max, err);
}

int red_integrator_step_to(red_integrator *in, double t_out, dv_error *err) {
  const double t_max = in->type->caps & RED_CAP_DENSE ? in->t_end : fmin(t_out, in->t_end);
  in->paused = 0;
  while (in->event < 0 && !in->paused && in->t_step < fmin(t_out, in->t_end)) {
    const int status = step_once(in, t_max, err);
    if (status) return status;
  }
  return DV_OK;
}

int red_integrator_advance(red_integrator *in, double t_out, double *t, double *y, int *event,
                           dv_error *err) {
  if (t_out <= in->t0) { /* ARKODE cannot interpolate before its first step */
    *t = in->t0;
    *event = -1;
    memcpy(y, in->y0, in->sys->dim * sizeof(double));
    return DV_OK;
  }
  int status;
  do /* past any pause the observer asked for */
    status = red_integrator_step_to(in, t_out, err);
  while (!status && in->paused);
  if (status) return status;
  *event = in->event;
  if (in->event >= 0 && in->t_event <= t_out) {
    in->done = 1;
    *t = in->t_event;
    status = in->type->dense(in->stepper, *t, y, err);
    return status ? status : DV_EVENT;
  }
  *event = -1;
  *t = t_out;
  return in->type->dense(in->stepper, t_out, y, err);
}

double red_grid_time(double t0, double dt, double t_end, long k) {
  const double t = t0 + (double)k * dt;
  return (fabs(t - t_end) <= 1e-9 * dt || t > t_end) ? t_end : t;
}

int red_solve(const red_system *sys, const red_run *run, double *y, red_result *res,
              dv_error *err) {
  memset(res, 0, sizeof *res);
  res->event = -1;
  res->t_final = run->t0;
  if (!(run->output_dt > 0.0) || !(run->t_end >= run->t0))
    return dv_fail(err, DV_EINPUT, "output_dt must be > 0 and t_end >= t0");
  red_integrator *in = red_integrator_alloc(sys, run->stepper, run->rtol, run->atol, err);
  if (!in) return DV_ESYSTEM;
  int status = red_integrator_reset(in, run->t0, run->t_end, y, err);
  if (!status) status = run->sample(run->t0, y, run->sample_ctx);
  for (long k = 1; status == DV_OK && res->t_final < run->t_end; k++) {
    double t;
    status = red_integrator_advance(in, red_grid_time(run->t0, run->output_dt, run->t_end, k), &t,
                                    y, &res->event, err);
    if (status >= 0) {
      res->t_final = t;
      int s = run->sample(t, y, run->sample_ctx);
      if (s) status = s;
    }
  }
  red_integrator_stats(in, &res->stats);
  red_integrator_free(in);
  return status;
}
