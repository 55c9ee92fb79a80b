/* run_horizon: the reference's predictability horizon (run_horizon.h). */
#include "run_horizon.h"

#include <math.h>

#include "dv_reference.h"
#include "run_trajectory.h"

/* the nudges of theta(0) that start inside the lying-down limits (0: none) */
static void nudges(const dv_scenario *sc, double nudge[2]) {
  const double lim = dv_reference_settings(sc)->theta_limit, th = sc->initial[RED_TH];
  for (int k = 0; k < 2; k++) {
    const double t0 = th + (k ? 1 : -1) * DV_HORIZON_NUDGE;
    nudge[k] = t0 > lim && t0 < M_PI - lim ? t0 - th : 0.0;
  }
  if (nudge[0] == 0.0 && nudge[1] == 0.0) /* the limits lie within a nudge of each side */
    nudge[th < M_PI_2] = 0.5 * (th < M_PI_2 ? M_PI - lim - th : lim - th);
}

int dv_run_horizon(const dv_scenario *sc, const dv_traj *ref, double *horizon,
                   double spread[DV_NMETRICS], dv_run_end nudged[2], dv_error *err) {
  const dv_engine_type *thin = dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
  double nudge[2];
  nudges(sc, nudge);
  *horizon = INFINITY;
  for (int m = 0; m < DV_NMETRICS; m++) spread[m] = 0.0;
  for (int k = 0; k < 2; k++) {
    nudged[k] = (dv_run_end){.nudge = nudge[k]};
    if (nudge[k] == 0.0) continue;
    dv_scenario moved_sc = *sc;
    moved_sc.initial[RED_TH] += nudge[k];
    dv_traj tr = {0};
    dv_engine_stats st;
    const int status = dv_run_collect(thin, &moved_sc, dv_run_traj_keep, &tr, &st, err);
    if (status < 0) {
      dv_error cause = *err;
      dv_run_traj_free(&tr);
      return dv_fail(err, status, "the %s reference nudged by %+g rad (for the horizon): %s",
                     thin->name, nudge[k], cause.msg);
    }
    nudged[k] = (dv_run_end){nudge[k], 1, tr.n ? tr.s[tr.n - 1].t : 0.0, st.lay_down};
    size_t i = 0;
    for (; i < tr.n && i < ref->n && fabs(tr.s[i].t - ref->s[i].t) < 1e-9; i++)
      if (fabs(tr.s[i].y[RED_TH] - ref->s[i].y[RED_TH]) > DV_HORIZON_SPREAD) break;
    /* the first sample past the spread, or where the nudged run ended first */
    if (i < ref->n && i < tr.n)
      *horizon = fmin(*horizon, tr.s[i].t);
    else if (i < ref->n && i > 0)
      *horizon = fmin(*horizon, tr.s[i - 1].t);
    dv_metrics moved;
    dv_run_compare(&tr, ref, INFINITY, &moved);
    for (int m = 0; m < DV_NMETRICS; m++) spread[m] = fmax(spread[m], moved.value[m]);
    dv_run_traj_free(&tr);
  }
  return DV_OK;
}
