/* dv_io_owned: diskval replaces only what it made.
 *
 * Every directory diskval makes for its output (a scenario's report
 * OUT/<name>/, the --out of suite, sweep and map) holds DV_IO_MARK, a file
 * naming the format. diskval removes or replaces a directory only when it
 * holds that mark; a path held by anything else is an error naming it, found
 * before anything is written. A command that writes files of fixed names
 * into --out (suite, sweep, map) takes only an --out that is new, empty, or
 * marked, so a user's own index.html or summary.json there is never replaced.
 */
#ifndef DV_IO_OWNED_H
#define DV_IO_OWNED_H

#include <stddef.h>
#include <stdint.h>

#include "dv_error.h"

#define DV_IO_MARK ".diskval-report"
#define DV_IO_MARK_TEXT "diskval output directory, format 1\n"
/* in the mark of a report directory put in place (dv_io_dir_install), after
 * the text: the names of its files, one a line; any other file found there
 * is a user's, and the directory is not replaced */
#define DV_IO_MARK_FILES "files:\n"
/* in the mark of a command's --out (suite, sweep, map), after the text and
 * before DV_IO_MARK_FILES, which lists the fixed-name files diskval wrote
 * there: any other file of such a name is a user's, never replaced */
#define DV_IO_MARK_OUT "out:\n"
/* in the mark of an --out whose files diskval checks by their bytes
 * (generate's scenes), between DV_IO_MARK_OUT and DV_IO_MARK_FILES: a line
 * "DIGEST NAME" for each such file, DIGEST the 16 hex digits of the
 * dv_io_digest of what diskval last wrote there */
#define DV_IO_MARK_SUMS "sums:\n"

/* path is a directory holding the mark */
int dv_io_owned(const char *path);

/* put the mark into dir (a directory this process made or owns) */
int dv_io_mark(const char *dir, dv_error *err);

/* path may be made or replaced: it does not exist, or it is a directory
 * holding the mark and nothing but the files its mark lists (a mark that
 * lists none, with a report.json there: report.json, report.md, *.csv,
 * *.svg); else DV_EINPUT, err naming path and what is there, or the file
 * diskval did not make */
int dv_io_check_replaceable(const char *path, dv_error *err);

/* make dir (mkdir -p) for a command's fixed-name outputs names (NULL-ended,
 * the command's main one first), or take an existing one that is empty
 * (apart from diskval's lock and temporaries) or marked, where each of names
 * is new or listed in the mark (a mark listing none: the directory holds
 * names[0]); the mark is put in, listing names; else DV_EINPUT naming dir,
 * or the file of those names diskval did not make */
int dv_io_own_dir(const char *dir, const char *const *names, dv_error *err);

/* the digest of len bytes (64-bit FNV-1a): what the mark records of a file */
uint64_t dv_io_digest(const void *bytes, size_t len);

/* says whether bytes (len of them) are what this run writes as names[i] */
typedef int (*dv_io_same_fn)(size_t i, const char *bytes, size_t len, void *arg);

/* each of names (NULL-ended) that is a file in the marked dir holds what
 * diskval last wrote there (a digest its mark records for that name), or
 * what this run writes there (same says so: a mark from before digests);
 * else DV_EINPUT naming the first that was edited. Nothing is written; a
 * dir not marked is left to dv_io_own_dir */
int dv_io_check_unedited(const char *dir, const char *const *names, dv_io_same_fn same, void *arg,
                         dv_error *err);

/* record in the mark of dir (taken by dv_io_own_dir) that diskval writes
 * names[i] as bytes of digests[i], i < n: beside the digests the mark holds
 * for them when also (before the files are written: a run stopped between
 * leaves either known), else in their place (once they are); the digests
 * of other names stay */
int dv_io_mark_sums(const char *dir, const char *const *names, const uint64_t *digests, size_t n,
                    int also, dv_error *err);

/* none of inputs[0..n) is the file dir/<one of names> (NULL-ended), an
 * output of the run; else DV_EINPUT naming both */
int dv_io_check_inputs(const char *dir, const char *const *names, const char *const *inputs,
                       size_t n, dv_error *err);

/* path is dir or lies inside it (both resolved as far as they exist, so
 * neither need exist yet): where path's name is, or where it leads */
int dv_io_within(const char *path, const char *dir);

/* a new temporary directory of parent (stale ones removed first), marked
 * and tracked for removal on a signal; its path in tmp */
int dv_io_dir_begin(char *tmp, size_t size, const char *parent, dv_error *err);

/* remove tmp (from dv_io_dir_begin) and stop tracking it */
void dv_io_dir_discard(const char *tmp);

/* put the complete directory tmp in place of final (in parent): a marked
 * final is set aside, tmp renamed in, the old one removed; anything else at
 * final is an error, and on failure tmp is removed and the old one kept */
int dv_io_dir_install(const char *tmp, const char *final, const char *parent, dv_error *err);

#endif
