/* dv_cli_sweep: diskval sweep (speed against error over a grid of settings)
 * and diskval best (the cheapest settings that meet a theta tolerance). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "exec_mpi.h"
#include "search_best.h"
#include "report_suite_run.h"
#include "search_sweep.h"

static const char SWEEP_HELP[] =
    "usage: diskval sweep SCENARIO --engine NAME --vary KEY=VALUES [--vary ...] [--out DIR]\n"
    "                     [--jobs N] [--set section.key=value]...\n"
    "\n"
    "Run SCENARIO in one engine at every point of a grid of settings and record the\n"
    "error against the reference and the cost (wall seconds per simulated second).\n"
    "VALUES is a list, v1,v2,..., or a log range, a..b:n (timestep=1e-2..1e-5:10);\n"
    "KEY is a key of [engines.NAME] or section.key. Writes DIR (default: sweep):\n"
    "sweep.csv (pareto = 1 where no point is both cheaper and more accurate),\n"
    "sweep.json (with the fitted order of convergence of each curve),\n"
    "work_precision.svg (with the reference's integrators over rtol 1e-6..1e-13) and,\n"
    "when a timestep varies, error_vs_timestep.svg.\n";

static const char BEST_HELP[] =
    "usage: diskval best SCENARIO --engine NAME --theta-tol X [--set section.key=value]...\n"
    "\n"
    "Search the engine's settings (its integrator or stepper, and its timestep; the\n"
    "reference: integrator and rtol) for the cheapest run whose max theta error is\n"
    "at most X rad: from the default step, double or halve until the answer changes,\n"
    "then bisect six times on a log scale, for each integrator. Prints every probe\n"
    "and the winner. Exit status 1 when no probe meets X.\n";

int dv_cli_sweep(int argc, char **argv) {
  dv_common_args a = {0};
  const char *engine = NULL, *out = "sweep";
  static dv_vary vary[DV_SWEEP_MAX_VARY];
  const char *specs[DV_SWEEP_MAX_VARY];
  size_t nvary = 0;
  int jobs = (int)sysconf(_SC_NPROCESSORS_ONLN);
  for (int i = 1; i < argc; i++) {
    const int set = dv_cli_take_set(&a, argc, argv, &i);
    if (set < 0) return dv_cli_usage_error("sweep", "--set needs section.key=value");
    if (set) continue;
    const int has = i + 1 < argc;
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h"))
      return fputs(SWEEP_HELP, stdout), DV_EXIT_OK;
    else if (!strcmp(argv[i], "--engine") && has)
      engine = argv[++i];
    else if (!strcmp(argv[i], "--out") && has)
      out = argv[++i];
    else if (!strcmp(argv[i], "--jobs") && has)
      jobs = atoi(argv[++i]);
    else if (!strcmp(argv[i], "--vary") && has && nvary < DV_SWEEP_MAX_VARY)
      specs[nvary++] = argv[++i];
    else if (argv[i][0] == '-' && argv[i][1])
      return dv_cli_usage_error("sweep", "unknown or incomplete option '%s'", argv[i]);
    else if (!a.scenario)
      a.scenario = argv[i];
    else
      return dv_cli_usage_error("sweep", "more than one scenario given");
  }
  if (!a.scenario || !engine || !nvary)
    return dv_cli_usage_error("sweep", "needs SCENARIO, --engine and at least one --vary");
  if (jobs < 1 || jobs > 1024) return dv_cli_usage_error("sweep", "--jobs takes 1 to 1024");
  dv_error err = {{0}};
  for (size_t v = 0; v < nvary; v++)
    if (dv_search_vary_parse(specs[v], engine, &vary[v], &err))
      return dv_cli_usage_error("sweep", "%s", err.msg);
  static dv_sweep s, ref;
  if (dv_exec_mpi_size() > 1) { /* rank 0 keeps the tables current as results arrive */
    if (dv_exec_mpi_rank() == 0 && dv_io_make_dirs(out, &err))
      return fprintf(stderr, "diskval sweep: %s\n", err.msg), DV_EXIT_ERROR;
    s.checkpoint_dir = out;
  }
  const int run =
      dv_search_sweep_run(a.scenario, a.sets, (size_t)a.nsets, engine, vary, nvary, jobs, &s, &err);
  if (run < 0) {
    fprintf(stderr, "%s\n", err.msg);
    return DV_EXIT_ERROR;
  }
  /* the reference's curves; not after an interrupted MPI run, whose ranks are going */
  const int with_ref = strcmp(engine, "reduced") && strcmp(engine, "matched") && !s.interrupted;
  if (with_ref) { /* the reference's own work-precision curves */
    dv_vary rv[2];
    dv_search_vary_parse(
        "integrator=gsl-rk8pd,gsl-rk8pd-stepped,gsl-msadams,cvode-adams,cvode-bdf,arkode-"
        "fehlberg13",
        "reduced", &rv[0], &err);
    dv_search_vary_parse("rtol=1e-6..1e-13:8", "reduced", &rv[1], &err);
    dv_search_sweep_run(a.scenario, a.sets, (size_t)a.nsets, "reduced", rv, 2, jobs, &ref, &err);
  }
  if (dv_exec_mpi_rank() != 0) return DV_EXIT_OK; /* rank 0 writes */
  int status = dv_io_make_dirs(out, &err);
  if (!status) status = dv_search_sweep_write(out, &s, with_ref ? &ref : NULL, &err);
  printf("%-40s %12s %12s %8s %s\n", "settings", "theta err", "s / sim s", "pareto", "outcome");
  for (size_t k = 0; k < s.n; k++) {
    char label[160] = "";
    for (size_t v = 0; v < nvary; v++)
      snprintf(label + strlen(label), sizeof label - strlen(label), "%s%s", v ? " " : "",
               s.p[k].values[v]);
    printf("%-40s %12.3e %12.4g %8s %s\n", label, s.p[k].metric[DV_THETA_MAX_ERR],
           s.p[k].wall_per_sim_s, s.p[k].pareto ? "*" : "", dv_run_verdict_name(s.p[k].verdict));
  }
  const int interrupted = s.interrupted;
  dv_search_sweep_free(&s);
  dv_search_sweep_free(&ref);
  s.interrupted = interrupted;
  if (status) return fprintf(stderr, "diskval sweep: %s\n", err.msg), DV_EXIT_ERROR;
  printf("sweep: %s/sweep.csv, %s/work_precision.svg\n", out, out);
  if (s.interrupted) {
    fprintf(stderr, "diskval sweep: stopped early: the points not run are marked missing\n");
    return DV_EXIT_ERROR;
  }
  return DV_EXIT_OK;
}

