/* dv_testlib: helpers shared by the reduced-solver tests: run a trajectory
 * of the reduced system (or another formulation) into memory. */
#ifndef DV_TESTLIB_H
#define DV_TESTLIB_H

#include "red_disk.h"
#include "red_solver.h"

#define TL_MAX_SAMPLES 200001

typedef struct tl_traj {
  long n;
  double *t;
  double (*y)[RED_NSTATE]; /* reduced states (converted from other formulations) */
  int status;
  red_result result;
} tl_traj;

/* a disk with A = a_ratio m r^2, C = c_ratio m r^2, r = 0.1, m = 1, g = 9.81 */
red_disk tl_disk(double a_ratio, double c_ratio);

/* integrate the reduced equations from y0 for duration, sampling every dt, at
 * rtol tol and atol tol / 100; events end the run when theta leaves
 * (theta_limit, pi - theta_limit) */
tl_traj tl_run(const red_disk *disk, const red_stepper_type *stepper, double tol,
               const double y0[RED_NSTATE], double duration, double dt, double theta_limit);

/* tl_run at the given rtol and atol */
tl_traj tl_run_tols(const red_disk *disk, const red_stepper_type *stepper, double rtol, double atol,
                    const double y0[RED_NSTATE], double duration, double dt, double theta_limit);

/* formulation: 0 reduced, 1 momentum (3.67), 2 Lagrange multipliers */
tl_traj tl_run_form(const red_disk *disk, int form, const red_stepper_type *stepper, double tol,
                    const double y0[RED_NSTATE], double duration, double dt);

void tl_free(tl_traj *tr);

/* the largest |theta| and contact-point differences between two trajectories
 * on their common samples */
void tl_compare(const red_disk *disk, const tl_traj *a, const tl_traj *b, double *theta_err,
                double *path_err);

#endif
