/* red_reference: the reduced system with its lying-down events. */
#include "red_reference.h"

#include <math.h>

static int reduced_rhs(double t, const double *y, double *f, void *p) {
  const red_reference *ref = p;
  return red_rhs(&ref->disk, y, f);
}

static double theta_low(double t, const double *y, void *p) {
  const red_reference *ref = p;
  return y[RED_TH] - ref->theta_limit;
}

static double theta_high(double t, const double *y, void *p) {
  const red_reference *ref = p;
  return (M_PI - ref->theta_limit) - y[RED_TH];
}

static double frequency(const double *y, void *p) {
  const red_reference *ref = p;
  return sqrt(ref->disk.g / ref->disk.r) + fabs(y[RED_VTH]) + fabs(y[RED_VPH]) + fabs(y[RED_VPS]);
}

void red_reference_init(red_reference *ref, const red_disk *disk, double theta_limit) {
  ref->disk = *disk;
  ref->theta_limit = theta_limit;
  ref->sys = (red_system){RED_NSTATE,
                          reduced_rhs,
                          ref,
                          frequency,
                          2,
                          {theta_low, theta_high},
                          {"theta_low", "theta_high"}};
}
