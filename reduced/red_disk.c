/* red_disk: the reduced equations (3.57) with their quadratures (3.28). */
#include "red_disk.h"

#include <math.h>
#include <stddef.h>

const char *red_state_name(int k) {
  static const char *const names[RED_NSTATE] = {
      [RED_TH] = "theta", [RED_VTH] = "theta_dot", [RED_VPH] = "phi_dot", [RED_VPS] = "psi_dot",
      [RED_PH] = "phi",   [RED_PS] = "psi",        [RED_X] = "x",         [RED_Y] = "y"};
  return k >= 0 && k < RED_NSTATE ? names[k] : NULL;
}

red_disk red_disk_uniform(double r, double m, double g) {
  red_disk d = {r, m, 0.25 * m * r * r, 0.5 * m * r * r, g};
  return d;
}

int red_rhs(const red_disk *dk, const double y[RED_NSTATE], double f[RED_NSTATE]) {
  const double th = y[RED_TH], vth = y[RED_VTH], vph = y[RED_VPH], vps = y[RED_VPS];
  const double s = sin(th), c = cos(th), mr2 = dk->m * dk->r * dk->r;
  if (!(s > 0.0)) return -1;
  const double w3 = vps + vph * c; /* spin about the axis, omega . n */
  f[RED_TH] = vth;
  f[RED_VTH] =
      (dk->A * vph * vph * c * s - dk->m * dk->g * dk->r * c - (dk->C + mr2) * w3 * vph * s) /
      (dk->A + mr2);
  f[RED_VPH] = vth / (dk->A * s) * (dk->C * w3 - 2.0 * dk->A * vph * c);
  f[RED_VPS] = (dk->C + 2.0 * mr2) / (dk->C + mr2) * vth * vph * s - c * f[RED_VPH];
  f[RED_PH] = vph;
  f[RED_PS] = vps;
  const double sp = sin(y[RED_PH]), cp = cos(y[RED_PH]), roll = dk->r * (vph * c + vps);
  f[RED_X] = dk->r * vth * s * cp + roll * sp;
  f[RED_Y] = dk->r * vth * s * sp - roll * cp;
  return isfinite(f[RED_VTH] + f[RED_VPH] + f[RED_VPS]) ? 0 : -1;
}

double red_energy(const red_disk *dk, const double y[RED_NSTATE]) {
  const double s = sin(y[RED_TH]), c = cos(y[RED_TH]), mr2 = dk->m * dk->r * dk->r;
  const double vth = y[RED_VTH], vph = y[RED_VPH], w3 = y[RED_VPS] + vph * c;
  return 0.5 * (dk->A + mr2) * vth * vth + 0.5 * (dk->C + mr2) * w3 * w3 +
         0.5 * dk->A * vph * vph * s * s + dk->m * dk->g * dk->r * s;
}

void red_contact_point(const red_disk *dk, const double y[RED_NSTATE], double p[2]) {
  const double rc = dk->r * cos(y[RED_TH]);
  p[0] = y[RED_X] + rc * cos(y[RED_PH]);
  p[1] = y[RED_Y] + rc * sin(y[RED_PH]);
}
