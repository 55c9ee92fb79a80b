/* test_rows: the rows' own checks (engine_watch.h), each at its boundary:
 * the rate scale, a turn near flat, the start against the state sent, an
 * angle's step and its summed misses against its rate, the centre against its
 * velocity. The rows are built here by hand; every bound is the documented
 * allowance times 0.9 (inside) or 1.1 (outside). */
#include <math.h>
#include <string.h>

#include "dv_test.h"
#include "engine_watch.h"

/* short_circle's start: theta 1, phi_dot 3.04, psi_dot -15.19 rad/s (r 0.1 m) */
static const double START[RED_NSTATE] = {[RED_TH] = 1.0, [RED_VPH] = 3.038, [RED_VPS] = -15.19};

static dv_sample row(double t, double theta, double theta_dot, double psi, double psi_dot) {
  dv_sample s;
  memset(&s, 0, sizeof s);
  s.t = t;
  s.y[RED_TH] = theta, s.y[RED_VTH] = theta_dot;
  s.y[RED_PS] = psi, s.y[RED_VPS] = psi_dot;
  return s;
}

static void rate_scale(const red_disk *disk) {
  CHECK_NEAR(dv_rows_rate_scale(disk, START), 15.19, 0.0, "the rate scale: psi_dot's");
  const double slow[RED_NSTATE] = {[RED_TH] = 1.0, [RED_VPS] = 2.0};
  CHECK_NEAR(dv_rows_rate_scale(disk, slow), sqrt(9.81 / 0.1), 1e-15, "the rate scale: sqrt(g/r)");
}

static void near_flat(void) {
  dv_sample a = row(0.0, 0.15, -2.0, 0.0, 0.0), s = row(0.01, 0.30, 2.0, 0.0, 0.0);
  CHECK(dv_rows_turn_near_flat(&a, &s), "a turn at sin theta 0.15 is near flat");
  a = row(0.0, 1.0, -2.0, 0.0, 0.0), s = row(0.01, 1.1, 2.0, 0.0, 0.0);
  CHECK(!dv_rows_turn_near_flat(&a, &s), "a turn at theta 1 is not near flat");
  a = row(0.0, 0.15, 2.0, 0.0, 0.0), s = row(0.01, 0.17, 2.0, 0.0, 0.0);
  CHECK(!dv_rows_turn_near_flat(&a, &s), "no turn is no turn near flat");
}

static void start(double rate) {
  double y[RED_NSTATE];
  static const struct {
    int k;
    double scale; /* the allowance's: 1e-6 of it */
  } q[] = {{RED_TH, 1.0}, {RED_PH, 1.0}, {RED_X, 0.1}, {RED_Y, 0.1}, {RED_VPS, 15.19}};
  for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
    for (int out = 0; out < 2; out++) {
      memcpy(y, START, sizeof y);
      y[q[i].k] += (out ? 1.1 : 0.9) * DV_ROWS_START_TOL * q[i].scale;
      const int k = dv_rows_start_off(y, START, 0.1, rate);
      CHECK(k == (out ? q[i].k : -1), "state %d off by %g of the allowance: %d", q[i].k,
            out ? 1.1 : 0.9, k);
    }
  }
  memcpy(y, START, sizeof y);
  y[RED_PS] += 2.0 * M_PI;
  CHECK(dv_rows_start_off(y, START, 0.1, rate) == -1, "psi a turn round is the same psi");
}

/* psi from 0 at psi_dot -15.19 rad/s for 0.01 s, its step off by share of the
 * step allowance (0.3 of 0.01 s times 15.19 rad/s) */
static double one_step(double share, int *summed) {
  dv_rows_drift drift = {0};
  double miss;
  const double dt = 0.01, allowed = DV_ROWS_RATE_TOL * dt * 15.19;
  dv_sample a = row(0.0, 1.0, 0.0, 0.0, -15.19);
  dv_sample s = row(dt, 1.0, 0.0, -15.19 * dt + share * allowed, -15.19);
  return dv_rows_angle(&a, &s, 2, 15.19, &drift, &miss, summed);
}

