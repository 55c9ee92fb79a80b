/* dv_cli_best: diskval best: the cheapest settings that meet a theta tolerance. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "cli_args.h"
#include "search_best.h"
#include "run_progress.h"

static const char HELP[] =
    "usage: diskval best SCENARIO --engine NAME --theta-tol X [--set section.key=value]...\n"
    "\n"
    "Search the engine's settings (its integrator or stepper, and its timestep; the\n"
    "reference: integrator and rtol) for the cheapest run whose max theta error is\n"
    "at most 0.5 X rad (a margin of 2 below the limit): every integrator at the\n"
    "default step first; one whose error there ties another's (within 1 percent) at\n"
    "1.5x the cost a step or more is not searched further; for the others, double or\n"
    "halve the step until the answer changes, then bisect on a log scale until the\n"
    "step is known to 10 percent. Cost is counted, so the answer does not depend on\n"
    "timing: steps per simulated second times the integrator's seconds per step,\n"
    "calibrated once as the median over its probes (printed with min and max). Each\n"
    "probe is told on stderr as it ends, with a forecast of the rest (--quiet: not);\n"
    "stdout lists every probe (meets, marginal: within X but above the margin,\n"
    "exceeds, failed) and the winner.\n"
    "A failed probe says why. Exit status 1 when no probe meets 0.5 X, 2 when no probe\n"
    "could run at all.\n";

/* every probe, the calibration, then the winner; exit 1 when none passes, 2
 * when no probe's engine could run (each ended in an error) */
static int print_search(const dv_search *s) {
  printf("%-12s %12s %12s %12s %12s %s\n", "choice", "step", "theta err", "steps / sim s",
         "s / sim s", "state");
  size_t ran = 0; /* probes whose engine ran (an error or refused settings: not) */
  for (size_t i = 0; i < s->nprobes; i++) {
    const dv_probe *p = &s->probes[i];
    char err[32] = "n/a"; /* a run that failed measured nothing */
    if (p->state != DV_PROBE_FAILED)
      snprintf(err, sizeof err, "%.3e", p->point.metric[DV_THETA_MAX_ERR]);
    printf("%-12s %12.4g %12s %12.6g %12.4g %s", p->choice, p->step, err, p->steps_per_sim_s,
           p->cost, dv_probe_state_name(p->state));
    if (p->state == DV_PROBE_FAILED)
      printf(" (%s: %s)", dv_search_failure_mode(p), p->point.detail[0] ? p->point.detail : "?");
    printf("\n");
    ran += p->point.verdict != DV_VERDICT_ERROR && p->point.verdict != DV_VERDICT_INVALID;
  }
  if (s->nprobes && !ran)
    return dv_cli_error("best", "no probe could run: %s", s->probes[0].point.detail);
  printf("cost calibration, s per step (median of the probes' runs, min..max):");
  for (size_t k = 0; k < s->nchoices; k++) {
    const dv_step_cost *c = &s->step_cost[k];
    printf(" %s %.3g (%.3g..%.3g, %d)", c->choice, c->median, c->min, c->max, c->runs);
  }
  printf("\n");
  if (s->skipped[0]) printf("%s\n", s->skipped);
  if (s->best < 0) {
    printf("no probe meets theta error <= %g x %g rad\n", s->margin, s->tolerance);
    return DV_EXIT_FAIL;
  }
  const dv_probe *b = &s->probes[s->best];
  printf(
      "best: --set %s=%s --set %s=%.9g: theta error %.3e rad (%.2f of the limit %g; "
      "accepted up to %g of it) at %.4g s per simulated s\n",
      s->choice_key, b->choice, s->step_key, b->step, b->point.metric[DV_THETA_MAX_ERR],
      b->point.metric[DV_THETA_MAX_ERR] / s->tolerance, s->tolerance, s->margin, b->cost);
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
  dv_run_progress_start("best", a.quiet, 0);
  int code;
  dv_search *s = calloc(1, sizeof *s);
  dv_scenario *sc = malloc(sizeof *sc); /* read once: every probe varies it in memory */
  dv_error err = {{0}};
  if (engine) dv_cli_probe_only(dv_engine_find(engine)); /* probe the engine run only */
  if (!engine)
    code = dv_cli_usage_error("best", "no --engine given");
  else if (!dv_engine_find(engine))
    code = dv_cli_unknown_engine("best", engine);
  else if (isnan(tol))
    code = dv_cli_usage_error("best", "no --theta-tol given");
  else if (!s || !sc)
    code = dv_cli_error("best", "out of memory");
  else if (dv_cli_load_scenario("best", a.args.items[0], &a.sets, sc, &err) ||
           dv_search_best(sc, engine, tol, s, &err))
    code = dv_cli_error("best", "%s", err.msg);
  else
    code = print_search(s);
  free(s);
  free(sc);
  dv_cli_args_free(&cmd, &a);
  return code;
}
