/* run_horizon: the reference's predictability horizon (run_horizon.h). */
#include "run_horizon.h"

#include <math.h>

#include "run_trajectory.h"

int dv_run_horizon(const dv_scenario *sc, const dv_traj *ref, double *horizon,
                   double spread[DV_NMETRICS], dv_error *err) {
  const dv_engine_type *thin = dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
  *horizon = INFINITY;
  for (int m = 0; m < DV_NMETRICS; m++) spread[m] = 0.0;
  for (int sign = -1; sign <= 1; sign += 2) {
    dv_scenario nudged = *sc;
    nudged.initial[RED_TH] += sign * DV_HORIZON_NUDGE;
    dv_traj tr = {0};
    dv_engine_stats st;
    const int status = dv_run_collect(thin, &nudged, dv_run_traj_keep, &tr, &st, err);
    if (status < 0) return dv_run_traj_free(&tr), status;
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
