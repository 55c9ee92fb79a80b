/* dv_io_owned: the mark of a directory diskval made, and the checks on it. */
#include "io_owned.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io_file.h"
#include "io_lock.h"
#include "io_temp.h"

int dv_io_owned(const char *path) {
  char mark[4096], head[sizeof DV_IO_MARK_TEXT] = "";
  struct stat st;
  if (lstat(path, &st) || !S_ISDIR(st.st_mode)) return 0;
  if (snprintf(mark, sizeof mark, "%s/" DV_IO_MARK, path) >= (int)sizeof mark) return 0;
  if (lstat(mark, &st) || !S_ISREG(st.st_mode)) return 0;
  FILE *f = fopen(mark, "r");
  if (!f) return 0;
  const size_t n = fread(head, 1, sizeof head - 1, f);
  fclose(f);
  head[n] = '\0';
  return !strncmp(head, "diskval output directory", 24);
}

int dv_io_mark(const char *dir, dv_error *err) {
  return dv_io_write_text(dir, DV_IO_MARK, DV_IO_MARK_TEXT, err);
}

int dv_io_check_replaceable(const char *path, dv_error *err) {
  struct stat st;
  if (lstat(path, &st)) {
    if (errno == ENOENT) return DV_OK;
    return dv_fail(err, DV_EINPUT, "%s: cannot look at it: %s", path, strerror(errno));
  }
  if (dv_io_owned(path)) return DV_OK;
  return dv_fail(err, DV_EINPUT,
                 "%s: a %s that diskval did not make is in the way (it has no " DV_IO_MARK
                 "); nothing was written: move it, or choose another --out or scenario name",
                 path, S_ISDIR(st.st_mode) ? "directory" : "file");
}

/* dir holds nothing but diskval's lock and temporaries */
static int empty(const char *dir) {
  DIR *d = opendir(dir);
  if (!d) return 0;
  int any = 0;
  for (struct dirent *e; !any && (e = readdir(d));)
    any = strcmp(e->d_name, ".") && strcmp(e->d_name, "..") &&
          strcmp(e->d_name, DV_IO_LOCK_NAME) &&
          strncmp(e->d_name, DV_IO_TEMP_PREFIX, strlen(DV_IO_TEMP_PREFIX));
  closedir(d);
  return !any;
}

int dv_io_own_dir(const char *dir, dv_error *err) {
  int status = dv_io_make_dirs(dir, err);
  if (status || dv_io_owned(dir)) return status;
  if (!empty(dir))
    return dv_fail(err, DV_EINPUT,
                   "%s: holds files diskval did not make (it has no " DV_IO_MARK
                   "); nothing was written: give a new or empty --out, or one diskval wrote",
                   dir);
  return dv_io_mark(dir, err);
}

int dv_io_within(const char *path, const char *dir) {
  char p[PATH_MAX + 256], d[PATH_MAX];
  if (!realpath(dir, d) || (!realpath(path, p) && dv_io_canonical(path, p, sizeof p))) return 0;
  const size_t n = strlen(d);
  return !strncmp(p, d, n) && (p[n] == '/' || p[n] == '\0');
}

int dv_io_dir_begin(char *tmp, size_t size, const char *parent, dv_error *err) {
  if (dv_io_temp_template(tmp, size, parent, err)) return DV_EINPUT;
  dv_io_temp_remove_stale(parent); /* what runs killed while writing here left */
  if (!mkdtemp(tmp)) return dv_fail(err, DV_ESYSTEM, "%s: %s", tmp, strerror(errno));
  dv_io_temp_track(tmp);
  const mode_t mask = umask(0);
  umask(mask);
  chmod(tmp, 0777 & ~mask); /* mkdtemp makes it private; a report is for reading */
  if (dv_io_mark(tmp, err)) return dv_io_dir_discard(tmp), DV_ESYSTEM;
  return DV_OK;
}

void dv_io_dir_discard(const char *tmp) {
  dv_io_remove_tree(tmp);
  dv_io_temp_forget(tmp);
}

/* move the marked directory final aside, into a new temporary directory of
 * parent whose path goes into old; 0, or -1 when there is none */
static int set_aside(const char *final, const char *parent, char *old, size_t size) {
  if (!dv_io_owned(final) || dv_io_temp_template(old, size, parent, NULL) || !mkdtemp(old))
    return -1;
  if (rename(final, old) == 0) return 0; /* a directory replaces an empty one */
  rmdir(old);
  return -1;
}

int dv_io_dir_install(const char *tmp, const char *final, const char *parent, dv_error *err) {
  char old[PATH_MAX];
  if (dv_io_check_replaceable(final, err)) {
    dv_io_dir_discard(tmp);
    return DV_EINPUT;
  }
  const int had_old = set_aside(final, parent, old, sizeof old) == 0;
  if (rename(tmp, final)) {
    dv_fail(err, DV_ESYSTEM, "%s: %s", final, strerror(errno));
    if (had_old) rename(old, final);
    dv_io_dir_discard(tmp);
    return DV_ESYSTEM;
  }
  dv_io_temp_forget(tmp);
  if (had_old) dv_io_remove_tree(old);
  return DV_OK;
}
