/* dv_input: open(O_NONBLOCK), then blocking reads. */
#define _POSIX_C_SOURCE 200809L /* fdopen, O_CLOEXEC */
#include "dv_input.h"

#include <errno.h>
#include <fcntl.h>
#include <unistd.h>

FILE *dv_input_open(const char *path) {
  /* O_NONBLOCK: open(2) of a FIFO with no writer returns at once */
  const int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return NULL;
  const int flags = fcntl(fd, F_GETFL);
  FILE *fp = NULL;
  /* reads block again: a writer's pipe is waited for, one with none is at its end */
  if (flags >= 0 && fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) == 0) fp = fdopen(fd, "rb");
  if (!fp) {
    const int saved = errno;
    close(fd);
    errno = saved;
  }
  return fp;
}
