/* props_gen: the scenes props checks (props.h, props_generate).
 *
 * The generator's scene (engine_generate.h) where it compares something.
 * Where it compares nothing (its reference ends within 5 samples, or leaves
 * the friction cone in the first tenth of its run: mostly nutations, and
 * falls and steady circles that need more friction at once), the same
 * object (radius, mass, moments, thickness, friction, start x, y, phi) is
 * set going again, either way with even odds:
 *   periodic  on a steady circle the thin disk's linearisation calls
 *             stable, theta_dot set to a nutation of 0.003 to 0.05 rad,
 *             over 9.5 to 12 wobble periods, 25 samples a period or more:
 *             kept when the reference of the scene's body runs to the end
 *             inside the friction cone and turns 9 times each way
 *   unstable  released near an unstable state: a steady circle the
 *             linearisation calls unstable, theta_dot set to 1e-4 to 3e-3
 *             rad times its growth rate, or upright rolling at 0.3 to 0.9
 *             of the critical spin leaning 1e-3 to 3e-2 rad; over 1 to 1.5
 *             times the time the growth takes to reach 0.3 rad: kept when
 *             the reference's distance from that state grows x30 from the
 *             first tenth of its window
 * each drawn up to 30 times (then the other kind), else the generator's
 * scene stays. Drawn again: 137 of seed 2026's first 500 (74 periodic, 63
 * unstable), 20 of seed 1's first 60. The scene is built as a load builds
 * its .ini (engine_generate.c), so that property g checks the text against it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_reference.h"
#include "engine_scene.h"
#include "dv_rng.h"
#include "props.h"
#include "props_shadow.h"
#include "red_steady.h"
#include "run_trajectory.h"
#include "run_turning.h"

_Static_assert(PROPS_KIND_PERIODIC == DV_GEN_SPIN + 1, "props' kinds follow the generator's");

const char *const props_kind_names[PROPS_NKINDS] = {"steady", "fall",     "nutation",
                                                    "spin",   "periodic", "unstable"};

#define ATTEMPTS 30     /* draws of a scene drawn again */
#define MIN_SAMPLES 5   /* a reference ending within these compared nothing */
#define MIN_VALID 0.1   /* nor one leaving the friction cone within this share of its run */
#define MIN_TURNS 9     /* maxima and minima each: 8 nutation periods */
#define PER_PERIOD 25   /* samples a wobble period at least: turning points placed */
#define MAX_SAMPLES 600 /* samples at most (the cost of a judge grows with them) */
#define GROWTH 30.0     /* an unstable release's distance from its state grows this much */

/* sc's body's reference at its default settings into tr; where its
 * validity ends (s, INFINITY: never) */
static int body_run(const dv_scenario *sc, dv_traj *tr, double *valid, dv_error *err) {
  static dv_scenario body;
  const dv_engine_type *type = props_body_of(sc, &body);
  memset(tr, 0, sizeof *tr);
  dv_engine_stats st;
  const int status = dv_run_collect(type, &body, dv_run_traj_keep, tr, &st, err);
  *valid = dv_reference_valid_until(&body, tr->s, tr->n);
  return status < 0 ? status : DV_OK;
}

/* the generator's scene compares nothing: its reference ends at once, or
 * leaves the friction cone at once */
static int compares_nothing(const dv_scenario *sc) {
  dv_traj tr;
  double valid;
  dv_error err = {0};
  const int status = body_run(sc, &tr, &valid, &err);
  const double t_last = tr.n ? tr.s[tr.n - 1].t : 0.0;
  const int nothing = status < 0 || tr.n < MIN_SAMPLES || valid < MIN_VALID * t_last;
  dv_run_traj_free(&tr);
  return nothing;
}

/* the largest real part and imaginary modulus of sc's start linearised (thin) */
static int linearised(const dv_scenario *sc, double *re, double *im) {
  double eig[RED_NREDUCED][2];
  int stable;
  dv_error err = {0};
  if (red_linear_stability(&sc->disk, sc->initial, eig, &stable, &err)) return -1;
  *re = *im = 0.0;
  for (int i = 0; i < RED_NREDUCED; i++)
    *re = fmax(*re, eig[i][0]), *im = fmax(*im, fabs(eig[i][1]));
  return 0;
}

