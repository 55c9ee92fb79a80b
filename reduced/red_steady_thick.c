/* red_steady_thick: the thick disk's steady circles from its own theta''. */
#include "red_steady_thick.h"

#include <math.h>

/* theta'' at tilt theta with rates v_phi, v_psi (theta' = 0); NAN off the domain */
static double tilt(const red_rolling *rr, double theta, double v_phi, double v_psi) {
  double y[RED_NSTATE] = {0}, a;
  y[RED_TH] = theta;
  y[RED_VPH] = v_phi;
  y[RED_VPS] = v_psi;
  return red_rolling_tilt_acceleration(rr, y, &a) ? NAN : a;
}

/* theta'' at the solution is rounding next to the terms it balances */
static int balanced(const red_rolling *rr, double theta, double v_phi, double v_psi,
                    double scale, dv_error *err) {
  const double rest = tilt(rr, theta, v_phi, v_psi);
  if (fabs(rest) <= 1e-9 * scale) return DV_OK;
  return dv_fail(err, DV_ENUMERIC, "the thick disk's steady motion does not balance: theta'' = %g",
                 rest);
}

int red_steady_thick_from_radius(const red_rolling *rr, double theta, double R, double *v_phi,
                                 double *v_psi, dv_error *err) {
  const double c = cos(theta);
  if (!(R > 0.0) || !isfinite(R)) return dv_fail(err, DV_EINPUT, "radius must be > 0");
  if (fabs(c) < 1e-12)
    return dv_fail(err, DV_EINPUT, "an upright disk rolls straight: no circle of finite radius");
  const double k = -copysign(R / rr->disk.r, c); /* v_psi / v_phi, as for the thin disk */
  const double b = tilt(rr, theta, 0.0, 0.0), a = tilt(rr, theta, 1.0, k) - b;
  const double vph2 = -b / a;
  if (!(vph2 > 0.0) || !isfinite(vph2))
    return dv_fail(err, DV_EINPUT,
                   "no steady circle of radius %g m at theta %g rad for this thick disk: v_phi^2 "
                   "would be %g",
                   R, theta, vph2);
  *v_phi = sqrt(vph2);
  *v_psi = k * *v_phi;
  return balanced(rr, theta, *v_phi, *v_psi, fabs(b), err);
}

int red_steady_thick_from_phi_dot(const red_rolling *rr, double theta, double v_phi,
                                  double *v_psi, dv_error *err) {
  if (!(v_phi != 0.0) || !isfinite(v_phi))
    return dv_fail(err, DV_EINPUT, "a steady motion needs phi_dot != 0");
  const double b = tilt(rr, theta, v_phi, 0.0), a = tilt(rr, theta, v_phi, 1.0) - b;
  *v_psi = -b / a;
  if (!isfinite(*v_psi)) return dv_fail(err, DV_EINPUT, "no steady motion at this tilt");
  return balanced(rr, theta, v_phi, *v_psi, fmax(fabs(b), fabs(a * *v_psi)), err);
}
