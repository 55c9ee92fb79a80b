/* dv_cli_suite: diskval suite DIR|FILES...: every scenario compared, as
 * diskval compare does, in separate processes; then the suite's summary,
 * HTML page and JUnit XML. */
#include <cjson/cJSON.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "cli_args.h"
#include "engine_choose.h"
#include "exec_mpi.h"
#include "exec_pool.h"
#include "io_json.h"
#include "io_lock.h"
#include "io_owned.h"
#include "report_suite_dir.h"
#include "report_suite.h"
#include "report_suite_run.h"
#include "run_progress.h"
#include "run_scenario.h"
#include "search_stability.h"
#include "search_verify_suite.h"

static const char HELP[] =
    "usage: diskval suite DIR|FILES... [--out DIR] [--junit FILE] [--jobs N] [--engines LIST]\n"
    "                     [--timeout S] [--cause quick|full|none] [--stability | --verify]\n"
    "\n"
    "Compare every scenario (the *.ini files of each DIR, and each FILE) as diskval\n"
    "compare does, N at a time in separate processes (default: the number of cores),\n"
    "then write DIR/index.html, DIR/summary.json and the JUnit XML (default\n"
    "DIR/junit.xml). Every scenario file is checked before anything is written.\n"
    "A scenario (with --verify: a scenario and engine) still running after S seconds\n"
    "(--timeout, default 600; 0: no limit; none under mpirun) is\n"
    "ended and reported as an error, \"timed out after S s\"; its settings probes, its\n"
    "first work, are held to the limit too. One run at a time writes\n"
    "into DIR: a second one is refused.\n"
    "--stability also finds, per scenario and engine, the largest timestep that stays\n"
    "finite and within the scenario's theta tolerance (bisection), and the failure\n"
    "above it: DIR/stability.html, .md and .json, linked from index.html.\n"
    "--verify instead refines each contact engine's step and contact softness on every\n"
    "scenario (as diskval verify does): DIR/verify.md, DIR/verify.json and the JUnit XML,\n"
    "a failure wherever an engine does not converge to the reference. One of the two:\n"
    "both together are refused.\n"
    "--cause: as compare's (quick, the default: the knob the failure points to first, stopping\n"
    "at the first that removes it; full: every knob; none: no cause searched).\n"
    "--quiet: no progress line on a terminal (scenarios done, time left), no warning\n"
    "before a suite longer than a minute.\n"
    "Exit status: 0 all pass, 1 a tolerance or outcome failed, 2 bad input or error.\n";

typedef struct suite_opts {
  const char *out, *junit, *engines;
  int jobs;
  int stability;     /* also the largest stable timesteps and failure modes */
  int verify;        /* instead: do the engines converge to the reference */
  double timeout;    /* s of wall time a scenario may take (0: no limit) */
  const char *cause; /* --cause: quick (NULL), full or none */
} suite_opts;

/* load every scenario first: any bad file ends the command before output.
 * probed 0: the names and checks only, no settings probed (they are probed
 * as each scenario's work, under its time limit: probe_all) */
static int load_all(const dv_cli_list *files, const dv_cli_list *sets, dv_scenario *scs,
                    int probed) {
  dv_engine_choose_probing(probed);
  dv_scenario_keep_texts(!probed); /* probe_all loads them again: each file is read once */
  for (size_t i = 0; i < files->n; i++) {
    dv_error err = {{0}};
    if (probed ? dv_cli_load_scenario("suite", files->items[i], sets, &scs[i], &err)
               : dv_engine_load_scenario(files->items[i], (const char *const *)sets->items, sets->n,
                                         &scs[i], &err))
      return dv_engine_choose_probing(1), fprintf(stderr, "%s\n", err.msg), DV_EXIT_ERROR;
    for (size_t k = 0; k < i; k++)
      if (!strcmp(scs[k].name, scs[i].name))
        return dv_engine_choose_probing(1),
               dv_cli_error("suite", "%s and %s both name their scenario '%s'", scs[k].path,
                            scs[i].path, scs[k].name);
  }
  dv_engine_choose_probing(1);
  return DV_EXIT_OK;
}

/* the scenarios' settings probed, each in a process of its own under the
 * limit of a scenario (a scenario's work begins with them), and loaded again
 * with them into scs; one killed at the limit, or whose process died, is an
 * error with its error report (codes, causes), left out of the run
 * (ended[i] != DV_EXEC_ARRIVED). Stopped by a signal: every scenario an
 * error report "did not end" and the suite's files say so; 130 */
