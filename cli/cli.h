/* dv_commands: the diskval subcommands. Each returns the process exit status:
 * 0 success, 1 a tolerance failed, 2 bad input or a harness error. */
#ifndef DV_COMMANDS_H
#define DV_COMMANDS_H

enum { DV_EXIT_OK = 0, DV_EXIT_FAIL = 1, DV_EXIT_ERROR = 2 };

int dv_cli_simulate(int argc, char **argv);
int dv_cli_analyze(int argc, char **argv);
int dv_cli_engines(int argc, char **argv);
int dv_cli_compare(int argc, char **argv);
int dv_cli_suite(int argc, char **argv);
int dv_cli_sweep(int argc, char **argv);
int dv_cli_best(int argc, char **argv);
int dv_cli_attribute(int argc, char **argv);
int dv_cli_map(int argc, char **argv);

/* print "diskval: message" on stderr and return DV_EXIT_ERROR */
int dv_cli_usage_error(const char *command, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* shared option parsing: SCENARIO [--set k=v]... and command-specific flags */
typedef struct dv_common_args {
  const char *scenario;
  const char *sets[64];
  int nsets;
} dv_common_args;

/* consume --set at argv[*i]; 1 when consumed, 0 when not, -1 on error */
int dv_cli_take_set(dv_common_args *a, int argc, char **argv, int *i);

#endif
