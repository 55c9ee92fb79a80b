/* bench_engines: microseconds per step of every contact engine and
 * integrator, and the harness's overhead: the same run sampled every 10 ms
 * into a CSV (diskval's sampling, mapping and bookkeeping) against one
 * advance to the end. Ratios are measured in one run (best of 5). */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "dv_engine.h"
#include "run_trajectory.h"
#include "dv_clock.h"


static dv_scenario circle(void) {
  dv_scenario sc;
  dv_engine_init_scenario(&sc);
  snprintf(sc.name, sizeof sc.name, "steady circle");
  sc.duration = 5.0;
  sc.output_dt = 0.01;
  sc.disk = red_disk_uniform(0.1, 1.0, 9.81);
  const double y[RED_NSTATE] = {1.0, 0, 3.038043841609511, -15.190219208047555, 0, 0, 0, 0};
  memcpy(sc.initial, y, sizeof y);
  return sc;
}

/* best-of-5 seconds: one advance to the end (mode 0), sampled every
 * output_dt without output (1), or sampled into a CSV (2) */
static double time_run(const dv_engine_type *e, const dv_scenario *sc, int mode, long *steps) {
  double best = INFINITY;
  for (int r = 0; r < 5; r++) {
    dv_error err;
    dv_engine_stats st;
    const double t0 = dv_clock_now();
    if (mode) {
      FILE *sink = mode == 2 ? fopen("/dev/null", "w") : NULL;
      dv_run_write_csv(e, sc, sink, NULL, &st, &err);
      if (sink) fclose(sink);
    } else {
      dv_sample s;
      void *eng = e->alloc(sc, &err);
      e->reset(eng, sc->initial, &err);
      e->advance(eng, sc->duration, &s, &err);
      e->stats(eng, &st);
      e->free(eng);
    }
    best = fmin(best, dv_clock_now() - t0);
    *steps = st.steps;
  }
  return best;
}

int main(void) {
  gsl_set_error_handler_off();
  static const char *const mj[] = {"euler", "rk4", "implicit"};
  static const char *const ode[] = {"step", "quickstep"};
  printf("steady circle, 5 s, default settings but the integrator\n");
  printf("%-8s %-10s %10s %10s %15s %12s\n", "engine", "variant", "steps", "us/step",
         "sampling/bare", "+CSV/bare");
  for (int v = 0; v < 5; v++) {
    dv_scenario sc = circle();
    const dv_engine_type *e = v < 3 ? &dv_engine_mujoco : &dv_engine_ode;
    dv_scenario_set(&sc, e->name, e->search->choice_key, v < 3 ? mj[v] : ode[v - 3], NULL);
    long steps;
    const double bare = time_run(e, &sc, 0, &steps);
    const double sampled = time_run(e, &sc, 1, &steps);
    const double csv = time_run(e, &sc, 2, &steps);
    printf("%-8s %-10s %10ld %10.2f %15.3f %12.3f\n", e->name, v < 3 ? mj[v] : ode[v - 3], steps,
           1e6 * bare / steps, sampled / bare, csv / bare);
  }
  printf("target: sampling/bare <= 1.03 (sampling, mapping and bookkeeping, without output)\n");
  return 0;
}
