/* dv_io_file: files that appear whole or not at all, and the paths to them.
 *
 * Output goes to a temporary file beside the target and is renamed over it
 * on commit; abort (or a failed write), SIGINT, SIGTERM or SIGHUP (with
 * dv_io_temp_clean_on_signals) remove it, and opening a path removes the
 * temporaries dead runs left in its directory (io_temp.h). "-" means stdout; an
 * existing device or pipe (/dev/null) is written in place, never replaced.
 * A symbolic link is written through: the regular file it ends at is
 * replaced (its temporary beside that file) and the link stays; one that
 * leads through /proc (/dev/stdout, /proc/self/fd/1) is a stream, written in
 * place; one to nothing (dangling, a loop) is refused.
 * A path that does not fit its buffer is an error, never cut short.
 */
#ifndef DV_OUTPUT_H
#define DV_OUTPUT_H

#include <stddef.h>
#include <stdio.h>

#include "dv_error.h"

typedef struct dv_io_file {
  FILE *fp;
  char path[1024];     /* final name, "" for stdout */
  char tmp_path[1060]; /* temporary name while writing: DIR/.diskval-tmp.PID.XXXXXX (io_temp.h) */
  int direct;          /* a device or pipe: written in place */
  char *buffer;        /* the stream's buffer, or NULL (stdio's own) */
} dv_io_file;

int dv_io_open(dv_io_file *out, const char *path, dv_error *err);

/* path may be given to dv_io_open (checked there too, and by commands before
 * any work): not a directory, nor a symbolic link to nothing; else DV_EINPUT */
int dv_io_check_output(const char *path, dv_error *err);
int dv_io_commit(dv_io_file *out, dv_error *err); /* flush, close, rename */
void dv_io_abort(dv_io_file *out);                /* NULL-safe, idempotent */

/* dv_io_open of the file name in the directory dir */
int dv_io_open_in(dv_io_file *out, const char *dir, const char *name, dv_error *err);

/* text as the whole of the file dir/name, written as dv_io_open does */
int dv_io_write_text(const char *dir, const char *name, const char *text, dv_error *err);

/* format a path into buf (size bytes); DV_EINPUT when it does not fit */
int dv_io_path(char *buf, size_t size, dv_error *err, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* a and b name the same file: the same regular file when both exist, else
 * the same path once their directories are resolved ("x", "./x", "d/../x") */
int dv_io_same_file(const char *a, const char *b);

/* path with its directory resolved (symbolic links, ".", ".."): the file
 * itself need not exist; 0, or -1 when the directory cannot be resolved */
int dv_io_canonical(const char *path, char *out, size_t size);

/* mkdir -p, but nothing made when a ".." would leave a directory not there
 * yet ("new/.."): an error naming path, DV_EINPUT */
int dv_io_make_dirs(const char *path, dv_error *err);

#endif
