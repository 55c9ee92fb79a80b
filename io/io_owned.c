/* dv_io_owned: the mark of a directory diskval made, and the checks on it. */
#include "io_owned.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

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
