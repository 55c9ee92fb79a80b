/* test_engine_simbody: the Simbody engine's own contract (exact constraints).
 *
 * 1. Mapping: reset to a state (theta on both sides of pi/2, angles beyond
 *    pi), advance(0) without a step: the same state, the energy of its pose,
 *    a rim point at rest on the ground, for both integrators; the version is
 *    Simbody's; samples land on the step grid with one contact.
 * 2. The constraints: over a wobbling, turning run the disk's rim point at
 *    the contact stays at rest (the sample's slip) and on the ground (no
 *    depth; the pose's energy is the state's, so the centre is at r sin
 *    theta; the pose's lowest point is the state's contact point).
 * 3. Ends: a disk falling from 0.1 rad off upright falls monotonically and
 *    ends where the matched reference does: at the friction limit
 *    ([disk] friction 2), at the normal force's zero (friction
 *    1e9), and lying down at a raised theta_limit.
 * 4. Convergence: halving the step divides theta's error by 2^p, p = 3 for
 *    rk3, 4 for rkmerson; the steady circle holds theta; energy
 *    and the reference's integrals f1, f2 are held.
 * 5. Faults end the run, not the process: NaN state, C = 0 refused, a disk
 *    thrown up ends at the normal force's zero (it cannot lose contact).
 * 6. A thick disk ([disk] thickness): the chain holds the rim corner and
 *    follows the matched reference of that half-thickness leaning either
 *    way; crossing upright ends the run there, an event that says so.
 * Every tolerance is a measurement: DV_TEST_MEASURE=1 build/engines/simbody/test_engine_simbody
 * prints each CHECK_NEAR's measured value.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_pose.h"
#include "dv_test.h"
#include "dv_test_traj.h"
#include "red_invariants.h"

static const dv_engine_type *const E = &dv_engine_simbody;
static const char *const INTEGRATORS[] = {"rk3", "rkmerson"};
/* the steady circle of scenarios/steady_circle.ini: theta 1, contact circle 0.5 m */
static const double CIRCLE[RED_NSTATE] = {1.0, 0, 3.038043841609511, -15.190219208047555, 0, 0,
                                          0,   0};
/* a disk that wobbles (theta 1.2 to 0.93) and turns: neither steady nor upright */
static const double WOBBLE[RED_NSTATE] = {1.2, 0.5, 2.0, -8.0, 0.3, 0.1, 0.0, 0.0};
/* 0.1 rad off upright, no spin: it falls */
static const double FALL[RED_NSTATE] = {M_PI / 2 - 0.1, 0, 0, 0, 0, 0, 0, 0};

/* a uniform disk (r 0.1 m, m 1 kg) with every engine setting at its default */
static dv_scenario base(void) {
  dv_scenario sc;
  dv_engine_init_scenario(&sc);
  sc.duration = 1.0;
  sc.output_dt = 0.01;
  sc.disk = red_disk_uniform(0.1, 1.0, 9.81);
  return sc;
}

static traj tr, ref;

/* run engine e on sc from y to t_end into t (dv_test_traj.h); its status */
static int run_on(const dv_engine_type *e, dv_scenario sc, const double y[RED_NSTATE], double t_end,
                  traj *t) {
  memcpy(sc.initial, y, sizeof sc.initial);
  sc.duration = t_end;
  dv_test_run(e, &sc, t);
  if (t->status < 0) CHECK(t->msg[0], "a failed run without a message");
  return t->status;
}

static int run(dv_scenario sc, const double y[RED_NSTATE], double t_end) {
  return run_on(E, sc, y, t_end, &tr);
}

