/* cli_args: one option parser for every diskval command (glibc getopt_long).
 *
 * A command describes its options in a table; the parser fills the caller's
 * variables, takes --help, --set and --quiet for every command, and refuses
 * with one line on stderr and exit status 2: an unknown option, a missing value, a
 * number that is not wholly a finite number in range ("1e-3x", "nan", ""),
 * an option of one value given twice (--out a --out b), and more or fewer
 * positional arguments than the command takes.
 */
#ifndef DV_CLI_ARGS_H
#define DV_CLI_ARGS_H

#include <stddef.h>

typedef enum dv_cli_kind {
  DV_CLI_FLAG = 0, /* int: set to 1 */
  DV_CLI_TEXT,     /* const char *: the argument */
  DV_CLI_REAL,     /* double: a finite number in [lo, hi] */
  DV_CLI_INT,      /* int: a whole number in [lo, hi] */
  DV_CLI_LIST,     /* dv_cli_list: every occurrence, in order */
} dv_cli_kind;

/* the values of an option that may be given many times (--set, --vary) */
typedef struct dv_cli_list {
  const char **items;
  size_t n, cap;
} dv_cli_list;

typedef struct dv_cli_option {
  const char *name; /* without the dashes: "engine" */
  dv_cli_kind kind;
  void *value; /* where the value goes, typed by kind */
  double lo, hi;
} dv_cli_option;

typedef struct dv_cli_command {
  const char *name; /* "simulate" */
  const char *help; /* printed for --help */
  const dv_cli_option *options;
  size_t noptions;
  size_t min_args, max_args; /* positional arguments (max: SIZE_MAX for any number) */
} dv_cli_command;

/* what every command gets */
typedef struct dv_cli_args {
  dv_cli_list sets; /* --set section.key=value, in order */
  dv_cli_list args; /* positional arguments */
  int quiet;        /* --quiet: no progress line or long-run warning (run_progress.h) */
} dv_cli_args;

enum { DV_CLI_RUN = -1 };

/* parse argv (argv[0] is the command's name): DV_CLI_RUN to go on, else the
 * exit status to end with (0 after --help, 2 after the one-line error) */
int dv_cli_parse(const dv_cli_command *cmd, int argc, char **argv, dv_cli_args *out);

/* free what dv_cli_parse allocated in out and in the command's list options */
void dv_cli_args_free(const dv_cli_command *cmd, dv_cli_args *out);

/* append item to list; -1 without memory */
int dv_cli_list_push(dv_cli_list *list, const char *item);

/* the jobs default: the number of processors online */
int dv_cli_default_jobs(void);

#endif
