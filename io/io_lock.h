/* dv_io_lock: one diskval run at a time writing into an output directory.
 *
 * The lock is a POSIX record lock (fcntl F_SETLK) on DIR/.diskval.lock: the
 * kernel drops it when its holder ends, however it ends, and a forked worker
 * never inherits it, so a killed run never leaves the directory locked, even
 * while its workers are still ending. The file is removed when the lock is
 * released, or when a signal ends the holder (io_temp.h).
 */
#ifndef DV_IO_LOCK_H
#define DV_IO_LOCK_H

#include "dv_error.h"

/* the lock file's name inside the directory */
#define DV_IO_LOCK_NAME ".diskval.lock"

/* take dir's lock into *fd without waiting: DV_OK, or DV_EINPUT when
 * another process holds it (err names the directory), DV_ESYSTEM when the
 * lock file cannot be made */
int dv_io_lock_dir(const char *dir, int *fd, dv_error *err);

/* release a lock taken by dv_io_lock_dir (fd < 0: nothing) */
void dv_io_unlock_dir(const char *dir, int fd);

/* hold the directory of path against other diskval runs committing files
 * there (flock on the directory, waiting), so that files renamed into place
 * together stay a pair; the descriptor to release, or -1 (nothing held) */
int dv_io_hold_dir_of(const char *path);
void dv_io_release_dir(int fd);

#endif
