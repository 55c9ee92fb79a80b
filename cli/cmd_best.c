/* dv_cli_best: diskval best: the cheapest settings that meet a theta tolerance. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "cli_args.h"
#include "search_best.h"

static const char HELP[] =
    "usage: diskval best SCENARIO --engine NAME --theta-tol X [--set section.key=value]...\n"
    "\n"
    "Search the engine's settings (its integrator or stepper, and its timestep; the\n"
    "reference: integrator and rtol) for the cheapest run whose max theta error is\n"
    "at most X rad: from the default step, double or halve until the answer changes,\n"
    "then bisect six times on a log scale, for each integrator. Prints every probe\n"
    "and the winner. Exit status 1 when no probe meets X.\n";

/* every probe, then the winner; exit 1 when none meets tol */
static int print_search(const dv_search *s, double tol) {
  printf("%-20s %12s %12s %12s %s\n", "choice", "step", "theta err", "s / sim s", "verdict");
  for (size_t i = 0; i < s->nprobes; i++) {
    const dv_probe *p = &s->probes[i];
    printf("%-20s %12.4g %12.3e %12.4g %s\n", p->choice, p->step, p->point.metric[DV_THETA_MAX_ERR],
           p->point.wall_per_sim_s,
           p->pass       ? "meets"
           : p->point.ok ? "exceeds"
                         : dv_run_verdict_name(p->point.verdict));
  }
  if (s->best < 0) {
    printf("no probe meets theta error <= %g rad\n", tol);
    return DV_EXIT_FAIL;
  }
  const dv_probe *b = &s->probes[s->best];
  printf("best: --set %s=%s --set %s=%.9g: theta error %.3e rad at %.4g s per simulated s\n",
         s->choice_key, b->choice, s->step_key, b->step, b->point.metric[DV_THETA_MAX_ERR],
         b->point.wall_per_sim_s);
  return DV_EXIT_OK;
}

int dv_cli_best(int argc, char **argv) {
  const char *engine = NULL;
  double tol = NAN;
  const dv_cli_option options[] = {
      {"engine", DV_CLI_TEXT, &engine, 0, 0},
      {"theta-tol", DV_CLI_REAL, &tol, 1e-15, 3.2},
  };
  const dv_cli_command cmd = {"best", HELP, options, 2, 1, 1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  int code;
  dv_search *s = calloc(1, sizeof *s);
  dv_error err = {{0}};
  if (!engine)
    code = dv_cli_usage_error("best", "no --engine given");
  else if (!dv_engine_find(engine))
    code = dv_cli_unknown_engine("best", engine);
  else if (isnan(tol))
    code = dv_cli_usage_error("best", "no --theta-tol given");
  else if (!s)
    code = dv_cli_error("best", "out of memory");
  else if (dv_search_best(a.args.items[0], a.sets.items, a.sets.n, engine, tol, s, &err))
    code = dv_cli_error("best", "%s", err.msg);
  else
    code = print_search(s, tol);
  free(s);
  dv_cli_args_free(&cmd, &a);
  return code;
}
