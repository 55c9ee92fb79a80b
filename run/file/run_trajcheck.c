/* run_trajcheck: a trajectory's columns against each other and the ground (run_trajcheck.h). */
#include "run_trajcheck.h"

#include <math.h>
#include <stdio.h>

#include "engine_watch.h"

void dv_run_trajcheck_ground(dv_trajfile *f, const dv_scenario *sc, double height) {
  const double r = sc->disk.r, t = f->s[f->n].t;
  if (f->ground_fault) return;
  if (height < -DV_WATCH_SUNK * r) {
    f->ground_fault = DV_FAILURE_SANK;
    snprintf(f->ground_detail, sizeof f->ground_detail,
             "sank %g m into the ground at t = %g s (line %ld: the lowest point of the pose; "
             "limit %g m, %g radii)",
             -height, t, f->line[f->n], DV_WATCH_SUNK * r, DV_WATCH_SUNK);
  } else if (height > DV_WATCH_AIR * r) {
    if (!f->airborne) f->airborne = 1, f->air_since = t;
    if (t - f->air_since > DV_WATCH_AIR_TIME) {
      f->ground_fault = DV_FAILURE_LOST_CONTACT;
      snprintf(f->ground_detail, sizeof f->ground_detail,
               "lowest point %g m above the ground for %g s at t = %g s (line %ld: the pose; "
               "limit %g m, %g radii, for %g s)",
               height, t - f->air_since, t, f->line[f->n], DV_WATCH_AIR * r, DV_WATCH_AIR,
               DV_WATCH_AIR_TIME);
    }
  } else {
    f->airborne = 0;
  }
  if (f->ground_fault) f->ground_row = f->n;
}

/* theta turns between rows a and s with sin theta below DV_TRAJ_FLAT_TURN:
 * phi, psi and the centre whirl there, unresolved by the rows */
static int turns_near_flat(const dv_sample *a, const dv_sample *s) {
  return a->y[RED_VTH] * s->y[RED_VTH] < 0.0 &&
         fmin(sin(a->y[RED_TH]), sin(s->y[RED_TH])) < DV_TRAJ_FLAT_TURN;
}

/* the scene's rate scale: sqrt(g/r), or a larger initial rate */
static double rate_scale_of(const dv_scenario *sc) {
  double rate_scale = sqrt(sc->disk.g / sc->disk.r);
  for (int k = RED_VTH; k <= RED_VPS; k++) rate_scale = fmax(rate_scale, fabs(sc->initial[k]));
  return rate_scale;
}

double dv_run_trajcheck_centre(dv_trajfile *f, const dv_scenario *sc, const double pos[2],
                               const double vel[2], int *k) {
  double worst = 0.0, e[2] = {0.0, 0.0};
  *k = 0;
  if (f->n) {
    const double dt = f->s[f->n].t - f->s[f->n - 1].t;
    const double speed =
        fmax(sc->disk.r * rate_scale_of(sc),
             fmax(hypot(vel[0], vel[1]), hypot(f->centre_vel[0], f->centre_vel[1])));
    const dv_sample *a = &f->s[f->n - 1], *s = &f->s[f->n];
    /* theta turning near flat within the step: the centre whirls with phi
     * between the rows, unresolved by them (as in dv_run_trajcheck_columns) */
    const int flat_turn = turns_near_flat(a, s);
    for (int i = 0; i < 2; i++) {
      /* a velocity that changes by more than the allowance within the step
       * is not resolved by the samples (a fall near lying down, as the
       * angles' rates in dv_run_trajcheck_columns): the trapezoid says
       * nothing there, nor about the next step's change of miss */
      if (flat_turn || fabs(vel[i] - f->centre_vel[i]) > DV_TRAJ_CENTRE_TOL * speed) {
        e[i] = NAN;
        continue;
      }
      /* the step's miss of the trapezoid, and its change from the step
       * before: smooth motion misses by a smooth amount, a centre sliding
       * back and forth under rolling velocities by turns */
      e[i] = (pos[i] - f->centre[i] - 0.5 * dt * (f->centre_vel[i] + vel[i])) / (dt * speed);
      const double turn = f->n > 1 && !isnan(f->centre_miss[i])
                              ? fabs(e[i] - f->centre_miss[i]) / DV_TRAJ_CENTRE_TURN
                              : 0.0;
      const double d = fmax(fabs(e[i]) / DV_TRAJ_CENTRE_TOL, turn);
      if (!(d <= worst)) worst = d, *k = i;
    }
  }
  for (int i = 0; i < 2; i++)
    f->centre[i] = pos[i], f->centre_vel[i] = vel[i], f->centre_miss[i] = e[i];
  return worst;
}

