/* test_turning: turning points and nutation periods (run_turning.h) on
 * synthetic nutations whose answers are known in closed form:
 * theta = c + a(t) cos(2 pi t / T), phi = w t. A longer period moves no
 * turning point and shows as the period and heading differences; a decaying
 * amplitude shows as the turning points; a run that stops nutating has
 * lost its periods; steady runs and contact-sized noise have no turns. The
 * lag of a longer period adds up turn by turn (dv_run_turning_lags). Of two maxima a reversal too small to
 * count lies between, the higher is kept. */
#include <math.h>
#include <string.h>

#include "dv_test.h"
#include "run_turning.h"

#define DT 0.005
#define DURATION 8.0
/* off the sample grid: no turning point falls on a sample (DT / T irrational-ish) */
#define T0 1.7413

/* theta = c + (a - decay t) cos(2 pi t / T) + noise sin(900 t), phi = w t, sampled every DT */
static void nutation(dv_traj *tr, double T, double a, double decay, double w, double noise) {
  const double c = 0.9, k = 2 * M_PI / T;
  for (double t = 0.0; t <= DURATION + 1e-9; t += DT) {
    dv_sample s;
    memset(&s, 0, sizeof s);
    s.t = t;
    const double amp = a - decay * t;
    s.y[RED_TH] = c + amp * cos(k * t) + noise * sin(900 * t);
    s.y[RED_VTH] = -decay * cos(k * t) - amp * k * sin(k * t) + 900 * noise * cos(900 * t);
    s.y[RED_PH] = w * t;
    s.y[RED_VPH] = w;
    dv_run_traj_push(tr, &s);
  }
}

/* a decaying nutation sampled every 0.1 s whose first maximum is at t_max:
 * theta = 0.9 + (0.5 - 0.01 t) cos(2 pi (t - t_max) / T0) */
static void coarse(dv_traj *tr, double t_max) {
  const double k = 2 * M_PI / T0;
  for (int i = 0; i <= 40; i++) {
    dv_sample s;
    memset(&s, 0, sizeof s);
    s.t = 0.1 * i;
    const double amp = 0.5 - 0.01 * s.t;
    s.y[RED_TH] = 0.9 + amp * cos(k * (s.t - t_max));
    s.y[RED_VTH] = -0.01 * cos(k * (s.t - t_max)) - amp * k * sin(k * (s.t - t_max));
    dv_run_traj_push(tr, &s);
  }
}

