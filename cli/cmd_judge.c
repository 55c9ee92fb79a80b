/* dv_cli_judge: diskval judge SCENARIO TRAJECTORY...: trajectories from any
 * other engine judged against the reference as compare judges a linked one. */
#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cli_args.h"
#include "engine_choose.h"
#include "io_lock.h"
#include "report_judge.h"
#include "report_suite_dir.h"
#include "run_progress.h"
#include "search_verify.h"

static const char HELP[] =
    "usage: diskval judge SCENARIO TRAJECTORY... [--name NAME[,NAME...]] [--out DIR] [--junit "
    "FILE]\n"
    "\n"
    "Judge trajectories of SCENARIO recorded elsewhere (any engine, any sampling) against the\n"
    "reference, as compare judges a linked engine: every metric with its limit, the horizon,\n"
    "the lying down, the validity window; DIR/<scenario>/ as compare writes it (default DIR:\n"
    "report), and the JUnit XML to FILE. A TRAJECTORY is a CSV in the state form\n"
    "(t,theta[,phi,psi,x,y][,contact_x,contact_y][,theta_dot,phi_dot,psi_dot][,energy]) or the\n"
    "pose form (t,x,y,z,qw,qx,qy,qz[,vx,vy,vz,wx,wy,wz]); docs/judge.md.\n"
    "--name: each trajectory's name in the report: 1 to 40 letters, digits, '_-.+', not\n"
    "starting with '.' (as a scenario's). Default: its file name without extension, cut to 40\n"
    "characters, and where that is no such name, every character but those '_'. No name is\n"
    "matched-NAME of another, whose matched reference a thick scene's report writes so.\n"
    "--step H1,H2,H3[,...]: the time step of each of 3 to 8 trajectories of one engine, each\n"
    "smaller than the one before (halving, as verify refines, or any ratio of at least 1.1):\n"
    "their theta errors give the order and the extrapolated discrepancy, as verify does (exit 1\n"
    "unless it converges to the reference; errors that do not fall, or two the same: not\n"
    "judged). Without --step: the files' own \"# dt = H\" comment lines, when 3 or more files\n"
    "all give one.\n"
    "Exit status: 0 all pass, 1 a tolerance failed or nothing could be judged, 2 bad input\n"
    "(a bad file: one line naming its file, line and column) or error.\n";

#define MAX_NAME 40 /* a report's column */

/* a name a report can carry: letters, digits, '_', '-', '.', '+', not a linked
 * engine's, and a file name as a scenario's name is (no leading '.') */
static int check_name(const char *name, dv_error *err) {
  if (!*name || strlen(name) > MAX_NAME)
    return dv_fail(err, DV_EINPUT, "name '%.60s': 1 to %d characters", name, MAX_NAME);
  for (const char *p = name; *p; p++)
    if (!isalnum((unsigned char)*p) && !strchr("_-.+", *p))
      return dv_fail(err, DV_EINPUT,
                     "name '%.60s': only letters, digits, '_', '-', '.' and '+' (give --name)",
                     name);
  char what[200];
  if (dv_scenario_check_name(name, what, sizeof what)) /* a file in the report, as a scenario's */
    return dv_fail(err, DV_EINPUT, "name %s (give --name)", what);
  if (dv_engine_find(name))
    return dv_fail(err, DV_EINPUT,
                   "name '%s' is a linked engine's: its report would carry that engine's "
                   "settings (give --name)",
                   name);
  return DV_OK;
}

/* --step: one step a trajectory, DV_CONVERGE_MIN_LEVELS..MAX_LEVELS of them,
 * each smaller than the one before by a ratio of at least DV_CONVERGE_MIN_RATIO */
static int parse_steps(const char *list, size_t n, double *steps, dv_error *err) {
  char buf[512];
  snprintf(buf, sizeof buf, "%s", list);
  size_t k = 0;
  for (char *save, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save), k++) {
    char *end;
    const double h = strtod(tok, &end);
    if (*end || end == tok || !(h > 0.0) || !isfinite(h))
      return dv_fail(err, DV_EINPUT, "--step: '%.40s' is not a positive number", tok);
    if (k < DV_CONVERGE_MAX_LEVELS) steps[k] = h;
    /* Richardson extrapolation over refined steps (search_verify.h): steps
     * closer than that ratio make the differences of their errors noise */
    if (k && k < DV_CONVERGE_MAX_LEVELS && !(steps[k - 1] / h >= DV_CONVERGE_MIN_RATIO))
      return dv_fail(err, DV_EINPUT,
                     "--step: %g is not smaller than %g by a ratio of at least %g (the steps "
                     "must be refined, finest last)",
                     h, steps[k - 1], DV_CONVERGE_MIN_RATIO);
  }
  if (k != n || k < DV_CONVERGE_MIN_LEVELS || k > DV_CONVERGE_MAX_LEVELS)
    return dv_fail(err, DV_EINPUT,
                   "--step gives %zu steps for %zu trajectories: one each, %d to %d of them", k, n,
                   DV_CONVERGE_MIN_LEVELS, DV_CONVERGE_MAX_LEVELS);
  return DV_OK;
}

