/* test_plot_marks: what the plots show and what the verdict used, read back
 * from the SVG dv_plot writes. Each engine has the same colour in every plot,
 * whatever else is drawn (and in dv_report_plot_xy's plots through
 * dv_report_plot_engine_colour), the thin reference is black; a series without
 * data is left out of the legend and named in the title, never "(no data)";
 * the compared window's end is marked when the runs go on after it, not when
 * it is the end; legends lie right of the frame (the grid's box).
 * What the verdict used: mujoco over its whole run with a horizon at 3 s, ode
 * to 6 s, dart comparing nothing (its window 0 s), their limits unequal:
 * theta_error.svg draws dart only faintly, mujoco strongly to its horizon,
 * marks it there, labels each limit; theta.svg marks the turns compared; every
 * legend is beside the data. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_test.h"
#include "plot_svg.h"
#include "report_plot.h"

/* ---- what the plots show ---- */

#define SVG_MAX_COLOURS 16

/* the stroke colours of the polylines that are neither black, white nor the grid's */
static int svg_series_colours(const char *svg, char out[][8], int max) {
  int n = 0;
  for (const char *p = svg; (p = strstr(p, "<polyline")); p++) {
    char c[8];
    if (!pt_attr_of(p, "stroke=\"", c, sizeof c) || !strcmp(c, "#000000") ||
        !strcmp(c, "#FFFFFF") || !strcmp(c, "#E1E1E1"))
      continue;
    int seen = 0;
    for (int i = 0; i < n; i++) seen |= !strcmp(out[i], c);
    if (!seen && n < max) snprintf(out[n++], 8, "%s", c);
  }
  return n;
}

/* whether a text element reads exactly label; its anchor (x, y) into at */
static int svg_text_at(const char *svg, const char *label, double at[2]) {
  for (const char *p = svg; (p = strstr(p, "<text")); p++) {
    char line[512], m[128];
    double a, b, c, d;
    pt_decode_text(p, line, sizeof line);
    if (strcmp(line, label)) continue;
    if (at && (!pt_attr_of(p, "transform=\"matrix(", m, sizeof m) ||
               sscanf(m, "%lf %lf %lf %lf %lf %lf", &a, &b, &c, &d, &at[0], &at[1]) != 6))
      return 0;
    return 1;
  }
  return 0;
}

/* the box (x0, x1, y0, y1) the grid lines span: the frame */
static int svg_grid_box(const char *svg, double box[4]) {
  int any = 0;
  for (const char *p = svg; (p = strstr(p, "<polyline")); p++) {
    char c[16], pts[256];
    if (!pt_attr_of(p, "stroke=\"", c, sizeof c) || strcmp(c, "#E1E1E1") ||
        !pt_attr_of(p, "points=\"", pts, sizeof pts))
      continue;
    double x, y;
    for (const char *q = pts; q && sscanf(q, "%lf,%lf", &x, &y) == 2; q = strchr(q + 1, ' ')) {
      if (!any || x < box[0]) box[0] = x;
      if (!any || x > box[1]) box[1] = x;
      if (!any || y < box[2]) box[2] = y;
      if (!any || y > box[3]) box[3] = y;
      any = 1;
    }
  }
  return any;
}

/* the series colours of dir/theta.svg equal want[0..nwant) as a set */
static void check_colours(const char *dir, const char *const *want, int nwant, const char *what) {
  char *svg = pt_plot_text(dir, "theta.svg"), got[SVG_MAX_COLOURS][8];
  const int n = svg ? svg_series_colours(svg, got, SVG_MAX_COLOURS) : -1;
  CHECK(n == nwant, "%s: %d series colours, want %d", what, n, nwant);
  for (int k = 0; k < nwant; k++) {
    int found = 0;
    for (int i = 0; i < n; i++) found |= !strcmp(got[i], want[k]);
    CHECK(found, "%s: colour %s missing", what, want[k]);
  }
  free(svg);
}

/* the only series colour of dir/theta.svg into out ("" if not exactly one) */
static void only_colour(const char *dir, char out[8]) {
  char *svg = pt_plot_text(dir, "theta.svg"), got[SVG_MAX_COLOURS][8];
  const int n = svg ? svg_series_colours(svg, got, SVG_MAX_COLOURS) : 0;
  snprintf(out, 8, "%s", n == 1 ? got[0] : "");
  free(svg);
}

/* the four plots of in into a new directory (its name left in dir) */
static void plot_into(char *dir, const dv_plot_input *in) {
  dv_error err = {{0}};
  CHECK(mkdtemp(dir) != NULL, "mkdtemp failed");
  CHECK(dv_report_plot_scenario(dir, in, &err) == DV_OK, "%s: %s", in->title, err.msg);
}