/* the contact point row i gives against the one theta, phi, x, y put on the scene's disk */
static double contact_off(const dv_sample *s, const dv_geometry *geom, double *tol) {
  dv_pose p;
  double pt[3], slip;
  dv_pose_from_state(geom, s->y, &p);
  dv_pose_lowest_point(geom, &p, pt, &slip);
  *tol = DV_TRAJ_CONTACT_TOL * geom->radius + geom->half_thickness +
         DV_TRAJ_ROUND * hypot(s->contact[0], s->contact[1]);
  return hypot(s->contact[0] - pt[0], s->contact[1] - pt[1]);
}

int dv_run_trajcheck_columns(const dv_trajfile *f, const dv_scenario *sc, int ccol,
                             const int col[3], dv_error *err) {
  const dv_geometry geom = {DV_SHAPE_CYLINDER, sc->disk.r, f->half_thickness};
  const double rate_scale = rate_scale_of(sc);
  for (size_t i = 0; i < f->n; i++) {
    const dv_sample *s = &f->s[i];
    double tol = 0.0;
    const double off = ccol > 0 ? contact_off(s, &geom, &tol) : 0.0;
    if (off > tol)
      return dv_fail(err, DV_EINPUT,
                     "%.400s:%ld:%d: the contact point (%.6g, %.6g) is %.3g m from where theta, "
                     "phi, x, y put it on the scene's disk (%.3g m allowed): the columns disagree",
                     f->path, f->line[i], ccol, s->contact[0], s->contact[1], off, tol);
    if (!i || !f->has_rates) continue;
    const dv_sample *a = s - 1;
    const double dt = s->t - a->t;
    static const int angle[3] = {RED_TH, RED_PH, RED_PS}, rate[3] = {RED_VTH, RED_VPH, RED_VPS};
    static const char *const name[3] = {"theta", "phi", "psi"};
    if (f->form == DV_TRAJ_POSE && s->y[RED_TH] < 1e-3)
      continue; /* phi, psi undefined lying flat */
    /* theta turning near flat within the step: phi and psi whirl between the
     * rows (rates like 1 / sin^2 theta at the turn), unresolved by them */
    const int flat_turn = turns_near_flat(a, s);
    for (int k = 0; k < 3; k++) {
      if (k > 0 && flat_turn) continue;
      const double step = 0.5 * dt * (a->y[rate[k]] + s->y[rate[k]]);
      const double d = fabs(remainder(s->y[angle[k]] - a->y[angle[k]] - step, 2.0 * M_PI));
      const double scale = dt * fmax(rate_scale, fmax(fabs(a->y[rate[k]]), fabs(s->y[rate[k]])));
      /* a rate that changes by more than the allowance within the step is not
       * resolved by the samples (a fall spinning phi up near lying down): the
       * trapezoid says nothing there */
      if (dt * fabs(s->y[rate[k]] - a->y[rate[k]]) > DV_TRAJ_RATE_TOL * scale) continue;
      if (d > DV_TRAJ_RATE_TOL * scale)
        return dv_fail(err, DV_EINPUT,
                       "%.400s:%ld:%d: %s turns by %.6g rad from the line before, its rate by "
                       "%.6g rad (off by %.3g rad, more than %g of the step times the rate scale "
                       "%.3g rad/s): the columns disagree",
                       f->path, f->line[i], col[k], name[k],
                       remainder(s->y[angle[k]] - a->y[angle[k]], 2.0 * M_PI), step, d,
                       DV_TRAJ_RATE_TOL, rate_scale);
    }
  }
  return DV_OK;
}
