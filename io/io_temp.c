/* dv_io_temp: temporaries named after their owner; stale ones and signals. */
#include "io_temp.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <ftw.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { MAX_TRACKED = 16, TRACKED_PATH = 1100 };

/* the temporaries of this process a signal removes; a slot is in use while
 * its owner is set (written after the path, cleared before reuse) */
static struct {
  volatile pid_t owner;
  char path[TRACKED_PATH];
} tracked[MAX_TRACKED];

int dv_io_temp_template(char *buf, size_t size, const char *prefix, dv_error *err) {
  const int len = snprintf(buf, size, "%s.tmp.%ld.XXXXXX", prefix, (long)getpid());
  if (len >= 0 && (size_t)len < size) return DV_OK;
  return dv_fail(err, DV_EINPUT, "path too long: %.200s...", prefix);
}

/* the pid written after marker in name, when the rest of name is what
 * follows a pid in that kind of temporary ("." and 6 characters, or nothing) */
static long owner_after(const char *name, const char *marker, size_t tail) {
  const char *at = NULL;
  for (const char *p = name; (p = strstr(p, marker)); p++) at = p;
  if (!at) return 0;
  const char *digits = at + strlen(marker), *end = digits;
  while (isdigit((unsigned char)*end)) end++;
  if (end == digits || end - digits > 9) return 0;
  if (tail == 0 ? *end != '\0' : (*end != '.' || strlen(end + 1) != tail)) return 0;
  return strtol(digits, NULL, 10);
}

int dv_io_temp_is_stale(const char *name) {
  long pid = owner_after(name, ".tmp.", 6);
  if (!pid) pid = owner_after(name, ".old.", 0);
  return pid > 0 && kill((pid_t)pid, 0) != 0 && errno == ESRCH;
}

/* nftw's callback for dv_io_remove_tree: this entry, its contents already gone */
static int remove_entry(const char *path, const struct stat *st, int flag, struct FTW *ftw) {
  (void)st, (void)flag, (void)ftw;
  return remove(path);
}

int dv_io_remove_tree(const char *path) {
  return nftw(path, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

int dv_io_temp_remove_stale(const char *dir, const char *prefix) {
  DIR *d = opendir(dir);
  if (!d) return 0;
  const size_t plen = prefix ? strlen(prefix) : 0;
  int removed = 0;
  for (struct dirent *e; (e = readdir(d));) {
    char path[4096];
    if (strncmp(e->d_name, prefix ? prefix : "", plen) || !dv_io_temp_is_stale(e->d_name)) continue;
    const int len = snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    if (len > 0 && (size_t)len < sizeof path && dv_io_remove_tree(path) == 0) removed++;
  }
  closedir(d);
  return removed;
}

void dv_io_temp_track(const char *path) {
  if (strlen(path) >= TRACKED_PATH) return; /* left to a later run's clean-up */
  for (int i = 0; i < MAX_TRACKED; i++)
    if (!tracked[i].owner) {
      memcpy(tracked[i].path, path, strlen(path) + 1);
      tracked[i].owner = getpid();
      return;
    }
}

void dv_io_temp_forget(const char *path) {
  for (int i = 0; i < MAX_TRACKED; i++)
    if (tracked[i].owner && !strcmp(tracked[i].path, path)) tracked[i].owner = 0;
}

/* remove this process's temporaries (a forked child's copies of its
 * parent's slots are not its own), then die of sig */
static void clean_and_die(int sig) {
  const pid_t self = getpid();
  for (int i = 0; i < MAX_TRACKED; i++)
    if (tracked[i].owner == self) unlink(tracked[i].path);
  signal(sig, SIG_DFL);
  raise(sig); /* delivered when the handler returns */
}

void dv_io_temp_clean_on_signals(void) {
  static const int sigs[] = {SIGINT, SIGTERM, SIGHUP};
  for (size_t i = 0; i < sizeof sigs / sizeof *sigs; i++) {
    struct sigaction old, sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = clean_and_die;
    sigemptyset(&sa.sa_mask);
    for (size_t k = 0; k < sizeof sigs / sizeof *sigs; k++) sigaddset(&sa.sa_mask, sigs[k]);
    if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
      sigaction(sigs[i], &sa, NULL);
  }
}