int main(void) {
  dv_traj ref = {0}, slow = {0}, decaying = {0}, steady = {0}, noisy = {0};
  double v[3];
  nutation(&ref, T0, 0.5, 0.0, 0.7, 0.0);
  nutation(&slow, T0 + 0.02, 0.5, 0.0, 0.7, 0.0); /* 0.02 s longer */
  nutation(&decaying, T0, 0.5, 0.001, 0.7, 0.0);  /* loses 0.00174 rad a period */
  nutation(&steady, T0, 0.0, 0.0, 0.7, 0.0);
  nutation(&noisy, T0, 0.0, 0.0, 0.7, 1e-5); /* contact-sized wiggles, 1e-5 rad */

  dv_run_turning_compare(&ref, &ref, INFINITY, v);
  for (int i = 0; i < 3; i++) CHECK_NEAR(v[i], 0.0, 1e-12, "itself");

  /* the turning points are found by Hermite interpolation: the samples miss
   * them by up to a k^2 (DT/2)^2 / 2 = 2e-5 rad. Measured (DV_TEST_MEASURE=1):
   * turning points 6.1e-12 rad, the period 4.9e-10 s, the heading 3.4e-10 rad */
  dv_run_turning_compare(&slow, &ref, INFINITY, v);
  CHECK_NEAR(v[0], 0.0, 1e-9, "a longer period moves no turning point");
  CHECK_NEAR(v[1], 0.02, 1e-8, "the period is 0.02 s longer");
  CHECK_NEAR(v[2], 0.7 * 0.02, 1e-8, "the heading advances 0.7 rad/s x 0.02 s more");
  /* phi wrapped to (-pi, pi], as a file may give it (0.7 rad/s passes pi at 4.5 s): the same */
  dv_traj wrapped = {0};
  for (size_t i = 0; i < slow.n; i++) {
    dv_sample s = slow.s[i];
    s.y[RED_PH] = remainder(s.y[RED_PH], 2 * M_PI);
    dv_run_traj_push(&wrapped, &s);
  }
  dv_run_turning_compare(&wrapped, &ref, INFINITY, v);
  CHECK_NEAR(v[2], 0.7 * 0.02, 1e-8, "a wrapped heading advances as the unwrapped");
  dv_run_traj_free(&wrapped);

  /* one turn of each kind, then held at the maximum: the nutation is lost (no period) */
  dv_traj once = {0};
  const double kk = 2 * M_PI / T0;
  for (double t = 0.0; t <= DURATION + 1e-9; t += DT) {
    dv_sample s;
    memset(&s, 0, sizeof s);
    s.t = t;
    s.y[RED_TH] = t < T0 ? 0.9 + 0.5 * cos(kk * t) : 1.4;
    s.y[RED_VTH] = t < T0 ? -0.5 * kk * sin(kk * t) : 0.0;
    s.y[RED_PH] = 0.7 * t;
    s.y[RED_VPH] = 0.7;
    dv_run_traj_push(&once, &s);
  }
  dv_run_turning_compare(&once, &ref, INFINITY, v);
  CHECK(isinf(v[1]) && isinf(v[2]), "one turn of each kind: period %g, heading %g, not lost", v[1],
        v[2]);
  dv_run_traj_free(&once);

  /* the other way round: an engine 0.02 s faster errs as much */
  dv_run_turning_compare(&ref, &slow, INFINITY, v);
  CHECK_NEAR(v[1], 0.02, 1e-8, "the period is 0.02 s shorter");
  CHECK_NEAR(v[2], 0.7 * 0.02, 1e-8, "the heading advances 0.7 rad/s x 0.02 s less");

  /* turning points are paired by count: the k-th minimum at (k - 1/2) T
   * has amplitude a - 0.001 t; the largest difference is the last one inside 8 s */
  dv_run_turning_compare(&decaying, &ref, INFINITY, v);
  const double last = 0.001 * T0 * 4.0;     /* the fourth maximum, t = 4 T = 6.97 s */
  const double last_min = 0.001 * T0 * 4.5; /* the fifth minimum, t = 4.5 T = 7.84 s */
  /* measured 7.8e-8 rad (the decay shifts each turn off c +- amp) and 5.5e-7 s */
  CHECK_NEAR(v[0], fmax(last, last_min), 1e-6, "decaying amplitude: turning error");
  CHECK_NEAR(v[1], 0.0, 5e-6, "the decay barely moves the period");
  /* which turn that is, for the one line that decides (run_decided.h): the
   * fifth minimum, both runs making it; the decay moves it 1.56e-4 s earlier
   * (measured: this check's message with the bound at 0) */
  dv_turning_worst w;
  dv_run_turning_worst(&decaying, &ref, INFINITY, &w);
  CHECK(w.kind == -1 && w.ordinal == 5 && w.only == 0 && w.lag < 0 && w.lag > -1e-3,
        "the worst turn: kind %d, ordinal %zu, only %d, lag %g s", w.kind, w.ordinal, w.only,
        w.lag);

  /* an engine that stops nutating has lost every period, and its missing turns
   * compare with its own extremes (0.9): the amplitude */
  dv_run_turning_compare(&steady, &ref, INFINITY, v);
  CHECK_NEAR(v[0], 0.5, 1e-9, "no turns where the reference turns");
  CHECK(isinf(v[1]) && isinf(v[2]), "lost periods: %g %g", v[1], v[2]);
  dv_run_turning_worst(&steady, &ref, INFINITY, &w); /* the reference's, which it does not make */
  CHECK(w.kind != 0 && w.only == -1 && isnan(w.lag), "a turn it does not make: only %d, lag %g",
        w.only, w.lag);

  /* nothing turns: nothing to compare (not judged), whatever the noise */
  dv_run_turning_compare(&noisy, &steady, INFINITY, v);
  CHECK(isnan(v[0]) && isnan(v[1]) && isnan(v[2]), "steady: %g %g %g", v[0], v[1], v[2]);

  /* the window bounds the turns compared: to 2 s no period completes, to 4 s one */
  dv_run_turning_compare(&slow, &ref, 2.0, v);
  CHECK(isnan(v[1]), "no period in 2 s: %g", v[1]);
  CHECK_NEAR(v[0], 0.0, 1e-9, "no turning point moved in 2 s");
  dv_run_turning_compare(&slow, &ref, 4.0, v);
  CHECK_NEAR(v[1], 0.02, 1e-8, "one period in 4 s");
  CHECK_NEAR(dv_run_theta_rate_max(&ref, INFINITY), 0.5 * 2 * M_PI / T0, 2e-6,
             "fastest rate"); /* 1.8e-7 */

  /* the turning lag, cumulative: the slow run's k-th turn lags by 0.01 k s
   * (turns every T0 / 2 from a maximum at the start, no turn), paired kind
   * with kind; measured 1.25e-8 s off each turn (the Hermite interpolant) */
  double tk[4096], lag[4096];
  size_t nl = dv_run_turning_lags(&slow, &ref, INFINITY, tk, lag, NULL);
  CHECK(nl == 9, "9 turns in 8 s: %zu", nl);
  for (size_t k = 0; k < nl; k++) { /* minima first, then maxima */
    const double t_ref = tk[k], ord = round(t_ref / (T0 / 2));
    CHECK(fabs(t_ref - ord * T0 / 2) < 1e-7, "the reference's turn %zu at %g", k, t_ref);
    CHECK(fabs(lag[k] - 0.01 * ord) < 1e-7, "turn %g lags 0.01 s a turn: %g", ord, lag[k]);
  }
  /* an engine early by as much leads by as much */
  nl = dv_run_turning_lags(&ref, &slow, INFINITY, tk, lag, NULL);
  for (size_t k = 0; k < nl; k++)
    CHECK(fabs(lag[k] + 0.01 * round(tk[k] / ((T0 + 0.02) / 2))) < 1e-7, "early turn %zu: %g", k,
          lag[k]);
  /* a turn the engine makes past the window's end lags by at least the rest
   * of the window: to 1.75 s its second turn (1.7613 s) is not in it, the
   * reference's (T0 = 1.7413 s) is: 0.0087 s, a bound under the true 0.02 */
  nl = dv_run_turning_lags(&slow, &ref, 1.75, tk, lag, NULL);
  CHECK(nl == 2, "two turns to 1.75 s: %zu", nl);
  for (size_t k = 0; k < nl; k++) /* the first, paired, lags 0.01 s */
    CHECK(fabs(lag[k] - (fabs(tk[k] - T0) < 1e-7 ? 1.75 - T0 : 0.01)) < 1e-7,
          "turn at %g s: lag %g (the unpaired one's bound 0.0087)", tk[k], lag[k]);
  /* an engine without turns lags each of the reference's by the rest of the
   * run; the reference's turns the engine makes with none leads by as much */
  nl = dv_run_turning_lags(&steady, &ref, INFINITY, tk, lag, NULL);
  CHECK(nl == 9, "every turn of the reference: %zu", nl);
  for (size_t k = 0; k < nl; k++)
    CHECK(fabs(lag[k] - (DURATION - tk[k])) < 1e-6, "lost turn %zu: %g", k, lag[k]);
  nl = dv_run_turning_lags(&ref, &steady, INFINITY, tk, lag, NULL);
  for (size_t k = 0; k < nl; k++)
    CHECK(fabs(lag[k] + (DURATION - tk[k])) < 1e-6, "extra turn %zu: %g", k, lag[k]);

  /* a turn just inside the window, where the reference's comes just after
   * it: timing, not a turning point off (upright_unstable's MuJoCo: a minimum
   * at 1.94 s, the reference's past 2 s, was compared with its start, 0.024
   * rad away). Starting at a minimum whose swing shrinks 0.05 rad/s, the
   * start lies 0.085 rad below the faster run's first minimum at 1.70 s */
  dv_traj rising = {0}, rising_fast = {0};
  nutation(&rising, 1.74, -0.5, -0.05, 0.7, 0.0);
  nutation(&rising_fast, 1.70, -0.5, -0.05, 0.7, 0.0);
  dv_run_turning_compare(&rising_fast, &rising, 1.72, v);
  /* measured 9.9e-4 rad; the start, wrongly paired, is 0.085 rad away */
  CHECK_NEAR(v[0], 0.0, 2e-3, "a minimum the reference makes just past the window");
  dv_run_turning_compare(&rising_fast, &rising, 2.5, v);
  /* the first minima, at 1.70 and 1.74 s, differ by the swing shrunk over 0.04 s
   * (measured 1.2e-5 rad off it: a minimum moves as its swing shrinks) */
  CHECK_NEAR(v[0], 0.05 * 0.04, 5e-5, "both minima inside");

  /* a turn inside the first sample interval is a turn (a swing of 8e-3 rad from
   * the start at 0.1 s samples): maxima 0.1 s apart are paired in order, each
   * off by the decay over 0.1 s (1e-3 rad), not by a period's (1.7e-2 rad).
   * Measured 2e-8 rad off that (a missed first maximum: 2.7e-2 rad off) */
  dv_traj early = {0}, later = {0};
  coarse(&early, 0.05);
  coarse(&later, 0.15);
  dv_run_turning_compare(&early, &later, INFINITY, v);
  CHECK_NEAR(v[0], 0.01 * 0.1, 1e-5, "a maximum inside the first interval");

  /* an engine that drifts 0.02 rad in 1 s and then holds, its rate wiggling
   * about 0 (1e-5 rad at 900 rad/s): its maximum is the plateau whatever the
   * count of the wiggles' sign changes up to the window's end. Before, each
   * small reversal dropped the turn before it, so the maximum came and went
   * with that count's parity (0.02 at one end, none a sample later) */
  dv_traj settles = {0};
  for (double t = 0.0; t <= DURATION + 1e-9; t += DT) {
    dv_sample s;
    memset(&s, 0, sizeof s);
    s.t = t;
    s.y[RED_TH] = 0.9 + 0.02 * fmin(t, 1.0) + 1e-5 * sin(900 * t);
    s.y[RED_VTH] = (t < 1.0 ? 0.02 : 0.0) + 9e-3 * cos(900 * t);
    s.y[RED_PH] = 0.7 * t;
    s.y[RED_VPH] = 0.7;
    dv_run_traj_push(&settles, &s);
  }
  for (int k = 0; k < 12; k++) {
    dv_run_turning_compare(&settles, &steady, 5.0 + k * DT, v);
    CHECK_NEAR(v[0], 0.02, 1e-4, "a drift that settles: its maximum, at any window's end");
  }

  /* two maxima 5e-4 rad apart with a dip of 5e-4 rad between them (under
   * DV_TURNING_MIN_SWING: no turn): theta = 1 - c (t-1)^2 (t-2)^2 + d t. One
   * maximum is kept, the more extreme (the second), located by a scan of 1e6 points */
  dv_traj twin = {0};
  const double c = 0.008, d = 0.0005;
  for (double t = 0.0; t <= 3.0 + 1e-9; t += DT) {
    dv_sample s;
    memset(&s, 0, sizeof s);
    s.t = t;
    s.y[RED_TH] = 1.0 - c * (t - 1) * (t - 1) * (t - 2) * (t - 2) + d * t;
    s.y[RED_VTH] = -2 * c * (t - 1) * (t - 2) * (2 * t - 3) + d;
    dv_run_traj_push(&twin, &s);
  }
  double highest = -INFINITY;
  for (int i = 0; i <= 1000000; i++) {
    const double t = 3.0 * i / 1e6;
    highest = fmax(highest, 1.0 - c * (t - 1) * (t - 1) * (t - 2) * (t - 2) + d * t);
  }
  static double tt[1000], th[1000]; /* room for a turn a sample (601) */
  static int kinds[1000];
  const size_t nturns = dv_run_turning_points(&twin, INFINITY, tt, th, kinds);
  CHECK(nturns == 1 && kinds[0] == 1, "twin maxima: %zu turns, the first of kind %d", nturns,
        nturns ? kinds[0] : 0);
  if (nturns) CHECK_NEAR(th[0], highest, 1e-7, "twin maxima: the more extreme kept");

  dv_traj *all[] = {&ref,    &slow,        &decaying, &steady, &noisy,
                    &rising, &rising_fast, &early,    &later,  &settles, &twin};
  for (size_t i = 0; i < 11; i++) dv_run_traj_free(all[i]);
  return TEST_RESULT();
}