static int probe_all(const suite_opts *o, const dv_cli_list *files, const dv_cli_list *sets,
                     dv_scenario *scs, unsigned char *ended, int *codes, dv_error *causes) {
  const size_t n = files->n;
  dv_error err = {{0}};
  const int status =
      dv_cli_load_all_within("suite", files, sets, o->jobs, o->timeout, scs, ended, &err);
  if (status < 0) return dv_cli_error("suite", "%s", err.msg);
  for (size_t i = 0; i < n; i++) {
    if (status == DV_OK && ended[i] == DV_EXEC_ARRIVED) continue;
    codes[i] = status == DV_EVENT ? DV_SUITE_NOT_ENDED : DV_SUITE_ERROR;
    if (status == DV_EVENT)
      dv_fail(&causes[i], DV_EVENT, "did not end: the suite was interrupted");
    else if (ended[i] == DV_EXEC_TIMED_OUT)
      dv_fail(&causes[i], DV_ESYSTEM, "timed out after %g s, probing its settings", o->timeout);
    else
      dv_fail(&causes[i], DV_ESYSTEM,
              "its process ended without a result (crashed or killed), probing its settings");
    if (status == DV_OK) fprintf(stderr, "diskval suite: %s: %s\n", scs[i].name, causes[i].msg);
    dv_error ignored; /* never an earlier run's report beside this run's summary */
    dv_report_dir_write_error(o->out, &scs[i], causes[i].msg, &ignored);
  }
  if (status != DV_EVENT) return DV_EXIT_OK;
  const char **dirs = malloc((2 * n + 1) * sizeof *dirs), **not_ended = dirs + n;
  if (!dirs) return dv_cli_error("suite", "out of memory");
  for (size_t i = 0; i < n; i++) dirs[i] = scs[i].name, not_ended[i] = causes[i].msg;
  char junit[1100];
  snprintf(junit, sizeof junit, "%s/junit.xml", o->out);
  const int written = !o->verify && dv_report_suite_write_ended(o->out, dirs, not_ended, n,
                                                                o->junit ? o->junit : junit, &err);
  free(dirs);
  if (written) return dv_cli_error("suite", "%s", err.msg);
  dv_cli_error("suite", "interrupted while the scenarios chose their settings: none ended%s",
               o->verify ? "" : "; the suite's files say so");
  return 130; /* 128 + SIGINT, as shells report it */
}

/* the files the suite writes into --out, besides the scenarios' directories */
static const char *const suite_files[] = {"index.html",   "summary.json",   "junit.xml",
                                          "verify.md",    "verify.json",    "stability.html",
                                          "stability.md", "stability.json", NULL};

/* before anything runs: --out may take the suite's files and directories
 * (io_owned.h), and the JUnit file is none of the run's inputs or other outputs */
static int check_outputs(const suite_opts *o, const dv_cli_list *files, const dv_scenario *scs,
                         dv_error *err) {
  const char *const *inputs = (const char *const *)files->items;
  if (dv_report_dir_check(o->out, scs, files->n, NULL, 0, err)) return DV_EXIT_ERROR;
  for (const char *const *f = suite_files; *f; f++) {
    char path[1100];
    if (dv_io_path(path, sizeof path, err, "%s/%s", o->out, *f)) return DV_EXIT_ERROR;
    for (size_t i = 0; i < files->n; i++)
      if (dv_io_same_file(inputs[i], path))
        return dv_fail(err, DV_EINPUT, "%s: an input of this run is the suite's own %s", inputs[i],
                       *f),
               DV_EXIT_ERROR;
    if (o->junit && strcmp(o->junit, "-") && strcmp(*f, "junit.xml") &&
        dv_io_same_file(o->junit, path))
      return dv_fail(err, DV_EINPUT, "--junit '%s' is the suite's own %s", o->junit, path),
             DV_EXIT_ERROR;
  }
  return dv_report_dir_check_junit(o->junit, o->out, scs, files->n, NULL, 0, err) ? DV_EXIT_ERROR
                                                                                  : DV_EXIT_OK;
}

/* the scenarios whose settings were probed (ended[i], NULL: all), copied
 * into run[0..*m), map[j] the index of run[j] in scs */
static dv_scenario *runnable(const dv_scenario *scs, size_t n, const unsigned char *ended,
                             size_t *map, size_t *m) {
  dv_scenario *run = malloc((n ? n : 1) * sizeof *run);
  *m = 0;
  for (size_t i = 0; run && i < n; i++)
    if (!ended || ended[i] == DV_EXEC_ARRIVED) map[*m] = i, run[(*m)++] = scs[i];
  return run;
}