static void test_engine_plots(const dv_traj *ref, const dv_traj *a, const dv_traj *b,
                              const dv_traj *empty) {
  char dirs[5][32];
  for (int k = 0; k < 5; k++) snprintf(dirs[k], sizeof dirs[k], "/tmp/test_plot_eng.XXXXXX");
  /* mujoco alone, ode alone, both the other way round: an engine keeps its colour */
  dv_plot_input mj = {.title = "mujoco", .thin = ref, .nseries = 1, .window_end = INFINITY};
  mj.series[0] = pt_whole_run("mujoco", a, ref);
  dv_plot_input od = mj, both = mj;
  od.series[0] = pt_whole_run("ode", b, ref);
  both.nseries = 3;
  both.series[0] = od.series[0];
  both.series[1] = pt_whole_run("matched", empty, ref); /* no data: left out */
  both.series[2] = mj.series[0];
  both.window_end = 6.0; /* the runs last 10 s */
  dv_plot_input whole = mj;
  whole.window_end = 10.0; /* the window is the whole run: nothing to mark */
  plot_into(dirs[0], &mj);
  plot_into(dirs[1], &od);
  plot_into(dirs[2], &both);
  plot_into(dirs[3], &whole);
  char c_mj[8], c_od[8];
  only_colour(dirs[0], c_mj);
  only_colour(dirs[1], c_od);
  CHECK(c_mj[0] && c_od[0] && strcmp(c_mj, c_od), "mujoco %s and ode %s share a colour", c_mj,
        c_od);
  const char *const pair[] = {c_mj, c_od};
  check_colours(dirs[2], pair, 2, "ode, matched (empty), mujoco");
  CHECK(dv_report_plot_engine_colour("reduced") == 0, "the thin reference is not black");

  /* dv_report_plot_xy draws an engine in the same colour */
  char path[PATH_MAX];
  double x[2] = {0, 1}, y[2] = {0, 1};
  const dv_plot_curve phase = {
      "ode", 2, x, y, NULL, DV_CURVE_LINE, dv_report_plot_engine_colour("ode")};
  dv_error err = {{0}};
  CHECK(mkdtemp(dirs[4]) != NULL, "mkdtemp failed");
  snprintf(path, sizeof path, "%s/theta.svg", dirs[4]);
  CHECK(dv_report_plot_xy(path, "phase", "x", "y", &phase, 1, 0, &err) == DV_OK, "%s", err.msg);
  char c_xy[8];
  only_colour(dirs[4], c_xy);
  CHECK(!strcmp(c_xy, c_od), "ode is %s in an x-y plot, %s in theta.svg", c_xy, c_od);
  unlink(path);
  rmdir(dirs[4]);

  for (const char *const *name = dv_report_plot_files; *name; name++) {
    char *svg = pt_plot_text(dirs[2], *name), *text = svg ? pt_svg_text(svg) : NULL;
    CHECK(text && !strstr(text, "(no data)"), "%s: a \"(no data)\" entry", *name);
    CHECK(text && strstr(text, "no data: matched"), "%s: the title does not name matched", *name);
    CHECK(svg && !svg_text_at(svg, "matched", NULL), "%s: matched in the legend", *name);
    /* the error plot has no thin reference: the engines' errors reach the end */
    CHECK(text && strstr(text, "window end"), "%s: the window's end is not marked", *name);
    double box[4] = {0}, at[2] = {0};
    const int boxed = svg && svg_grid_box(svg, box), legend = svg && svg_text_at(svg, "mujoco", at);
    CHECK(boxed && legend, "%s: no grid (%d) or no legend (%d)", *name, boxed, legend);
    if (boxed && legend)
      CHECK(at[0] > box[1] && at[1] > box[2] && at[1] < box[3],
            "%s: legend text at (%g, %g) not right of the frame [%g, %g] x [%g, %g]", *name, at[0],
            at[1], box[0], box[1], box[2], box[3]);
    free(text);
    free(svg);
    svg = pt_plot_text(dirs[3], *name), text = svg ? pt_svg_text(svg) : NULL;
    CHECK(text && !strstr(text, "window end"), "%s: a window that is the whole run is marked",
          *name);
    free(text);
    free(svg);
  }
  for (int k = 0; k < 4; k++) pt_remove_dir(dirs[k]);
}

/* ---- what the verdict used ---- */

/* mujoco over its whole run with a horizon at 3 s, ode to 6 s, dart comparing
 * nothing (its window 0 s), their limits unequal: theta_error.svg draws dart
 * only faintly, mujoco strongly to its horizon, marks it there, labels each
 * limit; theta.svg marks the turns compared; every legend is beside the data */
