/* test_steady_thick: the thick disk's steady circles (red_steady_thick.h).
 * At h = 0 they are the thin disk's closed forms; at h > 0 the geometry-
 * matched reference started on one stays on it (theta constant, contact
 * point on the circle of the requested radius) for 10 s, and the thin disk's
 * rates, which a thick scene used to start from, do not. */
#include <math.h>
#include <string.h>

#include "dv_test.h"
#include "dv_testlib.h"
#include "red_steady.h"
#include "red_steady_thick.h"

enum { NOUT = 1001 };

typedef struct run_out {
  long n;
  double th[NOUT], p[NOUT][2];
  const red_rolling *rr;
} run_out;

static int keep(double t, const double *s, void *ctx) {
  run_out *o = ctx;
  if (o->n >= NOUT) return -1;
  o->th[o->n] = s[RR_TH];
  red_rolling_contact_point(o->rr, s, o->p[o->n]);
  o->n++;
  return 0;
}

/* the matched reference from y0 for 10 s, every 0.01 s */
static int run(const red_rolling *rr, const double y0[RED_NSTATE], run_out *o) {
  double s[RR_NSTATE];
  red_rolling_from_state(rr, y0, s);
  memset(o, 0, sizeof *o);
  o->rr = rr;
  red_run r = {red_stepper_default(), 1e-13, 1e-15, 0.0, 10.0, 0.01, keep, o};
  red_result res;
  return red_solve(&rr->sys, &r, s, &res, NULL);
}

/* h = 0: the thin disk's closed forms (measured within 1e-15 relative) */
static void check_thin_limit(void) {
  const red_disk dk = tl_disk(0.25, 0.5);
  red_rolling rr;
  red_rolling_init(&rr, &dk, 0.0, 1.0, 0.0);
  const double cases[][2] = {{1.0, 0.5}, {0.4, 1.0}, {M_PI - 1.0, 0.5}, {1.4, 2.0}};
  for (size_t k = 0; k < 4; k++) {
    double a, b, c, d, e, f;
    const double th = cases[k][0], R = cases[k][1];
    CHECK(red_steady_from_radius(&dk, th, R, &a, &b, NULL) == DV_OK &&
              red_steady_thick_from_radius(&rr, th, R, &c, &d, NULL) == DV_OK,
          "theta %g R %g: no circle", th, R);
    CHECK(fabs(c - a) <= 1e-12 * fabs(a) && fabs(d - b) <= 1e-12 * fabs(b),
          "theta %g R %g: thick at h = 0 gives %.17g, %.17g; thin %.17g, %.17g", th, R, c, d, a, b);
    CHECK(red_steady_from_phi_dot(&dk, th, 3.0, &e, NULL) == DV_OK &&
              red_steady_thick_from_phi_dot(&rr, th, 3.0, &f, NULL) == DV_OK &&
              fabs(f - e) <= 1e-12 * fabs(e),
          "theta %g phi_dot 3: thick at h = 0 gives %.17g, thin %.17g", th, f, e);
    printf("h = 0, theta %.2f R %.1f: relative differences %.1e %.1e %.1e\n", th, R,
           fabs(c / a - 1.0), fabs(d / b - 1.0), fabs(f / e - 1.0));
  }
}

/* the largest |theta - theta0| and |distance to the centre - R| over a run */
static void drift(const run_out *o, const double y0[RED_NSTATE], double R, double *th,
                  double *rad) {
  const double side = copysign(1.0, y0[RED_VPS] * y0[RED_VPH]);
  const double cx = o->p[0][0] + side * R * cos(y0[RED_PH]);
  const double cy = o->p[0][1] + side * R * sin(y0[RED_PH]);
  *th = *rad = 0.0;
  for (long i = 0; i < o->n; i++) {
    *th = fmax(*th, fabs(o->th[i] - y0[RED_TH]));
    *rad = fmax(*rad, fabs(hypot(o->p[i][0] - cx, o->p[i][1] - cy) - R));
  }
}

