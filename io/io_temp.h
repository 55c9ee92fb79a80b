/* dv_io_temp: temporaries that name their owner, and their clean-up.
 *
 * Every temporary file or directory diskval makes is named
 * .diskval-tmp.PID.XXXXXX (PID: the process that made it), in the directory
 * its output goes to: a file being written, a report directory being built,
 * and a report set aside while its replacement moves in. Nothing else is
 * ever taken for a temporary. One whose PID is no live process (kill(PID, 0)
 * says ESRCH) was left by a run that died (kill -9, a crash, a time limit):
 * a later run writing into that directory may remove it (a directory only
 * when diskval made it, io_owned.h, or when it is empty). One whose owner
 * lives is never touched, so runs writing beside each other do not harm
 * each other.
 *
 * The temporaries a process tracks (files, and report directories of plain
 * files) are removed when it is ended by SIGINT, SIGTERM or SIGHUP, once
 * dv_io_temp_clean_on_signals is installed.
 */
#ifndef DV_IO_TEMP_H
#define DV_IO_TEMP_H

#include <signal.h>
#include <stddef.h>

#include "dv_error.h"

/* the one prefix of every temporary's name */
#define DV_IO_TEMP_PREFIX ".diskval-tmp."

/* "DIR/.diskval-tmp.PID.XXXXXX" into buf, a template for mkstemp or mkdtemp */
int dv_io_temp_template(char *buf, size_t size, const char *dir, dv_error *err);

/* name (a file name, no directory) is a temporary whose owner is dead */
int dv_io_temp_is_stale(const char *name);

/* remove the stale temporaries in dir; the number removed */
int dv_io_temp_remove_stale(const char *dir);

/* rm -r path (a file or a directory); 0 or -1 */
int dv_io_remove_tree(const char *path);

/* mkstemp (dir 0: returns the descriptor) or mkdtemp (dir 1: returns 0) on
 * templ, tracked for removal on a signal; the signals wait meanwhile, so a
 * temporary exists only once it is tracked. -1 with errno on failure */
int dv_io_temp_make(char *templ, int dir);

/* remove a temporary file dv_io_temp_make made, and forget it */
void dv_io_temp_remove(const char *path);

/* hold SIGINT, SIGTERM and SIGHUP back (old: the mask to restore), and let
 * them through again: around making a file and tracking it */
void dv_io_temp_hold_signals(sigset_t *old);
void dv_io_temp_release_signals(const sigset_t *old);

/* remember path (a temporary of this process, or its lock file) for
 * removal on a signal; forget it once it is renamed or removed */
void dv_io_temp_track(const char *path);
void dv_io_temp_forget(const char *path);

/* on SIGINT, SIGTERM, SIGHUP (those not ignored): remove the tracked
 * temporaries of this process, then die of the signal as before */
void dv_io_temp_clean_on_signals(void);

#endif
