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

double dv_run_trajcheck_centre(dv_trajfile *f, const dv_scenario *sc, const double pos[2],
                               const double vel[2], int *k) {
  const double floor = sc->disk.r * dv_rows_rate_scale(&sc->disk, sc->initial);
  return dv_rows_centre(&f->centre, f->n ? &f->s[f->n - 1] : NULL, &f->s[f->n], pos, vel, floor,
                        k);
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
  const double rate_scale = dv_rows_rate_scale(&sc->disk, sc->initial);
  dv_rows_drift drift[3] = {{0}};
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
    static const char *const name[3] = {"theta", "phi", "psi"};
    static const int angle[3] = {RED_TH, RED_PH, RED_PS};
    if (f->form == DV_TRAJ_POSE && s->y[RED_TH] < 1e-3)
      continue; /* phi, psi undefined lying flat (and theta not checked there either) */
    double d, miss;
    int summed;
    const int k = dv_rows_angles(a, s, 0, rate_scale, drift, &d, &miss, &summed);
    if (k >= 0 && summed)
      return dv_fail(err, DV_EINPUT,
                     "%.400s:%ld:%d: %s's steps add up to %.6g rad off the trapezoids of its "
                     "rate over %.6g rad of them (%.3g times %g of that, plus a step's "
                     "allowance): the columns disagree",
                     f->path, f->line[i], col[k], name[k], drift[k].miss, drift[k].travel, d,
                     DV_ROWS_DRIFT);
    if (k >= 0)
      return dv_fail(err, DV_EINPUT,
                     "%.400s:%ld:%d: %s turns by %.6g rad from the line before, its rate by "
                     "%.6g rad (off by %.3g rad, more than %g of the step times the rate scale "
                     "%.3g rad/s): the columns disagree",
                     f->path, f->line[i], col[k], name[k],
                     remainder(s->y[angle[k]] - a->y[angle[k]], 2.0 * M_PI),
                     remainder(s->y[angle[k]] - a->y[angle[k]], 2.0 * M_PI) - miss, fabs(miss),
                     DV_TRAJ_RATE_TOL, rate_scale);
  }
  return DV_OK;
}