/* the duration and sample interval of g: duration d, n samples at least */
static void set_time(dv_rng *r, dv_gen_scene *g, double d, double n) {
  g->duration = dv_round6(d);
  const double samples = fmin(MAX_SAMPLES, fmax(floor(dv_rng_uniform(r, 150.0, 300.0)), ceil(n)));
  g->output_dt = dv_round6(g->duration / samples);
}

/* a draw of g (the object kept) as a periodic start; 0, or -1 no such draw */
static int draw_periodic(dv_rng *r, dv_gen_scene *g, dv_scenario *sc) {
  dv_error err = {0};
  g->kind = DV_GEN_STEADY;
  g->theta = dv_round6(dv_rng_uniform(r, 0.35, 1.45));
  g->steady_circle_radius = dv_round6(g->radius * dv_rng_log_uniform(r, 2.0, 100.0));
  g->duration = 1.0, g->output_dt = 0.01; /* for the steady rates; set below */
  double re, im;
  if (dv_engine_generate_build(g, sc, &err) || linearised(sc, &re, &im) || !(im > 0.0) ||
      re > 1e-6 * im)
    return -1;
  const double period = 2.0 * M_PI / im;
  g->kind = DV_GEN_NUTATION;
  g->steady_circle_radius = NAN;
  g->phi_dot = sc->initial[RED_VPH], g->psi_dot = sc->initial[RED_VPS];
  g->theta_dot =
      dv_round6((dv_rng_u01(r) < 0.5 ? -1 : 1) * dv_rng_log_uniform(r, 0.003, 0.05) * im);
  const double periods = dv_rng_uniform(r, 9.5, 12.0);
  set_time(r, g, periods * period, PER_PERIOD * periods);
  return dv_engine_generate_build(g, sc, &err) ? -1 : 0;
}

/* a draw of g (the object kept) as a release near an unstable state: the
 * state's theta into *th0; 0, or -1 no such draw */
static int draw_unstable(dv_rng *r, dv_gen_scene *g, dv_scenario *sc, double *th0) {
  dv_error err = {0};
  double re, im, delta;
  g->duration = 1.0, g->output_dt = 0.01; /* for the linearisation; set below */
  if (dv_rng_u01(r) < 0.5) {              /* an unstable steady circle */
    g->kind = DV_GEN_STEADY;
    g->theta = dv_round6(dv_rng_u01(r) < 0.8 ? dv_rng_uniform(r, 0.25, 1.45)
                                             : dv_rng_uniform(r, 1.65, 2.2));
    g->steady_circle_radius = dv_round6(g->radius * dv_rng_log_uniform(r, 2.0, 100.0));
    if (dv_engine_generate_build(g, sc, &err) || linearised(sc, &re, &im) ||
        !(re > 1e-6 * fmax(re, im)))
      return -1;
    g->kind = DV_GEN_NUTATION;
    g->steady_circle_radius = NAN;
    g->phi_dot = sc->initial[RED_VPH], g->psi_dot = sc->initial[RED_VPS];
    delta = dv_rng_log_uniform(r, 1e-4, 3e-3);
    g->theta_dot = dv_round6((dv_rng_u01(r) < 0.5 ? -1 : 1) * delta * re);
    *th0 = g->theta;
  } else { /* upright rolling below the critical spin, leaning a little */
    red_disk d = {g->radius, g->mass, g->A, g->C, g->gravity};
    const double spin = dv_rng_uniform(r, 0.3, 0.9) * red_upright_critical_spin(&d);
    g->kind = DV_GEN_NUTATION;
    g->steady_circle_radius = NAN;
    g->theta = M_PI_2, g->theta_dot = g->phi_dot = 0.0;
    g->psi_dot = dv_round6((dv_rng_u01(r) < 0.5 ? -1 : 1) * spin);
    if (dv_engine_generate_build(g, sc, &err) || linearised(sc, &re, &im) ||
        !(re > 1e-6 * fmax(re, im)))
      return -1;
    delta = dv_rng_log_uniform(r, 1e-3, 3e-2);
    *th0 = M_PI_2;
    g->theta = dv_round6(M_PI_2 - delta);
  }
  const double d = fmax(dv_rng_uniform(r, 1.0, 1.5) * log(0.3 / delta) / re,
                        4.0 * M_PI * sqrt(g->radius / g->gravity));
  set_time(r, g, d, 5.0 * d * re);
  return dv_engine_generate_build(g, sc, &err) ? -1 : 0;
}