/* --verify: every scenario's engines refined; verify.md, verify.json, JUnit */
static int verify(const suite_opts *o, const dv_cli_list *files,
                  const dv_engine_type *const *engines, const dv_scenario *all,
                  const unsigned char *ended, const int *codes, const dv_error *causes) {
  size_t ne = 0;
  while (engines[ne]) ne++;
  /* a scenario whose settings probes did not end (probe_all) is an error, not verified */
  size_t n = 0, *map = malloc((files->n ? files->n : 1) * sizeof *map);
  dv_scenario *scs = map ? runnable(all, files->n, ended, map, &n) : NULL;
  free(map);
  dv_verify_case *cases = scs ? calloc(n * ne > 0 ? n * ne : 1, sizeof *cases) : NULL;
  dv_error err = {{0}};
  int code = DV_EXIT_OK;
  if (!cases) code = dv_cli_error("suite", "out of memory");
  for (size_t i = 0; !code && i < files->n; i++)
    if (codes[i] == DV_SUITE_ERROR) printf("%s: error: %s\n", all[i].name, causes[i].msg);
  if (!code && dv_io_make_dirs(o->out, &err)) code = dv_cli_error("suite", "%s", err.msg);
  const int ran =
      code ? DV_OK : dv_search_verify_suite(scs, n, engines, ne, o->jobs, o->timeout, cases, &err);
  if (!code && ran < 0) code = dv_cli_error("suite", "%s", err.msg);
  const int written = !code && (ran == DV_OK || ran == DV_VERIFY_SUITE_INTERRUPTED);
  char junit[1100];
  snprintf(junit, sizeof junit, "%s/junit.xml", o->out);
  if (written && dv_search_verify_write(o->out, o->junit ? o->junit : junit, cases, n * ne, &err))
    code = dv_cli_error("suite", "%s", err.msg);
  size_t converge = 0, skipped = 0, errors = 0;
  for (size_t k = 0; !code && written && k < n * ne; k++) {
    if (cases[k].status < 0 && ++errors)
      printf("%s: %s: error: %s\n", cases[k].scenario, cases[k].engine, cases[k].message);
    skipped += cases[k].status == DV_EVENT;
    converge += cases[k].status == 0 && cases[k].v.verdict == DV_CONVERGES;
  }
  if (!code && errors) code = DV_EXIT_ERROR;
  if (!code && converge + skipped < n * ne) code = DV_EXIT_FAIL;
  const int none = !code && written && skipped == n * ne; /* not judged, never a pass */
  if (none) code = DV_EXIT_FAIL;
  if (written && (code == DV_EXIT_OK || code == DV_EXIT_FAIL || converge))
    printf(
        "%zu of %zu engine runs converge to the reference (%zu skipped: the scenario names "
        "other engines); report: %s/verify.md\n",
        converge, n * ne - skipped, skipped, o->out);
  if (none) printf("not judged: every case was skipped, none verified\n");
  if (written && ran == DV_VERIFY_SUITE_INTERRUPTED) {
    dv_cli_error("suite", "interrupted: the cases that ended are in %s/verify.md", o->out);
    code = 130; /* 128 + SIGINT, as shells report it, and as a compare suite exits */
  }
  for (size_t i = 0; code != 130 && i < files->n; i++)
    if (codes[i] == DV_SUITE_ERROR) code = DV_EXIT_ERROR;
  free(cases);
  free(scs);
  return code;
}

/* every failing engine run of the suite's summary.json, one line each, so
 * that a CI log names every failing case */
static void print_failures(const char *out) {
  char path[1100];
  snprintf(path, sizeof path, "%s/summary.json", out);
  cJSON *sum = dv_io_json_read(path, 1L << 30, NULL, 0);
  const cJSON *sc;
  cJSON_ArrayForEach(sc, cJSON_GetObjectItem(sum, "scenarios")) {
    const cJSON *eng;
    cJSON_ArrayForEach(eng, cJSON_GetObjectItem(sc, "engines")) {
      if (cJSON_IsTrue(cJSON_GetObjectItem(eng, "pass"))) continue;
      const cJSON *f, *failures = cJSON_GetObjectItem(eng, "failures");
      const char *body = cJSON_GetStringValue(cJSON_GetObjectItem(eng, "judged"));
      char judged[64] = "";
      if (body) snprintf(judged, sizeof judged, " [%s]", body); /* which body's reference */
      cJSON_ArrayForEach(f, failures) if (cJSON_IsString(f))
          printf("%s%s\n", f->valuestring, judged);
      if (!cJSON_GetArraySize(failures))
        printf("%s: %s: %s%s\n", cJSON_GetStringValue(cJSON_GetObjectItem(sc, "scenario")),
               eng->string, cJSON_GetStringValue(cJSON_GetObjectItem(eng, "outcome")), judged);
    }
  }
  cJSON_Delete(sum);
}