static void check_round_trip(void) {
  static const double states[][RED_NSTATE] = {
      {1.0, 0.3, 2.0, -5.0, 0.4, 1.2, 0.1, -0.2},
      {M_PI / 2, 0.01, 0.0, 8.5, 0.0, 0.0, 0.0, 0.0},
      {2.2, -0.5, 1.0, 3.0, -2.0, 3.0, 0.5, 0.25},
      {0.3, 0.0, 7.0, -1.0, 3.0, -3.0, -1.0, 2.0},
  };
  for (int in = 0; in < 2; in++)
    for (size_t k = 0; k < sizeof states / sizeof states[0]; k++) {
      dv_scenario sc = base();
      dv_scenario_set(&sc, "simbody", "integrator", INTEGRATORS[in], NULL);
      dv_scenario_set_number(&sc, "simbody", "timestep", 1e-3, NULL);
      dv_error err = {{0}};
      dv_sample s;
      dv_engine_stats st;
      void *e = E->alloc(&sc, &err);
      CHECK(e, "alloc: %s", err.msg);
      if (!e) return;
      CHECK(E->reset(e, states[k], &err) == DV_OK, "reset: %s", err.msg);
      CHECK(E->advance(e, 0.0, &s, &err) == DV_OK, "advance(0): %s", err.msg);
      E->stats(e, &st);
      CHECK(st.steps == 0 && s.t == 0.0, "%s state %zu: %ld steps before t = 0", INTEGRATORS[in], k,
            st.steps);
      /* rounding: measured (DV_TEST_MEASURE=1, both integrators) state
       * 2.8e-17 (the coordinates are the state's own), energy 0 J, the rim
       * point's speed 2.2e-16 m/s, depth 6.9e-18 m (the joint chain puts
       * the rim point on the ground) */
      for (int i = 0; i < RED_NSTATE; i++)
        CHECK_NEAR(s.y[i], states[k][i], 1e-13 * (1 + fabs(states[k][i])), "state component");
      const dv_geometry g = {DV_SHAPE_CYLINDER, sc.disk.r, 0.0};
      dv_pose pose;
      dv_pose_from_state(&g, states[k], &pose);
      const double energy = dv_pose_energy(&sc.disk, &pose);
      CHECK_NEAR(s.energy, energy, 1e-13 * fabs(energy), "energy of the pose");
      CHECK_NEAR(s.slip, 0.0, 1e-13, "rim point's speed");
      CHECK_NEAR(s.penetration, 0.0, 1e-15, "depth");
      CHECK(s.contacts == 1 && isfinite(s.force[2]), "contacts %d, force %g", s.contacts,
            s.force[2]);
      E->free(e);
    }
}

static void check_grid(void) {
  for (int in = 0; in < 2; in++) {
    dv_scenario sc = base();
    dv_scenario_set(&sc, "simbody", "integrator", INTEGRATORS[in], NULL);
    dv_scenario_set_number(&sc, "simbody", "timestep", 1e-3, NULL);
    CHECK(run(sc, CIRCLE, 0.05) == DV_OK, "%s", tr.stats.detail);
    const dv_sample *s = &tr.s[tr.n - 1];
    CHECK(tr.stats.steps == 50 && s->t == 0.05, "%s: %ld steps to t = %g, want 50", INTEGRATORS[in],
          tr.stats.steps, s->t);
    CHECK(tr.stats.contacts_max == 1 && s->contacts == 1, "%s: %d contacts", INTEGRATORS[in],
          tr.stats.contacts_max);
  }
}

/* the constraints over a wobbling, turning run of 2 s (200 poses) at the
 * step the scene derives (rk3 at the fall time / 100 = 1e-3 s): the rim
 * point's velocity and height */
/* the rim point's largest speed, depth, the centre's height error and the
 * contact point's distance from the state's over tr */