/* the convergence of the trajectories' theta errors over their steps, as
 * verify prints it; 1 unless it converges to the reference */
static int print_convergence(const double *steps, const double *errors, size_t n) {
  dv_convergence_fit v;
  dv_search_convergence_judge(steps, errors, (int)n, &v);
  printf("convergence:");
  for (size_t i = 0; i < n; i++) printf(" %.3e (dt %.3g)", errors[i], steps[i]);
  printf("\n  order %s", isnan(v.order) ? "none (the errors do not fall)" : "");
  if (!isnan(v.order)) printf("%.2f", v.order);
  printf("; extrapolated discrepancy %.3e rad (floor %g", v.extrapolated, DV_VERIFY_FLOOR);
  if (v.uncertainty > 0.0)
    printf(", uncertainty %.2e%s", v.uncertainty,
           n == DV_CONVERGE_MIN_LEVELS ? " (grid convergence index, 3 levels)" : "");
  if (v.verdict == DV_CONVERGE_NOT_JUDGED) {
    char why[256];
    dv_search_convergence_why(steps, errors, (int)n, v.verdict, why, sizeof why);
    printf("): not judged: %s\n", why);
    return 1;
  }
  printf("): %s%s\n", dv_search_convergence_name(v.verdict),
         v.verdict == DV_CONVERGES_ELSEWHERE
             ? " (no cause: recorded trajectories cannot be re-run with their knobs turned)"
             : "");
  return v.verdict != DV_CONVERGES;
}

/* a file's name (no more than MAX_NAME characters) made one a report can
 * carry when it is not: every other character '_' */
static void default_name(char *name) {
  if (!check_name(name, NULL)) return;
  for (char *p = name; *p; p++)
    if (!isalnum((unsigned char)*p) && *p != '-' && *p != '+') *p = '_';
  if (!*name) snprintf(name, 64, "trajectory");
}

/* each file's name: from --name, else its file name without its extension */
static int make_names(const char *list, const dv_cli_list *files, char names[][64], dv_error *err) {
  const size_t n = files->n - 1;
  if (list) {
    char buf[1024];
    snprintf(buf, sizeof buf, "%s", list);
    size_t k = 0;
    for (char *save, *tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save), k++)
      if (k < n) snprintf(names[k], 64, "%s", tok);
    if (k != n) return dv_fail(err, DV_EINPUT, "--name gives %zu names for %zu trajectories", k, n);
  } else {
    for (size_t i = 0; i < n; i++) {
      const char *path = files->items[i + 1], *base = strrchr(path, '/');
      base = base ? base + 1 : path;
      const char *dot = strrchr(base, '.');
      const int len = dot && dot > base ? (int)(dot - base) : (int)strlen(base);
      snprintf(names[i], 64, "%.*s", len > MAX_NAME ? MAX_NAME : len, base);
      default_name(names[i]);
    }
  }
  for (size_t i = 0; i < n; i++) {
    if (check_name(names[i], err)) return DV_EINPUT;
    for (size_t j = 0; j < i; j++)
      if (!strcmp(names[i], names[j]))
        return dv_fail(err, DV_EINPUT, "two trajectories named '%s' (give --name)", names[i]);
  }
  /* a thick scene's report also holds MATCHED-NAME.csv, each trajectory's
   * matched reference: no trajectory may take that file */
  const char *matched = dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE)->name;
  const size_t len = strlen(matched);
  for (size_t i = 0; i < n; i++)
    for (size_t j = 0; j < n; j++)
      if (!strncmp(names[i], matched, len) && names[i][len] == '-' &&
          !strcmp(names[i] + len + 1, names[j]))
        return dv_fail(err, DV_EINPUT,
                       "name '%s' is the file of the matched reference of '%s' in the report "
                       "(give --name)",
                       names[i], names[j]);
  return DV_OK;
}

