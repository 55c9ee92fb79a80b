/* run_replay: a trajectory read from a file (run_trajfile.h) as an engine.
 *
 * Its table (dv_engine_type, alloc_self) serves the recorded samples at the
 * times the harness asks for, so a comparison judges a file exactly as it
 * judges a linked engine (run_scenario.h): one code path. At a recorded time
 * (to 1e-9 s relative) the row itself; between rows an Akima interpolant
 * (GSL) of each column, and its difference to a Steffen interpolant of the same
 * rows as its error estimate (largest over the run, in theta and in the
 * contact point). Measured on MuJoCo's steady circle sampled every 0.05 s and
 * 0.1 s: Akima's true error in the contact point 1.0e-4 and 8.6e-4 m, the
 * estimate 8.3e-4 and 3.3e-3 m (Steffen, monotone between samples, flattens
 * every extremum of contact_x: the estimate errs on the safe side).
 * Rows between the scenario's sample times are served by no sample: each is
 * measured against the Akima interpolant through the rows at the sample times
 * (between_theta, between_path), so a row that disagrees with them counts
 * (run_judge.h refuses the file) instead of going unseen.
 * The run ends with the file: at the first row where theta reaches the lying-down
 * limit (DV_EVENT, lay_down), or at the last row when it ends before the
 * scenario's duration (DV_EVENT, lay_down 0; the comparison does not judge
 * what the file does not cover).
 */
#ifndef DV_RUN_REPLAY_H
#define DV_RUN_REPLAY_H

#include "dv_engine.h"
#include "run_trajfile.h"

typedef struct dv_replay {
  dv_engine_type type; /* data points back here */
  char name[64];
  char description[200];
  const dv_trajfile *file;
  /* the interpolation's largest estimated error over the runs, and the line
   * of the row before it */
  double interp_theta, interp_path; /* rad, m */
  long theta_line, path_line;
  /* rows between the scenario's sample times, which no sample serves: the
   * largest distance of one from the Akima interpolant through the rows at
   * the sample times, and its line (0: no such row, or too few at them) */
  double between_theta, between_path; /* rad, m */
  long between_theta_line, between_path_line;
  double t_end;   /* s: the last row served */
  int ends_early; /* the file ends before the duration, not lying down */
} dv_replay;

/* rp as an engine named name replaying f (kept by the caller) */
void dv_run_replay_init(dv_replay *rp, const dv_trajfile *f, const char *name);

/* the replay whose table type is, or NULL */
const dv_replay *dv_run_replay_of(const dv_engine_type *type);

#endif
