/* dv_cli_engines: diskval engines: every engine, its library version and
 * its settings table (key, default, range or choices, unit, what it is). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "adapter.h"
#include "cli.h"
#include "cli_args.h"
#include "dv_engine.h"
#include "red_solver.h"

static const char HELP[] =
    "usage: diskval engines [--scene SCENARIO NAME]\n\n"
    "List the engines, their library versions and settings\n"
    "([engines.NAME] KEY = VALUE in a scenario, or --set engines.NAME.KEY=VALUE), and\n"
    "the reference's integrators. Engines outside the build (adapters: the source tree's\n"
    "adapters/ and the folders DISKVAL_ADAPTERS lists) say where they are, or why they\n"
    "cannot run; they run only where named (--engines, [scenario] engines).\n"
    "  --scene S NAME  print the lines adapter NAME is sent for scenario S, up to 'start'\n"
    "                  (docs/adapters.md): run an adapter by hand with them\n";

/* the scene's lines for adapter name in scenario path, as a run sends them */
static int print_scene(const char *path, const char *name, const dv_cli_list *sets) {
  const dv_engine_type *e = dv_engine_find(name);
  const dv_adapter *a = e ? dv_adapter_of(e) : NULL;
  if (!a) return dv_cli_error("engines", "'%s' is no adapter (diskval engines lists them)", name);
  const dv_engine_type *const only[] = {e, NULL};
  dv_engine_choose_only(only);
  dv_scenario *sc = malloc(sizeof *sc);
  char text[8192];
  dv_error err;
  if (!sc) return dv_cli_error("engines", "out of memory");
  int status = dv_cli_load_scenario("engines", path, sets, sc, &err);
  if (status != DV_OK)
    status = dv_cli_error("engines", "%s", err.msg);
  else if (dv_adapter_scene_text(a, sc, NULL, text, sizeof text, &err))
    status = dv_cli_error("engines", "%s", err.msg);
  if (status == DV_OK) fputs(text, stdout);
  free(sc);
  return status == DV_OK ? DV_EXIT_OK : status;
}

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
  const char *scene = NULL;
  const dv_cli_option options[] = {{"scene", DV_CLI_TEXT, &scene, 0, 0}};
  const dv_cli_command cmd = {"engines", HELP, options, 1, 0, 1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  if (scene || a.args.n) {
    const int status =
        !scene ? dv_cli_usage_error("engines", "unexpected argument '%s'", a.args.items[0])
        : a.args.n == 1 ? print_scene(scene, a.args.items[0], &a.sets)
                        : dv_cli_usage_error("engines", "--scene SCENARIO NAME: give the NAME");
    dv_cli_args_free(&cmd, &a);
    return status;
  }
  dv_cli_args_free(&cmd, &a);
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++) {
    const dv_adapter *ad = dv_adapter_of(*e);
    const char *why = dv_engine_unavailable(*e); /* a module missing or broken, an adapter's program */
    if (why)
      printf("%-10s %s [not available: %s]\n", (*e)->name, (*e)->description, why);
    else
      printf("%-10s %s [%s]\n", (*e)->name, (*e)->description, (*e)->version());
    if (ad) printf("    (outside the build: %s, run as: %s)\n", ad->dir, ad->command);
    for (size_t i = 0; (*e)->settings && i < (*e)->settings->nspecs; i++)
      print_setting(&(*e)->settings->specs[i]);
  }
  if (dv_adapter_problems()[0])
    printf("\nadapters that cannot be read:\n%s", dv_adapter_problems());
  printf("\nreference integrators (default %s):\n", red_stepper_default()->name);
  for (const red_stepper_type *const *t = red_steppers; *t; t++)
    printf("  %-20s %s\n", (*t)->name, (*t)->description);
  return DV_EXIT_OK;
}
