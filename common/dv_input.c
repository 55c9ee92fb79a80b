/* dv_input: open(O_NONBLOCK), a bounded wait for a FIFO's writer, then blocking reads. */
#define _POSIX_C_SOURCE 200809L /* fdopen, O_CLOEXEC */
#include "dv_input.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

/* ms a FIFO waits for its first byte or its writer's end. A writer started
 * beside the reader ((cat s.ini > pipe &) then diskval pipe) had written
 * within 7.1 ms, the largest of 200 tries at load 2.7 (re-run: time
 * open(O_NONBLOCK) then poll(POLLIN) on such a pipe, 200 times). */
enum { WRITER_WAIT_MS = 2000 };

/* fd to blocking reads, as a stream; the byte already read (-1: none) put back */
static FILE *stream(int fd, int first) {
  const int flags = fcntl(fd, F_GETFL);
  FILE *fp = NULL;
  if (flags >= 0 && fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) == 0) fp = fdopen(fd, "rb");
  if (!fp) {
    const int saved = errno;
    close(fd);
    errno = saved;
    return NULL;
  }
  if (first >= 0) ungetc(first, fp);
  return fp;
}

FILE *dv_input_open(const char *path) {
  /* O_NONBLOCK: open(2) of a FIFO with no writer returns at once */
  const int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  struct stat st;
  if (fd < 0) return NULL;
  if (fstat(fd, &st) || !S_ISFIFO(st.st_mode)) return stream(fd, -1);
  /* its first byte, or its writer's end; a writer that has not come by then
   * never will, and the pipe reads as empty */
  struct pollfd pfd = {fd, POLLIN, 0};
  while (poll(&pfd, 1, WRITER_WAIT_MS) < 0 && errno == EINTR) {
  }
  unsigned char c;
  const ssize_t n = read(fd, &c, 1);
  /* EAGAIN: a writer has it open but has not written yet: wait for it */
  return stream(fd, n == 1 ? c : -1);
}