/* g's reference shows what its kind promises (props.h): periodic, it runs
 * to the end in the friction cone and turns MIN_TURNS times; unstable, its
 * distance from th0 grows GROWTH times from the first tenth of its window */
static int keeps(const dv_scenario *sc, int kind, double th0) {
  dv_traj tr;
  double valid;
  dv_error err = {0};
  int ok = 0;
  if (body_run(sc, &tr, &valid, &err) == DV_OK && tr.n >= MIN_SAMPLES) {
    const double t_last = tr.s[tr.n - 1].t, end = fmin(t_last, valid);
    if (kind == PROPS_KIND_PERIODIC && t_last >= sc->duration * (1 - 1e-9) && valid >= t_last) {
      double *t = malloc(tr.n * sizeof *t), *th = malloc(tr.n * sizeof *th);
      int *k = malloc(tr.n * sizeof *k), most[2] = {0, 0};
      const size_t nt = t && th && k ? dv_run_turning_points(&tr, end, t, th, k) : 0;
      for (size_t i = 0; i < nt; i++) most[k[i] > 0]++;
      ok = most[0] >= MIN_TURNS && most[1] >= MIN_TURNS;
      free(t), free(th), free(k);
    } else if (kind == PROPS_KIND_UNSTABLE && end >= MIN_VALID * sc->duration) {
      double first = 0.0, all = 0.0;
      for (size_t i = 0; i < tr.n && tr.s[i].t <= end; i++) {
        const double off = fabs(tr.s[i].y[RED_TH] - th0);
        all = fmax(all, off);
        if (tr.s[i].t <= 0.1 * end) first = fmax(first, off);
      }
      ok = all >= GROWTH * first && first > 0.0;
    }
  }
  dv_run_traj_free(&tr);
  return ok;
}

int props_generate(uint64_t seed, size_t index, int plain, dv_gen_scene *g, dv_scenario *sc,
                   int *kind, dv_error *err) {
  int status = dv_engine_generate(seed, index, 9.81, g, sc, err);
  *kind = g->kind;
  if (status || plain || !compares_nothing(sc)) return status;
  const dv_gen_scene base = *g;
  static dv_scenario drawn;
  dv_rng r = {seed * 0x9E3779B97F4A7C15ull ^ ((uint64_t)index << 24) ^ 0x5A};
  const int first = dv_rng_u01(&r) < 0.5 ? PROPS_KIND_PERIODIC : PROPS_KIND_UNSTABLE;
  for (int k = 0; k < 2; k++) { /* the kind drawn, else the other */
    const int want = k ? PROPS_KIND_PERIODIC + PROPS_KIND_UNSTABLE - first : first;
    for (int attempt = 0; attempt < ATTEMPTS; attempt++) {
      *g = base;
      double th0 = NAN;
      const int made = want == PROPS_KIND_PERIODIC ? draw_periodic(&r, g, &drawn)
                                                   : draw_unstable(&r, g, &drawn, &th0);
      if (made == 0 && keeps(&drawn, want, th0)) {
        *sc = drawn;
        *kind = want;
        return DV_OK;
      }
    }
  }
  *g = base; /* none kept: the generator's own */
  return dv_engine_generate(seed, index, 9.81, g, sc, err);
}
