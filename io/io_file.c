/* dv_io_file: write to a temporary file, rename on success. */
#include "io_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int dv_io_open(dv_io_file *out, const char *path, dv_error *err) {
  memset(out, 0, sizeof *out);
  if (!path || strcmp(path, "-") == 0) {
    out->fp = stdout;
    return DV_OK;
  }
  struct stat st;
  if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
    /* a device or a pipe (/dev/null, a FIFO): written directly, never replaced */
    if (S_ISDIR(st.st_mode)) return dv_fail(err, DV_ESYSTEM, "%s: is a directory", path);
    if (!(out->fp = fopen(path, "w")))
      return dv_fail(err, DV_ESYSTEM, "%s: cannot open: %s", path, strerror(errno));
    out->direct = 1;
    return DV_OK;
  }
  snprintf(out->path, sizeof out->path, "%s", path);
  snprintf(out->tmp_path, sizeof out->tmp_path, "%s.tmp.XXXXXX", path);
  int fd = mkstemp(out->tmp_path);
  if (fd < 0) return dv_fail(err, DV_ESYSTEM, "%s: cannot create: %s", path, strerror(errno));
  const mode_t mask = umask(0);
  umask(mask);
  fchmod(fd, 0666 & ~mask); /* mkstemp makes it private; outputs are for reading */
  out->fp = fdopen(fd, "w");
  if (!out->fp) {
    close(fd);
    unlink(out->tmp_path);
    return dv_fail(err, DV_ESYSTEM, "%s: cannot open: %s", path, strerror(errno));
  }
  return DV_OK;
}

int dv_io_commit(dv_io_file *out, dv_error *err) {
  if (!out->fp) return dv_fail(err, DV_ESYSTEM, "output not open");
  if (out->fp == stdout) {
    out->fp = NULL;
    return fflush(stdout) == 0 ? DV_OK : dv_fail(err, DV_ESYSTEM, "stdout: %s", strerror(errno));
  }
  if (out->direct) {
    const int bad = ferror(out->fp) | fclose(out->fp);
    out->fp = NULL;
    return bad ? dv_fail(err, DV_ESYSTEM, "write failed: %s", strerror(errno)) : DV_OK;
  }
  const int bad = ferror(out->fp) | fflush(out->fp) | fsync(fileno(out->fp));
  const int close_bad = fclose(out->fp);
  out->fp = NULL;
  if (bad || close_bad || rename(out->tmp_path, out->path)) {
    const int e = errno;
    unlink(out->tmp_path);
    return dv_fail(err, DV_ESYSTEM, "%s: write failed: %s", out->path, strerror(e));
  }
  return DV_OK;
}

void dv_io_abort(dv_io_file *out) {
  if (!out || !out->fp) return;
  if (out->fp != stdout) {
    fclose(out->fp);
    if (!out->direct) unlink(out->tmp_path);
  }
  out->fp = NULL;
}