static void residuals(const dv_scenario *sc, double r[4]) {
  const dv_geometry g = {DV_SHAPE_CYLINDER, sc->disk.r, 0.0};
  r[0] = r[1] = r[2] = r[3] = 0.0;
  for (long k = 0; k < tr.n; k++) {
    const dv_sample *s = &tr.s[k];
    dv_pose pose;
    double p[2];
    dv_pose_from_state(&g, s->y, &pose);
    r[0] = fmax(r[0], s->slip);
    r[1] = fmax(r[1], s->penetration);
    /* the engine's energy is its pose's; the state's pose has the centre at
     * r sin theta and rolls without slip: their difference over m g bounds
     * the centre's height error (and the slip's kinetic energy) */
    r[2] =
        fmax(r[2], fabs(s->energy - dv_pose_energy(&sc->disk, &pose)) / (sc->disk.m * sc->disk.g));
    red_contact_point(&sc->disk, s->y, p);
    r[3] = fmax(r[3], hypot(s->contact[0] - p[0], s->contact[1] - p[1]));
  }
}

static void check_constraints(void) {
  dv_scenario sc = base();
  dv_scenario_set_number(&sc, "simbody", "friction", 1e9, NULL);  /* only N <= 0 ends it */
  dv_scenario_set_number(&sc, "simbody", "timestep", 1e-3, NULL); /* the scene's: T / 100 */
  CHECK(run(sc, WOBBLE, 2.0) == DV_OK && tr.n == 201, "wobble: %ld samples, %s", tr.n,
        tr.stats.detail);
  double th_lo = INFINITY, th_hi = 0.0, r[4], tight[4];
  for (long k = 0; k < tr.n; k++) {
    th_lo = fmin(th_lo, tr.s[k].y[RED_TH]);
    th_hi = fmax(th_hi, tr.s[k].y[RED_TH]);
  }
  CHECK(th_hi - th_lo > 0.2, "the wobble swings %g rad only", th_hi - th_lo);
  residuals(&sc, r);
  /* a tighter constraint_tolerance: the key bounds the drift */
  dv_scenario_set_number(&sc, "simbody", "constraint_tolerance", 1e-14, NULL);
  run(sc, WOBBLE, 2.0);
  residuals(&sc, tight);
  printf(
      "wobble, 2 s (theta %.3f to %.3f), constraint_tolerance 1e-10 / 1e-14: slip %.2e / "
      "%.2e m/s, depth %.2e / %.2e m, height %.2e / %.2e m, contact %.2e / %.2e m\n",
      th_lo, th_hi, r[0], tight[0], r[1], tight[1], r[2], tight[2], r[3], tight[3]);
  /* measured at 1e-10 (the default): slip 1.4e-10 m/s (the no-slip error
   * reaches about the tolerance before the integrator projects), depth
   * 1.4e-17 m, contact 5.7e-17 m, and the energy's 9.4e-12 m is the slip's
   * kinetic energy (m v slip); at 1e-14: slip 4.8e-16 m/s, and the centre's
   * height error 4.5e-17 m (rounding: the joint chain puts it at r sin theta) */
  CHECK_NEAR(r[0], 0.0, 5e-10, "rim point's speed over the run");
  CHECK_NEAR(r[1], 0.0, 1e-15, "depth over the run");
  CHECK_NEAR(r[2], 0.0, 3e-11, "the centre's height error and the slip's energy over the run");
  CHECK_NEAR(r[3], 0.0, 1e-14, "the contact point against the state's");
  CHECK_NEAR(tight[0], 0.0, 1e-14, "rim point's speed at constraint_tolerance 1e-14");
  CHECK_NEAR(tight[2], 0.0, 1e-14, "the centre's height error at constraint_tolerance 1e-14");
  CHECK(tight[0] < r[0], "constraint_tolerance 1e-14: slip %g, at 1e-10 %g", tight[0], r[0]);
}

/* theta falls at every sample, the last included */
static int falls(const traj *t) {
  int ok = t->n > 1;
  for (long k = 1; k < t->n; k++) ok &= t->s[k].y[RED_TH] < t->s[k - 1].y[RED_TH];
  return ok;
}

/* the fall from 0.1 rad off upright ends as the matched reference's (the thin
 * disk, the same friction), within one step of it */
