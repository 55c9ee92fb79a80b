/* adapter_child: a child process spoken to by lines (adapter_child.h). */
#define _GNU_SOURCE /* pipe2, syscall */
#include "adapter_child.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/syscall.h>
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

/* The guard. An adapter's run must take with it every process the adapter
 * starts, whatever ends diskval, SIGKILL included. Its process group alone
 * does not: a child may leave it (setsid), and a diskval that dies of a
 * signal kills no group. So the adapter runs under a guard, the process
 * diskval starts (dv_child.pid), which
 *   - is a child subreaper (PR_SET_CHILD_SUBREAPER): whatever the adapter
 *     starts, once its parent dies, becomes the guard's child, never init's;
 *   - starts the adapter in a process group of its own (the guard's: no
 *     terminal's signal reaches it), the adapter dying with the guard
 *     (PR_SET_PDEATHSIG, SIGKILL);
 *   - waits for the run's end: the adapter exited (its end closes the run,
 *     as dv_child_read_line reads it), SIGTERM from dv_child_stop, or
 *     diskval's death (PR_SET_PDEATHSIG, SIGTERM: catchable, unlike the
 *     SIGKILL that killed diskval);
 *   - then kills the adapter's every descendant (their parent links read
 *     from /proc, scanned again until the guard has no child left: a process
 *     forked meanwhile is found at the next scan, an orphan is the guard's
 *     own) and ends as the adapter ended (its exit status, or its signal).
 * Why a process and not a cgroup: a cgroup needs a writable cgroupfs, which a
 * CI container seldom gives. Why in this process, not /proc/self/exe run
 * again: the C API runs adapters inside another program. So after fork the
 * guard makes only async-signal-safe calls (system calls, no allocation; the
 * calling process may have threads). /proc/PID/task/TID/children would give
 * the tree directly, but needs CONFIG_PROC_CHILDREN, which not every kernel
 * has (the test machine's has not): the scan of /proc/PID/stat works on all.
 *
 * The guard's own end. The adapter shares the guard's process group and
 * user, so it may stop the guard (SIGSTOP) or kill it (SIGKILL), and so may
 * anyone from outside. A stopped guard is continued (SIGCONT) when the run
 * ends, before its SIGTERM: it then ends the tree as ever; one stopped
 * again is killed, with its group, after GUARD_WAIT. A dead guard's
 * orphans (the adapter, killed by its PR_SET_PDEATHSIG, and all it started)
 * go to the nearest child subreaper above: under the diskval command
 * (dv_child_adopt_orphans) that is the process that started the guard,
 * diskval or a pool's task, made a subreaper at its first dv_child_start
 * (the flag is not inherited by fork). When it reaps a guard it sweeps
 * (sweep): every child of its that is a stray, neither a live guard of its
 * own (the registry, guard_pids) nor in its own process group (a pool's
 * tasks, which never leave it), is killed with all its descendants, the
 * scan repeated until none is left, as the guard does. Left out, and said:
 * a library's caller (a subreaper would change its own children's fate, and
 * the sweep would kill its children in other groups: so only on request),
 * and a process that both stops its guard and then outlives a diskval killed
 * by SIGKILL (nobody is left to continue the guard). Why not a cgroup or a
 * PID namespace, which no process escapes: neither is there without
 * privileges on a CI machine, and a fallback would be needed anyway. */

/* the guard's bounds: processes one scan of /proc holds and descendants it
 * kills (more: the next scan); scans, 5 ms apart, before it gives up (5 s: a
 * process in uninterruptible sleep dies only when it leaves it); the s
 * dv_child_stop gives a guard it told to end (its scans, and more), before it
 * kills the guard's group */
#define GUARD_SCAN 65536
#define GUARD_TREE 4096
#define GUARD_ROUNDS 1000
#define GUARD_WAIT 10.0

/* a scan's processes, their parents and groups, and the tree found: written
 * in a guard (its copy of this process's memory) and by the sweep of an
 * adopting process (the diskval command's: one thread) */
static pid_t scan_pid[GUARD_SCAN], scan_ppid[GUARD_SCAN], scan_pgid[GUARD_SCAN], tree[GUARD_TREE];
static unsigned char in_tree[GUARD_SCAN];

/* the live guards this process started (0: a free slot), at most GUARD_SLOTS
 * at a time; whether this process adopts orphans (dv_child_adopt_orphans);
 * the process made a subreaper (a fork's copy names its parent, not it) */