/* psi's steps scaled by 1 + excess over 100 steps of 0.01 s: the largest
 * share of the allowance, and whether the sum decided there */
static double scaled_steps(double excess, int *summed) {
  dv_rows_drift drift = {0};
  double worst = 0.0, miss;
  for (int i = 0; i < 100; i++) {
    int by_sum;
    dv_sample a = row(0.01 * i, 1.0, 0.0, -15.19 * 0.01 * i * (1.0 + excess), -15.19);
    dv_sample s = row(0.01 * (i + 1), 1.0, 0.0, -15.19 * 0.01 * (i + 1) * (1.0 + excess), -15.19);
    const double d = dv_rows_angle(&a, &s, 2, 15.19, &drift, &miss, &by_sum);
    if (d > worst) worst = d, *summed = by_sum;
  }
  return worst;
}

static void angles(void) {
  int summed;
  double d = one_step(0.9, &summed);
  CHECK(d > 0.85 && d < 1.0 && !summed, "a step 0.9 of its allowance off: %g", d);
  d = one_step(1.1, &summed);
  CHECK(d > 1.0 && !summed, "a step 1.1 of its allowance off: %g", d);
  /* a rate that jumps by more than 0.3 of its scale is not resolved: unchecked */
  dv_rows_drift drift = {0};
  double miss;
  dv_sample a = row(0.0, 1.0, 0.0, 0.0, -15.19), s = row(0.01, 1.0, 0.0, 5.0, 0.0);
  CHECK(dv_rows_angle(&a, &s, 2, 15.19, &drift, &miss, &summed) == 0.0,
        "a rate that jumps is not checked");
  /* steps scaled by 1 + 0.9 and 1.1 of DV_ROWS_DRIFT: the sum decides, past
   * its allowance only outside (each step's own miss is within its own) */
  d = scaled_steps(0.9 * DV_ROWS_DRIFT, &summed);
  CHECK(d < 1.0, "steps 0.9 of the drift allowance long: %g", d);
  d = scaled_steps(1.1 * DV_ROWS_DRIFT, &summed);
  CHECK(d > 1.0 && summed, "steps 1.1 of the drift allowance long: %g (summed %d)", d, summed);
}

/* the centre moving at 1 m/s along x, its second step off by share of
 * DV_ROWS_CENTRE_TOL of the step times the speed */
static double centre(double share) {
  dv_rows_centre_track c = {0};
  const double vel[2] = {1.0, 0.0}, dt = 0.01;
  int k;
  dv_sample s[3];
  double worst = 0.0;
  for (int i = 0; i < 3; i++) {
    s[i] = row(dt * i, 1.0, 0.0, 0.0, 0.0);
    const double pos[2] = {dt * i + (i == 2 ? share * DV_ROWS_CENTRE_TOL * dt : 0.0), 0.0};
    worst = fmax(worst, dv_rows_centre(&c, i ? &s[i - 1] : NULL, &s[i], pos, vel, 0.5, &k));
  }
  return worst;
}

int main(void) {
  const red_disk disk = red_disk_uniform(0.1, 1.0, 9.81);
  rate_scale(&disk);
  near_flat();
  start(15.19);
  angles();
  /* the miss's change from the step before (0 here) is held to 0.25: a miss
   * 0.9 of the 0.3 allowed changes by 0.27, past it; so the bound is the
   * change's: 0.9 and 1.1 of DV_ROWS_CENTRE_TURN */
  double d = centre(0.9 * DV_ROWS_CENTRE_TURN / DV_ROWS_CENTRE_TOL);
  CHECK(d > 0.85 && d < 1.0, "the centre 0.9 of its allowance off: %g", d);
  d = centre(1.1 * DV_ROWS_CENTRE_TURN / DV_ROWS_CENTRE_TOL);
  CHECK(d > 1.0, "the centre 1.1 of its allowance off: %g", d);
  return TEST_RESULT();
}
