/* dv_input: opening a file diskval reads, never blocking on a FIFO.
 *
 * A FIFO (or a named pipe of a shell's <(...)) is opened without waiting
 * for a writer: one that has a writer is read as any file, one that has
 * none reads as empty at once, so a command fails on it with one line
 * instead of waiting for ever. */
#ifndef DV_INPUT_H
#define DV_INPUT_H

#include <stdio.h>

/* path opened for reading (binary), close-on-exec; NULL with errno set */
FILE *dv_input_open(const char *path);

#endif
