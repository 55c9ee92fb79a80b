/* engine_generate: real objects drawn from a seed (engine_generate.h). */
#include "engine_generate.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_rng.h"

const char *const dv_gen_kind_names[4] = {"steady", "fall", "nutation", "spin"};

/* one draw of every value of g */
static void draw(dv_rng *r, double gravity, dv_gen_scene *g) {
  const double u = dv_rng_u01(r);
  g->kind = u < 0.3    ? DV_GEN_STEADY
            : u < 0.5  ? DV_GEN_FALL
            : u < 0.75 ? DV_GEN_NUTATION
                       : DV_GEN_SPIN;
  g->gravity = gravity;
  g->radius = dv_round6(dv_rng_log_uniform(r, 0.008, 0.35));
  const double rad = g->radius;
  g->thickness = dv_rng_u01(r) < 0.4 ? 0.0 : dv_round6(2.0 * rad * dv_rng_uniform(r, 0.005, 0.6));
  /* steel to wood: the density scales the mass, nothing else */
  const double t_eff = fmax(g->thickness, 0.02 * rad);
  g->mass = dv_round6(dv_rng_uniform(r, 700.0, 8000.0) * M_PI * rad * rad * t_eff);
  const double mr2 = g->mass * rad * rad;
  /* a hoop (A = m r^2 / 2, C = 2A) to an axle-heavy wheel (C small against A) */
  g->A = dv_round6(
      mr2 * (dv_rng_uniform(r, 0.15, 0.5) + g->thickness * g->thickness / (12.0 * rad * rad)));
  g->C = dv_round6(fmin(dv_rng_uniform(r, 0.02, 1.0) * 2.0 * g->A, mr2));
  g->friction = dv_round6(dv_rng_uniform(r, 0.3, 2.0));
  g->x = dv_round6(dv_rng_uniform(r, -1.0, 1.0));
  g->y = dv_round6(dv_rng_uniform(r, -1.0, 1.0));
  g->phi = dv_round6(dv_rng_uniform(r, -M_PI, M_PI));
  const double w0 = sqrt(gravity / rad); /* the fall's rate */
  g->theta_dot = g->phi_dot = g->psi_dot = 0.0;
  g->steady_circle_radius = NAN;
  switch (g->kind) {
    case DV_GEN_STEADY: /* either lean: leaning over the centre, or away (past upright) */
      g->theta = dv_round6(dv_rng_u01(r) < 0.8 ? dv_rng_uniform(r, 0.25, 1.45)
                                               : dv_rng_uniform(r, 1.65, 2.2));
      g->steady_circle_radius = dv_round6(rad * dv_rng_log_uniform(r, 2.0, 100.0));
      break;
    case DV_GEN_FALL:
      g->theta = dv_round6(dv_rng_uniform(r, 0.6, 1.55));
      g->psi_dot = dv_round6(dv_rng_uniform(r, -0.5, 0.5) * w0);
      break;
    case DV_GEN_NUTATION:
      g->theta = dv_round6(dv_rng_uniform(r, 0.3, 1.5));
      g->psi_dot = dv_round6((dv_rng_u01(r) < 0.5 ? -1 : 1) * dv_rng_uniform(r, 1.0, 12.0) * w0);
      g->phi_dot = dv_round6(dv_rng_uniform(r, -1.0, 1.0) * w0);
      g->theta_dot = dv_round6(dv_rng_uniform(r, -0.5, 0.5) * w0);
      break;
    case DV_GEN_SPIN:
      g->theta = dv_round6(dv_rng_uniform(r, 1.2, 1.57));
      g->psi_dot = dv_round6((dv_rng_u01(r) < 0.5 ? -1 : 1) * dv_rng_uniform(r, 3.0, 30.0) * w0);
      g->theta_dot = dv_round6(dv_rng_uniform(r, -0.1, 0.1) * w0);
      break;
  }
  g->duration = dv_round6(fmin(2.5, dv_rng_uniform(r, 2.0, 6.0) * 2.0 * M_PI / w0));
  g->output_dt = dv_round6(g->duration / floor(dv_rng_uniform(r, 150.0, 300.0)));
}

