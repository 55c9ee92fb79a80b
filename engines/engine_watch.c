/* engine_watch: the faults that end a contact engine's run (engine_watch.h). */
#include "engine_watch.h"

#include <math.h>
#include <stdio.h>

int dv_pose_finite(const dv_pose *p) {
  double sum = 0.0;
  for (int i = 0; i < 3; i++) sum += p->pos[i] + p->vel[i] + p->omega[i];
  for (int i = 0; i < 9; i++) sum += p->R[i];
  return isfinite(sum);
}

dv_failure dv_engine_watch_start(dv_engine_watch *w, const red_disk *disk, const dv_pose *pose,
                                 char *msg, size_t size) {
  w->e0 = dv_pose_energy(disk, pose);
  w->e_max = w->e0 + 0.5 * fabs(w->e0) + disk->m * disk->g * disk->r;
  w->airborne = 0.0;
  w->checked = 0;
  if (dv_pose_finite(pose) && isfinite(w->e0)) return DV_FAILURE_NONE;
  snprintf(msg, size, "the initial pose or energy is not finite");
  return DV_FAILURE_SETUP;
}

dv_failure dv_engine_watch_check(dv_engine_watch *w, const red_disk *disk, const dv_geometry *geom,
                                 const dv_pose *p, long k, double dt, char *msg, size_t size) {
  const double t = k * dt;
  if (!dv_pose_finite(p)) {
    snprintf(msg, size, "non-finite state at t = %g s", t);
    return DV_FAILURE_NAN;
  }
  const double energy = dv_pose_energy(disk, p);
  if (!(energy <= w->e_max)) {
    snprintf(msg, size, "runaway energy at t = %g s: %g J > %g J (E0 = %g J)", t, energy,
             w->e_max, w->e0);
    return DV_FAILURE_ENERGY;
  }
  const double height = p->pos[2] + dv_geometry_contact_height(geom, p->R);
  if (height < -DV_WATCH_SUNK * disk->r) {
    snprintf(msg, size, "sank %g m into the ground at t = %g s", -height, t);
    return DV_FAILURE_SANK;
  }
  w->airborne = height > DV_WATCH_AIR * disk->r ? w->airborne + (k - w->checked) * dt : 0.0;
  if (w->airborne > DV_WATCH_AIR_TIME) {
    snprintf(msg, size, "lowest point %g m above the ground for %g s at t = %g s", height,
             w->airborne, t);
    return DV_FAILURE_LOST_CONTACT;
  }
  w->checked = k;
  return DV_FAILURE_NONE;
}

double dv_rows_rate_scale(const red_disk *disk, const double y0[RED_NSTATE]) {
  double scale = sqrt(disk->g / disk->r);
  for (int k = RED_VTH; k <= RED_VPS; k++) scale = fmax(scale, fabs(y0[k]));
  return scale;
}

int dv_rows_turn_near_flat(const dv_sample *a, const dv_sample *s) {
  return a->y[RED_VTH] * s->y[RED_VTH] < 0.0 &&
         fmin(sin(a->y[RED_TH]), sin(s->y[RED_TH])) < DV_ROWS_FLAT_TURN;
}

