/* red_momentum: the momentum form (3.67) of the reduced equations. */
#include <math.h>

#include "red_formulations.h"

void red_momentum_from_state(const red_disk *dk, const double y[RED_NSTATE], double p[RED_NSTATE]) {
  const double s = sin(y[RED_TH]), c = cos(y[RED_TH]), mr2 = dk->m * dk->r * dk->r;
  const double rho_psi = (dk->C + mr2) * (y[RED_VPS] + y[RED_VPH] * c);
  p[0] = y[RED_TH];
  p[1] = (dk->A + mr2) * y[RED_VTH];
  p[2] = rho_psi * c + dk->A * y[RED_VPH] * s * s;
  p[3] = rho_psi;
  for (int i = RED_PH; i < RED_NSTATE; i++) p[i] = y[i];
}

void red_state_from_momentum(const red_disk *dk, const double p[RED_NSTATE], double y[RED_NSTATE]) {
  const double s = sin(p[0]), c = cos(p[0]), mr2 = dk->m * dk->r * dk->r;
  y[RED_TH] = p[0];
  y[RED_VTH] = p[1] / (dk->A + mr2);
  y[RED_VPH] = (p[2] - p[3] * c) / (dk->A * s * s);
  y[RED_VPS] = p[3] / (dk->C + mr2) - y[RED_VPH] * c;
  for (int i = RED_PH; i < RED_NSTATE; i++) y[i] = p[i];
}

int red_momentum_rhs(double t, const double *p, double *f, void *params) {
  const red_disk *dk = params;
  const double th = p[0], s = sin(th), c = cos(th), mr2 = dk->m * dk->r * dk->r;
  const double Amr = dk->A + mr2, rt = p[1], rph = p[2], rps = p[3];
  if (!(s > 0.0)) return -1;
  const double dif = rph - rps * c; /* = A v_phi s^2 */
  f[0] = rt / Amr;
  f[1] = c / (dk->A * s * s * s) * dif * dif - rps * dif / (dk->A * s) - dk->m * dk->g * dk->r * c;
  f[2] = mr2 / (dk->A * Amr) * rt * (c / s) * dif - mr2 * s / ((dk->C + mr2) * Amr) * rt * rps;
  f[3] = mr2 / (dk->A * Amr) * rt / s * dif;
  /* quadratures (3.28) with the rates recovered from the momenta */
  double y[RED_NSTATE], dy[RED_NSTATE];
  red_state_from_momentum(dk, p, y);
  if (red_rhs(dk, y, dy)) return -1;
  for (int i = RED_PH; i < RED_NSTATE; i++) f[i] = dy[i];
  return isfinite(f[1] + f[2] + f[3]) ? 0 : -1;
}
