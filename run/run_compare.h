/* dv_run_compare: trajectories in memory and the metrics that compare them.
 *
 * Metrics of an engine against a reference, over the compared window: the
 * samples both have at equal times, up to the reference's end (its event or
 * validity limit) and the engine's. No metric reads a sample past t_end or
 * the reference's last; a window of fewer than 2 samples (the shared start
 * alone) measured nothing: every metric NAN.
 *   theta_max_err, theta_rms_err   |theta - theta_ref| (rad)
 *   path_max_err, path_rms_err     |contact - contact_ref| at equal times (m)
 *   path_hausdorff                 Hausdorff distance between the two contact
 *                                  paths as polylines: insensitive to timing (m)
 *   energy_drift                   max |E(t) - E(0)| / |E(0)| of the engine
 *   slip_max                       largest slip speed of the engine (m/s)
 *   theta_extrema_err              the larger of |min theta - min theta_ref| and
 *                                  |max theta - max theta_ref| (rad), each over its
 *                                  own run to the window's end (t_end, and never
 *                                  past the reference's last sample):
 *                                  timing-insensitive
 *   invariant_drift                max |f_i(t) - f_i(0)| of the engine's own states
 *                                  over the momentum scale sqrt(2 E0 (A + m r^2))
 *                                  (dv_run_invariant_drift; NAN from dv_run_compare)
 *   theta_turning_err,             theta's turning points and the nutation period
 *   nutation_period_err,           and heading advance, cycle by cycle
 *   heading_period_err             (run_turning.h; NAN: nothing to compare)
 *   turning_lag                    the largest |time of the engine's k-th turn -
 *                                  time of the reference's k-th| (s), maxima with
 *                                  maxima, minima with minima: cumulative, a drift
 *                                  each period adds up (run_turning.h; NAN: no turn)
 *   phase_err                      how far along the reference's contact path
 *                                  the engine's contact point is, as an arc
 *                                  length at equal times (run_phase.h, m)
 */
#ifndef DV_COMPARE_H
#define DV_COMPARE_H

#include <stddef.h>

#include "dv_engine.h"
#include "run_hausdorff.h"

/* a trajectory: samples in time order */
typedef struct dv_traj {
  size_t n, cap;
  dv_sample *s;
} dv_traj;

int dv_run_traj_push(dv_traj *tr, const dv_sample *s); /* 0, or -1 out of memory */
int dv_run_traj_keep(void *traj, const dv_sample *s);  /* a run's sink: push into a dv_traj */
void dv_run_traj_free(dv_traj *tr);                    /* NULL-safe */

typedef struct dv_metrics {
  double value[DV_NMETRICS];
  size_t n_window; /* samples compared */
  double t_window; /* end of the compared window, s */
} dv_metrics;

/* metrics of engine against reference; t_end bounds the window (INFINITY: none) */
void dv_run_compare(const dv_traj *engine, const dv_traj *reference, double t_end, dv_metrics *out);

/* the drift of the integrals f1, f2 (red_invariants.h) along tr up to t_end,
 * over the momentum scale sqrt(2 E0 (A + m r^2)); NAN where they cannot be
 * evaluated (C = 0 in a contact engine, theta at 0 or pi) */
double dv_run_invariant_drift(const red_disk *disk, const dv_traj *tr, double t_end);

#endif
