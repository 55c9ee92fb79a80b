/* run_trajfile: a trajectory from outside (another engine, often Python),
 * read strictly and converted to diskval's samples.
 *
 * Two forms, told apart by the header (docs/judge.md):
 *   the state form, diskval's own CSV (run_trajectory.h: DV_CSV_HEADER):
 *     t and theta, plus contact_x,contact_y or phi,psi,x,y (or both); any of
 *     theta_dot,phi_dot,psi_dot (all three or none) and energy;
 *   the pose form: t,x,y,z,qw,qx,qy,qz and optionally vx,vy,vz,wx,wy,wz:
 *     the centre, the body-to-world quaternion (body z along the disk's
 *     axis), the centre's velocity and the angular velocity, world frame.
 * The pose form goes through dv_state_from_pose and dv_sample_from_pose, the
 * conversion the linked engines use. What a file does not give is derived
 * where it can be (rates from the interpolant's derivative, the contact point
 * and the energy from the pose of a rolling disk) and NAN where it cannot
 * (then the metrics needing it are not judged): a state-form file gives no
 * velocity of its own, so its slip is NAN.
 *
 * Lines starting with '#' are comments; "# dt = H" gives the engine's time
 * step H (s), for a convergence check over steps (judge --step).
 * Every error is one line naming the file, the line and the column:
 * "FILE:LINE:COLUMN: what".
 */
#ifndef DV_RUN_TRAJFILE_H
#define DV_RUN_TRAJFILE_H

#include <stddef.h>

#include "dv_engine.h"
#include "engine_watch.h"
#include "scenario.h"

/* the start must match the scenario's initial state to this: angles in rad,
 * positions over the radius, rates over the scene's rate scale. Measured:
 * the linked engines' first rows match to 1e-15 (they are read back from the
 * state they were given); a float32 engine holds 6e-8. */
#define DV_TRAJ_START_TOL DV_ROWS_START_TOL
/* a quaternion's norm must be 1 to this (float32 storage rounds to 6e-8) */
#define DV_TRAJ_QUAT_TOL 1e-6

/* a row judged takes this many bytes: read, replayed and interpolated
 * (Akima and Steffen, every column). Measured: the slope of judge's peak RSS
 * over 1e5 and 3e5 rows of the state form with every column on
 * tests/data/short_circle.ini, 1046 bytes a row (re-run: /usr/bin/time -v
 * diskval judge on such files, generated as tests/check_judge_memory.sh does),
 * and the 11 bytes of a row's printed digits (digit) added since: 1057 */
#define DV_TRAJ_ROW_BYTES 1100
/* the state form's value columns, DV_CSV_HEADER's after t (theta .. energy) */
#define DV_TRAJ_NVALUES 11
/* a value's last digit when it was not written in decimal (pushed in code, or
 * hexadecimal): the value is exact */
#define DV_TRAJ_EXACT (-128)
/* rows past the scenario's duration kept for the interpolant (Akima uses two
 * on either side); the rest of a file is not read */
#define DV_TRAJ_ROWS_PAST 3
/* fewer samples than this cannot be interpolated (gsl_interp_akima's minimum) */
#define DV_TRAJ_MIN_SAMPLES 5

typedef enum dv_traj_form { DV_TRAJ_STATE = 0, DV_TRAJ_POSE = 1 } dv_traj_form;

typedef struct dv_trajfile {
  char path[1024];
  dv_traj_form form;
  int has_rates;    /* the file gives rates (state form) or velocities (pose form) */
  int has_angles;   /* phi, psi and x, y: the whole state */
  int has_energy;   /* given, or computed from a pose with velocities */
  int energy_given; /* the state form's energy column */
  int has_slip;     /* measured: the pose form with velocities */
  unsigned given;   /* the state form's value columns it gives: bit k for DV_CSV_HEADER's k+1 */
  /* the state form read from text: each row's value columns' last printed
   * digit, the decimal exponent of its place ("0.25": -2, "3e-7": -7; -127
   * to 127, DV_TRAJ_EXACT); NULL (every value exact) for samples pushed in code */
  signed char (*digit)[DV_TRAJ_NVALUES];
  size_t n, cap;
  dv_sample *s;          /* each row, converted */
  long *line;            /* each row's line in the file */
  double half_thickness; /* m: the disk the scenario describes */
  double step; /* s: the engine's time step from a "# dt = H" comment line, NAN when none */
  /* the pose form's lowest point against the ground (run_trajcheck.h): the
   * fault at row ground_row, DV_FAILURE_NONE when none */
  dv_failure ground_fault;
  size_t ground_row;
  char ground_detail[240];
  /* the pose form with velocities: the last row's centre x, y and its
   * velocity vx, vy, for the next row's step (run_trajcheck.h) */
  dv_rows_centre_track centre;
  int airborne;     /* the lowest point is off the ground since air_since */
  double air_since; /* s */
} dv_trajfile;

/* read path for sc into out: DV_OK, or DV_EINPUT / DV_ESYSTEM with err the
 * one-line "PATH:LINE:COLUMN: what" */
int dv_run_trajfile_read(const char *path, const dv_scenario *sc, dv_trajfile *out, dv_error *err);

void dv_run_trajfile_free(dv_trajfile *f);

/* the most rows (every file's) judged with sc's comparison within its memory_budget */
size_t dv_run_trajfile_max_rows(const dv_scenario *sc);

/* the largest distance, as a share of the starting energy, of a given energy
 * column (energy_given) from the energy of the state its row gives (rates
 * given or derived), over the rows to t_end; *row: where (0 when none) */
double dv_run_trajfile_energy_gap(const dv_trajfile *f, const struct dv_scenario *sc, double t_end,
                                  size_t *row);

/* a trajectory built in code (the C API), checked as a file is: begin with
 * the label its errors name in place of the file ("LABEL:N:COLUMN: ...", N
 * the sample, from 1), push samples (every one a state, or every one a pose:
 * the centre, the unit quaternion (w, x, y, z), and the velocities, both or
 * neither NULL), then end (at least DV_TRAJ_MIN_SAMPLES, the start checked) */
void dv_run_trajfile_begin(dv_trajfile *f, const char *label);
int dv_run_trajfile_push_state(dv_trajfile *f, const dv_scenario *sc, double t,
                               const double y[RED_NSTATE], dv_error *err);
int dv_run_trajfile_push_pose(dv_trajfile *f, const dv_scenario *sc, double t, const double pos[3],
                              const double q[4], const double *vel, const double *omega,
                              dv_error *err);
int dv_run_trajfile_end(dv_trajfile *f, const dv_scenario *sc, dv_error *err);

#endif
