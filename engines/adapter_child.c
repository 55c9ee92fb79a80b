/* adapter_child: a child process spoken to by lines (adapter_child.h). */
#define _GNU_SOURCE /* pipe2 */
#include "adapter_child.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define EXIT_POLL 0.25 /* s between looks at whether a silent adapter has exited */

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void close_fd(int *fd) {
  if (*fd >= 0) close(*fd);
  *fd = -1;
}

int dv_child_start(dv_child *c, const char *dir, char *const argv[], char *what, size_t size) {
  int in[2], out[2], err[2];
  memset(c, 0, sizeof *c);
  c->in = c->out = c->err = -1;
  /* close-on-exec from birth: another run's adapter, started meanwhile, inherits none */
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, in)) goto fail;
  if (pipe2(out, O_CLOEXEC)) goto fail_in;
  if (pipe2(err, O_CLOEXEC)) goto fail_out;
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) goto fail_err;
  if (pid == 0) {
    setpgid(0, 0);                    /* its own group: whatever it starts is killed with it */
    prctl(PR_SET_PDEATHSIG, SIGKILL); /* and it outlives no diskval, even a killed one */
    if (getppid() != parent) _exit(1);
    dup2(in[1], 0), dup2(out[1], 1), dup2(err[1], 2); /* dup2 clears close-on-exec */
    if (chdir(dir) == 0) execvp(argv[0], argv);
    dprintf(2, "cannot run %s in %s: %s\n", argv[0], dir, strerror(errno));
    _exit(127);
  }
  setpgid(pid, pid); /* as the child does: whichever runs first */
  close(in[1]), close(out[1]), close(err[1]);
  c->pid = pid, c->in = in[0], c->out = out[0], c->err = err[0];
  fcntl(c->err, F_SETFL, O_NONBLOCK);
  return 0;
fail_err:
  close(err[0]), close(err[1]);
fail_out:
  close(out[0]), close(out[1]);
fail_in:
  close(in[0]), close(in[1]);
fail:
  snprintf(what, size, "cannot start %s: %s", argv[0], strerror(errno));
  return -1;
}

int dv_child_write(dv_child *c, const char *text, char *what, size_t size) {
  size_t n = strlen(text), done = 0;
  while (done < n) {
    const ssize_t w = send(c->in, text + done, n - done, MSG_NOSIGNAL);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      snprintf(what, size, "the adapter closed its input (%s)", strerror(errno));
      return -1;
    }
    done += (size_t)w;
  }
  return 0;
}

/* keep the last non-empty line of standard error */
static void drain_err(dv_child *c) {
  char chunk[1024];
  ssize_t n;
  while (c->err >= 0 && (n = read(c->err, chunk, sizeof chunk)) != 0) {
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno != EAGAIN && errno != EWOULDBLOCK) close_fd(&c->err);
      return;
    }
    for (ssize_t i = 0; i < n; i++) {
      if (chunk[i] == '\n') {
        if (c->err_len) {
          c->err_line[c->err_len] = '\0';
          snprintf(c->err_tail, sizeof c->err_tail, "%s", c->err_line);
        }
        c->err_len = 0;
      } else if (c->err_len + 1 < sizeof c->err_line) {
        c->err_line[c->err_len++] = chunk[i] == '\t' || chunk[i] >= ' ' ? chunk[i] : '?';
      }
    }
  }
  if (c->err_len) { /* a last line without its newline is still its last line */
    c->err_line[c->err_len] = '\0';
    snprintf(c->err_tail, sizeof c->err_tail, "%s", c->err_line);
    c->err_len = 0;
  }
  close_fd(&c->err); /* its end */
}

/* a whole line in buf: moved to line, 1; else 0 */
static int take_line(dv_child *c, char *line, size_t size) {
  char *nl = memchr(c->buf, '\n', c->len);
  if (!nl) return 0;
  const size_t n = (size_t)(nl - c->buf);
  const size_t keep = n && c->buf[n - 1] == '\r' ? n - 1 : n; /* a CRLF line is a line */
  snprintf(line, size, "%.*s", (int)keep, c->buf);
  memmove(c->buf, nl + 1, c->len - n - 1);
  c->len -= n + 1;
  return 1;
}

int dv_child_read_line(dv_child *c, double timeout, char *line, size_t size, char *what,
                       size_t wsize) {
  const double end = now() + timeout;
  for (;;) {
    if (take_line(c, line, size)) return 0;
    if (c->len == sizeof c->buf) {
      snprintf(what, wsize, "a line longer than %d bytes", DV_CHILD_LINE);
      return -1;
    }
    if (c->out < 0) return 1;
    struct pollfd fds[2] = {{c->out, POLLIN, 0}, {c->err, POLLIN, 0}};
    const double left = end - now();
    if (left <= 0) {
      snprintf(what, wsize, "no answer within %g s", timeout);
      return -1;
    }
    const int r = poll(fds, c->err >= 0 ? 2 : 1, (int)ceil(fmin(left, EXIT_POLL) * 1000));
    if (r < 0 && errno != EINTR) {
      snprintf(what, wsize, "poll: %s", strerror(errno));
      return -1;
    }
    /* exited, though something it started may hold its output open: its end */
    if (r == 0 && !c->reaped && waitpid(c->pid, &c->status, WNOHANG) == c->pid) c->reaped = 1;
    if (r == 0 && c->reaped) return take_line(c, line, size) ? 0 : 1;
    if (r <= 0) continue;
    if (c->err >= 0 && fds[1].revents) drain_err(c);
    if (fds[0].revents) {
      const ssize_t n = read(c->out, c->buf + c->len, sizeof c->buf - c->len);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        close_fd(&c->out);
        if (c->len) { /* a last line without its newline is still a line */
          c->buf[c->len < sizeof c->buf ? c->len : sizeof c->buf - 1] = '\n';
          c->len = c->len < sizeof c->buf ? c->len + 1 : c->len;
        }
        continue;
      }
      c->len += (size_t)n;
    }
  }
}

void dv_child_stop(dv_child *c, double grace) {
  if (!c->pid) return;
  close_fd(&c->in);
  close_fd(&c->out);
  const double end = now() + grace;
  while (!c->reaped) {
    const pid_t r = waitpid(c->pid, &c->status, WNOHANG);
    if (r == c->pid || (r < 0 && errno != EINTR)) {
      c->reaped = 1;
      break;
    }
    if (now() >= end) {
      kill(-c->pid, SIGKILL);
      kill(c->pid, SIGKILL);
      while (waitpid(c->pid, &c->status, 0) < 0 && errno == EINTR) {
      }
      c->reaped = c->killed = 1;
      break;
    }
    struct timespec nap = {0, 2000000};
    nanosleep(&nap, NULL);
  }
  kill(-c->pid, SIGKILL); /* what it left running in its group */
  if (c->err >= 0) drain_err(c);
  close_fd(&c->err);
  c->pid = 0;
}

void dv_child_end_text(const dv_child *c, char *buf, size_t size) {
  if (c->killed)
    snprintf(buf, size, "it did not exit once its input was closed: killed");
  else if (WIFSIGNALED(c->status))
    snprintf(buf, size, "killed by signal %d", WTERMSIG(c->status));
  else
    snprintf(buf, size, "exited with status %d", WEXITSTATUS(c->status));
}
