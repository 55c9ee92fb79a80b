/* test_plot: the plots written at all. dv_plot writes four complete SVG files
 * from synthetic trajectories (offset, NaN-holed, empty, constant), leaves no
 * temporary file behind, works twice in one process, and fails cleanly on a
 * missing dir. dv_report_plot_xy writes single plots (log-log with
 * non-positive values, marks, empty curves, 16 curves, equal aspect, nothing at
 * all) and rejects bad paths and arguments without leaving files.
 * What the plots show and what the verdict used are test_plot_marks's checks,
 * what a newcomer reads test_plot_reading's.
 * usage: test_plot [KEEP] (with an argument, the plots are kept to look at) */
#include <dirent.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_test.h"
#include "plot_svg.h"
#include "report_plot.h"

/* ---- the plots written at all ---- */

/* the four files are complete SVG documents with drawn lines, and nothing else is in dir */
static void check_dir(const char *dir) {
  size_t nfiles = 0;
  for (const char *const *name = dv_report_plot_files; *name; name++, nfiles++) {
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, *name);
    long size = 0;
    char *text = pt_slurp(path, &size);
    CHECK(text != NULL, "%s: missing", path);
    if (!text) continue;
    CHECK(size > 0, "%s: empty", path);
    CHECK(strncmp(text, "<?xml", 5) == 0 || strncmp(text, "<svg", 4) == 0, "%s: no SVG header",
          path);
    CHECK(strstr(text, "<polyline") || strstr(text, "<path"), "%s: no line drawn", path);
    CHECK(strstr(text, "</svg>") != NULL, "%s: not closed", path);
    free(text);
  }
  CHECK(nfiles == 4, "dv_report_plot_files lists %zu files", nfiles);
  DIR *d = opendir(dir);
  CHECK(d != NULL, "%s: cannot list", dir);
  if (!d) return;
  size_t seen = 0;
  for (struct dirent *e; (e = readdir(d)) != NULL;) {
    if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
    int known = 0;
    for (const char *const *name = dv_report_plot_files; *name; name++)
      known |= !strcmp(*name, e->d_name);
    CHECK(known, "%s: stray file %s", dir, e->d_name);
    seen++;
  }
  closedir(d);
  CHECK(seen == nfiles, "%s: %zu files, want %zu", dir, seen, nfiles);
}

/* ---- dv_report_plot_xy ---- */

#define NXY 40
static const char *const xy_files[] = {"wp.svg",   "many.svg", "phase.svg",
                                       "flat.svg", "none.svg", NULL};

/* the file at path is a complete SVG document with a line drawn; star: whether marks are in it */
static void check_svg(const char *path, int star) {
  long size = 0;
  char *text = pt_slurp(path, &size);
  CHECK(text != NULL, "%s: missing", path);
  if (!text) return;
  CHECK(size > 0, "%s: empty", path);
  CHECK(strncmp(text, "<?xml", 5) == 0 || strncmp(text, "<svg", 4) == 0, "%s: no SVG header", path);
  CHECK(strstr(text, "<polyline") || strstr(text, "<path"), "%s: no line drawn", path);
  CHECK(strstr(text, "</svg>") != NULL, "%s: not closed", path);
  CHECK(!strstr(text, "&#x2605;") == !star, "%s: marks %s", path, star ? "missing" : "drawn");
  free(text);
}

/* dir holds exactly the files of xy_files */
static void check_xy_dir(const char *dir) {
  DIR *d = opendir(dir);
  CHECK(d != NULL, "%s: cannot list", dir);
  if (!d) return;
  size_t seen = 0, want = 0;
  for (struct dirent *e; (e = readdir(d)) != NULL;) {
    if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
    int known = 0;
    for (const char *const *name = xy_files; *name; name++) known |= !strcmp(*name, e->d_name);
    CHECK(known, "%s: stray file %s", dir, e->d_name);
    seen++;
  }
  closedir(d);
  for (const char *const *name = xy_files; *name; name++) want++;
  CHECK(seen == want, "%s: %zu files, want %zu", dir, seen, want);
}

