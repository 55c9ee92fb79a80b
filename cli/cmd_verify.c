/* dv_cli_verify: diskval verify SCENARIO: do the contact engines converge to
 * the reference as their step and contact softness are refined? */
#include <math.h>
#include <stdio.h>

#include "cli.h"
#include "cli_args.h"
#include "dv_engine.h"
#include "run_progress.h"
#include "run_scenario.h"
#include "search_verify.h"

static const char HELP[] =
    "usage: diskval verify SCENARIO [--engines LIST] [--set section.key=value]...\n"
    "\n"
    "Refine each contact engine's time step and contact softness together (dt, dt/2,\n"
    "dt/4, dt/8 from the scenario's step) and report the max theta error against the\n"
    "reference at each, the observed order, and the Richardson-extrapolated\n"
    "discrepancy at dt -> 0. 'converges to the reference' when that is at most\n"
    "1e-4 rad; 'converges elsewhere' (with the dominant cause from attribution)\n"
    "when it is above; 'does not converge' when the errors do not fall; 'not judged'\n"
    "when two levels have the same error exactly, or errors that do not fall sit under\n"
    "the floor (neither shows convergence).\n"
    "--quiet: no progress line on a terminal, no warning before a run longer than a minute.\n"
    "Exit status: 0 every engine converges to the reference, 1 one does not,\n"
    "2 bad input or a run that fails.\n";

/* one engine's table; 0 when it converges to the reference */
static int print_verification(const char *engine, const dv_verification *v) {
  printf("%s:", engine);
  for (int i = 0; i < DV_VERIFY_LEVELS; i++) printf(" %.3e (dt %.3g)", v->error[i], v->step[i]);
  printf("\n  order %s", isnan(v->order) ? "none (the errors do not fall)" : "");
  if (!isnan(v->order)) printf("%.2f", v->order);
  printf("; extrapolated discrepancy %.3e rad (floor %g", v->extrapolated, DV_VERIFY_FLOOR);
  if (v->uncertainty > 0.0) printf(", uncertainty %.2e", v->uncertainty);
  if (v->verdict == DV_CONVERGE_NOT_JUDGED) {
    char why[256];
    dv_search_convergence_why(v->step, v->error, DV_VERIFY_LEVELS, v->verdict, why, sizeof why);
    printf("): not judged: %s\n", why);
    return 1;
  }
  printf("): %s%s%s\n", dv_search_convergence_name(v->verdict), v->cause[0] ? ", cause: " : "",
         v->cause);
  return v->verdict != DV_CONVERGES;
}

int dv_cli_verify(int argc, char **argv) {
  const char *list = NULL;
  const dv_cli_option options[] = {{"engines", DV_CLI_TEXT, &list, 0, 0}};
  const dv_cli_command cmd = {"verify", HELP, options, 1, 1, 1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_run_progress_start("verify", a.quiet, 0);
  const dv_engine_type *engines[DV_MAX_ENGINES + 1];
  dv_scenario sc; /* read once: every engine and step varies it in memory */
  dv_error err = {{0}};
  int code = DV_EXIT_OK;
  if (dv_cli_engine_list(list, engines, &err)) code = dv_cli_error("verify", "%s", err.msg);
  for (size_t i = 0; !code && engines[i]; i++) /* not after the engines before it have run */
    if (!engines[i]->contact || !engines[i]->search)
      code = dv_cli_usage_error(
          "verify", "--engines: %s is not a contact engine: nothing to verify", engines[i]->name);
  if (!code && dv_cli_load_scenario("verify", a.args.items[0], &a.sets, &sc, &err))
    code = dv_cli_error("verify", "%s", err.msg);
  if (!code) { /* a verification longer than a minute says so first */
    size_t n = 0;
    while (engines[n]) n++;
    dv_run_progress_plan_levels(&sc, engines, n, DV_VERIFY_LEVELS);
  }
  for (size_t i = 0; code != DV_EXIT_ERROR && engines[i]; i++) {
    dv_verification v;
    if (dv_search_verify(&sc, engines[i]->name, &v, &err))
      code = dv_cli_error("verify", "%s", err.msg);
    else if (print_verification(engines[i]->name, &v))
      code = DV_EXIT_FAIL;
  }
  dv_cli_args_free(&cmd, &a);
  return code;
}
