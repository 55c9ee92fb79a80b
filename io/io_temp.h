/* dv_io_temp: temporaries that name their owner, and their clean-up.
 *
 * Every temporary file or directory beside an output is named
 * PREFIX.tmp.PID.XXXXXX (PID: the process writing it), and a report set aside
 * while its replacement moves in is PREFIX.old.PID. A temporary whose PID is
 * no live process (kill(PID, 0) says ESRCH) was left by a run that died
 * (kill -9, a crash, a time limit): any later run may remove it. One whose
 * owner lives is never touched, so runs writing beside each other do not
 * harm each other.
 *
 * The files dv_io_open makes are also removed when the process is ended by
 * SIGINT, SIGTERM or SIGHUP, once dv_io_temp_clean_on_signals is installed.
 */
#ifndef DV_IO_TEMP_H
#define DV_IO_TEMP_H

#include <stddef.h>

#include "dv_error.h"

/* prefix ".tmp.PID.XXXXXX" into buf, a template for mkstemp or mkdtemp */
int dv_io_temp_template(char *buf, size_t size, const char *prefix, dv_error *err);

/* name (a file name, no directory) is a temporary whose owner is dead */
int dv_io_temp_is_stale(const char *name);

/* remove the stale temporaries in dir whose names start with prefix ("" or
 * NULL: any), directories with their contents; the number removed */
int dv_io_temp_remove_stale(const char *dir, const char *prefix);

/* rm -r path (a file or a directory); 0 or -1 */
int dv_io_remove_tree(const char *path);

/* remember path (a temporary of this process) for removal on a signal;
 * forget it once it is renamed or removed */
void dv_io_temp_track(const char *path);
void dv_io_temp_forget(const char *path);

/* on SIGINT, SIGTERM, SIGHUP (those not ignored): remove the tracked
 * temporaries of this process, then die of the signal as before */
void dv_io_temp_clean_on_signals(void);

#endif