static void test_xy(int keep) {
  char dir[] = "/tmp/test_plot_xy.XXXXXX", path[PATH_MAX];
  CHECK(mkdtemp(dir) != NULL, "mkdtemp failed");
  dv_error err = {{0}};
  double h[NXY], e1[NXY], e2[NXY], e3[NXY], th[NXY], p[NXY], ct[NXY], st[NXY], u[NXY];
  int pareto[NXY] = {0}, pareto3[NXY] = {0};
  for (int i = 0; i < NXY; i++) {
    h[i] = pow(10.0, -4.0 + 3.0 * i / (NXY - 1)); /* 1e-4 .. 1e-1 */
    e1[i] = 0.3 * pow(h[i], 4.0);
    e2[i] = 2.0 * h[i] * h[i];
    e3[i] = 1e-3 * h[i];
    const double a = 6.283185307179586 * i / (NXY - 1);
    ct[i] = cos(a);
    st[i] = 2.0 * sin(a);
    th[i] = (1.0 - 0.01 * i) * cos(a);
    p[i] = 2.0 * (1.0 - 0.01 * i) * sin(a);
    u[i] = 3.0; /* a flat potential: a collapsed y range */
    pareto[i] = i % 7 == 0;
    pareto3[i] = i > 30;
  }
  e1[3] = 0.0;   /* not drawable on the log axis */
  e1[4] = -1e-9; /* nor this */
  h[10] = -1.0;  /* nor this x (e1, e2 and e3 lose it) */
  e2[20] = NAN;  /* a hole */
  e3[5] = INFINITY;
  const double lone_x = 1e-2, lone_y = 1e-9, neg = -1.0;
  dv_plot_curve wp[] = {
      {"reference (#1)", NXY, h, e3, NULL, DV_CURVE_LINE, 0},
      {"rk4 (order 3.9)", NXY, h, e1, pareto, DV_CURVE_LINE_POINTS, 1},
      {"euler (order 2.0)", NXY, h, e2, NULL, DV_CURVE_LINE, 2},
      {"points", NXY, e2, e1, pareto3, DV_CURVE_POINTS, 3},
      {"empty", 0, NULL, NULL, NULL, DV_CURVE_LINE, 4},
      {"lone point", 1, &lone_x, &lone_y, NULL, DV_CURVE_LINE, 5},
      {"non-positive", 1, &neg, &neg, NULL, DV_CURVE_POINTS, 6},
  };
  snprintf(path, sizeof path, "%s/wp.svg", dir);
  for (int round = 0; round < 2; round++) /* the second replaces the first */
    CHECK(dv_report_plot_xy(path, "work-precision: #gh error", "wall s / simulated s",
                            "|#gh - #gh#dref#u| (rad)", wp, sizeof wp / sizeof wp[0],
                            DV_PLOT_LOGX | DV_PLOT_LOGY, &err) == DV_OK,
          "wp: %s", err.msg);
  check_svg(path, 1);

  dv_plot_curve many[DV_PLOT_MAX_CURVES];
  char labels[DV_PLOT_MAX_CURVES][32];
  double ys[DV_PLOT_MAX_CURVES][NXY];
  for (int k = 0; k < DV_PLOT_MAX_CURVES; k++) {
    snprintf(labels[k], sizeof labels[k], "integrator %d", k + 1);
    for (int i = 0; i < NXY; i++) ys[k][i] = e2[i] * pow(2.0, k);
    many[k] = (dv_plot_curve){labels[k],
                              NXY,
                              h,
                              ys[k],
                              k == 2 ? pareto : NULL,
                              k % 3 == 0 ? DV_CURVE_LINE_POINTS : DV_CURVE_LINE,
                              k + 1};
  }
  snprintf(path, sizeof path, "%s/many.svg", dir);
  CHECK(dv_report_plot_xy(path, "16 curves", "h (s)", "error", many, DV_PLOT_MAX_CURVES,
                          DV_PLOT_LOGX | DV_PLOT_LOGY, &err) == DV_OK,
        "many: %s", err.msg);
  check_svg(path, 1);

  dv_plot_curve phase[] = {
      {"reference level set", NXY, ct, st, NULL, DV_CURVE_LINE, 0},
      {"mujoco", NXY, th, p, NULL, DV_CURVE_LINE, 1},
      {"ode", NXY, p, th, NULL, DV_CURVE_LINE, 2},
  };
  snprintf(path, sizeof path, "%s/phase.svg", dir);
  CHECK(dv_report_plot_xy(path, "phase plane", "#gh (rad)", "p#d#gh#u", phase, 3, DV_PLOT_EQUAL,
                          &err) == DV_OK,
        "phase: %s", err.msg);
  check_svg(path, 0);

  dv_plot_curve flat[] = {{"U(\u03b8)", NXY, th, u, NULL, DV_CURVE_LINE, 1}};
  snprintf(path, sizeof path, "%s/flat.svg", dir);
  CHECK(dv_report_plot_xy(path, "effective potential", "#gh (rad)", "U (J)", flat, 1, 0, &err) ==
            DV_OK,
        "flat: %s", err.msg);
  check_svg(path, 0);

  /* nothing drawable (only non-positive values on log axes, no curves at all): "no data" */
  snprintf(path, sizeof path, "%s/none.svg", dir);
  CHECK(dv_report_plot_xy(path, NULL, NULL, NULL, &wp[6], 1, DV_PLOT_LOGX | DV_PLOT_LOGY, &err) ==
            DV_OK,
        "none: %s", err.msg);
  check_svg(path, 0);
  CHECK(dv_report_plot_xy(path, "nothing", "x", "y", NULL, 0, DV_PLOT_LOGY, &err) == DV_OK,
        "none: %s", err.msg);
  check_svg(path, 0);
  /* a curve whose every error is 0 (an exact steady motion) is named as such, not "no data" */
  static const double zero[2] = {0.0, 0.0}, hs[2] = {1e-4, 2e-4}, es[2] = {1e-6, 2e-6};
  const dv_plot_curve exact[] = {{"rk4", 2, hs, es, NULL, DV_CURVE_LINE_POINTS, 1},
                                 {"exact", 2, hs, zero, NULL, DV_CURVE_LINE_POINTS, 2}};
  snprintf(path, sizeof path, "%s/exact.svg", dir);
  CHECK(dv_report_plot_xy(path, "errors", "h", "e", exact, 2, DV_PLOT_LOGX | DV_PLOT_LOGY, &err) ==
            DV_OK,
        "exact: %s", err.msg);
  {
    long size;
    char *svg = pt_slurp(path, &size), *text = svg ? pt_svg_text(svg) : NULL;
    CHECK(text && strstr(text, "zero at every point: exact") && !strstr(text, "no data"),
          "an all-zero curve is not named as zero: %s", text ? text : "(unreadable)");
    free(text);
    free(svg);
  }
  unlink(path);
  check_xy_dir(dir);

  /* bad paths and arguments: an error status and a message, no file left */
  const struct {
    const char *name;
    const dv_plot_curve *c;
    size_t n;
    int flags, status;
  } bad[] = {
      {"no/such/dir/x.svg", wp, 2, 0, DV_ESYSTEM},
      {"", wp, 2, 0, DV_EINPUT}, /* path is dir/: no file name */
      {"x.svg", NULL, 2, 0, DV_EINPUT},
      {"x.svg", many, DV_PLOT_MAX_CURVES + 1, 0, DV_EINPUT},
      {"x.svg", wp, 2, 8, DV_EINPUT},
  };
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    snprintf(path, sizeof path, "%s/%s", dir, bad[k].name);
    err.msg[0] = '\0';
    const int status =
        dv_report_plot_xy(path, "bad", "x", "y", bad[k].c, bad[k].n, bad[k].flags, &err);
    CHECK(status == bad[k].status, "bad %zu (%s): status %d, want %d", k, bad[k].name, status,
          bad[k].status);
    CHECK(err.msg[0] != '\0', "bad %zu: no message", k);
  }
  dv_plot_curve nocoords = {"x", 3, NULL, NULL, NULL, DV_CURVE_LINE, 1};
  dv_plot_curve badstyle = {"x", 1, &lone_x, &lone_y, NULL, 3, 1};
  snprintf(path, sizeof path, "%s/x.svg", dir);
  CHECK(dv_report_plot_xy(path, "", "", "", &nocoords, 1, 0, &err) == DV_EINPUT, "no coordinates");
  CHECK(dv_report_plot_xy(path, "", "", "", &badstyle, 1, 0, &err) == DV_EINPUT, "bad style");
  CHECK(dv_report_plot_xy(NULL, "", "", "", wp, 1, 0, &err) == DV_EINPUT, "NULL path");
  check_xy_dir(dir);

  if (keep) {
    printf("xy plots kept in %s\n", dir);
    return;
  }
  for (const char *const *name = xy_files; *name; name++) {
    snprintf(path, sizeof path, "%s/%s", dir, *name);
    unlink(path);
  }
  rmdir(dir);
}

