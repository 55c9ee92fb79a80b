/* run_limits: limits from the scenario or the scene (run_limits.h). */
#include "run_limits.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "run_turning.h"

double dv_run_distance_rolled(const dv_traj *tr, double t_end) {
  double d = 0.0;
  /* to the window's end as dv_run_compare pairs samples, 1e-9 s apart: a
   * reference's event sample that lies just past the engine's is in it */
  for (size_t i = 1; i < tr->n && tr->s[i].t <= t_end + 1e-9; i++)
    d += hypot(tr->s[i].contact[0] - tr->s[i - 1].contact[0],
               tr->s[i].contact[1] - tr->s[i - 1].contact[1]);
  return d;
}

double dv_run_motion_extent(const dv_traj *tr, double t_end) {
  double mean[2] = {0.0, 0.0}, far = 0.0;
  size_t n = 0;
  for (size_t i = 0; i < tr->n && tr->s[i].t <= t_end + 1e-12; i++)
    if (!isnan(tr->s[i].contact[0]) && !isnan(tr->s[i].contact[1]))
      mean[0] += tr->s[i].contact[0], mean[1] += tr->s[i].contact[1], n++;
  if (!n) return 0.0;
  mean[0] /= n, mean[1] /= n;
  for (size_t i = 0; i < tr->n && tr->s[i].t <= t_end + 1e-12; i++)
    if (!isnan(tr->s[i].contact[0]) && !isnan(tr->s[i].contact[1]))
      far = fmax(far, hypot(tr->s[i].contact[0] - mean[0], tr->s[i].contact[1] - mean[1]));
  return 2.0 * far;
}

/* the path limit: the share of the distance rolled, capped by the share of
 * the motion's size, at least the share of the radius; its words into why */
static double path_limit(double rolled, double extent, double r, char *why, size_t size) {
  const double by_roll = DV_LIMIT_PATH * rolled, by_size = DV_LIMIT_EXTENT * extent;
  const double floor = DV_LIMIT_PATH * r;
  if (fmin(by_roll, by_size) <= floor) {
    snprintf(why, size, "default: %g%% of the %.3g m radius", 100 * DV_LIMIT_PATH, r);
    return floor;
  }
  if (by_roll <= by_size) {
    snprintf(why, size, "default: %g%% of the %.3g m rolled", 100 * DV_LIMIT_PATH, rolled);
    return by_roll;
  }
  snprintf(why, size,
           "default: %g%% of the motion's size %.3g m (less than %g%% of the %.3g m rolled)",
           100 * DV_LIMIT_EXTENT, extent, 100 * DV_LIMIT_PATH, rolled);
  return by_size;
}

double dv_run_default_path_limit(const dv_scenario *sc, const dv_traj *ref, double t_end) {
  char why[112];
  return path_limit(dv_run_distance_rolled(ref, t_end), dv_run_motion_extent(ref, t_end),
                    sc->disk.r, why, sizeof why);
}

/* the limit the scenario gives for metric, with where it came from; 0 when none */
static int given(const dv_scenario *sc, const char *engine, dv_metric_id metric, dv_limit *out) {
  int own;
  out->value = dv_scenario_tolerance(sc, engine, metric, &own);
  if (own < 0) return 0;
  snprintf(out->why, sizeof out->why, "[tolerance%s%s]", own ? "." : "", own ? engine : "");
  return 1;
}

double dv_run_rate_scale(const dv_scenario *sc) {
  const double *y = sc->initial;
  return fmax(fmax(fabs(y[RED_VPS]), fabs(y[RED_VPH])), sqrt(sc->disk.g / sc->disk.r));
}

