/* dv_io_file: write to a temporary file, rename on success; paths. */
#include "io_file.h"

#include <errno.h>
#include <libgen.h>
#include <limits.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io_owned.h"
#include "io_temp.h"

/* vsnprintf that refuses to cut a path short */
int dv_io_path(char *buf, size_t size, dv_error *err, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  const int len = vsnprintf(buf, size, fmt, ap);
  va_end(ap);
  if (len >= 0 && (size_t)len < size) return DV_OK;
  return dv_fail(err, DV_EINPUT, "path too long: %.200s...", buf);
}

/* path is a symbolic link that leads, maybe through others, through /proc
 * (/dev/stdout, /proc/self/fd/1, /dev/fd/3): a stream of a process, not a
 * file's name, even when what is open there is a regular file */
static int through_proc(const char *path) {
  char cur[PATH_MAX], next[PATH_MAX], where[PATH_MAX + 256];
  snprintf(cur, sizeof cur, "%s", path);
  for (int hop = 0; hop < 40; hop++) { /* the kernel's own limit on a chain */
    struct stat st;
    if (lstat(cur, &st) || !S_ISLNK(st.st_mode)) return 0;
    if (dv_io_canonical(cur, where, sizeof where)) return 0;
    if (!strncmp(where, "/proc/", 6)) return 1;
    const ssize_t n = readlink(cur, next, sizeof next - 1);
    if (n < 0) return 0;
    next[n] = '\0';
    char *slash = strrchr(where, '/');
    slash[1] = '\0'; /* a relative link is read from the link's own directory */
    if (next[0] != '/' && (strlen(where) + strlen(next) >= sizeof cur)) return 0;
    snprintf(cur, sizeof cur, "%s%s", next[0] == '/' ? "" : where, next);
  }
  return 0;
}

/* a device or a pipe (/dev/null, a FIFO, a terminal), or a regular file
 * reached through /proc: written where it is (appended to, for a file: the
 * stream's own position is not ours to rewind), never replaced */
#define DV_IO_BUFFER_BYTES (256 * 1024)

static int open_in_place(dv_io_file *out, const char *path, int regular, dv_error *err) {
  if (!(out->fp = fopen(path, regular ? "a" : "w")))
    return dv_fail(err, DV_ESYSTEM, "%s: cannot open: %s", path, strerror(errno));
  out->direct = 1;
  return DV_OK;
}

int dv_io_check_output(const char *path, dv_error *err) {
  struct stat st;
  if (!path || !strcmp(path, "-") || lstat(path, &st)) return DV_OK;
  if (S_ISLNK(st.st_mode) && stat(path, &st))
    return dv_fail(err, DV_EINPUT,
                   "%s: a symbolic link to nothing (%s); nothing was written: make the file it "
                   "names, or give another path",
                   path, errno == ELOOP ? "a loop" : "its target does not exist");
  if (S_ISDIR(st.st_mode)) return dv_fail(err, DV_EINPUT, "%s: is a directory", path);
  return DV_OK;
}

int dv_io_open(dv_io_file *out, const char *path, dv_error *err) {
  memset(out, 0, sizeof *out);
  if (!path || strcmp(path, "-") == 0) {
    out->fp = stdout;
    return DV_OK;
  }
  if (strlen(path) >= sizeof out->path)
    return dv_fail(err, DV_EINPUT, "path too long: %.200s...", path);
  if (dv_io_check_output(path, err)) return DV_EINPUT;
  struct stat lst, st;
  const int link = lstat(path, &lst) == 0 && S_ISLNK(lst.st_mode);
  if (stat(path, &st)) st.st_mode = S_IFREG; /* a new file */
  if (!S_ISREG(st.st_mode)) return open_in_place(out, path, 0, err);
  if (link && through_proc(path)) return open_in_place(out, path, 1, err);
  char real[PATH_MAX];
  if (link) { /* written through: the file the link names is replaced, the link stays */
    if (!realpath(path, real))
      return dv_fail(err, DV_ESYSTEM, "%s: cannot resolve: %s", path, strerror(errno));
    if (strlen(real) >= sizeof out->path)
      return dv_fail(err, DV_EINPUT, "path too long: %.200s...", real);
    path = real;
  }
  snprintf(out->path, sizeof out->path, "%s", path);
  char dir[sizeof out->path];
  snprintf(dir, sizeof dir, "%s", path);
  const char *where = dirname(dir);
  dv_io_temp_remove_stale(where); /* what runs killed while writing here left */
  if (dv_io_temp_template(out->tmp_path, sizeof out->tmp_path, where, err)) return DV_EINPUT;
  int fd = dv_io_temp_make(out->tmp_path, 0);
  if (fd < 0) return dv_fail(err, DV_ESYSTEM, "%s: cannot create: %s", path, strerror(errno));
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask); /* mkstemp makes it private; outputs are for reading */
  out->fp = fdopen(fd, "w");
  if (!out->fp) {
    close(fd);
    unlink(out->tmp_path);
    dv_io_temp_forget(out->tmp_path);
    return dv_fail(err, DV_ESYSTEM, "%s: cannot open: %s", path, strerror(errno));
  }
  /* a fine trajectory is megabytes: a write call per 4 KiB block was a tenth of its run
   * (glibc takes the size only with the buffer) */
  out->buffer = malloc(DV_IO_BUFFER_BYTES);
  if (out->buffer) setvbuf(out->fp, out->buffer, _IOFBF, DV_IO_BUFFER_BYTES);
  return DV_OK;
}

