/* red_orbit_thick: turning points and period of the thick disk by integration. */
#include "red_orbit_thick.h"

#include <math.h>
#include <string.h>

/* samples per shortest time scale 1 / frequency: against 3200, the turning
 * points move by 2e-15 rad, the period by 4e-11 of itself, the advances by
 * 9e-12 rad (a euro coin and a nutating quarter; build with 3200 and compare
 * diskval analyze --json) */
#define SAMPLES 400.0

/* at most this many samples (a second or two): a period longer than that is not seen */
#define MAX_SAMPLES 1e6

typedef struct sample {
  double t, y[RED_NSTATE];
} sample;

/* cubic Hermite between b and c at u in [0, 1] of the step h, of a value f with rate df */
static double hermite(double fb, double dfb, double fc, double dfc, double h, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * fb + (u3 - 2 * u2 + u) * h * dfb + (-2 * u3 + 3 * u2) * fc +
         (u3 - u2) * h * dfc;
}

/* the turning point between b and c (theta' changes sign there): the zero of
 * the parabola of theta' through a, b, c (equal steps), by Newton from the
 * secant; its time, and theta, phi, psi there by Hermite on b and c */
static void turning_point(const sample *a, const sample *b, const sample *c, double *t,
                          double v[3]) {
  const double h = c->t - b->t, pa = a->y[RED_VTH], pb = b->y[RED_VTH], pc = c->y[RED_VTH];
  const double d1 = 0.5 * (pc - pa), d2 = pc - 2.0 * pb + pa;
  double u = pb / (pb - pc);
  for (int i = 0; i < 8; i++) {
    const double f = pb + u * d1 + 0.5 * u * u * d2, df = d1 + u * d2;
    if (df == 0.0) break;
    u -= f / df;
  }
  if (!(u >= 0.0)) u = 0.0;
  if (u > 1.0) u = 1.0;
  *t = b->t + u * h;
  static const int k[3][2] = {{RED_TH, RED_VTH}, {RED_PH, RED_VPH}, {RED_PS, RED_VPS}};
  for (int i = 0; i < 3; i++)
    v[i] = hermite(b->y[k[i][0]], b->y[k[i][1]], c->y[k[i][0]], c->y[k[i][1]], h, u);
}

int red_orbit_thick_run(const red_rolling *rr, const red_stepper_type *stepper, double rtol,
                        double atol, const double y0[RED_NSTATE], double t_max, red_orbit_thick *o,
                        dv_error *err) {
  memset(o, 0, sizeof *o);
  o->event = -1;
  o->range[0] = o->range[1] = y0[RED_TH];
  const double w = sqrt(rr->disk.g / rr->disk.r) + fabs(y0[RED_VPH]) + fabs(y0[RED_VPS]);
  double thdd = 0.0;
  if (red_rolling_tilt_acceleration(rr, y0, &thdd))
    return dv_fail(err, DV_ENUMERIC, "the thick disk's equations fail at the start");
  o->steady = fabs(y0[RED_VTH]) <= 1e-9 * w && fabs(thdd) <= 1e-9 * w * w;
  if (o->steady) return DV_OK;
  double s[RR_NSTATE];
  red_rolling_from_state(rr, y0, s);
  const double dt = 1.0 / (SAMPLES * rr->sys.frequency(s, (void *)rr));
  t_max = fmin(t_max, MAX_SAMPLES * dt); /* a bounded run: the text says none was seen */
  red_integrator *in = red_integrator_alloc(&rr->sys, stepper, rtol, atol, err);
  if (!in) return DV_ENUMERIC;
  int status = red_integrator_reset(in, 0.0, t_max, s, err);
  /* turning points: time, then theta, phi, psi; the start is one where theta' = 0 */
  double turn[3][4];
  int nturn = 0;
  if (y0[RED_VTH] == 0.0) {
    turn[0][0] = 0.0;
    turn[0][1] = y0[RED_TH], turn[0][2] = y0[RED_PH], turn[0][3] = y0[RED_PS];
    nturn = 1;
  }
  sample win[3];
  win[2].t = 0.0;
  memcpy(win[2].y, y0, sizeof win[2].y);
  long n = 1;
  for (long k = 1; !status && nturn < 3; k++) {
    const double t = fmin(k * dt, t_max);
    double st[RR_NSTATE], t_got;
    int event = -1;
    win[0] = win[1];
    win[1] = win[2];
    status = red_integrator_advance(in, t, &t_got, st, &event, err);
    if (status < 0) break;
    win[2].t = t_got;
    red_rolling_to_state(st, win[2].y);
    n++;
    o->t_end = t_got;
    o->range[0] = fmin(o->range[0], win[2].y[RED_TH]);
    o->range[1] = fmax(o->range[1], win[2].y[RED_TH]);
    if (status == DV_EVENT) {
      o->event = event;
      o->t_event = t_got;
      o->falls = event == RR_EVENT_THETA_LOW || event == RR_EVENT_THETA_HIGH;
      status = DV_OK;
      break;
    }
    /* a turning point in the last interval: theta' changes sign across it */
    if (n >= 3 && t_got == k * dt && win[1].y[RED_VTH] * win[2].y[RED_VTH] < 0.0) {
      double tv, v[3];
      turning_point(&win[0], &win[1], &win[2], &tv, v);
      turn[nturn][0] = tv;
      turn[nturn][1] = v[0], turn[nturn][2] = v[1], turn[nturn][3] = v[2];
      nturn++;
      o->range[0] = fmin(o->range[0], v[0]);
      o->range[1] = fmax(o->range[1], v[0]);
    }
    if (t >= t_max) break;
  }
  red_integrator_free(in);
  if (status < 0) return status;
  if (nturn == 3) {
    o->nutates = 1;
    for (int i = 0; i < 3; i++)
      o->nutation[i] = turn[2][i == 0 ? 0 : i + 1] - turn[0][i == 0 ? 0 : i + 1];
  }
  return DV_OK;
}
