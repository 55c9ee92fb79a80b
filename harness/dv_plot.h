/* dv_plot: the plots of one scenario's comparison, drawn with PLplot (SVG).
 *
 * Files written into dir:
 *   theta.svg        theta(t) of every engine over the reference's
 *   theta_error.svg  |theta - theta_ref|(t) per engine, log axis (against
 *                    each engine's own reference: matched, or thin)
 *   path.svg         contact paths, equal aspect, start and end marked
 *   energy.svg       (E(t) - E(0)) / |E(0)| per engine and reference
 */
#ifndef DV_PLOT_H
#define DV_PLOT_H

#include <stddef.h>

#include "dv_compare.h"
#include "dv_error.h"

#define DV_PLOT_MAX_SERIES 8

typedef struct dv_plot_series {
  const char *label;        /* legend text, e.g. "mujoco" */
  const dv_traj *traj;      /* the engine's samples */
  const dv_traj *reference; /* what its error is measured against (same times) */
} dv_plot_series;

typedef struct dv_plot_input {
  const char *title;   /* scenario name */
  const dv_traj *thin; /* the thin-disk reference, drawn in every plot */
  size_t nseries;
  dv_plot_series series[DV_PLOT_MAX_SERIES];
} dv_plot_input;

/* the names of the files dv_plot_scenario writes, NULL-terminated */
extern const char *const dv_plot_files[];

/* write the plots into the existing directory dir */
int dv_plot_scenario(const char *dir, const dv_plot_input *in, dv_error *err);

#endif
