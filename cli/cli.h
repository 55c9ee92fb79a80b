/* cli: the diskval subcommands, one file each (cmd_NAME.c). Each returns the
 * process exit status: 0 success, 1 a tolerance failed, 2 bad input or a
 * harness error. Options are parsed by cli_args.h. */
#ifndef DV_CLI_H
#define DV_CLI_H

enum { DV_EXIT_OK = 0, DV_EXIT_FAIL = 1, DV_EXIT_ERROR = 2 };

int dv_cli_simulate(int argc, char **argv);
int dv_cli_analyze(int argc, char **argv);
int dv_cli_engines(int argc, char **argv);
int dv_cli_compare(int argc, char **argv);
int dv_cli_judge(int argc, char **argv);
int dv_cli_suite(int argc, char **argv);
int dv_cli_sweep(int argc, char **argv);
int dv_cli_best(int argc, char **argv);
int dv_cli_attribute(int argc, char **argv);
int dv_cli_map(int argc, char **argv);
int dv_cli_verify(int argc, char **argv);
int dv_cli_generate(int argc, char **argv);
int dv_cli_league(int argc, char **argv);

/* print "diskval COMMAND: message (see diskval COMMAND --help)" on stderr;
 * returns DV_EXIT_ERROR */
int dv_cli_usage_error(const char *command, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* print "diskval COMMAND: message" on stderr; returns DV_EXIT_ERROR */
int dv_cli_error(const char *command, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* "unknown engine 'NAME' (one of: ...)" as a usage error */
int dv_cli_unknown_engine(const char *command, const char *name);

/* engines from "mujoco,ode"; NULL or "": every contact engine (NULL-terminated,
 * at most DV_MAX_ENGINES); loads then probe the settings of these only */
struct dv_engine_type;
struct dv_error;
int dv_cli_engine_list(const char *list, const struct dv_engine_type **engines,
                       struct dv_error *err);

/* the one engine a command runs (NULL: unknown, a no-op): loads then probe its
 * settings only */
void dv_cli_probe_only(const struct dv_engine_type *engine);

/* load path with sets (--set) applied, as dv_engine_load_scenario; a line on
 * stderr for each engine whose check replaced a setting the file or --set gave */
struct dv_scenario;
struct dv_cli_list;
int dv_cli_load_scenario(const char *command, const char *path, const struct dv_cli_list *sets,
                         struct dv_scenario *sc, struct dv_error *err);

/* dv_cli_load_scenario under a wall-time limit (compare and simulate
 * --timeout S): the settings probes of the load (engine_choose.h) and then
 * forecast(sc, ctx) (may be NULL: the up-front estimate, run_progress.h)
 * run first in a process of their own, killed at the command's deadline
 * (dv_exec_set_deadline), and hand back their choices and estimate, so the
 * load here probes no more. timeout <= 0 (or under mpirun): a plain load.
 * The file is read once, here (dv_scenario_keep_texts), and checked
 * before any probe. Killed at the deadline: DV_ESYSTEM "timed out after S
 * s", *timed_out 1, sc as loaded with nothing probed (its name, for an error
 * report); stopped by a signal: ended as the signal would end it. */
int dv_cli_load_scenario_within(const char *command, const char *path,
                                const struct dv_cli_list *sets, double timeout,
                                double (*forecast)(const struct dv_scenario *sc, void *ctx),
                                void *ctx, struct dv_scenario *sc, int *timed_out,
                                struct dv_error *err);

/* a suite's scenarios, each of files loaded in a process of its own (up to
 * jobs at a time) with its settings probes, under timeout s each (<= 0: no
 * limit), its choices handed back and the load repeated here into scs[k]
 * (which the caller filled with a load that probed nothing: the names and
 * checks, with dv_scenario_keep_texts on: no file is read twice).
 * ended[k] (n dv_exec_end): DV_EXEC_ARRIVED, loaded; DV_EXEC_TIMED_OUT,
 * killed at the limit; DV_EXEC_LOST, its process died: scs[k] as it was.
 * DV_OK, DV_EVENT when SIGINT, SIGTERM or SIGHUP stopped them (exec_pool.h),
 * or an error (a load here that failed, with err). Not under mpirun. */
int dv_cli_load_all_within(const char *command, const struct dv_cli_list *files,
                           const struct dv_cli_list *sets, int jobs, double timeout,
                           struct dv_scenario *scs, unsigned char *ended, struct dv_error *err);

/* the scenario files args names, appended to files: each DIR's *.ini (sorted),
 * and each FILE; none is an error (a line on stderr, DV_EXIT_ERROR) */
int dv_cli_scenario_files(const char *command, const struct dv_cli_list *args,
                          struct dv_cli_list *files);

/* the report layer's explainer of an engine's excess: attribution of the
 * scenario as the command loaded it (its --set overrides applied: sets is
 * kept for the callers, the file is not read again) */
/* mode: --cause's value (NULL: quick): "quick" tries each failing engine's
 * knobs in the order its failure points to and stops at the first that
 * removes the error, "full" tries every knob, "none" runs none and says so;
 * another is a usage error (exit 2) */
struct dv_report_explain;
int dv_cli_explainer(const char *command, const char *mode, const struct dv_cli_list *sets,
                     struct dv_report_explain *out);

#endif
