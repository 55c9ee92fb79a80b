/* dv_suite: report directories built aside and renamed; the scenarios in the exec pool. */
#include "report_suite_run.h"

#include <dirent.h>
#include <errno.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "exec_pool.h"
#include "report_scenario.h"
#include "run_scenario.h"

/* nftw's callback for remove_tree: this entry, its contents already gone */
static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw) {
  return remove(path);
}

/* rm -r */
static int remove_tree(const char *path) {
  return nftw(path, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

/* the cause of each engine's excess, added to its failures */
static void explain_failures(const dv_scenario *sc, const dv_report_explain *explain,
                             dv_comparison *c) {
  for (size_t i = 0; explain && i < c->n; i++) {
    dv_engine_result *r = &c->r[i];
    if (r->verdict != DV_VERDICT_EXCEEDS ||
        explain->cause(explain->ctx, sc, r->engine->name, r->cause, sizeof r->cause))
      continue;
    for (size_t k = 0; k < r->nfailures; k++) {
      const size_t len = strlen(r->failures[k]);
      snprintf(r->failures[k] + len, sizeof r->failures[k] - len, "; cause: %s", r->cause);
    }
  }
}

/* compare sc into a new directory tmp; its dv_suite_result */
static int compare_into(const char *tmp, const dv_scenario *sc,
                        const dv_engine_type *const *engines, int verbose,
                        const dv_report_explain *explain, dv_error *err) {
  size_t n = 0;
  while (engines[n]) n++;
  dv_comparison *c = calloc(1, sizeof *c);
  if (!c) return dv_fail(err, DV_ESYSTEM, "out of memory"), DV_SUITE_ERROR;
  int status = dv_run_scenario(sc, NULL, engines, n, c, err);
  if (!status) explain_failures(sc, explain, c);
  if (!status) status = dv_report_scenario_write(tmp, c, err);
  if (!status && verbose) dv_report_scenario_print(stdout, c);
  const int pass = c->pass;
  dv_run_comparison_free(c);
  free(c);
  return status ? DV_SUITE_ERROR : pass ? DV_SUITE_PASS : DV_SUITE_FAIL;
}

int dv_report_suite_run_one(const dv_scenario *sc, const dv_engine_type *const *engines,
                            const char *out_dir, int verbose, const dv_report_explain *explain,
                            dv_error *err) {
  char tmp[1200], final[1200], old[1200];
  const dv_engine_type *own[DV_MAX_ENGINES + 1];
  /* a scenario may name its own engines */
  if (sc->engines[0]) {
    if (dv_engine_parse_list(sc->engines, own, DV_MAX_ENGINES + 1, err)) return DV_SUITE_ERROR;
    engines = own;
  }
  if (dv_io_path(final, sizeof final, err, "%s/%s", out_dir, sc->name) ||
      dv_io_path(tmp, sizeof tmp, err, "%s/.%s.tmp.XXXXXX", out_dir, sc->name) ||
      dv_io_path(old, sizeof old, err, "%s/.%s.old.%ld", out_dir, sc->name, (long)getpid()))
    return DV_SUITE_ERROR;
  if (!mkdtemp(tmp))
    return dv_fail(err, DV_ESYSTEM, "%s: %s", tmp, strerror(errno)), DV_SUITE_ERROR;
  const mode_t mask = umask(0);
  umask(mask);
  chmod(tmp, 0777 & ~mask); /* mkdtemp makes it private; a report is for reading */
  const int code = compare_into(tmp, sc, engines, verbose, explain, err);
  if (code == DV_SUITE_ERROR) {
    remove_tree(tmp);
    return DV_SUITE_ERROR;
  }
  /* replace an older report: move it aside, put the new one in place, drop the old */
  const int had_old = rename(final, old) == 0;
  if (rename(tmp, final)) {
    dv_fail(err, DV_ESYSTEM, "%s: %s", final, strerror(errno));
    if (had_old) rename(old, final);
    remove_tree(tmp);
    return DV_SUITE_ERROR;
  }
  if (had_old) remove_tree(old);
  return code;
}

/* remove the temporary directories that interrupted runs left in out_dir */
static void remove_temporaries(const char *out_dir) {
  DIR *d = opendir(out_dir);
  if (!d) return;
  for (struct dirent *e; (e = readdir(d));) {
    if (e->d_name[0] != '.' || (!strstr(e->d_name, ".tmp.") && !strstr(e->d_name, ".old.")))
      continue;
    char path[1200];
    if (!dv_io_path(path, sizeof path, NULL, "%s/%s", out_dir, e->d_name)) remove_tree(path);
  }
  closedir(d);
}

/* a suite run: what its tasks share, and its progress */
typedef struct suite_run {
  const dv_scenario *scs;
  size_t n;
  const dv_engine_type *const *engines;
  const char *out_dir;
  const dv_report_explain *explain;
  const int *codes; /* each scenario's dv_suite_result once it has ended */
  size_t ended;     /* scenarios ended so far */
  int tty;          /* progress on stderr */
} suite_run;

/* dv_exec_pool's task: scenario k into its report directory; its dv_suite_result */
static void run_task(size_t k, void *result, void *ctx) {
  const suite_run *s = ctx;
  dv_error e = {{0}};
  const int code = dv_report_suite_run_one(&s->scs[k], s->engines, s->out_dir, 0, s->explain, &e);
  if (code == DV_SUITE_ERROR) fprintf(stderr, "diskval suite: %s: %s\n", s->scs[k].name, e.msg);
  memcpy(result, &code, sizeof code);
}

/* how the progress line shows a dv_suite_result */
static const char *const verdicts[] = {
    [DV_SUITE_PASS] = "pass", [DV_SUITE_FAIL] = "FAIL", [DV_SUITE_ERROR] = "ERROR"};

/* after each scenario, on a terminal: [ended/n] name verdict */
static void progress(size_t k, int ran, void *ctx) {
  suite_run *s = ctx;
  s->ended++;
  if (s->tty)
    fprintf(stderr, "\r[%zu/%zu] %-40s %s", s->ended, s->n, s->scs[k].name,
            verdicts[ran ? s->codes[k] : DV_SUITE_ERROR]);
}

int dv_report_suite_run_all(const dv_scenario *scs, size_t n, const dv_engine_type *const *engines,
                            const char *out_dir, int jobs, const dv_report_explain *explain,
                            int *codes, dv_error *err) {
  for (size_t i = 0; i < n; i++) codes[i] = DV_SUITE_ERROR; /* a scenario that never ends */
  suite_run s = {scs, n, engines, out_dir, explain, codes, 0, isatty(STDERR_FILENO)};
  const dv_exec_options opt = {.jobs = jobs, .on_result = progress};
  const int pool = dv_exec_pool(n, sizeof *codes, run_task, &s, codes, &opt);
  if (s.tty && pool != DV_EXEC_WORKER) fputc('\n', stderr);
  if (pool == DV_EXEC_NOMEM) return dv_fail(err, DV_ESYSTEM, "out of memory");
  if (pool == DV_EXEC_WORKER) return DV_SUITE_RUN_WORKER;
  if (pool == DV_EXEC_INTERRUPTED) {
    remove_temporaries(out_dir);
    size_t finished = 0;
    for (size_t i = 0; i < n; i++)
      finished += codes[i] == DV_SUITE_PASS || codes[i] == DV_SUITE_FAIL;
    return dv_fail(err, DV_EVENT, "interrupted: %zu of %zu scenarios finished, their reports in %s",
                   finished, n, out_dir);
  }
  return DV_OK;
}