static void test_verdict_marks(const dv_traj *ref, const dv_traj *a, const dv_traj *b) {
  char dir[] = "/tmp/test_plot_marks.XXXXXX";
  dv_plot_input in = {.title = "marks", .thin = ref, .nseries = 3, .window_end = 10.0};
  in.series[0] = (dv_plot_series){"mujoco", a, ref, 10.0, 3.0, 0.01, 0};
  in.series[1] = (dv_plot_series){"ode", b, ref, 6.0, 6.0, 0.01, 0};
  in.series[2] = (dv_plot_series){"dart", b, ref, -INFINITY, -INFINITY, 0.02, 0};
  plot_into(dir, &in);
  char *err = pt_plot_text(dir, "theta_error.svg"), *theta = pt_plot_text(dir, "theta.svg");
  CHECK(err && theta, "no theta_error.svg or theta.svg");
  if (err && theta) {
    const char *dart = "#D62728", *mujoco = "#1F77B4";
    double box[4] = {0}, strong[4] = {0}, faint[4] = {0};
    CHECK(pt_svg_lines(err, dart, 2, 0.99, 1.0, strong) == 0,
          "dart, compared over 0 s, drawn strongly");
    CHECK(pt_svg_lines(err, dart, 2, 0.0, 0.5, faint) > 0, "dart's run not drawn faintly");
    const int boxed = svg_grid_box(err, box);
    CHECK(boxed, "theta_error.svg: no grid");
    /* the frame spans t = 0 .. 10 s: 3 s is 0.3 of it */
    const double at3 = box[0] + 0.3 * (box[1] - box[0]), px = 1.5;
    const double step =
        (box[1] - box[0]) / (PT_N - 1); /* a sample's interval: the last before 3 s */
    CHECK(pt_svg_lines(err, mujoco, 2, 0.99, 1.0, strong) > 0 && strong[1] <= at3 + px &&
              strong[1] > at3 - step,
          "mujoco's strong curve ends at x %g, its horizon is at %g", strong[1], at3);
    int at_horizon = 0;
    for (const char *p = err; (p = strstr(p, "<polyline")); p++) { /* a vertical mujoco segment */
      char c[16], pts[128];
      double x0, y0, x1, y1;
      if (pt_attr_of(p, "stroke=\"", c, sizeof c) && !strcmp(c, mujoco) &&
          pt_attr_of(p, "points=\"", pts, sizeof pts) &&
          sscanf(pts, "%lf,%lf %lf,%lf", &x0, &y0, &x1, &y1) == 4 && fabs(x0 - at3) < px &&
          fabs(x1 - at3) < px && y0 != y1)
        at_horizon = 1;
    }
    CHECK(at_horizon, "no mark at mujoco's horizon (x %g)", at3);
    char *text = pt_svg_text(err);
    CHECK(text && strstr(text, "mujoco horizon 3 s"), "the horizon is not labelled");
    CHECK(text && strstr(text, "mujoco limit 0.01 rad") && strstr(text, "dart limit 0.02 rad"),
          "each engine's own limit is not labelled");
    CHECK(text && !strstr(text, "ode horizon"), "ode's horizon at its window's end is marked");
    free(text);
    /* turns to each window's end: the thin disk's and mujoco's minimum at 3 pi / 2, ode's; none of
     * dart's */
    CHECK(pt_count_of(theta, "&#x25bc;") == 3, "theta.svg: %d minima marked, want 3",
          pt_count_of(theta, "&#x25bc;"));
    /* maxima at pi / 2 and 5 pi / 2: the thin disk's and mujoco's two, ode's first (its
     * window ends at 6 s), and the legend's two triangles */
    CHECK(pt_count_of(theta, "&#x25b2;") == 7, "theta.svg: %d maxima marked, want 7",
          pt_count_of(theta, "&#x25b2;"));
  }
  for (const char *const *name = dv_report_plot_files; *name; name++) {
    char *svg = pt_plot_text(dir, *name);
    double data[4] = {0}, legend[4] = {0};
    const int drawn = svg && pt_svg_lines(svg, "", 2, 0.0, 1.0, data) > 0;
    const int boxed = svg && pt_svg_legend_box(svg, legend);
    CHECK(drawn && boxed, "%s: no data (%d) or no legend box (%d)", *name, drawn, boxed);
    if (drawn && boxed)
      CHECK(
          legend[0] > data[1] || legend[1] < data[0] || legend[2] > data[3] || legend[3] < data[2],
          "%s: the legend [%g, %g] x [%g, %g] covers data [%g, %g] x [%g, %g]", *name, legend[0],
          legend[1], legend[2], legend[3], data[0], data[1], data[2], data[3]);
    CHECK(!boxed || legend[1] <= 960.0, "%s: the legend runs off the page at x %g", *name,
          legend[1]);
    free(svg);
  }
  free(err);
  free(theta);
  pt_remove_dir(dir);
}

int main(void) {
  dv_traj ref = {0}, close_by = {0}, holed = {0}, empty = {0};
  CHECK(pt_make_runs(&ref, &close_by, &holed) == 0, "out of memory");
  test_engine_plots(&ref, &close_by, &holed, &empty);
  test_verdict_marks(&ref, &close_by, &holed);
  dv_run_traj_free(&ref);
  dv_run_traj_free(&close_by);
  dv_run_traj_free(&holed);
  dv_run_traj_free(&empty);
  return TEST_RESULT();
}