int dv_engine_generate_build(const dv_gen_scene *g, dv_scenario *sc, dv_error *err) {
  dv_engine_init_scenario(sc);
  dv_scenario_core_defaults(sc);
  snprintf(sc->name, sizeof sc->name, "%s", g->name);
  const struct {
    const char *section, *key;
    double v;
  } keys[] = {
      {"scenario", "duration", g->duration},
      {"scenario", "output_dt", g->output_dt},
      {"disk", "radius", g->radius},
      {"disk", "mass", g->mass},
      {"disk", "gravity", g->gravity},
      {"disk", "thickness", g->thickness},
      {"disk", "A", g->A},
      {"disk", "C", g->C},
      {"disk", "friction", g->friction},
      {"initial", "theta", g->theta},
      {"initial", "phi", g->phi},
      {"initial", "x", g->x},
      {"initial", "y", g->y},
      {"initial", "theta_dot", g->theta_dot},
      {"initial", "phi_dot", g->phi_dot},
      {"initial", "psi_dot", g->psi_dot},
      {"initial", "steady_circle_radius", g->steady_circle_radius},
  };
  const int steady = g->kind == DV_GEN_STEADY;
  int status = DV_OK;
  for (size_t i = 0; i < sizeof keys / sizeof keys[0] && !status; i++) {
    const int rate = !strcmp(keys[i].section, "initial") && strstr(keys[i].key, "_dot");
    const int circle = !strcmp(keys[i].key, "steady_circle_radius");
    if ((steady && rate) || (!steady && circle)) continue; /* as the .ini leaves them out */
    status = dv_scenario_set_core(sc, keys[i].section, keys[i].key, keys[i].v, err);
  }
  if (!status) status = dv_scenario_check_core(sc, err);
  if (!status) status = dv_engine_derive_settings(sc, err);
  return status;
}

int dv_engine_generate(uint64_t seed, size_t index, double gravity, dv_gen_scene *g,
                       dv_scenario *sc, dv_error *err) {
  if (!(gravity > 0.0) || !isfinite(gravity))
    return dv_fail(err, DV_EINPUT, "gravity: %g is not a positive number", gravity);
  static dv_scenario scratch; /* a check needs a scenario even where the caller wants none */
  dv_scenario *into = sc ? sc : &scratch;
  dv_error why = {0};
  for (uint64_t attempt = 0; attempt < 200; attempt++) {
    dv_rng r = {seed * 0x100000001B3ull ^ ((uint64_t)index << 20) ^ attempt};
    for (int warm = 0; warm < 4; warm++) dv_rng_next(&r);
    memset(g, 0, sizeof *g);
    snprintf(g->name, sizeof g->name, "gen-%llu-%zu", (unsigned long long)seed, index);
    draw(&r, gravity, g);
    if (dv_engine_generate_build(g, into, &why) == DV_OK) return DV_OK;
  }
  return dv_fail(err, DV_EINPUT, "%s: no valid scene in 200 draws (the last: %s)", g->name,
                 why.msg);
}

int dv_engine_generate_ini(const dv_gen_scene *g, char *buf, size_t size) {
  char init[320];
  if (g->kind == DV_GEN_STEADY)
    snprintf(init, sizeof init, "steady_circle_radius = %.17g\n", g->steady_circle_radius);
  else
    snprintf(init, sizeof init, "theta_dot = %.17g\nphi_dot = %.17g\npsi_dot = %.17g\n",
             g->theta_dot, g->phi_dot, g->psi_dot);
  return snprintf(buf, size,
                  "; generated by diskval generate: a %s start\n"
                  "[scenario]\nname = %s\nduration = %.17g\noutput_dt = %.17g\n\n"
                  "[disk]\nradius = %.17g\nmass = %.17g\nthickness = %.17g\nA = %.17g\n"
                  "C = %.17g\ngravity = %.17g\nfriction = %.17g\n\n"
                  "[initial]\ntheta = %.17g\nphi = %.17g\nx = %.17g\ny = %.17g\n%s",
                  dv_gen_kind_names[g->kind], g->name, g->duration, g->output_dt, g->radius,
                  g->mass, g->thickness, g->A, g->C, g->gravity, g->friction, g->theta, g->phi,
                  g->x, g->y, init);
}
