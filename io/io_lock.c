/* dv_io_lock: flock on DIR/.diskval.lock. */
#define _DEFAULT_SOURCE /* flock */
#include "io_lock.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

int dv_io_lock_dir(const char *dir, int *fd, dv_error *err) {
  char path[4096];
  *fd = -1;
  if (snprintf(path, sizeof path, "%s/" DV_IO_LOCK_NAME, dir) >= (int)sizeof path)
    return dv_fail(err, DV_EINPUT, "path too long: %.200s...", dir);
  /* a holder may remove the file between our open and our flock: the lock
   * counts only on the file that is still there under that name */
  for (int attempt = 0; attempt < 100; attempt++) {
    const int f = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (f < 0) return dv_fail(err, DV_ESYSTEM, "%s: cannot create: %s", path, strerror(errno));
    if (flock(f, LOCK_EX | LOCK_NB)) {
      const int e = errno;
      close(f);
      if (e == EWOULDBLOCK)
        return dv_fail(err, DV_EINPUT,
                       "%s: another diskval run is writing into this directory (%s is locked); "
                       "wait for it to end or choose another --out",
                       dir, path);
      return dv_fail(err, DV_ESYSTEM, "%s: cannot lock: %s", path, strerror(e));
    }
    struct stat held, named;
    if (fstat(f, &held) == 0 && stat(path, &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino) {
      *fd = f;
      return DV_OK;
    }
    close(f);
  }
  return dv_fail(err, DV_ESYSTEM, "%s: cannot lock: the lock file keeps changing", path);
}

void dv_io_unlock_dir(const char *dir, int fd) {
  char path[4096];
  if (fd < 0) return;
  if (snprintf(path, sizeof path, "%s/" DV_IO_LOCK_NAME, dir) < (int)sizeof path) unlink(path);
  close(fd);
}
