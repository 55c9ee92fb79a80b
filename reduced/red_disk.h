/* red_disk: the rolling disk and its reduced equations of motion.
 *
 * A rigid disk of radius r, mass m, moments A (any diameter) and C (symmetry
 * axis) rolls without slipping on z = 0 under gravity g. Coordinates after
 * Pars: theta (tilt, pi/2 upright), phi (heading), psi (spin), (x, y) the
 * ground projection of the centre. The reduced system (Bates-Sniatycki; the
 * thesis's (3.30)/(3.57), identical to Pars 3.31) is
 *
 *   th'   = v_th
 *   v_th' = (A v_ph^2 c s - m g r c - (C + m r^2)(v_ps + v_ph c) v_ph s) / (A + m r^2)
 *   v_ph' = v_th / (A s) (C (v_ps + v_ph c) - 2 A v_ph c)
 *   v_ps' = (C + 2 m r^2)/(C + m r^2) v_th v_ph s - c v_ph'
 *
 * with s = sin(theta), c = cos(theta), plus the quadratures phi' = v_ph,
 * psi' = v_ps and (3.28)
 *
 *   x' = r v_th s cos(phi) + r (v_ph c + v_ps) sin(phi)
 *   y' = r v_th s sin(phi) - r (v_ph c + v_ps) cos(phi)
 *
 * Valid for 0 < theta < pi and any C >= 0 (C = 0 included). SI units.
 */
#ifndef RED_DISK_H
#define RED_DISK_H

/* the physical disk */
typedef struct red_disk {
  double r; /* radius, m */
  double m; /* mass, kg */
  double A; /* moment about a diameter, kg m^2 */
  double C; /* moment about the symmetry axis, kg m^2; 0 <= C <= 2A */
  double g; /* gravity, m/s^2 (>= 0) */
} red_disk;

/* indices into the 8-component state vector */
enum {
  RED_TH = 0, /* theta, rad */
  RED_VTH,    /* theta_dot, rad/s */
  RED_VPH,    /* phi_dot, rad/s */
  RED_VPS,    /* psi_dot, rad/s */
  RED_PH,     /* phi, rad */
  RED_PS,     /* psi, rad */
  RED_X,      /* centre x, m */
  RED_Y,      /* centre y, m */
  RED_NSTATE
};

/* number of components of the reduced (shape) system: theta and the rates */
#define RED_NREDUCED 4

/* the name of state component k ("theta", "theta_dot", ..., "y"), as the
 * scenario file and the CSV columns spell it; NULL off 0 .. RED_NSTATE - 1 */
const char *red_state_name(int k);

/* a uniform thin disk: A = m r^2 / 4, C = m r^2 / 2 */
red_disk red_disk_uniform(double r, double m, double g);

/* derivative of the 8-component state; returns 0, or -1 off (0, pi) or non-finite */
int red_rhs(const red_disk *disk, const double y[RED_NSTATE], double dydt[RED_NSTATE]);

/* total energy: E = 1/2 (A + m r^2) v_th^2 + 1/2 (C + m r^2)(v_ps + v_ph c)^2
 *                 + 1/2 A v_ph^2 s^2 + m g r s                              (J) */
double red_energy(const red_disk *disk, const double y[RED_NSTATE]);

/* contact point P = G + r d on the ground (m) */
void red_contact_point(const red_disk *disk, const double y[RED_NSTATE], double p[2]);

#endif