int main(int argc, char **argv) {
  dv_traj ref = {0}, close_by = {0}, holed = {0}, empty = {0}, flat = {0};
  CHECK(pt_make_runs(&ref, &close_by, &holed) == 0, "out of memory");
  for (size_t i = 0; i < 5; i++) { /* a constant tilt: a collapsed range of its own */
    dv_sample s = pt_sample((double)i, 0.0);
    s.y[RED_TH] = 1.0;
    s.energy = 0.0;
    CHECK(dv_run_traj_push(&flat, &s) == 0, "out of memory");
  }

  dv_plot_input in = {.title = "synthetic #1", .thin = &ref, .nseries = 4, .window_end = INFINITY};
  in.series[0] = pt_whole_run("close (1e-6)", &close_by, &ref);
  in.series[1] = pt_whole_run("holed", &holed, &ref);
  in.series[2] = pt_whole_run("empty", &empty, &ref);
  in.series[3] = pt_whole_run("flat", &flat, &flat);

  /* a kept dir (argv[1]) lets one look at the plots */
  char dir[] = "/tmp/test_plot.XXXXXX";
  CHECK(mkdtemp(dir) != NULL, "mkdtemp failed");
  dv_error err = {{0}};
  for (int round = 0; round < 2; round++) { /* twice: PLplot's global state is reset */
    const int status = dv_report_plot_scenario(dir, &in, &err);
    CHECK(status == DV_OK, "round %d: status %d: %s", round, status, err.msg);
    check_dir(dir);
  }

  /* nothing to draw at all: still four valid plots */
  dv_plot_input none = {.title = "nothing", .thin = &empty, .nseries = 1, .window_end = INFINITY};
  none.series[0] = pt_whole_run("empty", &empty, &empty);
  char dir2[] = "/tmp/test_plot.XXXXXX";
  CHECK(mkdtemp(dir2) != NULL, "mkdtemp failed");
  CHECK(dv_report_plot_scenario(dir2, &none, &err) == DV_OK, "empty input: %s", err.msg);
  check_dir(dir2);
  if (argc > 1)
    printf("empty plots kept in %s\n", dir2);
  else
    pt_remove_dir(dir2);

  /* a missing directory: an error, no crash */
  char missing[PATH_MAX];
  snprintf(missing, sizeof missing, "%s/no/such/dir", dir);
  err.msg[0] = '\0';
  CHECK(dv_report_plot_scenario(missing, &in, &err) == DV_ESYSTEM, "missing dir accepted");
  CHECK(err.msg[0] != '\0', "missing dir: no message");

  if (argc > 1)
    printf("plots kept in %s\n", dir);
  else
    pt_remove_dir(dir);
  dv_run_traj_free(&ref);
  dv_run_traj_free(&close_by);
  dv_run_traj_free(&holed);
  dv_run_traj_free(&empty);
  dv_run_traj_free(&flat);
  test_xy(argc > 1);
  return TEST_RESULT();
}
