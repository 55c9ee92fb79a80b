/* dv_input: opening a file diskval reads, never waiting for ever on a FIFO.
 *
 * A FIFO (a named pipe, or a shell's <(...)) is opened without waiting for a
 * writer, then given 2 s for its first byte: one that has a writer by then
 * is read as any file (its writer waited for), one that has none reads as
 * empty, so a command fails on it with one line instead of blocking. */
#ifndef DV_INPUT_H
#define DV_INPUT_H

#include <stdio.h>

/* path opened for reading (binary), close-on-exec; NULL with errno set */
FILE *dv_input_open(const char *path);

#endif
