/* adapter_child: a child process spoken to by lines (docs/adapters.md).
 *
 * Its standard input is a socket (written with MSG_NOSIGNAL: a child that
 * died is a failed run, never a SIGPIPE that kills diskval); its standard
 * output is read line by line with a time-out; its standard error is drained
 * as it comes and its last line kept for the report. It runs under a guard
 * process (adapter_child.c), which ends it and every process it started,
 * in its process group or not, when it exits, when it is stopped, and when
 * diskval dies of any signal, SIGKILL included. A guard that is itself
 * stopped (SIGSTOP) is continued when the run ends; one that dies (killed by
 * its adapter, or from outside) leaves the adapter's processes to the process
 * that started it, which ends them if dv_child_adopt_orphans was called.
 */
#ifndef DV_ADAPTER_CHILD_H
#define DV_ADAPTER_CHILD_H

#include <stddef.h>
#include <sys/types.h>

#define DV_CHILD_LINE 4096 /* the longest line read */

typedef struct dv_child {
  pid_t pid; /* its guard's, which ends as it ended; 0: not running */
  int in, out, err;
  char buf[DV_CHILD_LINE]; /* standard output read, not yet a line */
  size_t len;
  char err_tail[160]; /* its last non-empty line on standard error */
  char err_line[160]; /* the line on standard error being read */
  size_t err_len;
  int status; /* as waitpid gave it, once reaped */
  int reaped;
  int killed; /* dv_child_stop killed it: it did not exit in its grace */
} dv_child;

/* from now on, this process and its forks (a pool's tasks) become child
 * subreapers (PR_SET_CHILD_SUBREAPER) as they start their first adapter, so
 * that what an adapter started, had its guard died, becomes theirs and is
 * killed as the guard's end is seen. The diskval command's, not a library's:
 * once called, the orphans of any grandchild of this process become its
 * children, and at a guard's end every child of this process that is outside
 * its process group and is no live guard of its own is killed with all it
 * started. Never undone. */
void dv_child_adopt_orphans(void);

/* run argv (argv[0] looked up on PATH) in dir; 0, or -1 with what set */
int dv_child_start(dv_child *c, const char *dir, char *const argv[], char *what, size_t size);

/* write text whole; 0, or -1 with what set (the child closed its input) */
int dv_child_write(dv_child *c, const char *text, char *what, size_t size);

/* the next line of standard output, without its '\n'. 0; 1 at the end of the
 * output (the child closed it or exited); -1 with what set: no line within
 * timeout s, or a line longer than DV_CHILD_LINE */
int dv_child_read_line(dv_child *c, double timeout, char *line, size_t size, char *what,
                       size_t wsize);

/* close its input, give it grace s to exit, then kill it and all it started; reap it.
 * Safe twice. */
void dv_child_stop(dv_child *c, double grace);

/* how it ended, once stopped: "exited with status 3", "killed by signal 11" */
void dv_child_end_text(const dv_child *c, char *buf, size_t size);

#endif