#define GUARD_SLOTS 64
static atomic_int guard_pids[GUARD_SLOTS];
static atomic_int adopting;
static atomic_int subreaper;

/* the stops a guard waits for, and the end of a child of its */
static const int guard_signals[] = {SIGTERM, SIGINT, SIGHUP, SIGQUIT, SIGCHLD};
enum { NGUARD_SIGNALS = sizeof guard_signals / sizeof *guard_signals };

/* never called (they are blocked and taken with sigwaitinfo): a signal the
 * caller ignores would be discarded, a SIGCHLD ignored would reap alone */
static void on_guard_signal(int sig) {
  (void)sig;
}

static void nap_ms(long ms) {
  struct timespec nap = {0, ms * 1000000L};
  nanosleep(&nap, NULL);
}

/* name as a whole decimal number in *n: 1, else 0 */
static int whole(const char *name, long *n) {
  *n = 0;
  if (!*name) return 0;
  for (; *name; name++) {
    if (*name < '0' || *name > '9' || *n > 100000000L) return 0;
    *n = *n * 10 + (*name - '0');
  }
  return 1;
}

/* fn(n, ctx) for every entry of the open directory dir named by a number */
static void each_numbered(int dir, void (*fn)(long n, int dir, void *ctx), void *ctx) {
  char buf[4096];
  long got;
  while ((got = syscall(SYS_getdents64, dir, buf, sizeof buf)) > 0)
    for (long off = 0; off < got;) {
      /* struct linux_dirent64: u64 ino, s64 off, u16 reclen, u8 type, the name */
      unsigned short reclen;
      memcpy(&reclen, buf + off + 16, sizeof reclen);
      long n;
      if (whole(buf + off + 19, &n)) fn(n, dir, ctx);
      off += reclen;
    }
}

/* one process of /proc: its parent and group, from /proc/PID/stat ("PID (comm) S PPID PGID ...") */
static void scan_one(long pid, int dir, void *ctx) {
  size_t *n = ctx;
  char path[24], stat[256];
  size_t len = 0;
  if (*n == GUARD_SCAN) return;
  for (long d = pid; d; d /= 10) len++; /* the digits, written backwards */
  for (long d = pid, k = (long)len - 1; k >= 0; d /= 10, k--) path[k] = (char)('0' + d % 10);
  memcpy(path + len, "/stat", 6);
  const int fd = openat(dir, path, O_RDONLY | O_CLOEXEC);
  if (fd < 0) return; /* gone meanwhile */
  const ssize_t got = read(fd, stat, sizeof stat - 1);
  close(fd);
  if (got <= 0) return;
  ssize_t k = got - 1; /* the comm may hold ')' and spaces: the last ')' ends it */
  while (k >= 0 && stat[k] != ')') k--;
  if (k < 0 || k + 4 >= got) return;
  long ppid = 0, pgid = 0;
  for (k += 4; k < got && stat[k] >= '0' && stat[k] <= '9'; k++) ppid = ppid * 10 + stat[k] - '0';
  for (k++; k < got && stat[k] >= '0' && stat[k] <= '9'; k++) pgid = pgid * 10 + stat[k] - '0';
  scan_pid[*n] = (pid_t)pid, scan_ppid[*n] = (pid_t)ppid, scan_pgid[*n] = (pid_t)pgid;
  in_tree[*n] = 0;
  ++*n;
}

/* a child of a sweeping process, pid in group pgid: a stray (no live guard of
 * its, no pool task: outside its group) */
static int stray(pid_t pid, pid_t pgid) {
  if (pgid == getpgrp()) return 0;
  for (int i = 0; i < GUARD_SLOTS; i++)
    if (atomic_load(&guard_pids[i]) == pid) return 0;
  return 1;
}

/* SIGKILL every descendant of self a scan of /proc finds; with strays_only,
 * those of its strays (stray) only. Its children killed, in tree[1..], their count */
