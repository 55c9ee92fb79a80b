/* bench_sweep: what sweeps cost, and what accuracy costs.
 *   1. a sweep of N points on 2 processes against 1 (target <= 0.55)
 *   2. the overhead of a point (parsing, setup, the references, comparison,
 *      bookkeeping) against a 1 s simulation in the engine (target <= 2%)
 *   3. headline: the cost of theta error 1e-3 in each engine (diskval best)
 *      against the reference's cost at 1e-10, for the steady circle and
 *      upright rolling
 * Ratios are measured in one run. usage: bench_sweep SCENARIO_DIR TEST_DATA_DIR */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "search_best.h"
#include "search_sweep.h"
#include "run_trajectory.h"
#include "dv_clock.h"

static int discard(void *ctx, const dv_sample *s) {
  return 0;
}

int main(int argc, char **argv) {
  gsl_set_error_handler_off();
  if (argc != 3) return fprintf(stderr, "usage: bench_sweep SCENARIO_DIR TEST_DATA_DIR\n"), 2;
  char circle[1024], upright[1024], shortc[1024];
  snprintf(circle, sizeof circle, "%s/steady_circle.ini", argv[1]);
  snprintf(upright, sizeof upright, "%s/upright_stable.ini", argv[1]);
  snprintf(shortc, sizeof shortc, "%s/short_circle.ini", argv[2]);
  dv_error err = {{0}};
  static dv_vary v;
  static dv_sweep s;
  static dv_scenario short_sc, loaded;
  dv_search_vary_parse("timestep=1e-3..2e-4:16", "mujoco", &v, &err);
  dv_engine_load_scenario(shortc, NULL, 0, &short_sc, &err);

  double t[2];
  for (int jobs = 1; jobs <= 2; jobs++) {
    const double t0 = dv_clock_now();
    dv_search_sweep_run(&short_sc, "mujoco", &v, 1, jobs, &s, &err);
    t[jobs - 1] = dv_clock_now() - t0;
    if (jobs == 2) break;
    dv_search_sweep_free(&s);
  }
  printf(
      "sweep of %zu points (MuJoCo, 1 s each): 1 process %.3f s, 2 processes %.3f s: "
      "ratio %.2f (target <= 0.55)\n",
      s.n, t[0], t[1], t[1] / t[0]);

  /* overhead: the serial sweep's time per point less its timed engine runs */
  static dv_scenario sc;
  double engine = 0.0;
  int runs = 0;
  for (size_t k = 0; k < s.n; k++) {
    char o[96];
    const char *over[1] = {o};
    snprintf(o, sizeof o, "engines.mujoco.timestep=%s", s.p[k].values[0]);
    dv_engine_load_scenario(shortc, over, 1, &sc, &err);
    dv_engine_stats st;
    const double t0 = dv_clock_now();
    dv_run_collect(&dv_engine_mujoco, &sc, discard, NULL, &st, &err);
    engine +=
        (dv_clock_now() - t0) * s.p[k].timed_runs; /* the compared run is the first timed one */
    runs += s.p[k].timed_runs;
  }
  const double overhead = (t[0] - engine) / (double)s.n;
  const double one_second = engine / (double)runs;
  printf("overhead per point %.2f ms against %.1f ms for a 1 s run: %.1f%% (target <= 2%%)\n",
         1e3 * overhead, 1e3 * one_second, 100.0 * overhead / one_second);
  dv_search_sweep_free(&s);

  const char *paths[2] = {circle, upright}, *names[2] = {"steady circle", "upright"};
  static dv_search b;
  for (int i = 0; i < 2; i++) {
    dv_engine_load_scenario(paths[i], NULL, 0, &loaded, &err);
    dv_search_best(&loaded, "reduced", 1e-10, &b, &err);
    const double ref = b.best >= 0 ? b.probes[b.best].point.wall_per_sim_s : NAN;
    printf("%s: reference at theta error 1e-10: %s, %.3g s per simulated s\n", names[i],
           b.best >= 0 ? b.probes[b.best].choice : "-", ref);
    const char *engines[2] = {"mujoco", "ode"};
    for (int e = 0; e < 2; e++) {
      dv_search_best(&loaded, engines[e], 1e-3, &b, &err);
      if (b.best < 0) {
        printf("  %-7s cannot reach 1e-3 rad\n", engines[e]);
        continue;
      }
      const dv_probe *p = &b.probes[b.best];
      printf(
          "  %-7s theta error 1e-3: %s, timestep %.3g s: %.3g s per simulated s = %.1fx the "
          "reference at 1e-10\n",
          engines[e], p->choice, p->step, p->point.wall_per_sim_s, p->point.wall_per_sim_s / ref);
    }
  }
  return 0;
}