int dv_cli_best(int argc, char **argv) {
  dv_common_args a = {0};
  const char *engine = NULL;
  double tol = NAN;
  for (int i = 1; i < argc; i++) {
    const int set = dv_cli_take_set(&a, argc, argv, &i);
    if (set < 0) return dv_cli_usage_error("best", "--set needs section.key=value");
    if (set) continue;
    const int has = i + 1 < argc;
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h"))
      return fputs(BEST_HELP, stdout), DV_EXIT_OK;
    else if (!strcmp(argv[i], "--engine") && has)
      engine = argv[++i];
    else if (!strcmp(argv[i], "--theta-tol") && has)
      tol = strtod(argv[++i], NULL);
    else if (argv[i][0] == '-' && argv[i][1])
      return dv_cli_usage_error("best", "unknown or incomplete option '%s'", argv[i]);
    else if (!a.scenario)
      a.scenario = argv[i];
    else
      return dv_cli_usage_error("best", "more than one scenario given");
  }
  if (!a.scenario || !engine || !(tol > 0.0))
    return dv_cli_usage_error("best", "needs SCENARIO, --engine and --theta-tol X > 0");
  static dv_search s;
  dv_error err = {{0}};
  if (dv_search_best(a.scenario, a.sets, (size_t)a.nsets, engine, tol, &s, &err)) {
    fprintf(stderr, "%s\n", err.msg);
    return DV_EXIT_ERROR;
  }
  printf("%-20s %12s %12s %12s %s\n", "choice", "step", "theta err", "s / sim s", "outcome");
  for (size_t i = 0; i < s.nprobes; i++) {
    const dv_probe *p = &s.probes[i];
    printf("%-20s %12.4g %12.3e %12.4g %s%s\n", p->choice, p->step,
           p->point.metric[DV_THETA_MAX_ERR], p->point.wall_per_sim_s, dv_run_verdict_name(p->point.verdict),
           p->pass ? "" : " (fails)");
  }
  if (s.best < 0) {
    printf("no probe meets theta error <= %g rad\n", tol);
    return DV_EXIT_FAIL;
  }
  const dv_probe *b = &s.probes[s.best];
  printf("best: --set %s=%s --set %s=%.9g: theta error %.3e rad at %.4g s per simulated s\n",
         s.choice_key, b->choice, s.step_key, b->step, b->point.metric[DV_THETA_MAX_ERR],
         b->point.wall_per_sim_s);
  return DV_EXIT_OK;
}
