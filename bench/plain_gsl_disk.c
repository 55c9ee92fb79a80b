/* plain_gsl_disk: the baseline of bench_output.sh, the reduced equations
 * integrated the plain way: GSL's rk8pd driver (eps_abs = eps_rel = EPS)
 * stepping onto every output time, one CSV row per output with diskval's
 * columns. A uniform disk (r 0.1 m, m 1 kg, g 9.81) from theta 1.0 rad
 * spinning at psi_dot -12 rad/s.
 *
 *   plain_gsl_disk DURATION OUTPUT_DT EPS > trajectory.csv
 */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "red_disk.h"

static int rhs(double t, const double y[], double f[], void *disk) {
  (void)t;
  return red_rhs(disk, y, f) ? GSL_EBADFUNC : GSL_SUCCESS;
}

static void write_row(const red_disk *disk, double t, const double *y) {
  double p[2];
  red_contact_point(disk, y, p);
  printf("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", t, y[RED_TH],
         y[RED_PH], y[RED_PS], y[RED_X], y[RED_Y], p[0], p[1], y[RED_VTH], y[RED_VPH], y[RED_VPS],
         red_energy(disk, y));
}

int main(int argc, char **argv) {
  const double duration = argc == 4 ? atof(argv[1]) : 0.0;
  const double dt = argc == 4 ? atof(argv[2]) : 0.0, eps = argc == 4 ? atof(argv[3]) : 0.0;
  if (!(duration > 0.0 && dt > 0.0 && eps > 0.0)) {
    fprintf(stderr, "usage: plain_gsl_disk DURATION OUTPUT_DT EPS\n");
    return 2;
  }
  gsl_set_error_handler_off();
  red_disk disk = red_disk_uniform(0.1, 1.0, 9.81);
  gsl_odeiv2_system sys = {rhs, NULL, RED_NSTATE, &disk};
  gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-4, eps, eps);
  double y[RED_NSTATE] = {1.0, 0.0, 0.0, -12.0, 0.0, 0.0, 0.0, 0.0}, t = 0.0;
  printf("t,theta,phi,psi,x,y,contact_x,contact_y,theta_dot,phi_dot,psi_dot,energy\n");
  write_row(&disk, t, y);
  const long n = lround(duration / dt);
  for (long k = 1; k <= n; k++) {
    if (gsl_odeiv2_driver_apply(d, &t, (double)k * dt, y) != GSL_SUCCESS) {
      fprintf(stderr, "plain_gsl_disk: GSL failed at t = %g\n", t);
      gsl_odeiv2_driver_free(d);
      return 1;
    }
    write_row(&disk, t, y);
  }
  gsl_odeiv2_driver_free(d);
  return 0;
}
