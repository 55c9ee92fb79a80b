/* cli_load: a scenario loaded for a command, with a line on stderr for every
 * setting the file gave that an engine's check replaced, its settings probes
 * under a time limit where the command has one; the files a command's
 * arguments name. */
#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "cli_args.h"
#include "dv_engine.h"
#include "engine_choose.h"
#include "exec_mpi.h"
#include "exec_pool.h"
#include "run_progress.h"
#include "run_within.h"

int dv_cli_load_scenario(const char *command, const char *path, const dv_cli_list *sets,
                         dv_scenario *sc, dv_error *err) {
  const int status = dv_engine_load_scenario(path, sets->items, sets->n, sc, err);
  for (size_t i = 0; !status && i < sc->nsections; i++)
    if (sc->replaced[i][0])
      fprintf(stderr, "diskval %s: %s: engines.%s: given %s, replaced (%s)\n", command, path,
              sc->sections[i]->name, sc->replaced[i], sc->derived[i]);
  return status;
}

/* the load's process: what it is given, and hands back */
typedef struct load_job {
  const char *path;
  const dv_cli_list *sets;
  double (*forecast)(const dv_scenario *sc, void *ctx);
  void *ctx;
} load_job;

typedef struct load_result {
  int arrived;     /* the probes' choices are in memo */
  double estimate; /* s: forecast's, or NAN */
  unsigned char memo[DV_CHOOSE_MEMO_BYTES];
} load_result;

static void load_task(void *ctx, void *result) {
  const load_job *j = ctx;
  load_result *r = result;
  dv_scenario *sc = malloc(sizeof *sc);
  dv_error err = {{0}}; /* a bad file is the load here to report */
  if (sc &&
      !dv_engine_load_scenario(j->path, (const char *const *)j->sets->items, j->sets->n, sc,
                               &err) &&
      j->forecast)
    r->estimate = j->forecast(sc, j->ctx);
  free(sc);
  dv_engine_choose_memo_save(r->memo);
  r->arrived = 1;
}

int dv_cli_load_scenario_within(const char *command, const char *path, const dv_cli_list *sets,
                                double timeout,
                                double (*forecast)(const dv_scenario *sc, void *ctx), void *ctx,
                                dv_scenario *sc, int *timed_out, dv_error *err) {
  *timed_out = 0;
  if (timeout > 0.0 && dv_exec_mpi_size() <= 1) {
    /* read and checked here first, nothing probed: a bad file is said at
     * once, and the file is read once (a FIFO): its process and the load
     * below take the text kept */
    dv_scenario_keep_texts(1);
    dv_engine_choose_probing(0);
    const int checked =
        dv_engine_load_scenario(path, (const char *const *)sets->items, sets->n, sc, err);
    dv_engine_choose_probing(1);
    if (checked) return checked;
    load_job job = {path, sets, forecast, ctx};
    load_result *r = calloc(1, sizeof *r);
    if (!r) return dv_fail(err, DV_ESYSTEM, "out of memory");
    r->estimate = NAN;
    const dv_run_within_end end = dv_run_within(timeout, load_task, &job, r, sizeof *r);
    if (end == DV_RUN_WITHIN_DONE && r->arrived) {
      dv_engine_choose_memo_restore(r->memo);
      if (!isnan(r->estimate)) dv_run_progress_keep_estimate(r->estimate);
    }
    free(r);
    if (end == DV_RUN_WITHIN_STOPPED) return dv_run_within_stop(err);
    if (end == DV_RUN_WITHIN_TIMED_OUT) { /* sc as checked: its name, for an error report */
      *timed_out = 1;
      return dv_fail(err, DV_ESYSTEM, "timed out after %g s, probing its settings and cost",
                     timeout);
    }
    /* its process lost (crashed): the load here does the work, as without a limit */
  }
  return dv_cli_load_scenario(command, path, sets, sc, err);
}

/* a suite's loads: file k's, as the pool's task k */
typedef struct load_all_job {
  const dv_cli_list *files, *sets;
} load_all_job;

static void load_all_task(size_t k, void *result, void *ctx) {
  const load_all_job *j = ctx;
  load_job one = {j->files->items[k], j->sets, NULL, NULL};
  load_task(&one, result);
}

int dv_cli_load_all_within(const char *command, const dv_cli_list *files, const dv_cli_list *sets,
                           int jobs, double timeout, dv_scenario *scs, unsigned char *ended,
                           dv_error *err) {
  const size_t n = files->n;
  load_all_job job = {files, sets};
  load_result *r = calloc(n ? n : 1, sizeof *r);
  if (!r) return dv_fail(err, DV_ESYSTEM, "out of memory");
  for (size_t k = 0; k < n; k++) r[k].estimate = NAN;
  const dv_exec_options opt = {.jobs = jobs,
                               .on_result = dv_run_progress_on_result,
                               .done = ended,
                               .timeout = timeout,
                               .local = 1};
  dv_run_progress_tasks_begin("scenario's settings", n); /* the tasks draw no line */
  const int pool = dv_exec_pool(n, sizeof *r, load_all_task, &job, r, &opt);
  dv_run_progress_tasks_end();
  int status = DV_OK;
  if (pool == DV_EXEC_NOMEM) status = dv_fail(err, DV_ESYSTEM, "out of memory");
  if (pool == DV_EXEC_INTERRUPTED) status = dv_fail(err, DV_EVENT, "interrupted by a signal");
  /* each scenario loaded again here, its probes' choices remembered */
  for (size_t k = 0; status == DV_OK && k < n; k++) {
    if (ended[k] != DV_EXEC_ARRIVED || !r[k].arrived) {
      if (ended[k] == DV_EXEC_ARRIVED) ended[k] = DV_EXEC_LOST;
      continue;
    }
    dv_engine_choose_memo_restore(r[k].memo);
    status = dv_cli_load_scenario(command, files->items[k], sets, &scs[k], err);
  }
  free(r);
  return status;
}

static int by_name(const void *a, const void *b) {
  return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* the .ini files of dir, sorted, appended to files (the strings are the caller's to free) */
static int list_dir(const char *dir, dv_cli_list *files) {
  DIR *d = opendir(dir);
  if (!d) return -1;
  const size_t first = files->n;
  int status = 0;
  for (struct dirent *e; !status && (e = readdir(d));) {
    const size_t len = strlen(e->d_name);
    if (len < 5 || strcmp(e->d_name + len - 4, ".ini")) continue;
    char *path = malloc(strlen(dir) + len + 2);
    if (!path) status = -1;
    if (path) sprintf(path, "%s/%s", dir, e->d_name);
    if (path && dv_cli_list_push(files, path)) free(path), status = -1;
  }
  closedir(d);
  qsort(files->items + first, files->n - first, sizeof *files->items, by_name);
  return status;
}

int dv_cli_scenario_files(const char *command, const dv_cli_list *args, dv_cli_list *files) {
  for (size_t i = 0; i < args->n; i++) {
    struct stat st;
    if (stat(args->items[i], &st) == 0 && S_ISDIR(st.st_mode)) {
      if (list_dir(args->items[i], files))
        return dv_cli_error(command, "cannot read directory %s", args->items[i]);
    } else {
      char *copy = strdup(args->items[i]);
      if (!copy || dv_cli_list_push(files, copy))
        return free(copy), dv_cli_error(command, "out of memory");
    }
  }
  return files->n ? DV_EXIT_OK : dv_cli_error(command, "no scenario files found");
}