/* run the loaded scenarios and write the suite's files */
static int run(const suite_opts *o, const dv_cli_list *sets, const dv_engine_type *const *engines,
               const dv_scenario *scs, size_t n, const unsigned char *ended, int *codes,
               dv_error *causes) {
  dv_error err = {{0}};
  dv_report_explain explain;
  dv_cli_explainer("suite", o->cause, sets, &explain); /* checked when parsed */
  size_t m = 0, *map = malloc((n ? n : 1) * sizeof *map);
  dv_scenario *ok = map ? runnable(scs, n, ended, map, &m) : NULL;
  int *ok_codes = malloc((n ? n : 1) * sizeof *ok_codes);
  dv_error *ok_causes = malloc((n ? n : 1) * sizeof *ok_causes);
  int ran = DV_OK;
  if (!ok || !ok_codes || !ok_causes)
    ran = dv_fail(&err, DV_ESYSTEM, "out of memory");
  else if (m)
    ran = dv_report_suite_run_all(ok, m, engines, o->out, o->jobs, o->timeout, &explain, ok_codes,
                                  ok_causes, &err);
  for (size_t j = 0; ran != DV_ESYSTEM && j < m; j++)
    codes[map[j]] = ok_codes[j], causes[map[j]] = ok_causes[j];
  free(map);
  free(ok_codes);
  free(ok_causes);
  if (ran < 0) return free(ok), dv_cli_error("suite", "%s", err.msg);
  if (ran == DV_SUITE_RUN_WORKER) return free(ok), DV_EXIT_OK; /* an MPI worker rank */
  int stopped = ran == DV_EVENT; /* the suite-level files then say what did not end */
  if (stopped) dv_cli_error("suite", "%s", err.msg);
  const int stable = o->stability && !stopped && m
                         ? dv_search_stability_run(ok, m, engines, o->out, o->jobs, &err)
                         : DV_OK;
  free(ok);
  if (stable < 0) return dv_cli_error("suite", "stability: %s", err.msg);
  if (stable == DV_EVENT) stopped = 1, dv_cli_error("suite", "stability: %s", err.msg);
  const char **dirs = malloc((2 * n + 1) * sizeof *dirs), **not_ended = dirs + n;
  if (!dirs) return dv_cli_error("suite", "out of memory");
  int code = DV_EXIT_OK;
  for (size_t i = 0; i < n; i++) {
    dirs[i] = scs[i].name;
    not_ended[i] = codes[i] == DV_SUITE_NOT_ENDED ? causes[i].msg : NULL;
    if (codes[i] > code) code = codes[i] > DV_EXIT_ERROR ? DV_EXIT_ERROR : codes[i];
  }
  char junit[1100];
  snprintf(junit, sizeof junit, "%s/junit.xml", o->out);
  const int written =
      dv_report_suite_write_ended(o->out, dirs, not_ended, n, o->junit ? o->junit : junit, &err);
  free(dirs);
  if (written) return dv_cli_error("suite", "%s", err.msg);
  if (stopped) return 130; /* 128 + SIGINT, as shells report it */
  for (size_t i = 0; i < n; i++)
    if (codes[i] == DV_EXIT_ERROR) printf("%s: error: %s\n", scs[i].name, causes[i].msg);
  if (code == DV_EXIT_FAIL || code == DV_EXIT_ERROR) print_failures(o->out);
  printf("%zu scenarios: %s; report: %s/index.html\n", n,
         code == DV_EXIT_OK     ? "all pass"
         : code == DV_EXIT_FAIL ? "tolerances failed"
                                : "errors",
         o->out);
  return code;
}

