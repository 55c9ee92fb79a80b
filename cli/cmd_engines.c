/* dv_cli_engines: diskval engines: every engine, its library version and
 * its settings table (key, default, range or choices, unit, what it is). */
#include <math.h>
#include <stdio.h>

#include "cli.h"
#include "cli_args.h"
#include "dv_engine.h"
#include "red_solver.h"

static const char HELP[] =
    "usage: diskval engines\n\nList the engines, their library versions and settings\n"
    "([engines.NAME] KEY = VALUE in a scenario, or --set engines.NAME.KEY=VALUE), and\n"
    "the reference's integrators.\n";

/* one setting: key, default, range or choices, unit and what it is */
static void print_setting(const dv_setting_spec *sp) {
  printf("    %-20s default ", sp->key);
  if (sp->type == DV_SETTING_CHOICE) {
    printf("%-10s (", dv_setting_choice(sp, (size_t)sp->def));
    for (size_t j = 0; dv_setting_choice(sp, j); j++)
      printf("%s%s", j ? ", " : "", dv_setting_choice(sp, j));
    printf(")");
  } else {
    char range[96];
    dv_setting_range_text(sp, range, sizeof range);
    if (isnan(sp->def)) /* the engine derives it from the scene */
      printf("%-10s %s", "(scene)", range);
    else
      printf("%-10g %s", sp->def, range);
  }
  printf("%s%s%s%s\n", sp->unit[0] || sp->doc[0] ? "  " : "", sp->unit,
         sp->unit[0] && sp->doc[0] ? ", " : "", sp->doc);
}

int dv_cli_engines(int argc, char **argv) {
  const dv_cli_command cmd = {"engines", HELP, NULL, 0, 0, 0};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_cli_args_free(&cmd, &a);
  for (const dv_engine_type *const *e = dv_engines; *e; e++) {
    printf("%-10s %s [%s]\n", (*e)->name, (*e)->description, (*e)->version());
    for (size_t i = 0; (*e)->settings && i < (*e)->settings->nspecs; i++)
      print_setting(&(*e)->settings->specs[i]);
  }
  printf("\nreference integrators (default %s):\n", red_stepper_default()->name);
  for (const red_stepper_type *const *t = red_steppers; *t; t++)
    printf("  %-20s %s\n", (*t)->name, (*t)->description);
  return DV_EXIT_OK;
}
