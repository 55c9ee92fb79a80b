/* dv_cli_suite: diskval compare SCENARIO ... and diskval suite DIR|FILES ...:
 * run scenarios through the engines and the references and write reports. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "exec_mpi.h"
#include "run_scenario.h"
#include "search_stability.h"
#include "report_suite_run.h"
#include "report_suite.h"

static const char COMPARE_HELP[] =
    "usage: diskval compare SCENARIO [--engines LIST] [--out DIR] [--set section.key=value]...\n"
    "\n"
    "Run SCENARIO in the engines (default: mujoco,ode) and in the references, compare\n"
    "theta(t) and the contact path, check the scenario's tolerances, and write\n"
    "DIR/<scenario>/ (default DIR: report): every trajectory as CSV, the plots,\n"
    "report.json and report.md. Prints one line per engine.\n"
    "Exit status: 0 all pass, 1 a tolerance or outcome failed, 2 bad input or error.\n";

static const char SUITE_HELP[] =
    "usage: diskval suite DIR|FILES... [--out DIR] [--junit FILE] [--jobs N] [--engines LIST]\n"
    "                     [--stability]\n"
    "\n"
    "Compare every scenario (the *.ini files of each DIR, and each FILE) as diskval\n"
    "compare does, N at a time in separate processes (default: the number of cores),\n"
    "then write DIR/index.html, DIR/summary.json and the JUnit XML (default\n"
    "DIR/junit.xml). Every scenario file is checked before anything is written.\n"
    "--stability also finds, per scenario and engine, the largest timestep that stays\n"
    "finite and within the scenario's theta tolerance (bisection), and the failure\n"
    "above it: DIR/stability.html, .md and .json, linked from index.html.\n"
    "Exit status: 0 all pass, 1 a tolerance or outcome failed, 2 bad input or error.\n";

#define MAX_SCENARIOS 256

typedef struct suite_args {
  const char *paths[MAX_SCENARIOS];
  size_t npaths;
  const char *out, *junit, *engines;
  int jobs;
  int stability; /* also the largest stable timesteps and failure modes */
  dv_common_args common;
} suite_args;

static int by_name(const void *a, const void *b) {
  return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* the .ini files of dir, sorted, appended to files (strings owned by the caller) */
static int list_dir(const char *dir, char **files, size_t *n, size_t max) {
  DIR *d = opendir(dir);
  if (!d) return -1;
  const size_t first = *n;
  for (struct dirent *e; (e = readdir(d));) {
    const size_t len = strlen(e->d_name);
    if (len < 5 || strcmp(e->d_name + len - 4, ".ini") || *n == max) continue;
    files[*n] = malloc(strlen(dir) + len + 2);
    if (!files[*n]) break;
    sprintf(files[*n], "%s/%s", dir, e->d_name);
    (*n)++;
  }
  closedir(d);
  qsort(files + first, *n - first, sizeof *files, by_name);
  return 0;
}

static int parse(const char *cmd, int argc, char **argv, suite_args *a, int *done) {
  memset(a, 0, sizeof *a);
  a->out = "report";
  a->engines = "mujoco,ode";
  a->jobs = (int)sysconf(_SC_NPROCESSORS_ONLN);
  *done = 0;
  for (int i = 1; i < argc; i++) {
    const int set = dv_cli_take_set(&a->common, argc, argv, &i);
    if (set < 0) return dv_cli_usage_error(cmd, "--set needs section.key=value");
    if (set) continue;
    const int has = i + 1 < argc;
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      fputs(!strcmp(cmd, "suite") ? SUITE_HELP : COMPARE_HELP, stdout);
      *done = 1;
      return DV_EXIT_OK;
    } else if (!strcmp(argv[i], "--out") && has) {
      a->out = argv[++i];
    } else if (!strcmp(argv[i], "--engines") && has) {
      a->engines = argv[++i];
    } else if (!strcmp(cmd, "suite") && !strcmp(argv[i], "--stability")) {
      a->stability = 1;
    } else if (!strcmp(cmd, "suite") && !strcmp(argv[i], "--junit") && has) {
      a->junit = argv[++i];
    } else if (!strcmp(cmd, "suite") && !strcmp(argv[i], "--jobs") && has) {
      char *end;
      const long j = strtol(argv[++i], &end, 10);
      if (*end || j < 1 || j > 1024)
        return dv_cli_usage_error(cmd, "--jobs takes a number from 1 to 1024");
      a->jobs = (int)j;
    } else if (argv[i][0] == '-' && argv[i][1]) {
      return dv_cli_usage_error(cmd, "unknown or incomplete option '%s'", argv[i]);
    } else if (a->npaths < MAX_SCENARIOS) {
      a->paths[a->npaths++] = argv[i];
    }
  }
  if (!a->npaths) return dv_cli_usage_error(cmd, "no scenario given");
  if (!strcmp(cmd, "compare") && a->npaths > 1)
    return dv_cli_usage_error(cmd, "one scenario at a time");
  if (a->jobs < 1) a->jobs = 1;
  return DV_EXIT_OK;
}

