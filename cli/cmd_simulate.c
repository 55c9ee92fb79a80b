/* dv_cli_simulate: diskval simulate SCENARIO --engine NAME [--set k=v] [--out FILE]. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "dv_engine.h"
#include "run_meta.h"
#include "io_file.h"
#include "run_trajectory.h"

static const char HELP[] =
    "usage: diskval simulate SCENARIO --engine NAME [--set section.key=value]... [--out FILE]\n"
    "                        [--forces FILE]\n"
    "\n"
    "Simulate SCENARIO with one engine and write its trajectory as CSV:\n"
    "  " DV_CSV_HEADER
    "\n"
    "one row every output_dt (and a last row where an event ends the run).\n"
    "  --engine NAME   engine to run (diskval engines lists them)\n"
    "  --set S.K=V     override key K of section S, e.g. --set engines.reduced.rtol=1e-10\n"
    "  --out FILE      write to FILE (default, or '-': stdout); written whole or not at all,\n"
    "                  with FILE.json beside it: engine, versions, settings, outcome, stats\n"
    "  --forces FILE   the contact force along the run (references: the force rolling needs)\n"
    "                  as t,force_x,force_y,force_z,friction_ratio (N; NaN where unknown)\n"
    "A run that fails (diverged, lost contact, library error) exits 2 and writes no CSV.\n";

int dv_cli_usage_error(const char *command, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "diskval %s: ", command);
  vfprintf(stderr, fmt, ap);
  fprintf(stderr, " (see diskval %s --help)\n", command);
  va_end(ap);
  return DV_EXIT_ERROR;
}

int dv_cli_take_set(dv_common_args *a, int argc, char **argv, int *i) {
  if (strcmp(argv[*i], "--set") != 0) return 0;
  if (*i + 1 >= argc || a->nsets == (int)(sizeof a->sets / sizeof a->sets[0])) return -1;
  a->sets[a->nsets++] = argv[++*i];
  return 1;
}

int dv_cli_simulate(int argc, char **argv) {
  dv_common_args a = {0};
  const char *engine_name = NULL, *out_path = "-", *forces_path = NULL;
  for (int i = 1; i < argc; i++) {
    const int set = dv_cli_take_set(&a, argc, argv, &i);
    if (set < 0) return dv_cli_usage_error("simulate", "--set needs section.key=value");
    if (set) continue;
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      fputs(HELP, stdout);
      return DV_EXIT_OK;
    } else if (!strcmp(argv[i], "--engine") && i + 1 < argc) {
      engine_name = argv[++i];
    } else if (!strcmp(argv[i], "--out") && i + 1 < argc) {
      out_path = argv[++i];
    } else if (!strcmp(argv[i], "--forces") && i + 1 < argc) {
      forces_path = argv[++i];
    } else if (argv[i][0] == '-' && argv[i][1]) {
      return dv_cli_usage_error("simulate", "unknown or incomplete option '%s'", argv[i]);
    } else if (!a.scenario) {
      a.scenario = argv[i];
    } else {
      return dv_cli_usage_error("simulate", "more than one scenario given");
    }
  }
  if (!a.scenario) return dv_cli_usage_error("simulate", "no scenario given");
  if (!engine_name) return dv_cli_usage_error("simulate", "no --engine given");
  const dv_engine_type *engine = dv_engine_find(engine_name);
  if (!engine) return dv_cli_usage_error("simulate", "unknown engine '%s'", engine_name);

  static dv_scenario sc;
  dv_error err = {{0}};
  if (dv_engine_load_scenario(a.scenario, a.sets, (size_t)a.nsets, &sc, &err)) {
    fprintf(stderr, "%s\n", err.msg);
    return DV_EXIT_ERROR;
  }
  dv_io_file out, forces = {0};
  if (dv_io_open(&out, out_path, &err) ||
      (forces_path && dv_io_open(&forces, forces_path, &err))) {
    dv_io_abort(&out);
    fprintf(stderr, "diskval simulate: %s\n", err.msg);
    return DV_EXIT_ERROR;
  }
  dv_engine_stats stats;
  int status = dv_run_write_csv(engine, &sc, out.fp, forces.fp, &stats, &err);
  if (status < 0) {
    dv_io_abort(&out);
    dv_io_abort(&forces);
    fprintf(stderr, "diskval simulate: %s: %s: %s: %s\n", sc.name, engine->name,
            dv_outcome_name(stats.outcome), err.msg);
    return DV_EXIT_ERROR;
  }
  if (dv_io_commit(&out, &err) || (forces_path && dv_io_commit(&forces, &err))) {
    dv_io_abort(&forces);
    fprintf(stderr, "diskval simulate: %s\n", err.msg);
    return DV_EXIT_ERROR;
  }
  if (strcmp(out_path, "-") != 0 && !out.direct) { /* metadata beside a regular file */
    char meta[1100];
    snprintf(meta, sizeof meta, "%s.json", out_path);
    if (dv_run_meta_write(meta, engine, &sc, &stats, &err)) {
      fprintf(stderr, "diskval simulate: %s\n", err.msg);
      return DV_EXIT_ERROR;
    }
  }
  if (status == DV_EVENT)
    fprintf(stderr, "diskval simulate: %s: %s: the run ended early: %s\n", sc.name, engine->name,
            stats.detail);
  return DV_EXIT_OK;
}
