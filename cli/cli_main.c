/* diskval: cross-validation of rolling-disk simulations against the reduced
 * equations. The entry point dispatches to the subcommands. */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "exec_mpi.h"
#include "dv_engine.h"
#include "scenario.h"
#include "red_solver.h"

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
    "  suite DIR|FILES... [--out DIR] [--junit FILE] [--jobs N]   many scenarios, reports\n"
    "  sweep SCENARIO --engine NAME --vary KEY=VALUES speed against error over settings\n"
    "  best SCENARIO --engine NAME --theta-tol X      the cheapest settings meeting X\n"
    "  attribute SCENARIO --engine NAME               why an engine disagrees, in shares\n"
    "  map [--c A..B:N] [--spin A..B:N]               stability map of upright rolling\n"
    "  engines                                        the engines and integrators\n";

int dv_cli_engines(int argc, char **argv) {
  if (argc > 1 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
    puts(
        "usage: diskval engines\n\nList the engines, their library versions and the\n"
        "reference's integrators ([engines.reduced] integrator = NAME).");
    return DV_EXIT_OK;
  }
  for (const dv_engine_type *const *e = dv_engines; *e; e++) {
    printf("%-10s %s [%s]\n", (*e)->name, (*e)->description, (*e)->version());
    for (size_t i = 0; (*e)->settings && i < (*e)->settings->nspecs; i++) {
      const dv_setting_spec *sp = &(*e)->settings->specs[i];
      char range[96];
      printf("    %-20s default ", sp->key);
      if (sp->type == DV_SETTING_CHOICE) {
        printf("%-10s (", dv_setting_choice(sp, (size_t)sp->def));
        for (size_t j = 0; dv_setting_choice(sp, j); j++)
          printf("%s%s", j ? ", " : "", dv_setting_choice(sp, j));
        printf(")");
      } else {
        dv_setting_range_text(sp, range, sizeof range);
        printf("%-10g %s", sp->def, range);
      }
      printf("%s%s%s%s\n", sp->unit[0] || sp->doc[0] ? "  " : "", sp->unit,
             sp->unit[0] && sp->doc[0] ? ", " : "", sp->doc);
    }
  }
  printf("\nreference integrators (default %s):\n", red_stepper_default()->name);
  for (const red_stepper_type *const *t = red_steppers; *t; t++)
    printf("  %-20s %s\n", (*t)->name, (*t)->description);
  return DV_EXIT_OK;
}

int main(int argc, char **argv) {
  static const struct {
    const char *name;
    int (*run)(int, char **);
  } commands[] = {
      {"simulate", dv_cli_simulate},   {"analyze", dv_cli_analyze}, {"compare", dv_cli_compare},
      {"suite", dv_cli_suite},         {"sweep", dv_cli_sweep},     {"best", dv_cli_best},
      {"attribute", dv_cli_attribute}, {"map", dv_cli_map},         {"engines", dv_cli_engines}};
  gsl_set_error_handler_off();
  dv_exec_mpi_init(&argc, &argv);
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    fputs(HELP, argc < 2 ? stderr : stdout);
    return argc < 2 ? DV_EXIT_ERROR : DV_EXIT_OK;
  }
  for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
    if (!strcmp(argv[1], commands[i].name)) {
      const int code = commands[i].run(argc - 1, argv + 1);
      dv_exec_mpi_finalize();
      return code;
    }
  dv_exec_mpi_finalize();
  fprintf(stderr, "diskval: unknown command '%s' (see diskval --help)\n", argv[1]);
  return DV_EXIT_ERROR;
}