void dv_run_limits(const dv_scenario *sc, const char *engine, const dv_traj *ref, double t_end,
                   dv_limit out[DV_NMETRICS]) {
  const red_disk *d = &sc->disk;
  const double rolled = dv_run_distance_rolled(ref, t_end);
  const double extent = dv_run_motion_extent(ref, t_end);
  const double speed = d->r * dv_run_rate_scale(sc);
  for (int m = 0; m < DV_NMETRICS; m++) {
    dv_limit *l = &out[m];
    if (given(sc, engine, (dv_metric_id)m, l)) continue;
    switch ((dv_metric_id)m) {
      case DV_THETA_MAX_ERR:
      case DV_THETA_RMS_ERR:
      case DV_THETA_EXTREMA_ERR:
      case DV_THETA_TURNING_ERR:
        l->value = DV_LIMIT_THETA;
        snprintf(l->why, sizeof l->why, "default: %g rad", DV_LIMIT_THETA);
        break;
      case DV_PATH_MAX_ERR:
      case DV_PATH_RMS_ERR:
      case DV_PATH_HAUSDORFF:
        l->value = path_limit(rolled, extent, d->r, l->why, sizeof l->why);
        break;
      case DV_PHASE_ERR: { /* an angle round the motion, never more than the path allows */
        char path_why[sizeof l->why];
        const double path = path_limit(rolled, extent, d->r, path_why, sizeof path_why);
        const double arc = DV_LIMIT_PHASE * 0.5 * extent;
        l->value = fmin(arc, path);
        if (arc >= path)
          snprintf(l->why, sizeof l->why, "default: the path limit, %.80s", path_why + 9);
        else if (arc > DV_LIMIT_PATH * d->r)
          snprintf(l->why, sizeof l->why, "default: %g rad of half the motion's size %.3g m",
                   DV_LIMIT_PHASE, extent);
        else {
          l->value = DV_LIMIT_PATH * d->r;
          snprintf(l->why, sizeof l->why,
                   "default: %g%% of the %.3g m radius (more than %g rad of %.3g m)",
                   100 * DV_LIMIT_PATH, d->r, DV_LIMIT_PHASE, 0.5 * extent);
        }
        break;
      }
      case DV_ENERGY_DRIFT:
        l->value = DV_LIMIT_ENERGY;
        snprintf(l->why, sizeof l->why, "default: %g%% of the initial energy",
                 100 * DV_LIMIT_ENERGY);
        break;
      case DV_INVARIANT_DRIFT:
        l->value = DV_LIMIT_INVARIANTS;
        snprintf(l->why, sizeof l->why, "default: %g%% of the momentum scale",
                 100 * DV_LIMIT_INVARIANTS);
        break;
      case DV_NUTATION_PERIOD_ERR: { /* a timing error that moves theta by its limit */
        const double rate = dv_run_theta_rate_max(ref, t_end);
        l->value = rate > 0.0 ? DV_LIMIT_THETA / rate : INFINITY;
        snprintf(l->why, sizeof l->why,
                 "default: %g rad over the reference's fastest theta rate, %.3g rad/s",
                 DV_LIMIT_THETA, rate);
        break;
      }
      case DV_TURNING_LAG: { /* the time in which the fastest theta rate moves theta by its limit */
        const double rate = dv_run_theta_rate_max(ref, t_end);
        dv_limit theta;
        const int own = given(sc, engine, DV_THETA_MAX_ERR, &theta);
        if (!own) theta.value = DV_LIMIT_THETA;
        l->value = rate > 0.0 ? theta.value / rate : INFINITY;
        snprintf(l->why, sizeof l->why,
                 "default: the theta limit %g rad over the reference's fastest theta rate, %.3g "
                 "rad/s",
                 theta.value, rate);
        break;
      }
      case DV_HEADING_PERIOD_ERR:
        l->value = DV_LIMIT_HEADING;
        snprintf(l->why, sizeof l->why,
                 "default: %g rad, turns the path by %g%% of the distance rolled", DV_LIMIT_HEADING,
                 100 * DV_LIMIT_PATH);
        break;
      case DV_SLIP_MAX:
        l->value = DV_LIMIT_SLIP * speed;
        snprintf(l->why, sizeof l->why, "default: %g%% of the speed scale %.3g m/s",
                 100 * DV_LIMIT_SLIP, speed);
        break;
      default:
        l->value = NAN; /* not judged */
        snprintf(l->why, sizeof l->why, "not judged");
    }
  }
}
