/* dv_cli_generate: diskval generate --seed N --count K --out DIR: real
 * objects drawn at random (engine_generate.h), one scenario file each. */
#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "cli_args.h"
#include "dv_engine.h"
#include "engine_generate.h"
#include "io_file.h"
#include "io_owned.h"

static const char HELP[] =
    "usage: diskval generate --seed N --count K --out DIR [--first I] [--gravity G]\n"
    "\n"
    "Write K scenario files DIR/gen-N-I.ini (I from --first, default 0): real\n"
    "objects drawn from the seed N, the same files for the same N and I on every\n"
    "machine. Radii from a coin (8 mm) to a wheel (0.35 m), thin or a cylinder up\n"
    "to thickness / (2 r) = 0.6, moments from an axle-heavy wheel to a hoop\n"
    "(C up to 2A), friction 0.3 to 2; started on a steady circle of 2 r to 100 r,\n"
    "falling from near upright, nutating or spinning fast; 2 to 6 fall periods.\n"
    "Every file is checked as a load checks it. DIR is new, empty or one diskval\n"
    "wrote; a file of those names that diskval did not write is an error.\n"
    "\n"
    "options:\n"
    "  --seed N       the seed, 0 to 2147483647\n"
    "  --count K      how many scenes, 1 to 100000\n"
    "  --first I      the index of the first scene (default 0)\n"
    "  --gravity G    m/s^2 (default 9.81)\n"
    "  --out DIR      where the files go\n";

int dv_cli_generate(int argc, char **argv) {
  int seed = -1, count = 0, first = 0;
  double gravity = 9.81;
  const char *out = NULL;
  const dv_cli_option options[] = {
      {"seed", DV_CLI_INT, &seed, 0, 2147483647.0},
      {"count", DV_CLI_INT, &count, 1, 100000},
      {"first", DV_CLI_INT, &first, 0, 2147483647.0},
      {"gravity", DV_CLI_REAL, &gravity, 1e-3, 1e3},
      {"out", DV_CLI_TEXT, &out, 0, 0},
  };
  const dv_cli_command cmd = {"generate", HELP, options, 5, 0, 0};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  int code = DV_EXIT_OK;
  if (seed < 0)
    code = dv_cli_usage_error("generate", "--seed is required");
  else if (!count)
    code = dv_cli_usage_error("generate", "--count is required");
  else if (!out || !*out)
    code = dv_cli_usage_error("generate", "--out is required");
  else if (a.sets.n)
    code = dv_cli_usage_error("generate", "--set does not apply to generate");
  const size_t n = (size_t)count;
  char **names = code ? NULL : calloc(n + 1, sizeof *names);
  if (!code && !names) code = dv_cli_error("generate", "out of memory");
  dv_error err = {0};
  /* every name first: the directory is taken (or refused) before anything is written */
  for (size_t i = 0; !code && i < n; i++) {
    char buf[64];
    snprintf(buf, sizeof buf, "gen-%d-%zu.ini", seed, (size_t)first + i);
    if (!(names[i] = malloc(sizeof buf)))
      code = dv_cli_error("generate", "out of memory");
    else
      snprintf(names[i], sizeof buf, "%s", buf);
  }
  if (!code && dv_io_own_dir(out, (const char *const *)names, &err))
    code = dv_cli_error("generate", "%s", err.msg);
  static dv_scenario sc;
  /* the scenes are checked, not run: no engine's settings are probed */
  if (!code) dv_cli_probe_only(dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE));
  for (size_t i = 0; !code && i < n; i++) {
    dv_gen_scene g;
    char text[2048];
    if (dv_engine_generate((uint64_t)seed, (size_t)first + i, gravity, &g, &sc, &err) ||
        dv_engine_generate_ini(&g, text, sizeof text) >= (int)sizeof text ||
        dv_io_write_text(out, names[i], text, &err))
      code = dv_cli_error("generate", "%s", err.msg[0] ? err.msg : "a scene's text is too long");
  }
  if (names)
    for (size_t i = 0; i < n; i++) free(names[i]);
  free(names);
  if (!code) printf("%zu scenes in %s (seed %d, from %d)\n", n, out, seed, first);
  dv_cli_args_free(&cmd, &a);
  return code;
}
