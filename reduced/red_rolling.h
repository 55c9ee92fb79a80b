/* red_rolling: a disk of finite thickness rolling without slipping, in
 * Newton-Euler form: the geometry-matched reference for contact engines.
 *
 * A cylinder of radius r and half-thickness h touches the ground at its rim
 * corner; the contact vector from the centre G is
 *
 *   rho = r d - h sign(cos theta) n,
 *
 * and rolling without slip is v_G = -omega x rho. With the contact force F,
 *
 *   m a_G = F - m g ez,   I omega' + omega x I omega = rho x F,
 *   a_G = -omega' x rho - omega x rho'
 *
 * eliminate F: (I + m (|rho|^2 1 - rho rho^T)) omega' = -omega x I omega
 *                                               + m rho x (g ez - omega x rho')
 * with I = A 1 + (C - A) n n^T in the world frame and
 * rho' = r d' - h sign n', d' = -theta' n - cos(theta) phi' t, n' = omega x n.
 * At h = 0 this is the thin disk of red_disk.h (tests/reduced/test_rolling).
 *
 * Exactly upright (cos theta and theta' zero to 1e-9) a thick disk stands on
 * the line across its rim, not on a corner: the contact force acts at
 * rho = r d - h s n with s in [-1, 1] chosen so that theta'' = 0, and the
 * disk stays upright (rolling straight: constant spin, the thin disk's
 * motion). Where no point of the line balances it (turning too fast), it
 * tips smoothly onto the corner on that side.
 *
 * State (8): theta, phi, psi, omega (world, 3), x, y. The run ends where
 * theta reaches the lying-down limits, where a thick disk crosses upright
 * with theta' != 0 (switching rim corners is an impact), or where the rolling model stops
 * describing the physics: the normal force F.ez would turn negative, or
 * the friction needed |F_h| would exceed mu F.ez.
 */
#ifndef RED_ROLLING_H
#define RED_ROLLING_H

#include "red_disk.h"
#include "red_solver.h"

enum { RR_TH = 0, RR_PH, RR_PS, RR_WX, RR_WY, RR_WZ, RR_X, RR_Y, RR_NSTATE };

enum {
  RR_EVENT_THETA_LOW = 0,
  RR_EVENT_THETA_HIGH,
  RR_EVENT_NORMAL_FORCE, /* F.ez reached 0 */
  RR_EVENT_FRICTION,     /* |F_h| reached mu F.ez */
  RR_EVENT_UPRIGHT,      /* a thick disk reached theta = pi/2 */
};

typedef struct red_rolling {
  red_disk disk;
  double h;           /* half-thickness, m (>= 0) */
  double mu;          /* friction coefficient of the validity window */
  double theta_limit; /* rad */
  red_system sys;     /* params point back here: do not copy after init */
} red_rolling;

extern const char *const red_rolling_event_names[];

void red_rolling_init(red_rolling *rr, const red_disk *disk, double h, double mu,
                      double theta_limit);

/* rolling state from a canonical state (rates -> omega), and back */
void red_rolling_from_state(const red_rolling *rr, const double y[RED_NSTATE], double *s);
void red_rolling_to_state(const double *s, double y[RED_NSTATE]);

/* omega' and the contact force F (N) at s; returns 0 or -1 off the domain */
int red_rolling_dynamics(const red_rolling *rr, const double *s, double omega_dot[3],
                         double force[3]);

/* theta'' at the canonical state y, on the corner (or line) the disk stands on */
int red_rolling_tilt_acceleration(const red_rolling *rr, const double y[RED_NSTATE], double *thdd);

/* energy m v_G^2 / 2 + omega.I.omega / 2 + m g z_G (J) */
double red_rolling_energy(const red_rolling *rr, const double *s);

/* contact point G + rho on the ground (m) */
void red_rolling_contact_point(const red_rolling *rr, const double *s, double p[2]);

/* the contact point, the energy, omega' and F at s from one frame, each as
 * the functions above give it; returns red_rolling_dynamics's status */
int red_rolling_observe(const red_rolling *rr, const double *s, double p[2], double *energy,
                        double omega_dot[3], double force[3]);

#endif