static void check_fall(void) {
  struct {
    const char *what;
    double friction, theta_limit;
    const char *detail;
  } cases[] = {
      {"friction limit", 2.0, 0.01, "friction needed"},
      {"normal force", 1e6, 0.01, "normal force reached zero"},
      {"lying down", 2.0, 1.2, "lower limit 1.2 rad"},
  };
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
    dv_scenario sc = base();
    dv_scenario_set_number(&sc, "simbody", "timestep", 1e-3, NULL);
    dv_scenario_set_core(&sc, "disk", "friction", cases[c].friction, NULL);
    dv_scenario_set_number(&sc, "matched", "half_thickness", 0.0, NULL);
    dv_scenario_set_number(&sc, "reduced", "theta_limit", cases[c].theta_limit, NULL);
    const int status = run(sc, FALL, 3.0);
    run_on(&dv_engine_matched, sc, FALL, 3.0, &ref);
    const dv_engine_stats *st = &tr.stats;
    const dv_sample *s = &tr.s[tr.n - 1], *r = &ref.s[ref.n - 1];
    printf("fall, %s: %s at t = %.4f s, theta %.4f (matched: %s at %.6f s, theta %.4f)\n",
           cases[c].what, st->detail, s->t, s->y[RED_TH], ref.stats.detail, r->t, r->y[RED_TH]);
    CHECK(status == DV_EVENT && st->outcome == DV_OUTCOME_EVENT &&
              strstr(st->detail, cases[c].detail) && ref.status == DV_EVENT,
          "fall, %s: status %d, %s: %s", cases[c].what, status, dv_outcome_name(st->outcome),
          st->detail);
    CHECK(st->lay_down == (c == 2 ? -1 : 0), "fall, %s: lay_down %d", cases[c].what, st->lay_down);
    CHECK(falls(&tr), "fall, %s: theta rose", cases[c].what);
    /* the event is the first step past it: measured 0.4 to 0.9 ms after the
     * matched reference's root (0.3346, 0.4045, 0.1823 s), within one step */
    CHECK(s->t >= r->t && s->t - r->t <= 1e-3 + 1e-12, "fall, %s: at %.6f s, matched at %.6f s",
          cases[c].what, s->t, r->t);
    /* the sample the run ends with carries the force that ended it */
    const double *F = s->force;
    if (c == 0) CHECK(hypot(F[0], F[1]) > 2.0 * F[2], "F = (%g, %g, %g)", F[0], F[1], F[2]);
    if (c == 1) {
      CHECK(F[2] <= 0.0 && tr.s[tr.n - 2].force[2] > 0.0, "F.z %g, before %g", F[2],
            tr.s[tr.n - 2].force[2]);
      /* DESIGN section 4: F.z turns negative between theta 0.6 and 0.33 */
      CHECK(s->y[RED_TH] > 0.33 && s->y[RED_TH] < 0.6, "N = 0 at theta %g", s->y[RED_TH]);
    }
    /* the force along the run is the matched reference's (its constraint
     * force from the Newton-Euler equations): measured 1.1e-6, 1.4e-6,
     * 1.9e-7 N, of a weight 9.81 N (rk3's error at 1e-3 s, largest where
     * the fall is fastest) */
    double df = 0.0;
    for (long k = 0; k < tr.n - 1 && k < ref.n - 1; k++)
      for (int i = 0; i < 3; i++) df = fmax(df, fabs(tr.s[k].force[i] - ref.s[k].force[i]));
    CHECK_NEAR(df, 0.0, 5e-6, "contact force against the matched reference's");
  }
}

/* theta's largest distance from the reduced reference over 1 s of WOBBLE,
 * at a fixed step dt, or error-controlled to accuracy (> 0) */