/* a cylinder of radius r, half-thickness h and mass 1 with A, C of a solid
 * cylinder (a ring's when ring) on a circle of radius R at tilt theta:
 * steady to 1e-9 (measured below 7e-14 rad and 1.4e-14 m); the thin disk's
 * rates nutate it by more than 1e-4 rad (measured 0.021 to 0.19 rad) */
static void check_thick(double r, double h, int ring, double theta, double R) {
  red_disk dk = {r, 1.0, 0.0, 0.0, 9.81};
  dk.C = ring ? r * r : r * r / 2.0;
  dk.A = ring ? r * r / 2.0 + h * h / 3.0 : r * r / 4.0 + h * h / 3.0;
  static red_rolling rr;
  red_rolling_init(&rr, &dk, h, 1e9, 0.01);
  double y0[RED_NSTATE] = {theta, 0.0, 0.0, 0.0, 0.3, 0.0, 0.0, 0.0}, th, rad;
  dv_error err;
  CHECK(red_steady_thick_from_radius(&rr, theta, R, &y0[RED_VPH], &y0[RED_VPS], &err) == DV_OK,
        "r %g h %g theta %g R %g: %s", r, h, theta, R, err.msg);
  static run_out o;
  CHECK(run(&rr, y0, &o) == DV_OK && o.n == NOUT, "r %g h %g: the run ended early", r, h);
  drift(&o, y0, R, &th, &rad);
  printf("r %g h %g%s theta %.2f R %.3f: phi' %.6g psi' %.6g, theta drift %.2e rad, radius error "
         "%.2e m\n",
         r, h, ring ? " ring" : "", theta, R, y0[RED_VPH], y0[RED_VPS], th, rad);
  CHECK(th <= 1e-9 && rad <= 1e-9 * fmax(R, 1.0), "r %g h %g: not steady: %.3g rad, %.3g m", r, h,
        th, rad);
  double psi_dot;
  CHECK(red_steady_thick_from_phi_dot(&rr, theta, y0[RED_VPH], &psi_dot, NULL) == DV_OK &&
            fabs(psi_dot - y0[RED_VPS]) <= 1e-9 * fabs(y0[RED_VPS]),
        "r %g h %g: from phi_dot %.17g, from the radius %.17g", r, h, psi_dot, y0[RED_VPS]);
  double thin[RED_NSTATE];
  memcpy(thin, y0, sizeof thin);
  red_steady_from_radius(&dk, theta, R, &thin[RED_VPH], &thin[RED_VPS], NULL);
  CHECK(run(&rr, thin, &o) == DV_OK, "r %g h %g: the thin rates' run failed", r, h);
  drift(&o, thin, R, &th, &rad);
  printf("  from the thin disk's rates: theta drift %.2e rad\n", th);
  CHECK(th > 1e-4, "r %g h %g: the thin disk's rates are steady too (%.3g rad)", r, h, th);
}

int main(void) {
  check_thin_limit();
  check_thick(0.01213, 0.000875, 0, 1.2, 0.05); /* a US quarter */
  check_thick(0.1, 0.03, 0, 1.0, 0.4);          /* a thick puck */
  check_thick(0.15, 0.01, 1, 0.8, 0.6);         /* a plate with its mass at the rim */
  check_thick(0.3, 0.02, 1, 2.0, 1.5);          /* a hoop leaning the other way */
  /* impossible circles are refused */
  red_disk dk = {0.1, 1.0, 0.1 * 0.1 / 4.0 + 0.03 * 0.03 / 3.0, 0.1 * 0.1 / 2.0, 9.81};
  red_rolling rr;
  red_rolling_init(&rr, &dk, 0.03, 1.0, 0.0);
  double a, b;
  CHECK(red_steady_thick_from_radius(&rr, M_PI / 2, 1.0, &a, &b, NULL) == DV_EINPUT,
        "an upright circle accepted");
  CHECK(red_steady_thick_from_radius(&rr, 1.0, -1.0, &a, &b, NULL) == DV_EINPUT,
        "a negative radius accepted");
  return TEST_RESULT();
}