/* load every scenario first: any bad file ends the command before output */
static int load_all(const char *cmd, suite_args *a, dv_scenario *scs, size_t *n) {
  char *files[MAX_SCENARIOS];
  size_t nfiles = 0;
  int code = DV_EXIT_OK;
  for (size_t i = 0; i < a->npaths; i++) {
    struct stat st;
    if (!strcmp(cmd, "suite") && stat(a->paths[i], &st) == 0 && S_ISDIR(st.st_mode)) {
      if (list_dir(a->paths[i], files, &nfiles, MAX_SCENARIOS))
        code = dv_cli_usage_error(cmd, "cannot read directory %s", a->paths[i]);
    } else if (nfiles < MAX_SCENARIOS) {
      files[nfiles++] = strdup(a->paths[i]);
    }
  }
  *n = 0;
  for (size_t i = 0; i < nfiles; i++) {
    dv_error err = {{0}};
    if (code == DV_EXIT_OK &&
        dv_engine_load_scenario(files[i], a->common.sets, (size_t)a->common.nsets, &scs[*n], &err)) {
      fprintf(stderr, "%s\n", err.msg);
      code = DV_EXIT_ERROR;
    }
    for (size_t k = 0; code == DV_EXIT_OK && k < *n; k++)
      if (!strcmp(scs[k].name, scs[*n].name))
        code = dv_cli_usage_error(cmd, "%s and %s both name their scenario '%s'", scs[k].path, files[i],
                              scs[k].name);
    if (code == DV_EXIT_OK) (*n)++;
    free(files[i]);
  }
  if (code == DV_EXIT_OK && !*n) code = dv_cli_usage_error(cmd, "no scenario files found");
  return code;
}

typedef struct mpi_suite {
  const dv_scenario *scs;
  const dv_engine_type *const *engines;
  const char *out;
} mpi_suite;

/* dv_exec_mpi_farm's task: one scenario into its report directory; its exit code */
static void run_scenario_task(size_t k, void *result, void *ctx) {
  const mpi_suite *ms = ctx;
  dv_error e = {{0}};
  const int code = dv_report_suite_run_one(&ms->scs[k], ms->engines, ms->out, 0, &e);
  if (code == DV_EXIT_ERROR) fprintf(stderr, "diskval suite: %s: %s\n", ms->scs[k].name, e.msg);
  memcpy(result, &code, sizeof code);
}

static int run(const char *cmd, int argc, char **argv) {
  static suite_args a;
  static dv_scenario scs[MAX_SCENARIOS];
  int done, codes[MAX_SCENARIOS];
  size_t n;
  const dv_engine_type *engines[DV_MAX_ENGINES + 1];
  dv_error err = {{0}};
  int code = parse(cmd, argc, argv, &a, &done);
  if (code || done) return code;
  if (dv_engine_parse_list(a.engines, engines, DV_MAX_ENGINES + 1, &err))
    return dv_cli_usage_error(cmd, "%s", err.msg);
  if ((code = load_all(cmd, &a, scs, &n))) return code;
  if (dv_io_make_dirs(a.out, &err))
    return fprintf(stderr, "diskval %s: %s\n", cmd, err.msg), DV_EXIT_ERROR;
  if (!strcmp(cmd, "compare")) {
    code = dv_report_suite_run_one(&scs[0], engines, a.out, 1, &err);
    if (code == DV_EXIT_ERROR)
      fprintf(stderr, "diskval compare: %s: %s\n", scs[0].name, err.msg);
    else
      printf("report: %s/%s/report.md\n", a.out, scs[0].name);
    return code;
  }
  if (dv_exec_mpi_size() > 1) { /* under mpirun: the ranks share the scenarios */
    mpi_suite ms = {scs, engines, a.out};
    unsigned char finished[MAX_SCENARIOS] = {0};
    for (size_t i = 0; i < n; i++) codes[i] = DV_EXIT_ERROR;
    const int farm = dv_exec_mpi_farm(n, sizeof(int), run_scenario_task, &ms, codes, finished, NULL);
    if (farm == 1) return DV_EXIT_OK; /* a worker rank: rank 0 reports */
    if (farm == 2) fprintf(stderr, "diskval suite: stopped early: scenarios not run are errors\n");
  } else if (dv_report_suite_run_all(scs, n, engines, a.out, a.jobs, codes, &err) == DV_EVENT) {
    fprintf(stderr, "diskval suite: %s\n", err.msg);
    return 130; /* 128 + SIGINT, as shells report it */
  }
  if (a.stability && dv_search_stability_run(scs, n, engines, a.common.sets, (size_t)a.common.nsets, a.out,
                                      a.jobs, &err)) {
    fprintf(stderr, "diskval suite: stability: %s\n", err.msg);
    return DV_EXIT_ERROR;
  }
  const char *dirs[MAX_SCENARIOS];
  char junit[1100];
  snprintf(junit, sizeof junit, "%s/junit.xml", a.out);
  code = DV_EXIT_OK;
  for (size_t i = 0; i < n; i++) {
    dirs[i] = scs[i].name;
    if (codes[i] > code) code = codes[i] > DV_EXIT_ERROR ? DV_EXIT_ERROR : codes[i];
  }
  if (dv_report_suite_write(a.out, dirs, n, a.junit ? a.junit : junit, &err)) {
    fprintf(stderr, "diskval suite: %s\n", err.msg);
    return DV_EXIT_ERROR;
  }
  printf("%zu scenarios: %s; report: %s/index.html\n", n,
         code == DV_EXIT_OK     ? "all pass"
         : code == DV_EXIT_FAIL ? "tolerances failed"
                                : "errors",
         a.out);
  return code;
}

int dv_cli_compare(int argc, char **argv) {
  return run("compare", argc, argv);
}

int dv_cli_suite(int argc, char **argv) {
  return run("suite", argc, argv);
}
