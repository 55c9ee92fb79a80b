/* dv_cli_attribute: diskval attribute SCENARIO --engine NAME: why does the
 * engine disagree with the thin disk? Splits its theta error into geometry,
 * time discretisation, contact softness and slip, and the rest. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "scenario.h"
#include "search_sweep.h"

static const char HELP[] =
    "usage: diskval attribute SCENARIO --engine mujoco|ode [--set section.key=value]...\n"
    "\n"
    "Split the engine's max theta error against the thin disk into shares, each by\n"
    "a measured difference:\n"
    "  geometry     error against the thin disk minus error against the disk the\n"
    "               engine simulates (matched, same half-thickness)\n"
    "  time         Richardson: e(dt) - e(dt/2), scaled by 1 / (1 - 2^-p) with the\n"
    "               order p from e(dt), e(dt/2), e(dt/4)\n"
    "  contact      at dt/4, e minus e with a 4x stiffer contact and 10x friction\n"
    "  rest         what the three leave (interactions, the solver's tolerance)\n";

typedef struct probe_set {
  const char *path;
  const char *const *sets;
  size_t nsets;
  const char *engine;
} probe_set;

/* theta error of one run with up to three overrides; thin: against the thin disk */
static double err_of(const probe_set *ps, const char *o1, const char *o2, const char *o3,
                     int thin) {
  const char *over[3];
  size_t n = 0;
  const char *given[3] = {o1, o2, o3};
  for (int i = 0; i < 3; i++)
    if (given[i]) over[n++] = given[i];
  dv_sweep_point p;
  dv_search_sweep_probe(ps->path, ps->sets, ps->nsets, ps->engine, over, n, &p, NULL);
  return thin ? p.theta_thin : p.metric[DV_THETA_MAX_ERR];
}

int dv_cli_attribute(int argc, char **argv) {
  dv_common_args a = {0};
  const char *engine = NULL;
  for (int i = 1; i < argc; i++) {
    const int set = dv_cli_take_set(&a, argc, argv, &i);
    if (set < 0) return dv_cli_usage_error("attribute", "--set needs section.key=value");
    if (set) continue;
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h"))
      return fputs(HELP, stdout), DV_EXIT_OK;
    else if (!strcmp(argv[i], "--engine") && i + 1 < argc)
      engine = argv[++i];
    else if (argv[i][0] == '-' && argv[i][1])
      return dv_cli_usage_error("attribute", "unknown or incomplete option '%s'", argv[i]);
    else if (!a.scenario)
      a.scenario = argv[i];
    else
      return dv_cli_usage_error("attribute", "more than one scenario given");
  }
  if (!a.scenario || !engine || (strcmp(engine, "mujoco") && strcmp(engine, "ode")))
    return dv_cli_usage_error("attribute", "needs SCENARIO and --engine mujoco or ode");
  static dv_scenario sc;
  dv_error err = {{0}};
  if (dv_engine_load_scenario(a.scenario, a.sets, (size_t)a.nsets, &sc, &err))
    return fprintf(stderr, "%s\n", err.msg), DV_EXIT_ERROR;
  const int mj = !strcmp(engine, "mujoco");
  const double dt = mj ? dv_scenario_get(&sc, "mujoco", "timestep") : dv_scenario_get(&sc, "ode", "timestep");
  const double h = mj ? (dv_scenario_get(&sc, "mujoco", "geom") ? 0.0 : dv_scenario_get(&sc, "mujoco", "half_thickness")) : dv_scenario_get(&sc, "ode", "half_thickness");
  const probe_set ps = {a.scenario, a.sets, (size_t)a.nsets, engine};
  char s1[96], s2[96], s4[96], stiff[96], fric[96], tc1[96];
  snprintf(s1, sizeof s1, "engines.%s.timestep=%.9g", engine, dt);
  snprintf(s2, sizeof s2, "engines.%s.timestep=%.9g", engine, dt / 2);
  snprintf(s4, sizeof s4, "engines.%s.timestep=%.9g", engine, dt / 4);
  /* MuJoCo's contact time constant follows the step where it is clamped to 2 dt */
  const double tc = mj ? dv_scenario_get(&sc, "mujoco", "solref_timeconst") : 0.0;
  snprintf(tc1, sizeof tc1, "engines.mujoco.solref_timeconst=%.9g", fmax(tc, 2 * dt));
  if (mj)
    snprintf(stiff, sizeof stiff, "engines.mujoco.solref_timeconst=%.9g", fmax(tc, 2 * dt) / 4);
  else
    snprintf(stiff, sizeof stiff, "engines.ode.soft_cfm=%.9g", dv_scenario_get(&sc, "ode", "soft_cfm") / 100);
  snprintf(fric, sizeof fric, "engines.%s.friction=%.9g", engine,
           10 * (mj ? dv_scenario_get(&sc, "mujoco", "friction") : dv_scenario_get(&sc, "ode", "friction")));
  const double e_thin = err_of(&ps, s1, mj ? tc1 : NULL, NULL, 1);
  const double e_ref = err_of(&ps, s1, mj ? tc1 : NULL, NULL, 0);
  const double e2 = err_of(&ps, s2, mj ? tc1 : NULL, NULL, 0);
  const double e4 = err_of(&ps, s4, mj ? tc1 : NULL, NULL, 0);
  /* a 4x stiffer contact needs a step that resolves it: MuJoCo at dt / 8 */
  char s8[96];
  snprintf(s8, sizeof s8, "engines.%s.timestep=%.9g", engine, mj ? dt / 8 : dt / 4);
  const double e_stiff = err_of(&ps, mj ? s8 : s4, stiff, fric, 0);
  const double d1 = e_ref - e2, d2 = e2 - e4;
  const double p = (d1 > 0 && d2 > 0) ? log2(d1 / d2) : 1.0;
  const double time = d1 > 0 ? d1 / (1 - pow(2.0, -p)) : 0.0;
  const double geometry = h > 0.0 ? e_thin - e_ref : 0.0;
  const double contact = e4 - e_stiff;
  const double rest = e_thin - geometry - time - contact;
  printf("%s, %s: max theta error against the thin disk %.3e rad\n", sc.name, engine, e_thin);
  printf("%-10s %12s %8s  %s\n", "factor", "theta (rad)", "share", "method");
  const struct {
    const char *name;
    double v;
    const char *how;
  } rows[] = {
      {"geometry", geometry,
       h > 0 ? "thin disk against matched (same h)" : "smooth stand-in: none"},
      {"time", time, "Richardson over dt, dt/2, dt/4"},
      {"contact", contact, "4x stiffer contact, 10x friction, at a finer step"},
      {"rest", rest, "what the others leave"},
  };
  for (size_t i = 0; i < 4; i++)
    printf("%-10s %12.3e %7.1f%%  %s\n", rows[i].name, rows[i].v,
           e_thin > 0 ? 100.0 * rows[i].v / e_thin : 0.0, rows[i].how);
  printf("(errors: matched %.3e at dt %g, %.3e at dt/2, %.3e at dt/4; order %.2f; stiffer %.3e)\n",
         e_ref, dt, e2, e4, p, e_stiff);
  return DV_EXIT_OK;
}