static size_t kill_tree(pid_t self, int strays_only) {
  size_t n = 0, m = 0;
  const int dir = open("/proc", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return 0;
  each_numbered(dir, scan_one, &n);
  close(dir);
  tree[m++] = self;
  for (size_t i = 0; i < n && m < GUARD_TREE; i++) /* its children */
    if (scan_ppid[i] == self && (!strays_only || stray(scan_pid[i], scan_pgid[i])))
      tree[m++] = scan_pid[i], in_tree[i] = 1;
  const size_t children = m - 1;
  for (int grew = 1; grew && m < GUARD_TREE;) { /* a pass a generation */
    grew = 0;
    for (size_t i = 0; i < n && m < GUARD_TREE; i++)
      for (size_t j = 1; !in_tree[i] && j < m; j++)
        if (scan_ppid[i] == tree[j]) tree[m++] = scan_pid[i], in_tree[i] = 1, grew = 1;
  }
  for (size_t j = 1; j < m; j++) kill(tree[j], SIGKILL);
  return children;
}

/* end every descendant and reap them all; the adapter's wait status, if reaped, in *status */
static void end_tree(pid_t self, pid_t adapter, int *status) {
  for (int round = 0; round < GUARD_ROUNDS; round++) {
    int ws;
    pid_t r;
    kill_tree(self, 0);
    while ((r = waitpid(-1, &ws, WNOHANG)) > 0)
      if (r == adapter) *status = ws;
    if (r < 0 && errno == ECHILD) return; /* no descendant left: each had the guard above it */
    nap_ms(5);
  }
}

/* close every descriptor from 3 on (another run's pipes would keep its adapter's input open) */
static void close_one(long fd, int dir, void *ctx) {
  (void)ctx;
  if (fd >= 3 && fd != dir) close((int)fd);
}

static void close_from_3(void) {
#ifdef SYS_close_range
  if (syscall(SYS_close_range, 3U, ~0U, 0U) == 0) return;
#endif
  const int dir = open("/proc/self/fd", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) return;
  each_numbered(dir, close_one, NULL);
  close(dir);
}

/* the guard's life, in the child of fork; it ends as the adapter ended */
_Noreturn static void guard(pid_t parent, const int fds[3], const char *dir, char *const argv[]) {
  sigset_t waited, none;
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_guard_signal;
  sa.sa_flags = SA_NOCLDSTOP;
  sigemptyset(&waited);
  sigemptyset(&none);
  for (int i = 0; i < NGUARD_SIGNALS; i++) sigaddset(&waited, guard_signals[i]);
  sigprocmask(SIG_SETMASK, &waited, NULL); /* held from here: none is lost, none kills it */
  for (int i = 0; i < NGUARD_SIGNALS; i++) sigaction(guard_signals[i], &sa, NULL);
  setpgid(0, 0); /* its own group, the adapter's too */
  prctl(PR_SET_CHILD_SUBREAPER, 1);
  prctl(PR_SET_PDEATHSIG, SIGTERM); /* diskval's death, even by SIGKILL: caught, below */
  if (getppid() != parent) _exit(1);
  dup2(fds[0], 0), dup2(fds[1], 1), dup2(fds[2], 2); /* dup2 clears close-on-exec */
  close_from_3();
  const pid_t self = getpid();
  const pid_t adapter = fork();
  if (adapter == 0) {
    prctl(PR_SET_PDEATHSIG, SIGKILL); /* it outlives no guard */
    if (getppid() != self) _exit(1);
    sigprocmask(SIG_SETMASK, &none, NULL); /* exec gives the handlers back their defaults */
    if (chdir(dir) == 0) execvp(argv[0], argv);
    dprintf(2, "cannot run %s in %s: %s\n", argv[0], dir, strerror(errno));
    _exit(127);
  }
  if (adapter < 0) {
    static const char msg[] = "cannot start the adapter: fork failed\n";
    write(2, msg, sizeof msg - 1);
    _exit(127);
  }
  close(0), close(1), close(2); /* the pipes are the adapter's alone: its end closes them */
  int status = 0;
  siginfo_t si;
  for (;;) { /* until the adapter ends or a stop comes */
    const int sig = sigwaitinfo(&waited, &si);
    if (sig < 0) continue; /* EINTR */
    if (sig != SIGCHLD) break;
    siginfo_t w;
    for (;;) { /* reap the orphans that ended; look at the adapter, not reaping it */
      memset(&w, 0, sizeof w);
      if (waitid(P_ALL, 0, &w, WEXITED | WNOHANG | WNOWAIT) || w.si_pid == 0 || w.si_pid == adapter)
        break;
      waitpid(w.si_pid, NULL, 0);
    }
    if (w.si_pid == adapter) break;
  }
  end_tree(self, adapter, &status);
  if (WIFEXITED(status)) _exit(WEXITSTATUS(status));
  const int sig = WTERMSIG(status); /* die of the adapter's signal, dumping no core */
  const struct rlimit no_core = {0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  sa.sa_handler = SIG_DFL;
  sigaction(sig, &sa, NULL);
  sigprocmask(SIG_SETMASK, &none, NULL);
  kill(self, sig);
  _exit(128 + sig);
}

void dv_child_adopt_orphans(void) {
  atomic_store(&adopting, 1);
}

/* a slot of the registry that held from holds to (from 0: a guard enlisted;
 * to 0: struck off); 0, or -1: no slot held from */
static int registry_swap(pid_t from, pid_t to) {
  for (int i = 0; i < GUARD_SLOTS; i++) {
    int expected = from;
    if (atomic_compare_exchange_strong(&guard_pids[i], &expected, to)) return 0;
  }
  return -1;
}

/* an adopting process's strays, and all they started, killed and reaped (the
 * guard's end_tree, for the children of a guard that died) */
static void sweep(void) {
  const pid_t self = getpid();
  if (atomic_load(&subreaper) != self) return;
  for (int round = 0; round < GUARD_ROUNDS; round++) {
    const size_t children = kill_tree(self, 1);
    if (!children) return;
    for (size_t j = 1; j <= children; j++) waitpid(tree[j], NULL, WNOHANG);
    nap_ms(1);
  }
}

int dv_child_start(dv_child *c, const char *dir, char *const argv[], char *what, size_t size) {
  int in[2], out[2], err[2];
  memset(c, 0, sizeof *c);
  c->in = c->out = c->err = -1;
  if (atomic_load(&adopting) && atomic_load(&subreaper) != getpid()) {
    if (prctl(PR_SET_CHILD_SUBREAPER, 1)) goto fail;
    atomic_store(&subreaper, getpid());
  }
  /* close-on-exec from birth: another run's adapter, started meanwhile, inherits none */
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, in)) goto fail;
  if (pipe2(out, O_CLOEXEC)) goto fail_in;
  if (pipe2(err, O_CLOEXEC)) goto fail_out;
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) goto fail_err;
  if (pid == 0) {
    const int fds[3] = {in[1], out[1], err[1]};
    guard(parent, fds, dir, argv);
  }
  setpgid(pid, pid); /* as the guard does: whichever runs first */
  if (atomic_load(&adopting) && registry_swap(0, pid)) { /* a sweep would take it for a stray */
    kill(-pid, SIGKILL), kill(pid, SIGKILL);
    while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {
    }
    close(in[0]), close(out[0]), close(err[0]);
    close(in[1]), close(out[1]), close(err[1]);
    snprintf(what, size, "cannot start %s: %d adapters run in this process already", argv[0],
             GUARD_SLOTS);
    return -1;
  }
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