static double wobble_error_at(const char *integrator, double dt, double accuracy) {
  dv_scenario sc = base();
  sc.output_dt = 0.02;
  dv_scenario_set(&sc, "simbody", "integrator", integrator, NULL);
  dv_scenario_set_number(&sc, "simbody", "timestep", dt, NULL);
  dv_scenario_set_number(&sc, "simbody", "accuracy", accuracy, NULL);
  dv_scenario_set_number(&sc, "simbody", "friction", 1e9, NULL);
  run(sc, WOBBLE, 1.0);
  run_on(&dv_engine_reduced, sc, WOBBLE, 1.0, &ref);
  CHECK(tr.status == DV_OK && ref.status == DV_OK && tr.n == ref.n, "%s at %g s: %s", integrator,
        dt, tr.stats.detail);
  double err = 0.0;
  for (long k = 0; k < tr.n && k < ref.n; k++)
    err = fmax(err, fabs(tr.s[k].y[RED_TH] - ref.s[k].y[RED_TH]));
  return err;
}

static double wobble_error(const char *integrator, double dt) {
  return wobble_error_at(integrator, dt, 0.0);
}

static void check_convergence(void) {
  const double rk[3] = {wobble_error("rk3", 5e-3), wobble_error("rk3", 2.5e-3),
                        wobble_error("rk3", 1.25e-3)};
  const double me[2] = {wobble_error("rkmerson", 1e-2), wobble_error("rkmerson", 5e-3)};
  const double p1 = log2(rk[0] / rk[1]), p2 = log2(rk[1] / rk[2]), pm = log2(me[0] / me[1]);
  printf(
      "wobble, 1 s: theta error rk3 %.3e %.3e %.3e (order %.2f %.2f); rkmerson %.3e %.3e "
      "(order %.2f)\n",
      rk[0], rk[1], rk[2], p1, p2, me[0], me[1], pm);
  /* measured: rk3 9.54e-6, 1.19e-6, 1.49e-7 rad: orders 3.00 and 3.00;
   * rkmerson 1.79e-7, 1.13e-8 rad: 3.99 (fourth order; 3.96 from 5e-3 to
   * 2.5e-3 s, 7.3e-10 rad) */
  CHECK_NEAR(p1, 3.0, 0.2, "rk3's order (5e-3 -> 2.5e-3 s)");
  CHECK_NEAR(p2, 3.0, 0.2, "rk3's order (2.5e-3 -> 1.25e-3 s)");
  CHECK_NEAR(pm, 4.0, 0.25, "rkmerson's order (1e-2 -> 5e-3 s)");
  /* error-controlled: a tighter accuracy, a smaller error, every sample at
   * its own time (a sample labelled with a time its step only came near
   * erred 1.3e-5 rad at 1e-8 on nonuniform) */
  const double a6 = wobble_error_at("rk3", 1e-3, 1e-6), a8 = wobble_error_at("rk3", 1e-3, 1e-8);
  printf("wobble, 1 s: theta error rk3 at accuracy 1e-6 %.3e, 1e-8 %.3e\n", a6, a8);
  /* measured: 4.9e-7 rad at 1e-6, 4.8e-9 at 1e-8 */
  CHECK(a8 < 0.1 * a6, "accuracy 1e-8: %g rad, 1e-6: %g rad", a8, a6);
  CHECK_NEAR(a8, 0.0, 1.5e-8, "rk3 at accuracy 1e-8");
}

/* the largest |theta - theta0|, relative energy change and f1, f2 changes
 * (relative to the larger) over a run of duration from y at the scene's step */
static void drifts(const double y[RED_NSTATE], double duration, double *th, double *en, double *f) {
  dv_scenario sc = base();
  memcpy(sc.initial, y, sizeof sc.initial);
  sc.duration = duration;
  dv_scenario_set_number(&sc, "simbody", "friction", 1e9, NULL);
  dv_scenario_set_number(&sc, "simbody", "timestep", 1e-3, NULL); /* the scene's: T / 100 */
  CHECK(run(sc, y, duration) == DV_OK, "%s", tr.stats.detail);
  double f10, f20;
  red_invariants(&sc.disk, tr.s[0].y, &f10, &f20);
  const double fs = fmax(fabs(f10), fabs(f20));
  *th = *en = *f = 0.0;
  for (long k = 0; k < tr.n; k++) {
    double f1, f2;
    red_invariants(&sc.disk, tr.s[k].y, &f1, &f2);
    *th = fmax(*th, fabs(tr.s[k].y[RED_TH] - y[RED_TH]));
    *en = fmax(*en, fabs(tr.s[k].energy - tr.s[0].energy) / fabs(tr.s[0].energy));
    *f = fmax(*f, fmax(fabs(f1 - f10), fabs(f2 - f20)) / fs);
  }
}

