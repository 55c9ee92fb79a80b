/* dv_io_lock: a POSIX record lock on DIR/.diskval.lock; flock on a directory. */
#define _DEFAULT_SOURCE /* flock */
#include "io_lock.h"

#include <libgen.h>
#include <sys/file.h>

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io_temp.h"

int dv_io_lock_dir(const char *dir, int *fd, dv_error *err) {
  char path[4096];
  *fd = -1;
  if (snprintf(path, sizeof path, "%s/" DV_IO_LOCK_NAME, dir) >= (int)sizeof path)
    return dv_fail(err, DV_EINPUT, "path too long: %.200s...", dir);
  /* a holder may remove the file between our open and our lock: the lock
   * counts only on the file that is still there under that name */
  for (int attempt = 0; attempt < 100; attempt++) {
    const int f = open(path, O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (f < 0) return dv_fail(err, DV_ESYSTEM, "%s: cannot create: %s", path, strerror(errno));
    struct flock whole = {.l_type = F_WRLCK, .l_whence = SEEK_SET};
    if (fcntl(f, F_SETLK, &whole)) {
      const int e = errno;
      close(f);
      if (e == EACCES || e == EAGAIN)
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
      dv_io_temp_track(path); /* a run ended by a signal leaves no lock file */
      return DV_OK;
    }
    close(f);
  }
  return dv_fail(err, DV_ESYSTEM, "%s: cannot lock: the lock file keeps changing", path);
}

void dv_io_unlock_dir(const char *dir, int fd) {
  char path[4096];
  if (fd < 0) return;
  if (snprintf(path, sizeof path, "%s/" DV_IO_LOCK_NAME, dir) < (int)sizeof path)
    unlink(path), dv_io_temp_forget(path);
  close(fd);
}

int dv_io_hold_dir_of(const char *path) {
  char dir[4096];
  if (snprintf(dir, sizeof dir, "%s", path) >= (int)sizeof dir) return -1;
  const int fd = open(dirname(dir), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0 && flock(fd, LOCK_EX)) return close(fd), -1;
  return fd;
}

void dv_io_release_dir(int fd) {
  if (fd >= 0) close(fd); /* closing drops the flock */
}
