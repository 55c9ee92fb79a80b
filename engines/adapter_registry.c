/* adapter_registry: the adapters this process finds (adapter.h), loaded once:
 * the source tree's adapters/ (DV_ADAPTERS_DIR), then each folder
 * DISKVAL_ADAPTERS lists (':'-separated), each an adapter's folder or a
 * folder of them, in name order. */
#include <dirent.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "adapter.h"

#ifndef DV_ADAPTERS_DIR
#define DV_ADAPTERS_DIR "adapters"
#endif

static dv_adapter *found[DV_MAX_ADAPTERS];
static size_t nfound;
static char problems[2048];
static pthread_once_t once = PTHREAD_ONCE_INIT;

static void problem(const char *fmt, const char *a, const char *b) {
  const size_t n = strlen(problems);
  snprintf(problems + n, sizeof problems - n, fmt, a, b);
}

static int exists(const char *path) {
  struct stat st;
  return stat(path, &st) == 0;
}

/* "" where a can run; else why not */
static void availability(dv_adapter *a) {
  char words[sizeof a->requires], path[1600], program[256];
  snprintf(words, sizeof words, "%s", a->requires);
  for (char *save = NULL, *w = strtok_r(words, " ", &save); w; w = strtok_r(NULL, " ", &save)) {
    snprintf(path, sizeof path, "%s/%s", a->dir, w);
    if (!exists(path)) {
      snprintf(a->missing, sizeof a->missing, "%.120s is not installed (./run.sh installs it)", w);
      return;
    }
  }
  if (sscanf(a->command, "%255s", program) != 1) return;
  if (strchr(program, '/')) {
    snprintf(path, sizeof path, "%s/%s", a->dir, program);
    if (program[0] != '/' && !exists(path))
      snprintf(a->missing, sizeof a->missing, "%.120s is missing", program);
    return;
  }
  const char *dirs = getenv("PATH");
  char list[4096];
  snprintf(list, sizeof list, "%s", dirs ? dirs : "/usr/bin:/bin");
  for (char *save = NULL, *d = strtok_r(list, ":", &save); d; d = strtok_r(NULL, ":", &save)) {
    snprintf(path, sizeof path, "%s/%s", d, program);
    if (access(path, X_OK) == 0) return;
  }
  snprintf(a->missing, sizeof a->missing, "%.120s is not on PATH (./run.sh installs it)", program);
}

static void add(const char *dir) {
  dv_error err;
  dv_adapter *a = calloc(1, sizeof *a);
  if (!a) return;
  if (dv_adapter_load(dir, a, &err)) {
    problem("%s%s\n", err.msg, "");
    free(a);
    return;
  }
  for (const dv_engine_type *const *e = dv_engines_linked; *e; e++)
    if (strcmp((*e)->name, a->name) == 0) goto taken;
  for (size_t i = 0; i < nfound; i++)
    if (strcmp(found[i]->name, a->name) == 0) goto taken;
  if (nfound == DV_MAX_ADAPTERS) {
    problem("%s/manifest.ini: more than the %s adapters diskval takes\n", a->dir, "12");
    free(a);
    return;
  }
  availability(a);
  dv_adapter_make_type(a, nfound);
  found[nfound++] = a;
  return;
taken:
  problem("%s/manifest.ini: name: '%s' is an engine already\n", a->dir, a->name);
  free(a);
}

static int manifest_in(const char *dir) {
  char path[1200];
  snprintf(path, sizeof path, "%s/manifest.ini", dir);
  return exists(path);
}

static void scan(const char *dir, int quiet) {
  struct dirent **names;
  char sub[1024];
  if (manifest_in(dir)) return add(dir);
  const int n = scandir(dir, &names, NULL, alphasort);
  if (n < 0) {
    if (!quiet) problem("%s: no such folder (DISKVAL_ADAPTERS)%s\n", dir, "");
    return;
  }
  for (int i = 0; i < n; i++) {
    snprintf(sub, sizeof sub, "%s/%s", dir, names[i]->d_name);
    if (names[i]->d_name[0] != '.' && manifest_in(sub)) add(sub);
    free(names[i]);
  }
  free(names);
}

static void load(void) {
  scan(DV_ADAPTERS_DIR, 1);
  const char *extra = getenv("DISKVAL_ADAPTERS");
  if (!extra) return;
  char list[4096];
  snprintf(list, sizeof list, "%s", extra);
  for (char *save = NULL, *d = strtok_r(list, ":", &save); d; d = strtok_r(NULL, ":", &save))
    scan(d, 0);
}

size_t dv_adapters(const dv_adapter *const **out) {
  pthread_once(&once, load);
  if (out) *out = (const dv_adapter *const *)found;
  return nfound;
}

const char *dv_adapter_problems(void) {
  pthread_once(&once, load);
  return problems;
}

const dv_adapter *dv_adapter_of(const dv_engine_type *t) {
  pthread_once(&once, load);
  for (size_t i = 0; i < nfound; i++)
    if (&found[i]->type == t) return found[i];
  return NULL;
}