static void check_invariants(void) {
  double th, en, f;
  drifts(CIRCLE, 5.0, &th, &en, &f);
  printf("steady circle, 5 s: theta %.2e rad, energy %.2e, f1 f2 %.2e\n", th, en, f);
  /* measured (rk3 at 1e-3 s, the scene's): theta 0 rad, energy 3.2e-13, f1
   * f2 3.6e-16: the circle is held to rounding */
  CHECK_NEAR(th, 0.0, 2e-13, "steady circle: theta's drift over 5 s");
  CHECK_NEAR(en, 0.0, 1e-12, "steady circle: energy over 5 s");
  CHECK_NEAR(f, 0.0, 1e-13, "steady circle: f1, f2 over 5 s");
  drifts(WOBBLE, 5.0, &th, &en, &f);
  printf("wobble, 5 s: energy %.2e, f1 f2 %.2e\n", en, f);
  /* measured: energy 1.7e-8, f1 f2 6.7e-8 (rk3's error at 1e-3 s) */
  CHECK_NEAR(en, 0.0, 6e-8, "wobble: energy over 5 s");
  CHECK_NEAR(f, 0.0, 2e-7, "wobble: f1, f2 over 5 s");
}

static void check_faults(void) {
  dv_sample s;
  dv_engine_stats st;
  dv_error err = {{0}};
  /* a NaN state: reset fails, and so does every later call */
  dv_scenario sc = base();
  dv_scenario_set_number(&sc, "simbody", "timestep", 1e-3, NULL);
  const double bad[RED_NSTATE] = {1.0, NAN, 0, 0, 0, 0, 0, 0};
  void *e = E->alloc(&sc, &err);
  CHECK(e && E->reset(e, bad, &err) < 0, "NaN state accepted");
  CHECK(e && E->advance(e, 0.01, &s, &err) < 0, "advance after a failed reset");
  if (e) E->stats(e, &st);
  CHECK(e && st.outcome == DV_OUTCOME_ERROR && st.detail[0], "NaN: %s", st.detail);
  /* the same engine takes a good state after it */
  CHECK(e && E->reset(e, CIRCLE, &err) == DV_OK && E->advance(e, 0.01, &s, &err) == DV_OK,
        "reset after a failed one: %s", err.msg);
  E->free(e);
  /* tipping over at 20 rad/s needs r theta_dot^2 = 40 m/s^2 > g of pull: the
   * constraints hold the disk down, and the run ends at its first step where
   * the normal force is negative (a contact engine loses contact there) */
  const double jump[RED_NSTATE] = {M_PI / 2, 20.0, 0, 0, 0, 0, 0, 0};
  int status = run(sc, jump, 1.0);
  CHECK(status == DV_EVENT && strstr(tr.stats.detail, "normal force") && tr.stats.steps == 1,
        "jump: %s: %s after %ld steps", dv_outcome_name(tr.stats.outcome), tr.stats.detail,
        tr.stats.steps);
  /* a 50 ms step under a huge spin: an outcome with a reason, not a crash */
  dv_scenario_set_number(&sc, "simbody", "timestep", 0.05, NULL);
  dv_scenario_set_number(&sc, "simbody", "friction", 1e9, NULL);
  sc.output_dt = 0.05;
  const double spin[RED_NSTATE] = {1.0, 5.0, 300.0, -3000.0, 0, 0, 0, 0};
  status = run(sc, spin, 10.0);
  CHECK(tr.stats.outcome == DV_OUTCOME_COMPLETED || tr.stats.detail[0], "absurd run: %d", status);
  fprintf(stderr, "absurd run: %s (%s)\n", dv_outcome_name(tr.stats.outcome), tr.stats.detail);
  /* C = 0: refused with a message */
  sc = base();
  sc.disk.C = 0.0;
  err.msg[0] = 0;
  e = E->alloc(&sc, &err);
  CHECK(!e && strstr(err.msg, "Simbody"), "C = 0: %s", err.msg);
  E->free(e);
  E->free(NULL);
}