/* dir/name, refused when too long for a dv_io_file */
int dv_io_open_in(dv_io_file *out, const char *dir, const char *name, dv_error *err) {
  char path[sizeof out->path];
  memset(out, 0, sizeof *out);
  const int status = dv_io_path(path, sizeof path, err, "%s/%s", dir, name);
  return status ? status : dv_io_open(out, path, err);
}

int dv_io_write_text(const char *dir, const char *name, const char *text, dv_error *err) {
  dv_io_file f;
  int status = dv_io_open_in(&f, dir, name, err);
  if (status) return status;
  fputs(text, f.fp);
  status = dv_io_commit(&f, err);
  dv_io_abort(&f);
  return status;
}

/* fclose's status; the stream's buffer goes with it */
static int close_stream(dv_io_file *out) {
  const int status = fclose(out->fp);
  out->fp = NULL;
  free(out->buffer);
  out->buffer = NULL;
  return status;
}

int dv_io_commit(dv_io_file *out, dv_error *err) {
  if (!out->fp) return dv_fail(err, DV_ESYSTEM, "output not open");
  if (out->fp == stdout) {
    out->fp = NULL;
    return fflush(stdout) == 0 ? DV_OK : dv_fail(err, DV_ESYSTEM, "stdout: %s", strerror(errno));
  }
  if (out->direct) {
    const int bad = ferror(out->fp) | close_stream(out);
    return bad ? dv_fail(err, DV_ESYSTEM, "write failed: %s", strerror(errno)) : DV_OK;
  }
  const int bad = ferror(out->fp) | fflush(out->fp) | fsync(fileno(out->fp));
  const int close_bad = close_stream(out);
  if (bad || close_bad || rename(out->tmp_path, out->path)) {
    const int e = errno;
    unlink(out->tmp_path);
    dv_io_temp_forget(out->tmp_path);
    return dv_fail(err, DV_ESYSTEM, "%s: write failed: %s", out->path, strerror(e));
  }
  dv_io_temp_forget(out->tmp_path);
  return DV_OK;
}

void dv_io_abort(dv_io_file *out) {
  if (!out || !out->fp) return;
  if (out->fp != stdout) {
    close_stream(out);
    if (!out->direct) unlink(out->tmp_path), dv_io_temp_forget(out->tmp_path);
  }
  out->fp = NULL;
}

/* a ".." of path that would leave a directory not there yet ("new/.."): made
 * only to be left, it would stay behind a refused run; 0, or DV_EINPUT with err.
 * Nothing is made before this check. */
static int leaves_new(const char *path, char *buf, dv_error *err) {
  int missing = 0;
  for (char *p = buf + (buf[0] != '\0');; p++) {
    const char c = *p;
    if (c != '/' && c != '\0') continue;
    *p = '\0';
    const char *last = strrchr(buf, '/');
    struct stat st;
    if (missing && !strcmp(last ? last + 1 : buf, ".."))
      return dv_fail(err, DV_EINPUT,
                     "%s: its '..' leaves a directory that does not exist; nothing was written: "
                     "give the path without it",
                     path);
    if (!missing && buf[0] && stat(buf, &st)) missing = 1;
    *p = c;
    if (!c) return DV_OK;
  }
}

/* every missing directory of path, from the top; none when a ".." would
 * leave one of them */
int dv_io_make_dirs(const char *path, dv_error *err) {
  char buf[4096];
  int status = dv_io_path(buf, sizeof buf, err, "%s", path);
  if (status || (status = leaves_new(path, buf, err))) return status;
  for (char *p = buf + (buf[0] != '\0');; p++) { /* "/a/b": not "" first */
    const char c = *p;
    if (c != '/' && c != '\0') continue;
    *p = '\0';
    if (mkdir(buf, 0777) && errno != EEXIST)
      return dv_fail(err, DV_ESYSTEM, "%s: cannot create: %s", buf, strerror(errno));
    *p = c;
    if (!c) break;
  }
  /* an existing file of another kind, or a directory nothing can be written into */
  struct stat st;
  if (stat(buf, &st) || !S_ISDIR(st.st_mode))
    return dv_fail(err, DV_ESYSTEM, "%s: not a directory", buf);
  if (access(buf, W_OK | X_OK))
    return dv_fail(err, DV_ESYSTEM, "%s: cannot write into it: %s", buf, strerror(errno));
  return DV_OK;
}

int dv_io_canonical(const char *path, char *out, size_t size) {
  char dir[4096], base[4096], real[PATH_MAX];
  if (snprintf(dir, sizeof dir, "%s", path) >= (int)sizeof dir) return -1;
  snprintf(base, sizeof base, "%s", path);
  if (!realpath(dirname(dir), real)) return -1;
  const int len = snprintf(out, size, "%s/%s", real, basename(base));
  return len >= 0 && (size_t)len < size ? 0 : -1;
}

int dv_io_same_file(const char *a, const char *b) {
  struct stat sa, sb;
  if (stat(a, &sa) == 0 && stat(b, &sb) == 0) /* a device (/dev/null) may take both */
    return S_ISREG(sa.st_mode) && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  char ca[PATH_MAX + 256], cb[PATH_MAX + 256];
  if (dv_io_canonical(a, ca, sizeof ca) || dv_io_canonical(b, cb, sizeof cb))
    /* a directory not yet made: each resolved as far as it exists */
    return !strcmp(a, b) || (dv_io_within(a, b) && dv_io_within(b, a));
  return !strcmp(ca, cb);
}