/* the guard ended, or killed now (how: 0, the guard exited; 1, it is
 * killed): its group killed (what the adapter left there, had the guard
 * itself been killed) while its pid is still the guard's, the guard reaped,
 * out of the registry, and what it left to this process swept */
static void bury(dv_child *c, int kill_it) {
  kill(-c->pid, SIGKILL);
  if (kill_it) kill(c->pid, SIGKILL);
  while (waitpid(c->pid, &c->status, 0) < 0 && errno == EINTR) {
  }
  c->reaped = 1;
  registry_swap(c->pid, 0);
  sweep();
}

/* the guard reaped once it has ended (bury). 1 once reaped */
static int reap(dv_child *c) {
  siginfo_t si;
  memset(&si, 0, sizeof si);
  if (!c->reaped && waitid(P_PID, (id_t)c->pid, &si, WEXITED | WNOHANG | WNOWAIT) < 0 &&
      errno != EINTR) { /* reaped by someone else (SIGCHLD ignored): no status */
    c->reaped = 1;
    registry_swap(c->pid, 0);
    sweep();
  }
  if (!c->reaped && si.si_pid == c->pid) bury(c, 0);
  return c->reaped;
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
    if (r == 0 && reap(c)) return take_line(c, line, size) ? 0 : 1;
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
  if (!c->reaped) kill(c->pid, SIGCONT); /* a stopped guard never sees the adapter's end */
  while (!reap(c)) {
    if (!c->killed && now() >= end) {
      kill(c->pid, SIGTERM); /* the guard ends the adapter and all it started, then itself */
      kill(c->pid, SIGCONT);
      c->killed = 1;
    } else if (c->killed && now() >= end + GUARD_WAIT) { /* a guard that hangs: its group */
      bury(c, 1);
      break;
    }
    nap_ms(2);
  }
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