static void check_thick(void) {
  static const struct {
    const char *what;
    double y[RED_NSTATE];
  } cases[] = {
      {"wobble", {1.2, 0.5, 2.0, -8.0, 0.3, 0.1, 0.0, 0.0}},
      {"wobble past upright", {M_PI - 1.2, -0.5, 2.0, -8.0, 0.3, 0.1, 0.0, 0.0}},
  };
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
    dv_scenario sc = base();
    sc.thickness = 0.02; /* h = 0.01 m on r = 0.1 m: a puck */
    dv_scenario_set_number(&sc, "simbody", "timestep", 5e-4, NULL);
    CHECK(dv_engine_half_thickness(E, &sc) == 0.01, "%s: half-thickness %g", cases[c].what,
          dv_engine_half_thickness(E, &sc));
    run(sc, cases[c].y, 0.5);
    run_on(&dv_engine_matched, sc, cases[c].y, 0.5, &ref);
    double worst = 0.0, slip = 0.0;
    for (long i = 0; i < tr.n && i < ref.n; i++) {
      worst = fmax(worst, fabs(tr.s[i].y[RED_TH] - ref.s[i].y[RED_TH]));
      slip = fmax(slip, tr.s[i].slip);
    }
    CHECK(tr.n == ref.n && tr.n > 10, "%s: %ld samples, matched %ld", cases[c].what, (long)tr.n,
          (long)ref.n);
    printf("thick %s: theta %.3g rad from the matched reference, corner speed %.3g m/s\n",
           cases[c].what, worst, slip);
    /* rk3 against the matched reference, measured (the line printed): 1.4e-9
     * and 2.3e-8 rad at 5e-4 s, 1.1e-8 and 1.9e-7 at 1e-3 s: rk3's own third
     * order (x8), no error of the chain's */
    CHECK(worst < 1e-7, "%s: theta %g rad from the matched reference", cases[c].what, worst);
    CHECK(slip < 1e-8, "%s: the rim corner moves at %g m/s", cases[c].what, slip);
  }
  /* tilting through upright: the corner switches sides, the run ends */
  dv_scenario sc = base();
  sc.thickness = 0.02;
  dv_scenario_set_number(&sc, "simbody", "timestep", 1e-3, NULL);
  const double y[RED_NSTATE] = {M_PI / 2 - 0.05, 3.0, 0, 0, 0, 0, 0, 0};
  const int status = run(sc, y, 0.5);
  run_on(&dv_engine_matched, sc, y, 0.5, &ref);
  const double t = tr.n ? tr.s[tr.n - 1].t : -1, t_ref = ref.n ? ref.s[ref.n - 1].t : -1;
  CHECK(status == DV_EVENT && strstr(tr.stats.detail, "crossed upright"),
        "through upright: status %d: %s", status, tr.stats.detail);
  /* the first step past it, as every event: within one step of the matched root */
  CHECK(t >= t_ref && t - t_ref <= 1e-3 + 1e-12, "through upright at %g s, matched at %g s (%s)", t,
        t_ref, ref.stats.detail);
}

int main(void) {
  CHECK(!strncmp(E->version(), "Simbody 3.", 10), "version %s", E->version());
  check_round_trip();
  check_grid();
  check_constraints();
  check_fall();
  check_convergence();
  check_invariants();
  check_faults();
  check_thick();
  return TEST_RESULT();
}