double dv_rows_angle(const dv_sample *a, const dv_sample *s, int k, double rate_scale,
                     dv_rows_drift *drift, double *miss, int *summed) {
  static const int angle[3] = {RED_TH, RED_PH, RED_PS}, rate[3] = {RED_VTH, RED_VPH, RED_VPS};
  const int q = angle[k], v = rate[k];
  const double dt = s->t - a->t, ra = a->y[v], rs = s->y[v];
  const double scale = fmax(rate_scale, fmax(fabs(ra), fabs(rs)));
  *miss = remainder(s->y[q] - a->y[q] - 0.5 * dt * (ra + rs), 2.0 * M_PI);
  *summed = 0;
  /* a rate that changes by more than this within the step is not resolved
   * by the samples (a fall spinning phi up near lying down): the trapezoid
   * says nothing there */
  if (fabs(rs - ra) > DV_ROWS_RATE_TOL * scale) return 0.0;
  if (!drift->begun) *drift = (dv_rows_drift){0.0, 0.0, a->y[q], 1};
  drift->miss += *miss;
  drift->travel += 0.5 * dt * (fabs(ra) + fabs(rs));
  const double step = DV_ROWS_RATE_TOL * dt * scale + DV_ROWS_ROUND * (fabs(a->y[q]) + fabs(s->y[q]));
  const double sum = DV_ROWS_DRIFT * drift->travel + step +
                     DV_ROWS_ROUND * (fabs(drift->first) + fabs(s->y[q]));
  const double d = fabs(*miss) / step, ds = fabs(drift->miss) / sum;
  *summed = ds > d;
  return fmax(d, ds);
}

int dv_rows_angles(const dv_sample *a, const dv_sample *s, int pose, double rate_scale,
                   dv_rows_drift drift[3], double *d, double *miss, int *summed) {
  const int flat = (pose && s->y[RED_TH] < 1e-3) || dv_rows_turn_near_flat(a, s);
  for (int k = 0; k < (flat ? 1 : 3); k++) {
    *d = dv_rows_angle(a, s, k, rate_scale, &drift[k], miss, summed);
    if (*d > 1.0) return k;
  }
  return -1;
}

int dv_rows_start_off(const double y[RED_NSTATE], const double y0[RED_NSTATE], double r,
                      double rate_scale) {
  for (int k = 0; k < RED_NSTATE; k++) {
    const int angle = k == RED_PH || k == RED_PS;
    const double scale = k == RED_X || k == RED_Y ? r : (k == RED_TH || angle ? 1.0 : rate_scale);
    const double d = angle ? remainder(y[k] - y0[k], 2.0 * M_PI) : y[k] - y0[k];
    if (!(fabs(d) <= DV_ROWS_START_TOL * scale)) return k;
  }
  return -1;
}

double dv_rows_centre(dv_rows_centre_track *c, const dv_sample *a, const dv_sample *s,
                      const double pos[2], const double vel[2], double speed_floor, int *k) {
  double worst = 0.0, e[2] = {0.0, 0.0};
  *k = 0;
  if (c->n && a) {
    const double dt = s->t - c->t;
    const double speed =
        fmax(speed_floor, fmax(hypot(vel[0], vel[1]), hypot(c->vel[0], c->vel[1])));
    /* theta turning near flat within the step: the centre whirls with phi
     * between the rows, unresolved by them */
    const int flat_turn = dv_rows_turn_near_flat(a, s);
    for (int i = 0; i < 2; i++) {
      /* a velocity that changes by more than the allowance within the step
       * is not resolved by the samples (a fall near lying down, as the
       * angles' rates): the trapezoid says nothing there, nor about the next
       * step's change of miss */
      if (flat_turn || fabs(vel[i] - c->vel[i]) > DV_ROWS_CENTRE_TOL * speed) {
        e[i] = NAN;
        continue;
      }
      /* the step's miss of the trapezoid, and its change from the step
       * before: smooth motion misses by a smooth amount, a centre sliding
       * back and forth under rolling velocities by turns */
      e[i] = (pos[i] - c->pos[i] - 0.5 * dt * (c->vel[i] + vel[i])) / (dt * speed);
      const double turn =
          c->n > 1 && !isnan(c->miss[i]) ? fabs(e[i] - c->miss[i]) / DV_ROWS_CENTRE_TURN : 0.0;
      const double d = fmax(fabs(e[i]) / DV_ROWS_CENTRE_TOL, turn);
      if (!(d <= worst)) worst = d, *k = i;
    }
  }
  for (int i = 0; i < 2; i++) c->pos[i] = pos[i], c->vel[i] = vel[i], c->miss[i] = e[i];
  c->t = s->t;
  c->n++;
  return worst;
}
