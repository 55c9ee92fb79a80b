/* red_solver: integrate an ODE system with sampled output and events.
 *
 * A stepper is a const type (GSL-style method table) that advances one
 * internal step at a time and interpolates inside the last step (dense
 * output). The driver samples the trajectory on a fixed grid from the dense
 * output, watches event functions at step ends and locates a sign change by
 * Brent's method on the dense output; the run ends at the first event.
 */
#ifndef RED_SOLVER_H
#define RED_SOLVER_H

#include <stddef.h>

#include "dv_error.h"

#define RED_MAX_DIM 16
#define RED_MAX_EVENTS 6

/* y' = f(t, y); returns 0, or non-zero when y is outside the domain */
typedef int (*red_rhs_fn)(double t, const double *y, double *f, void *params);

/* event function: the run ends where g changes sign */
typedef double (*red_event_fn)(double t, const double *y, void *params);

typedef struct red_system {
  size_t dim;     /* number of states, <= RED_MAX_DIM */
  red_rhs_fn rhs; /* right-hand side */
  void *params;   /* passed to rhs and events */
  /* optional: the fastest angular frequency in the motion at y (rad/s); steppers
   * that interpolate from step ends bound h by it (see red_step_gsl.c) */
  double (*frequency)(const double *y, void *params);
  size_t nevents; /* <= RED_MAX_EVENTS */
  red_event_fn events[RED_MAX_EVENTS];
  const char *event_names[RED_MAX_EVENTS];
} red_system;

typedef struct red_stats {
  long steps;        /* accepted internal steps */
  long rhs_evals;    /* right-hand side evaluations */
  long failed_steps; /* rejected steps (where the method reports them) */
} red_stats;

/* stepper capabilities */
enum {
  RED_CAP_DENSE = 1, /* interpolates at the method's accuracy: may step past outputs */
};

typedef struct red_stepper_type {
  const char *name;        /* as written in a scenario: integrator = NAME */
  const char *description; /* one line for --help */
  int caps;                /* RED_CAP_* */
  void *(*alloc)(const red_system *sys, double rtol, double atol, dv_error *err);
  int (*reset)(void *state, double t0, const double *y0, dv_error *err);
  /* one internal step, never beyond t_max; sets *t to the time reached */
  int (*step)(void *state, double t_max, double *t, dv_error *err);
  /* interpolate y at t inside the last step */
  int (*dense)(void *state, double t, double *y, dv_error *err);
  void (*stats)(const void *state, red_stats *out);
  void (*free)(void *state);
} red_stepper_type;

extern const red_stepper_type red_gsl_rk8pd;         /* GSL rk8pd, free steps, Hermite output */
extern const red_stepper_type red_gsl_rk8pd_stepped; /* GSL rk8pd stepping onto outputs */
extern const red_stepper_type red_gsl_msadams;       /* GSL variable-order Adams, onto outputs */
extern const red_stepper_type red_cvode_adams;       /* CVODE Adams-Moulton, fixed point */
extern const red_stepper_type red_cvode_bdf;         /* CVODE BDF, Newton, dense LU */
extern const red_stepper_type red_arkode_fehlberg13; /* ARKODE ERK Fehlberg 13-stage 8th order */

/* NULL-terminated list of every stepper */
extern const red_stepper_type *const red_steppers[];

/* the stepper called name, or NULL */
const red_stepper_type *red_stepper_find(const char *name);

/* the default reference stepper (chosen by measurement, see bench/) */
const red_stepper_type *red_stepper_default(void);

/* an integration in progress: steps, dense output and events together */
typedef struct red_integrator red_integrator;

red_integrator *red_integrator_alloc(const red_system *sys, const red_stepper_type *stepper,
                                     double rtol, double atol, dv_error *err);

/* Progress guard: a run that stalls ends with DV_ENUMERIC, never hangs. It
 * stalls when it takes RED_MAX_SHORT_STEPS steps in a row shorter than
 * RED_MIN_STEP_FRACTION of the scene's time scale (1 / sys->frequency at the
 * start, else t_end - t0), or when it has taken max_steps steps. */
#define RED_DEFAULT_MAX_STEPS 1000000L
#define RED_MIN_STEP_FRACTION 1e-8
#define RED_MAX_SHORT_STEPS 1000
/* the default budget per shortest time scale of a scene (engine_reduced.c) */
#define RED_STEPS_PER_SCALE 1000.0

/* the step budget of the runs that follow (<= 0: RED_DEFAULT_MAX_STEPS) */
void red_integrator_set_max_steps(red_integrator *in, long max_steps);

/* told the end of every accepted step that has no event in it (y: the state
 * there); a non-zero return pauses the stepping (red_integrator_step_to) */
typedef int (*red_step_fn)(double t, const double *y, void *ctx);

/* the observer of the runs that follow (NULL: none) */
void red_integrator_observe(red_integrator *in, red_step_fn fn, void *ctx);

/* why the run stalled (the progress guard), or "" */
const char *red_integrator_stalled(const red_integrator *in);

/* start again from y0 at t0; no internal step goes beyond t_end */
int red_integrator_reset(red_integrator *in, double t0, double t_end, const double *y0,
                         dv_error *err);

/* advance to t_out, or to the first event before it; writes the time reached
 * and y there. Returns DV_OK, DV_EVENT (with *event its index) or < 0.
 * Once an event is reached, further calls return DV_EVENT again. */
int red_integrator_advance(red_integrator *in, double t_out, double *t, double *y, int *event,
                           dv_error *err);

/* step until a step ends at or past t_out (or t_end), at an event, or where
 * the observer pauses; no output. Returns DV_OK or < 0 */
int red_integrator_step_to(red_integrator *in, double t_out, dv_error *err);

void red_integrator_stats(const red_integrator *in, red_stats *out);
void red_integrator_free(red_integrator *in); /* NULL-safe */

/* output callback: one sample; non-zero stops the run (status returned) */
typedef int (*red_sample_fn)(double t, const double *y, void *ctx);

typedef struct red_run {
  const red_stepper_type *stepper;
  double rtol, atol; /* tolerances passed to the stepper */
  double t0, t_end;  /* s */
  double output_dt;  /* sample spacing, s; samples at t0 + k output_dt and at the end */
  red_sample_fn sample;
  void *sample_ctx;
} red_run;

typedef struct red_result {
  double t_final; /* time of the last sample, s */
  int event;      /* index of the event that ended the run, or -1 */
  red_stats stats;
} red_result;

/* the k-th output time t0 + k dt, snapped onto t_end within rounding */
double red_grid_time(double t0, double dt, double t_end, long k);

/* integrate sys from y0 sampling every output_dt; the final state is written
 * back to y0. Returns DV_OK, DV_EVENT (ended at an event), or < 0. */
int red_solve(const red_system *sys, const red_run *run, double *y0, red_result *res,
              dv_error *err);

#endif
