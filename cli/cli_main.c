/* diskval: cross-validation of rolling-disk simulations against the reduced
 * equations. The entry point dispatches to the subcommands. */
#include <errno.h>
#include <gsl/gsl_errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "adapter_child.h"
#include "cli.h"
#include "exec_mpi.h"
#include "io_temp.h"
#include "dv_engine.h"
#include "engine_choose.h"
#include "scenario.h"
#include "red_solver.h"
#include "run_scenario.h"

static const char HELP[] =
    "usage: diskval COMMAND [ARGS]   (diskval COMMAND --help for each)\n"
    "\n"
    "Checks simulations of a disk rolling without slipping against the exact\n"
    "reduced equations of motion.\n"
    "\n"
    "commands:\n"
    "  simulate SCENARIO --engine NAME [--out FILE]   one trajectory as CSV\n"
    "  analyze SCENARIO [--json]                      invariants, steady motion, stability\n"
    "  compare SCENARIO [--engines LIST] [--out DIR]  engines against the references\n"
    "  judge SCENARIO TRAJECTORY... [--out DIR]       trajectories from any engine, judged\n"
    "  suite DIR|FILES... [--out DIR] [--junit FILE] [--jobs N]   many scenarios, reports\n"
    "  sweep SCENARIO --engine NAME --vary KEY=VALUES speed against error over settings\n"
    "  best SCENARIO --engine NAME --theta-tol X      the cheapest settings meeting X\n"
    "  attribute SCENARIO --engine NAME               why an engine disagrees, in shares\n"
    "  map [--c A..B:N] [--spin A..B:N]               stability map of upright rolling\n"
    "  verify SCENARIO [--engines LIST]               do the engines converge to the reference\n"
    "  generate --seed N --count K --out DIR          real objects drawn at random, as scenarios\n"
    "  league [DIR|FILES...] [--targets T,...]        every engine on real objects: error, cost\n"
    "  engines                                        the engines and integrators\n";

int dv_cli_usage_error(const char *command, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "diskval %s: ", command);
  vfprintf(stderr, fmt, ap);
  fprintf(stderr, " (see diskval %s --help)\n", command);
  va_end(ap);
  return DV_EXIT_ERROR;
}

int dv_cli_error(const char *command, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "diskval %s: ", command);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  va_end(ap);
  return DV_EXIT_ERROR;
}

int dv_cli_unknown_engine(const char *command, const char *name) {
  char names[256] = "";
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++)
    snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s",
             e == dv_engine_list() ? "" : ", ", (*e)->name);
  return dv_cli_error(command, "unknown engine '%s' (one of: %s)", name, names);
}

int dv_cli_engine_list(const char *list, const dv_engine_type **engines, dv_error *err) {
  if (list) { /* given, even empty: '' is no engine, not every engine */
    const int status = dv_engine_parse_list(list, engines, DV_MAX_ENGINES + 1, err);
    if (status == DV_OK) dv_engine_choose_only(engines); /* probe only the engines run */
    return status;
  }
  size_t n = 0;
  _Static_assert(DV_NENGINES <= DV_MAX_ENGINES, "every linked engine fits in one comparison");
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++) { /* outside ones: by name */
    if ((*e)->role != DV_ENGINE_CONTACT || (*e)->outside) continue;
    const char *why = dv_engine_unavailable(*e); /* its module missing or broken: left out */
    if (why)
      fprintf(stderr, "diskval: %s: not available: %s\n", (*e)->name, why);
    else
      engines[n++] = *e;
  }
  engines[n] = NULL;
  return DV_OK;
}

void dv_cli_probe_only(const dv_engine_type *engine) {
  const dv_engine_type *const run[] = {engine, NULL};
  if (engine) dv_engine_choose_only(run);
}

int main(int argc, char **argv) {
  static const struct {
    const char *name;
    int (*run)(int, char **);
  } commands[] = {{"simulate", dv_cli_simulate}, {"analyze", dv_cli_analyze},
                  {"compare", dv_cli_compare},   {"judge", dv_cli_judge},
                  {"suite", dv_cli_suite},       {"sweep", dv_cli_sweep},
                  {"best", dv_cli_best},         {"attribute", dv_cli_attribute},
                  {"map", dv_cli_map},           {"engines", dv_cli_engines},
                  {"verify", dv_cli_verify},     {"generate", dv_cli_generate},
                  {"league", dv_cli_league}};
  gsl_set_error_handler_off();
  dv_io_temp_clean_on_signals(); /* a run ended by SIGINT or SIGTERM leaves no temporary */
  dv_child_adopt_orphans();      /* what an adapter starts outlives no guard of its either */
  dv_exec_mpi_init(&argc, &argv);
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    if (argc < 2) return fputs(HELP, stderr), DV_EXIT_ERROR;
    fputs(HELP, stdout);
    if (fflush(stdout) || ferror(stdout)) /* e.g. > /dev/full */
      return fprintf(stderr, "diskval: cannot write the output: %s\n", strerror(errno)),
             DV_EXIT_ERROR;
    return DV_EXIT_OK;
  }
  for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
    if (!strcmp(argv[1], commands[i].name)) {
      int code = commands[i].run(argc - 1, argv + 1);
      /* e.g. > /dev/full: the output is lost (said once: a failed command has said why) */
      if ((fflush(stdout) || ferror(stdout)) && code != DV_EXIT_ERROR)
        code = dv_cli_error(argv[1], "cannot write the output: %s", strerror(errno));
      dv_exec_mpi_finalize();
      return code;
    }
  dv_exec_mpi_finalize();
  fprintf(stderr, "diskval: unknown command '%s' (see diskval --help)\n", argv[1]);
  return DV_EXIT_ERROR;
}
