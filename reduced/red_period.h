/* red_period: the whole motion from one period of the reduced motion.
 *
 * Along a rolling disk's motion theta oscillates between two turning points,
 * and (theta', phi', psi') are functions of the place on that orbit: the
 * reduced state is periodic with the nutation period T. The disk's symmetries
 * (moving and turning in the plane, turning about its axis) then carry each
 * period of the whole motion onto the next. Between two maxima of theta at
 * t_a and t_b = t_a + T, where the reduced state closes:
 *
 *   t = t_a + k T + tau,   0 <= tau < T
 *   reduced(t) = reduced(t_a + tau)
 *   phi(t) = phi(t_a + tau) + k dphi,   psi(t) = psi(t_a + tau) + k dpsi
 *   p(t)   = p_a + R(k dphi) (p(t_a + tau) - p_a) + S_k (p_b - p_a)
 *   S_k    = sum_{j<k} R(j dphi) = sin(k dphi/2) / sin(dphi/2) R((k-1) dphi/2)
 *
 * with p = (x, y), R(a) the rotation by a, dphi = phi_b - phi_a and
 * dpsi = psi_b - psi_a. The recorder takes the step ends of a free-stepping
 * 8th-order integrator (red_integrator_observe) with y' there; between them
 * the state is the integrator's own degree-7 Hermite output (red_hermite).
 * That output keeps the tolerance only where the integrator's steps are
 * bounded by the motion's frequency (red_step_gsl.c), which they are while
 * nothing asks it for dense output: while recording, every output must come
 * from here (red_period_covers), not from the integrator.
 *
 * It folds only a motion that shows it is periodic: the reduced state at t_b
 * within RED_PERIOD_CLOSURE tolerances of the one at t_a, and a nutation
 * (theta's range over the period) of at least RED_PERIOD_AMPLITUDE
 * tolerances, so that rounding around a steady motion is not taken for one.
 * Otherwise, or past RED_PERIOD_MAX_NODES step ends, recording stops and the
 * integrator steps on as before.
 */
#ifndef RED_PERIOD_H
#define RED_PERIOD_H

#include "red_disk.h"
#include "red_solver.h"

#define RED_PERIOD_CLOSURE 100.0
#define RED_PERIOD_AMPLITUDE 1e4
#define RED_PERIOD_MAX_NODES 32768

typedef enum red_period_status {
  RED_PERIOD_RECORDING = 0, /* no period yet; the step ends so far are kept */
  RED_PERIOD_CLOSED,        /* a period found: every later time is answered */
  RED_PERIOD_OFF            /* no fold for this run (red_period_note says why) */
} red_period_status;

typedef struct red_period red_period;

/* a recorder for the disk; rtol, atol: the integrator's tolerances */
red_period *red_period_alloc(const red_disk *disk, double rtol, double atol, dv_error *err);
void red_period_free(red_period *p); /* NULL-safe */

/* start recording at (t0, y0) */
int red_period_reset(red_period *p, double t0, const double y0[RED_NSTATE], dv_error *err);

/* a red_step_fn: record a step end (ctx: the red_period); non-zero once closed */
int red_period_record(double t, const double *y, void *ctx);

red_period_status red_period_state(const red_period *p);

/* whether red_period_eval answers t */
int red_period_covers(const red_period *p, double t);

/* the state at t; DV_OK, or DV_EINPUT where t is not covered */
int red_period_eval(red_period *p, double t, double y[RED_NSTATE]);

/* the period found: it starts at *t_a (s), lasts *T (s), and phi and psi
 * advance by *dphi, *dpsi over it (rad); DV_OK, or DV_EINPUT before a
 * period is closed */
int red_period_orbit(const red_period *p, double *t_a, double *T, double *dphi, double *dpsi);

/* what was found: the period and its closure, or why there is no fold */
const char *red_period_note(const red_period *p);

#endif
