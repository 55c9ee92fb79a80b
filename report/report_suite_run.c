/* dv_suite: report directories built aside and renamed; a process pool. */
#include "report_suite_run.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "run_scenario.h"
#include "report_scenario.h"

int dv_io_make_dirs(const char *path, dv_error *err) {
  char buf[1024];
  snprintf(buf, sizeof buf, "%s", path);
  for (char *p = buf + 1;; p++) {
    const char c = *p;
    if (c != '/' && c != '\0') continue;
    *p = '\0';
    if (mkdir(buf, 0777) && errno != EEXIST)
      return dv_fail(err, DV_ESYSTEM, "%s: cannot create: %s", buf, strerror(errno));
    *p = c;
    if (!c) break;
  }
  return DV_OK;
}

static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw) {
  return remove(path);
}

/* rm -r */
static int remove_tree(const char *path) {
  return nftw(path, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

int dv_report_suite_run_one(const dv_scenario *sc, const dv_engine_type *const *engines,
                     const char *out_dir, int verbose, dv_error *err) {
  char tmp[1200], final[1200], old[1200];
  const dv_engine_type *own[DV_MAX_ENGINES + 1];
  /* a scenario may name its own engines */
  if (sc->engines[0]) {
    if (dv_engine_parse_list(sc->engines, own, DV_MAX_ENGINES + 1, err)) return DV_SUITE_ERROR;
    engines = own;
  }
  size_t n = 0;
  while (engines[n]) n++;
  snprintf(final, sizeof final, "%s/%s", out_dir, sc->name);
  snprintf(tmp, sizeof tmp, "%s/.%s.tmp.XXXXXX", out_dir, sc->name);
  if (!mkdtemp(tmp)) return dv_fail(err, DV_ESYSTEM, "%s: %s", tmp, strerror(errno)), DV_SUITE_ERROR;
  const mode_t mask = umask(0);
  umask(mask);
  chmod(tmp, 0777 & ~mask); /* mkdtemp makes it private; a report is for reading */
  static dv_comparison c;
  int status = dv_run_scenario(sc, NULL, engines, n, &c, err);
  if (!status) status = dv_report_scenario_write(tmp, &c, err);
  if (!status && verbose) dv_report_scenario_print(stdout, &c);
  const int pass = c.pass;
  dv_run_comparison_free(&c);
  if (status) {
    remove_tree(tmp);
    return DV_SUITE_ERROR;
  }
  /* replace an older report: move it aside, put the new one in place, drop the old */
  snprintf(old, sizeof old, "%s/.%s.old.%ld", out_dir, sc->name, (long)getpid());
  const int had_old = rename(final, old) == 0;
  if (rename(tmp, final)) {
    dv_fail(err, DV_ESYSTEM, "%s: %s", final, strerror(errno));
    if (had_old) rename(old, final);
    remove_tree(tmp);
    return DV_SUITE_ERROR;
  }
  if (had_old) remove_tree(old);
  return pass ? DV_SUITE_PASS : DV_SUITE_FAIL;
}

static volatile sig_atomic_t interrupted;

static void on_interrupt(int sig) {
  interrupted = sig;
}

/* remove the temporary directories that interrupted runs left in out_dir */
static void remove_temporaries(const char *out_dir) {
  DIR *d = opendir(out_dir);
  if (!d) return;
  for (struct dirent *e; (e = readdir(d));) {
    if (e->d_name[0] != '.' || (!strstr(e->d_name, ".tmp.") && !strstr(e->d_name, ".old.")))
      continue;
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", out_dir, e->d_name);
    remove_tree(path);
  }
  closedir(d);
}

int dv_report_suite_run_all(const dv_scenario *scs, size_t n, const dv_engine_type *const *engines,
                     const char *out_dir, int jobs, int *codes, dv_error *err) {
  pid_t *pids = calloc(n ? n : 1, sizeof *pids);
  if (!pids) return dv_fail(err, DV_ESYSTEM, "out of memory");
  const int tty = isatty(STDERR_FILENO);
  size_t started = 0, done = 0;
  int running = 0;
  struct sigaction sa, old_int, old_term;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_interrupt; /* no SA_RESTART: wait() returns to look at the flag */
  sigemptyset(&sa.sa_mask);
  interrupted = 0;
  sigaction(SIGINT, &sa, &old_int);
  sigaction(SIGTERM, &sa, &old_term);
  for (size_t i = 0; i < n; i++) codes[i] = DV_SUITE_ERROR;
  fflush(NULL);
  while (done < started || (!interrupted && done < n)) {
    while (!interrupted && running < jobs && started < n) {
      const pid_t pid = fork();
      if (pid == 0) {
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        dv_error e = {{0}};
        const int code = dv_report_suite_run_one(&scs[started], engines, out_dir, 0, &e);
        if (code == DV_SUITE_ERROR)
          fprintf(stderr, "diskval suite: %s: %s\n", scs[started].name, e.msg);
        fflush(NULL);
        free(pids);
        _exit(code);
      }
      if (pid < 0) {
        codes[started] = DV_SUITE_ERROR;
        done++;
      } else {
        running++;
      }
      pids[started++] = pid;
    }
    int wstatus;
    const pid_t pid = wait(&wstatus);
    if (pid < 0 && errno == EINTR) {
      for (size_t i = 0; i < started; i++) /* pass it on: a kill may reach only us */
        if (pids[i] > 0 && codes[i] == DV_SUITE_ERROR) kill(pids[i], interrupted);
      continue;
    }
    if (pid < 0) break;
    for (size_t i = 0; i < started; i++)
      if (pids[i] == pid) {
        codes[i] = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : DV_SUITE_ERROR;
        pids[i] = -1;
        running--;
        done++;
        if (tty)
          fprintf(stderr, "\r[%zu/%zu] %-40s %s", done, n, scs[i].name,
                  codes[i] == 0   ? "pass"
                  : codes[i] == 1 ? "FAIL"
                                  : "ERROR");
      }
  }
  if (tty) fputc('\n', stderr);
  sigaction(SIGINT, &old_int, NULL);
  sigaction(SIGTERM, &old_term, NULL);
  free(pids);
  if (interrupted) {
    remove_temporaries(out_dir);
    size_t finished = 0;
    for (size_t i = 0; i < n; i++) finished += codes[i] == DV_SUITE_PASS || codes[i] == DV_SUITE_FAIL;
    return dv_fail(err, DV_EVENT, "interrupted: %zu of %zu scenarios finished, their reports in %s",
                   finished, n, out_dir);
  }
  return DV_OK;
}