int dv_cli_judge(int argc, char **argv) {
  const char *out = "report", *list = NULL, *junit = NULL, *step_list = NULL;
  const dv_cli_option options[] = {
      {"out", DV_CLI_TEXT, &out, 0, 0},
      {"name", DV_CLI_TEXT, &list, 0, 0},
      {"junit", DV_CLI_TEXT, &junit, 0, 0},
      {"step", DV_CLI_TEXT, &step_list, 0, 0},
  };
  const dv_cli_command cmd = {"judge", HELP, options, 4, 2, SIZE_MAX};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_run_progress_start("judge", a.quiet, 0);
  const dv_engine_type *const none[] = {NULL};
  dv_engine_choose_only(none); /* a file runs no linked engine: none has its settings probed */
  const size_t n = a.args.n - 1;
  char names[DV_MAX_ENGINES][64];
  dv_trajfile files[DV_MAX_ENGINES];
  dv_replay replays[DV_MAX_ENGINES];
  size_t nread = 0;
  double steps[DV_CONVERGE_MAX_LEVELS], errors[DV_MAX_ENGINES];
  dv_scenario sc;
  dv_error err = {{0}};
  int code = DV_EXIT_OK, lock = -1;
  if (n > DV_MAX_ENGINES) {
    code = dv_cli_usage_error("judge", "%zu trajectories: at most %d at a time", n, DV_MAX_ENGINES);
  } else if (make_names(list, &a.args, names, &err) ||
             (step_list && parse_steps(step_list, n, steps, &err))) {
    code = dv_cli_usage_error("judge", "%s", err.msg);
  } else if (dv_cli_load_scenario("judge", a.args.items[0], &a.sets, &sc, &err)) {
    code = (fprintf(stderr, "%s\n", err.msg), DV_EXIT_ERROR);
  }
  for (size_t i = 0; code == DV_EXIT_OK && i < n; i++) {
    const char *path = a.args.items[i + 1];
    if (dv_run_trajfile_read(path, &sc, &files[i], &err))
      code = dv_cli_error("judge", "%s", err.msg);
    else
      dv_run_replay_init(&replays[nread++], &files[i], names[i]);
  }
  /* no --step: the files' own "# dt = H" lines, when 3 or more files all give one */
  int file_steps = !step_list && n >= DV_CONVERGE_MIN_LEVELS && code == DV_EXIT_OK;
  for (size_t i = 0; file_steps && i < n; i++) file_steps = !isnan(files[i].step);
  if (file_steps) {
    char list_buf[200] = "";
    for (size_t i = 0; i < n; i++)
      snprintf(list_buf + strlen(list_buf), sizeof list_buf - strlen(list_buf), "%s%.17g",
               i ? "," : "", files[i].step);
    if (parse_steps(list_buf, n, steps, &err))
      code = dv_cli_error("judge", "the files' dt lines: %s", err.msg);
  }
  /* no output over an input: the trajectories may not lie in the report the run replaces */
  const char *const *trajs = (const char *const *)a.args.items + 1;
  if (code != DV_EXIT_OK) {
  } else if (dv_report_dir_check(out, &sc, 1, trajs, n, &err) ||
             dv_report_dir_check_junit(junit, out, &sc, 1, trajs, n, &err) ||
             dv_io_make_dirs(out, &err) || dv_io_lock_dir(out, &lock, &err) ||
             dv_report_dir_check(out, &sc, 1, trajs, n, &err) ||
             dv_report_dir_check_junit(junit, out, &sc, 1, trajs, n, &err)) {
    code = dv_cli_error("judge", "%s", err.msg);
  } else {
    code = dv_report_judge_run(&sc, replays, nread, out, junit, errors, &err);
    if (code == DV_SUITE_ERROR) {
      code = dv_cli_error("judge", "%s", err.msg);
    } else {
      if ((step_list || file_steps) && print_convergence(steps, errors, n)) code = DV_EXIT_FAIL;
      printf("report: %s/%s/report.md\n", out, sc.name);
      printf("page: %s/%s/index.html\n", out, sc.name);
    }
  }
  dv_io_unlock_dir(out, lock);
  for (size_t i = 0; i < nread; i++) dv_run_trajfile_free(&files[i]);
  dv_cli_args_free(&cmd, &a);
  return code;
}
