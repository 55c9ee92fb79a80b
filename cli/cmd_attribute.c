/* dv_cli_attribute: diskval attribute SCENARIO --engine NAME: why a contact
 * engine disagrees with the thin disk, in shares (search_attribute.h). */
#include <math.h>
#include <stdio.h>

#include "cli.h"
#include "cli_args.h"
#include "dv_engine.h"
#include "search_attribute.h"
#include "run_progress.h"

static const char HELP[] =
    "usage: diskval attribute SCENARIO --engine NAME [--set section.key=value]...\n"
    "\n"
    "Split a contact engine's max theta error against the thin disk into shares,\n"
    "each by a measured difference:\n"
    "  geometry     error with the engine's stand-in shape minus error with the exact\n"
    "               thin disk (n/a when the scenario already uses the thin disk;\n"
    "               negative where the stand-in's geometry cancels other error)\n"
    "  time         Richardson over dt, dt/2, dt/4 (thin disk): e(dt) - e(0), with the\n"
    "               observed order; 0 where the errors do not fall with the step\n"
    "  contact      at dt/4, e minus e with a stiffer contact and 10x friction\n"
    "  rest         what the three leave (interactions, the solver's tolerance)\n"
    "Then every knob the engine declares is changed alone (its integrator or stepper\n"
    "to each other value, the step to a quarter, a stiffer contact, 10x friction, a\n"
    "stand-in to the thin disk) and the cause is the knob whose change removes the\n"
    "error (every metric over its limit within it; none over: theta halved).\n"
    "An engine that simulates the scene's cylinder ([disk] thickness) is measured\n"
    "against its own reference, in its own shape, and has no geometry share.\n"
    "A run that fails in any probe is an error (exit 2), not a zero share; a\n"
    "scenario whose run measures nothing (its compared window is too short, e.g.\n"
    "outside the friction cone from the start) is \"not measured\", no share and no\n"
    "cause (exit 1).\n";

/* each knob changed alone, and the cause: the one whose change removes the error */
static void print_knobs(const dv_attribution *at) {
  char cause[300];
  for (int m = 0; m < DV_NMETRICS; m++)
    if (at->judged >> m & 1u)
      printf("over its limit: %s = %.4g > %.4g\n", dv_metric_names[m], at->base[m], at->limit[m]);
  /* theta beside the worst: what a knob does where it does not remove the error */
  printf("%-17s %-28s %10s %11s  %s\n", "knob", "change", "worst", "theta (rad)",
         at->judged          ? "(worst: value / limit over the metrics over their limits)"
         : at->own_reference ? "(worst: theta against its own reference / the scenario's)"
                             : "(worst: theta against the thin disk / the scenario's)");
  printf("%-17s %-28s %10s %11.3g\n", "(none)", "the scenario's settings", "", at->base_theta_thin);
  for (size_t i = 0; i < at->nknobs; i++)
    printf("%-17s %-28s %10.3g %11.3g  %s\n", at->knobs[i].knob, at->knobs[i].change,
           at->knobs[i].worst, at->knobs[i].theta_thin, at->knobs[i].removes ? "removes it" : "");
  dv_search_attribute_cause(at, cause, sizeof cause);
  printf("cause: %s\n", cause);
}

/* the table of shares */
static void print_attribution(const char *engine, const dv_attribution *at) {
  const double e = at->e.stand_in;
  const char *against =
      at->own_reference ? "its own reference (the matched cylinder)" : "the thin disk";
  printf("%s: max theta error against %s %.3e rad\n", engine, against, e);
  printf("%-10s %12s %8s  %s\n", "factor", "theta (rad)", "share", "method");
  const struct {
    const char *name;
    double v;
    const char *how;
  } rows[] = {
      {"geometry", at->has_stand_in ? at->geometry : NAN,
       at->own_reference ? "n/a: measured in the engine's own shape, against its matched reference"
       : !at->has_stand_in ? "n/a: the scenario uses the exact thin disk, no stand-in"
       : at->geometry < 0  ? "stand-in against the exact thin disk; negative: its geometry "
                             "cancels part of the engine's other error"
                           : "stand-in against the exact thin disk"},
      {"time", at->time,
       isnan(at->order) ? "errors flat over dt, dt/2, dt/4: none"
                        : "Richardson over dt, dt/2, dt/4"},
      {"contact", at->contact, "stiffer contact, 10x friction, at a finer step"},
      {"rest", at->rest, "what the others leave"},
  };
  for (size_t i = 0; i < 4; i++)
    if (isnan(rows[i].v)) /* not applicable: no number, not a zero */
      printf("%-10s %12s %8s  %s\n", rows[i].name, "n/a", "n/a", rows[i].how);
    else
      printf("%-10s %12.3e %7.1f%%  %s\n", rows[i].name, rows[i].v,
             e > 0 ? 100.0 * rows[i].v / e : 0.0, rows[i].how);
  printf("(%s: %.3e at dt %g, %.3e at dt/2, %.3e at dt/4; ",
         at->own_reference ? "its own shape" : "thin disk", at->e.dt[0], at->timestep, at->e.dt[1],
         at->e.dt[2]);
  if (isnan(at->order))
    printf("no order: the errors do not fall with the step; ");
  else
    printf("order %.2f; ", at->order);
  printf("stiffer %.3e)\n", at->e.stiff);
  print_knobs(at);
}

int dv_cli_attribute(int argc, char **argv) {
  const char *engine = NULL;
  const dv_cli_option options[] = {{"engine", DV_CLI_TEXT, &engine, 0, 0}};
  const dv_cli_command cmd = {"attribute", HELP, options, 1, 1, 1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_run_progress_start("attribute", a.quiet, 0);
  int code = DV_EXIT_OK;
  dv_attribution at;
  dv_scenario sc; /* read once: every probe varies it in memory */
  dv_error err = {{0}};
  if (engine) dv_cli_probe_only(dv_engine_find(engine)); /* probe the engine run only */
  if (!engine)
    code = dv_cli_usage_error("attribute", "no --engine given");
  else if (!dv_engine_find(engine))
    code = dv_cli_unknown_engine("attribute", engine);
  else if (dv_cli_load_scenario("attribute", a.args.items[0], &a.sets, &sc, &err))
    code = dv_cli_error("attribute", "%s", err.msg);
  else if (dv_search_attribute(&sc, engine, &at, &err))
    code = dv_cli_error("attribute", "%s", err.msg);
  else if (at.not_measured[0]) { /* nothing to split: never a table of zeros, never a pass */
    printf("%s: not measured: %s\nno share, no cause: nothing was measured\n", engine,
           at.not_measured);
    code = DV_EXIT_FAIL;
  } else
    print_attribution(engine, &at);
  dv_cli_args_free(&cmd, &a);
  return code;
}