int dv_cli_suite(int argc, char **argv) {
  /* a stop before the scenarios run ends the suite as one while they run:
   * exit 130 and a line, never a silent death of the signal */
  dv_exec_hold_stops();
  suite_opts o = {"report", NULL, NULL, dv_cli_default_jobs(), 0, 0, 600.0, NULL};
  const dv_cli_option options[] = {
      {"out", DV_CLI_TEXT, &o.out, 0, 0},
      {"junit", DV_CLI_TEXT, &o.junit, 0, 0},
      {"engines", DV_CLI_TEXT, &o.engines, 0, 0},
      {"jobs", DV_CLI_INT, &o.jobs, 1, 1024},
      {"stability", DV_CLI_FLAG, &o.stability, 0, 0},
      {"verify", DV_CLI_FLAG, &o.verify, 0, 0},
      {"timeout", DV_CLI_REAL, &o.timeout, 0, 1e9},
      {"cause", DV_CLI_TEXT, &o.cause, 0, 0},
  };
  const dv_cli_command cmd = {"suite", HELP, options, 8, 1, (size_t)-1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  if (o.stability && o.verify) { /* two different runs: one would be dropped */
    dv_cli_args_free(&cmd, &a);
    return dv_cli_usage_error("suite", "--stability and --verify: one at a time, not both");
  }
  dv_report_explain check;
  if (dv_cli_explainer("suite", o.cause, &a.sets, &check) != DV_OK) {
    dv_cli_args_free(&cmd, &a);
    return DV_EXIT_ERROR;
  }
  if ((o.junit && !o.junit[0]) || !o.out[0]) {
    dv_cli_args_free(&cmd, &a);
    return dv_cli_usage_error("suite", "%s needs a %s", o.out[0] ? "--junit" : "--out",
                              o.out[0] ? "file name" : "directory");
  }
  dv_run_progress_start("suite", a.quiet, 0);
  const dv_engine_type *engines[DV_MAX_ENGINES + 1];
  dv_cli_list files = {0};
  dv_scenario *scs = NULL;
  int *codes = NULL;
  dv_error *causes = NULL;
  unsigned char *ended = NULL; /* how each scenario's settings probes ended */
  int lock = -1;
  dv_error err = {{0}};
  int code = DV_EXIT_OK;
  if (dv_cli_engine_list(o.engines, engines, &err)) code = dv_cli_error("suite", "%s", err.msg);
  if (!code) code = dv_cli_scenario_files("suite", &a.args, &files);
  if (!code &&
      (!(scs = calloc(files.n, sizeof *scs)) || !(codes = calloc(files.n, sizeof *codes)) ||
       !(causes = calloc(files.n, sizeof *causes))))
    code = dv_cli_error("suite", "out of memory");
  /* the settings probes are each scenario's work, timed and stopped as the
   * scenarios are (not under mpirun: there, while the files are read) */
  const int mpi = dv_exec_mpi_size() > 1;
  if (!code && !mpi && !(ended = calloc(files.n, 1))) code = dv_cli_error("suite", "out of memory");
  if (!code) code = load_all(&files, &a.sets, scs, mpi);
  if (!code && check_outputs(&o, &files, scs, &err)) code = dv_cli_error("suite", "%s", err.msg);
  if (!code && dv_exec_take_stop()) { /* nothing of this run to report yet */
    dv_cli_error("suite", "interrupted before any scenario ran: nothing written");
    code = 130;
  }
  /* one run at a time in --out: it removes what dead runs left there (under
   * mpirun, rank 0 holds the lock for all the ranks); checked again once held */
  /* the fixed names this run writes into --out, its main one first */
  const char *names[8] = {0};
  size_t nn = 0;
  names[nn++] = o.verify ? "verify.json" : "summary.json";
  names[nn++] = o.verify ? "verify.md" : "index.html";
  if (!o.junit) names[nn++] = "junit.xml";
  if (o.stability && !o.verify)
    names[nn++] = "stability.html", names[nn++] = "stability.md", names[nn++] = "stability.json";
  if (!code && (dv_io_own_dir(o.out, names, &err) ||
                (dv_exec_mpi_rank() == 0 && dv_io_lock_dir(o.out, &lock, &err)) ||
                check_outputs(&o, &files, scs, &err)))
    code = dv_cli_error("suite", "%s", err.msg);
  if (!code && ended) code = probe_all(&o, &files, &a.sets, scs, ended, codes, causes);
  if (!code && o.verify)
    code = verify(&o, &files, engines, scs, ended, codes, causes);
  else if (!code)
    code = run(&o, &a.sets, engines, scs, files.n, ended, codes, causes);
  if ((code == DV_EXIT_OK || code == DV_EXIT_FAIL) && dv_exec_take_stop()) {
    dv_cli_error("suite", "interrupted as it ended: the reports of this run are complete");
    code = 130;
  }
  dv_io_unlock_dir(o.out, lock);
  for (size_t i = 0; i < files.n; i++) free((char *)files.items[i]);
  free(files.items);
  free(scs);
  free(codes);
  free(causes);
  free(ended);
  dv_cli_args_free(&cmd, &a);
  return code;
}
