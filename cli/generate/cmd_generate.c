/* dv_cli_generate: diskval generate --seed N --count K --out DIR: real
 * objects drawn at random (engine_generate.h), one scenario file each. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
    "wrote; a file of those names that diskval did not write, or one edited since\n"
    "it wrote it, is an error and nothing is written.\n"
    "\n"
    "options:\n"
    "  --seed N       the seed, 0 to 2147483647\n"
    "  --count K      how many scenes, 1 to 100000\n"
    "  --first I      the index of the first scene (default 0)\n"
    "  --gravity G    m/s^2 (default 9.81)\n"
    "  --out DIR      where the files go\n";

/* what this run writes: scene first + i of seed at gravity */
typedef struct gen_run {
  int seed, first;
  double gravity;
  dv_scenario *sc;
} gen_run;

/* the text of scene i of r into text (size bytes): its length, or -1 (err) */
static int scene_text(const gen_run *r, size_t i, char *text, size_t size, dv_error *err) {
  dv_gen_scene g;
  if (dv_engine_generate((uint64_t)r->seed, (size_t)r->first + i, r->gravity, &g, r->sc, err))
    return -1;
  const int len = dv_engine_generate_ini(&g, text, size);
  if (len >= 0 && (size_t)len < size) return len;
  snprintf(err->msg, sizeof err->msg, "a scene's text is too long");
  return -1;
}

/* bytes are what this run writes as scene i (dv_io_same_fn) */
static int writes_same(size_t i, const char *bytes, size_t len, void *arg) {
  char text[2048];
  dv_error err = {{0}};
  const int n = scene_text(arg, i, text, sizeof text, &err);
  return n >= 0 && (size_t)n == len && !memcmp(text, bytes, len);
}

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
  static dv_scenario sc;
  gen_run run = {seed, first, gravity, &sc};
  /* the scenes are checked, not run: no engine's settings are probed */
  if (!code) dv_cli_probe_only(dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE));
  /* a scene diskval wrote here and the user edited since is kept: refused */
  if (!code && (dv_io_check_unedited(out, (const char *const *)names, writes_same, &run, &err) ||
                dv_io_own_dir(out, (const char *const *)names, &err)))
    code = dv_cli_error("generate", "%s", err.msg);
  /* the scenes in chunks (at most 17 rewrites of the mark): each chunk's
   * digests go into the mark beside the old ones before its files are
   * written, so that a run stopped between leaves every file known */
  const size_t chunk = n / 16 >= 256 ? n / 16 + 1 : 256;
  uint64_t *digests = code ? NULL : calloc(n, sizeof *digests);
  char(*texts)[2048] = code ? NULL : malloc((n < chunk ? n : chunk) * sizeof *texts);
  if (!code && (!digests || !texts)) code = dv_cli_error("generate", "out of memory");
  const int taken = !code;
  size_t written = 0;
  for (size_t at = 0; !code && at < n; at += chunk) {
    const size_t m = n - at < chunk ? n - at : chunk;
    for (size_t k = 0; !code && k < m; k++) {
      const int len = scene_text(&run, at + k, texts[k], sizeof texts[k], &err);
      if (len < 0)
        code = dv_cli_error("generate", "%s", err.msg);
      else
        digests[at + k] = dv_io_digest(texts[k], (size_t)len);
    }
    if (!code && dv_io_mark_sums(out, (const char *const *)names + at, digests + at, m, 1, &err))
      code = dv_cli_error("generate", "%s", err.msg);
    for (size_t k = 0; !code && k < m; k++) {
      if (dv_io_write_text(out, names[at + k], texts[k], &err))
        code = dv_cli_error("generate", "%s", err.msg);
      else
        written++;
    }
  }
  /* what was written is recorded alone: the old digests of those files go */
  if (taken && dv_io_mark_sums(out, (const char *const *)names, digests, written, 0, &err) && !code)
    code = dv_cli_error("generate", "%s", err.msg);
  free(texts);
  free(digests);
  if (names)
    for (size_t i = 0; i < n; i++) free(names[i]);
  free(names);
  if (!code) printf("%zu scenes in %s (seed %d, from %d)\n", n, out, seed, first);
  dv_cli_args_free(&cmd, &a);
  return code;
}
