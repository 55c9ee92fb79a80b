/* dv_io_temp: temporaries named after their owner; stale ones and signals. */
#define _GNU_SOURCE /* getdents64 through syscall, O_DIRECTORY */
#include "io_temp.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "io_owned.h"

enum { MAX_TRACKED = 16, TRACKED_PATH = 1100 };

/* the temporaries of this process a signal removes; a slot is in use while
 * its owner is set (written after the path, cleared before reuse) */
static struct {
  volatile pid_t owner;
  char path[TRACKED_PATH];
} tracked[MAX_TRACKED];

int dv_io_temp_template(char *buf, size_t size, const char *dir, dv_error *err) {
  const int len = snprintf(buf, size, "%s/" DV_IO_TEMP_PREFIX "%ld.XXXXXX", dir, (long)getpid());
  if (len >= 0 && (size_t)len < size) return DV_OK;
  return dv_fail(err, DV_EINPUT, "path too long: %.200s...", dir);
}

/* the owner's pid in name when it is exactly .diskval-tmp.PID.XXXXXX, else 0 */
static long owner_of(const char *name) {
  const size_t plen = strlen(DV_IO_TEMP_PREFIX);
  if (strncmp(name, DV_IO_TEMP_PREFIX, plen)) return 0;
  const char *digits = name + plen, *end = digits;
  while (isdigit((unsigned char)*end)) end++;
  /* a PID as diskval prints it: no leading zero */
  if (end == digits || *digits == '0' || end - digits > 9 || *end != '.' || strlen(end + 1) != 6)
    return 0;
  for (const char *c = end + 1; *c; c++)
    if (!isalnum((unsigned char)*c)) return 0;
  return strtol(digits, NULL, 10);
}

int dv_io_temp_is_stale(const char *name) {
  const long pid = owner_of(name);
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

int dv_io_temp_remove_stale(const char *dir) {
  DIR *d = opendir(dir);
  if (!d) return 0;
  int removed = 0;
  for (struct dirent *e; (e = readdir(d));) {
    char path[4096];
    if (!dv_io_temp_is_stale(e->d_name)) continue;
    const int len = snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    if (len < 0 || (size_t)len >= sizeof path) continue;
    struct stat st;
    if (lstat(path, &st)) continue;
    /* a directory: a report diskval marked (a dead run's, whatever it holds), or
     * one that died before its mark, holding at most the mark's own temporary
     * file (killed between its mkstemp and its rename) */
    if (S_ISDIR(st.st_mode) && !dv_io_owned(path)) dv_io_temp_remove_stale(path);
    if (S_ISDIR(st.st_mode) ? (dv_io_owned(path) ? dv_io_remove_tree(path) : rmdir(path))
                            : S_ISREG(st.st_mode) ? unlink(path) : -1)
      continue;
    removed++;
  }
  closedir(d);
  return removed;
}

static const int cleaning_signals[] = {SIGINT, SIGTERM, SIGHUP};
enum { NSIGNALS = sizeof cleaning_signals / sizeof *cleaning_signals };

void dv_io_temp_hold_signals(sigset_t *old) {
  sigset_t held;
  sigemptyset(&held);
  for (int i = 0; i < NSIGNALS; i++) sigaddset(&held, cleaning_signals[i]);
  pthread_sigmask(SIG_BLOCK, &held, old);
}

void dv_io_temp_release_signals(const sigset_t *old) {
  pthread_sigmask(SIG_SETMASK, old, NULL);
}

int dv_io_temp_make(char *templ, int dir) {
  sigset_t old;
  dv_io_temp_hold_signals(&old);
  const int fd = dir ? (mkdtemp(templ) ? 0 : -1) : mkstemp(templ);
  if (fd >= 0) dv_io_temp_track(templ);
  const int e = errno;
  dv_io_temp_release_signals(&old); /* a signal held meanwhile is handled here */
  errno = e;
  return fd;
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

void dv_io_temp_remove(const char *path) {
  unlink(path);
  dv_io_temp_forget(path);
}

/* rm of a directory of plain files, with async-signal-safe calls only */
static void remove_flat_dir(const char *path) {
  static char buf[8192];
  const int fd = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW);
  if (fd < 0) return;
  for (long n; (n = syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0;)
    for (long at = 0; at < n;) {
      const struct dirent64 *e = (const struct dirent64 *)(buf + at);
      if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..")) unlinkat(fd, e->d_name, 0);
      at += e->d_reclen;
    }
  close(fd);
  rmdir(path);
}

/* remove this process's temporaries (a forked child's copies of its
 * parent's slots are not its own), then die of sig */
static void clean_and_die(int sig) {
  const pid_t self = getpid();
  for (int i = 0; i < MAX_TRACKED; i++)
    if (tracked[i].owner == self && unlink(tracked[i].path) && (errno == EISDIR || errno == EPERM))
      remove_flat_dir(tracked[i].path);
  signal(sig, SIG_DFL);
  raise(sig); /* delivered when the handler returns */
}

void dv_io_temp_clean_on_signals(void) {
  for (int i = 0; i < NSIGNALS; i++) {
    struct sigaction old, sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = clean_and_die;
    sigemptyset(&sa.sa_mask);
    for (int k = 0; k < NSIGNALS; k++) sigaddset(&sa.sa_mask, cleaning_signals[k]);
    if (sigaction(cleaning_signals[i], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
      sigaction(cleaning_signals[i], &sa, NULL);
  }
}
