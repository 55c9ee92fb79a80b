/* test_plot: dv_plot writes four complete SVG files from synthetic
 * trajectories (offset, NaN-holed, empty, constant), leaves no temporary file
 * behind, works twice in one process, and fails cleanly on a missing dir.
 * dv_report_plot_xy writes single plots (log-log with non-positive values, marks,
 * empty curves, 16 curves, equal aspect, nothing at all) and rejects bad
 * paths and arguments without leaving files.
 * In the produced SVG: each engine has the same colour in every plot, whatever
 * else is drawn (and in dv_report_plot_xy's plots through
 * dv_report_plot_engine_colour), the thin reference is black; a series without
 * data is left out of the legend and named in the title, never "(no data)";
 * the compared window's end is marked when the runs go on after it, not when
 * it is the end; legends lie right of the frame (the grid's box). */
#include <dirent.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_test.h"
#include "report_plot.h"
#include "report_plot_ticks.h"

#define N 200

/* a sample at time t on a small circle, tilt 1 + 0.1 sin t + offset */
static dv_sample sample(double t, double offset) {
  dv_sample s;
  memset(&s, 0, sizeof s);
  s.t = t;
  s.y[RED_TH] = 1.0 + 0.1 * sin(t) + offset;
  s.y[RED_VTH] = 0.1 * cos(t); /* turns at t = pi/2 + k pi */
  s.contact[0] = 0.5 * cos(0.3 * t) + offset;
  s.contact[1] = 0.5 * sin(0.3 * t);
  s.energy = 2.0 + 1e-9 * t + offset;
  return s;
}

/* n samples over [0, 10] s with the given offset */
static int make_traj(dv_traj *tr, size_t n, double offset) {
  for (size_t i = 0; i < n; i++) {
    const dv_sample s = sample(10.0 * (double)i / (double)(N - 1), offset);
    if (dv_run_traj_push(tr, &s) != 0) return -1;
  }
  return 0;
}

/* a series compared over its whole run, no horizon, no limit */
static dv_plot_series whole_run(const char *label, const dv_traj *traj, const dv_traj *ref) {
  return (dv_plot_series){label, traj, ref, INFINITY, INFINITY, NAN, 0};
}

/* the whole file at path, or NULL */
static char *svg_text(const char *svg);

static char *slurp(const char *path, long *size) {
  FILE *fp = fopen(path, "rb");
  if (!fp) return NULL;
  char *buf = NULL;
  if (fseek(fp, 0, SEEK_END) == 0 && (*size = ftell(fp)) >= 0 && fseek(fp, 0, SEEK_SET) == 0 &&
      (buf = malloc((size_t)*size + 1)) != NULL) {
    buf[fread(buf, 1, (size_t)*size, fp)] = '\0';
  }
  fclose(fp);
  return buf;
}

/* the four files are complete SVG documents with drawn lines, and nothing else is in dir */
static void check_dir(const char *dir) {
  size_t nfiles = 0;
  for (const char *const *name = dv_report_plot_files; *name; name++, nfiles++) {
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, *name);
    long size = 0;
    char *text = slurp(path, &size);
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

/* remove the plots and dir */
static void remove_dir(const char *dir) {
  for (const char *const *name = dv_report_plot_files; *name; name++) {
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, *name);
    unlink(path);
  }
  rmdir(dir);
}

/* ---- dv_report_plot_xy ---- */

#define NXY 40
static const char *const xy_files[] = {"wp.svg",   "many.svg", "phase.svg",
                                       "flat.svg", "none.svg", NULL};

/* the file at path is a complete SVG document with a line drawn; star: whether marks are in it */
static void check_svg(const char *path, int star) {
  long size = 0;
  char *text = slurp(path, &size);
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
    char *svg = slurp(path, &size), *text = svg ? svg_text(svg) : NULL;
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

/* ---- what the plots show ---- */

#define SVG_MAX_COLOURS 16

/* the value of attribute name (e.g. "stroke=\"") in the element starting at el, copied */
static int attr_of(const char *el, const char *name, char *out, size_t size) {
  const char *end = strchr(el, '>'), *a = strstr(el, name);
  if (!a || (end && a > end)) return 0;
  a += strlen(name);
  const char *q = strchr(a, '"');
  if (!q) return 0;
  snprintf(out, size, "%.*s", (int)(q - a), a);
  return 1;
}

/* the stroke colours of the polylines that are neither black, white nor the grid's */
static int svg_series_colours(const char *svg, char out[][8], int max) {
  int n = 0;
  for (const char *p = svg; (p = strstr(p, "<polyline")); p++) {
    char c[8];
    if (!attr_of(p, "stroke=\"", c, sizeof c) || !strcmp(c, "#000000") || !strcmp(c, "#FFFFFF") ||
        !strcmp(c, "#E1E1E1"))
      continue;
    int seen = 0;
    for (int i = 0; i < n; i++) seen |= !strcmp(out[i], c);
    if (!seen && n < max) snprintf(out[n++], 8, "%s", c);
  }
  return n;
}

/* the text of the <text> element at el: PLplot writes each character as &#xNN; (non-ASCII: '?') */
static void decode_text(const char *el, char *out, size_t size) {
  const char *end = strstr(el, "</text>");
  size_t k = 0;
  for (const char *p = el; p && p < end && k + 1 < size; p++) {
    unsigned c;
    if (!strncmp(p, "&#x", 3) && sscanf(p + 3, "%x", &c) == 1) {
      out[k++] = c < 128 ? (char)c : '?';
      p = strchr(p, ';');
    }
  }
  out[k] = '\0';
}

/* every text element's text, one per line (caller frees) */
static char *svg_text(const char *svg) {
  size_t len = 1;
  char *all = calloc(strlen(svg) + 1, 1), line[512];
  for (const char *p = svg; all && (p = strstr(p, "<text")); p++) {
    decode_text(p, line, sizeof line);
    len += (size_t)sprintf(all + len - 1, "%s\n", line);
  }
  return all;
}

/* whether a text element reads exactly label; its anchor (x, y) into at */
static int svg_text_at(const char *svg, const char *label, double at[2]) {
  for (const char *p = svg; (p = strstr(p, "<text")); p++) {
    char line[512], m[128];
    double a, b, c, d;
    decode_text(p, line, sizeof line);
    if (strcmp(line, label)) continue;
    if (at && (!attr_of(p, "transform=\"matrix(", m, sizeof m) ||
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
    if (!attr_of(p, "stroke=\"", c, sizeof c) || strcmp(c, "#E1E1E1") ||
        !attr_of(p, "points=\"", pts, sizeof pts))
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

/* the scenario plot file of dir/name as text (caller frees), NULL if missing */
static char *plot_text(const char *dir, const char *name) {
  char path[PATH_MAX];
  long size = 0;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  return slurp(path, &size);
}

/* the series colours of dir/theta.svg equal want[0..nwant) as a set */
static void check_colours(const char *dir, const char *const *want, int nwant, const char *what) {
  char *svg = plot_text(dir, "theta.svg"), got[SVG_MAX_COLOURS][8];
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
  char *svg = plot_text(dir, "theta.svg"), got[SVG_MAX_COLOURS][8];
  const int n = svg ? svg_series_colours(svg, got, SVG_MAX_COLOURS) : 0;
  snprintf(out, 8, "%s", n == 1 ? got[0] : "");
  free(svg);
}

/* the four plots of in into a new directory (left in dirs[k]) */
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
  mj.series[0] = whole_run("mujoco", a, ref);
  dv_plot_input od = mj, both = mj;
  od.series[0] = whole_run("ode", b, ref);
  both.nseries = 3;
  both.series[0] = od.series[0];
  both.series[1] = whole_run("matched", empty, ref); /* no data: left out */
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
    char *svg = plot_text(dirs[2], *name), *text = svg ? svg_text(svg) : NULL;
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
            "%s: legend text at (%g, %g) not right of the frame [%g, %g] x [%g, %g]", *name,
            at[0], at[1], box[0], box[1], box[2], box[3]);
    free(text);
    free(svg);
    svg = plot_text(dirs[3], *name), text = svg ? svg_text(svg) : NULL;
    CHECK(text && !strstr(text, "window end"), "%s: a window that is the whole run is marked",
          *name);
    free(text);
    free(svg);
  }
  for (int k = 0; k < 4; k++) remove_dir(dirs[k]);
}

/* ---- what the verdict used ---- */

/* the polylines of svg stroked in colour ("": any but black, white and the grid's)
 * with more than min_pts points and an opacity in [op_lo, op_hi]: their count,
 * the box (x0, x1, y0, y1) of their points into box */
static int svg_lines(const char *svg, const char *colour, size_t min_pts, double op_lo,
                     double op_hi, double box[4]) {
  int n = 0, any = 0;
  for (const char *p = svg; (p = strstr(p, "<polyline")); p++) {
    char c[16], op[32];
    const char *end = strstr(p, "/>"), *pts = strstr(p, "points=\"");
    if (!end || !pts || pts > end || !attr_of(p, "stroke=\"", c, sizeof c) ||
        !attr_of(p, "stroke-opacity=\"", op, sizeof op))
      continue;
    const int other = strcmp(c, "#000000") && strcmp(c, "#FFFFFF") && strcmp(c, "#E1E1E1");
    if ((colour[0] ? strcmp(c, colour) != 0 : !other) || atof(op) < op_lo || atof(op) > op_hi)
      continue;
    double lbox[4] = {0};
    size_t m = 0;
    double x, y;
    for (const char *q = pts + 8; q < end && sscanf(q, "%lf,%lf", &x, &y) == 2; m++) {
      if (!m || x < lbox[0]) lbox[0] = x;
      if (!m || x > lbox[1]) lbox[1] = x;
      if (!m || y < lbox[2]) lbox[2] = y;
      if (!m || y > lbox[3]) lbox[3] = y;
      q += strcspn(q, " \n\"");
      q += strspn(q, " \n");
    }
    if (m <= min_pts) continue;
    for (int k = 0; k < 4; k++)
      box[k] = !any ? lbox[k] : k % 2 ? fmax(box[k], lbox[k]) : fmin(box[k], lbox[k]);
    any = 1;
    n++;
  }
  return n;
}

/* the box of the legend's frame: the black closed polyline of 5 points */
static int svg_legend_box(const char *svg, double box[4]) {
  for (const char *p = svg; (p = strstr(p, "<polyline")); p++) {
    char c[16], pts[512];
    if (!attr_of(p, "stroke=\"", c, sizeof c) || strcmp(c, "#000000") ||
        !attr_of(p, "points=\"", pts, sizeof pts))
      continue;
    double x[6], y[6];
    int m = 0;
    for (const char *q = pts; m < 6 && q && sscanf(q, "%lf,%lf", &x[m], &y[m]) == 2; m++)
      q = strpbrk(q + 1, " \n") ? q + strcspn(q, " \n") + 1 : NULL;
    if (m != 5 || x[0] != x[4] || y[0] != y[4]) continue;
    box[0] = fmin(fmin(x[0], x[1]), x[2]), box[1] = fmax(fmax(x[0], x[1]), x[2]);
    box[2] = fmin(fmin(y[0], y[1]), y[2]), box[3] = fmax(fmax(y[0], y[1]), y[2]);
    return 1;
  }
  return 0;
}

/* occurrences of needle in hay */
static int count_of(const char *hay, const char *needle) {
  int n = 0;
  for (const char *p = hay; (p = strstr(p, needle)); p++) n++;
  return n;
}

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
  char *err = plot_text(dir, "theta_error.svg"), *theta = plot_text(dir, "theta.svg");
  CHECK(err && theta, "no theta_error.svg or theta.svg");
  if (err && theta) {
    const char *dart = "#D62728", *mujoco = "#1F77B4";
    double box[4] = {0}, strong[4] = {0}, faint[4] = {0};
    CHECK(svg_lines(err, dart, 2, 0.99, 1.0, strong) == 0, "dart, compared over 0 s, drawn strongly");
    CHECK(svg_lines(err, dart, 2, 0.0, 0.5, faint) > 0, "dart's run not drawn faintly");
    const int boxed = svg_grid_box(err, box);
    CHECK(boxed, "theta_error.svg: no grid");
    /* the frame spans t = 0 .. 10 s: 3 s is 0.3 of it */
    const double at3 = box[0] + 0.3 * (box[1] - box[0]), px = 1.5;
    const double step = (box[1] - box[0]) / (N - 1); /* a sample's interval: the last before 3 s */
    CHECK(svg_lines(err, mujoco, 2, 0.99, 1.0, strong) > 0 && strong[1] <= at3 + px &&
              strong[1] > at3 - step,
          "mujoco's strong curve ends at x %g, its horizon is at %g", strong[1], at3);
    int at_horizon = 0;
    for (const char *p = err; (p = strstr(p, "<polyline")); p++) { /* a vertical mujoco segment */
      char c[16], pts[128];
      double x0, y0, x1, y1;
      if (attr_of(p, "stroke=\"", c, sizeof c) && !strcmp(c, mujoco) &&
          attr_of(p, "points=\"", pts, sizeof pts) &&
          sscanf(pts, "%lf,%lf %lf,%lf", &x0, &y0, &x1, &y1) == 4 && fabs(x0 - at3) < px &&
          fabs(x1 - at3) < px && y0 != y1)
        at_horizon = 1;
    }
    CHECK(at_horizon, "no mark at mujoco's horizon (x %g)", at3);
    char *text = svg_text(err);
    CHECK(text && strstr(text, "mujoco horizon 3 s"), "the horizon is not labelled");
    CHECK(text && strstr(text, "mujoco limit 0.01 rad") && strstr(text, "dart limit 0.02 rad"),
          "each engine's own limit is not labelled");
    CHECK(text && !strstr(text, "ode horizon"), "ode's horizon at its window's end is marked");
    free(text);
    /* turns to each window's end: the thin disk's and mujoco's minimum at 3 pi / 2, ode's; none of dart's */
    CHECK(count_of(theta, "&#x25bc;") == 3, "theta.svg: %d minima marked, want 3",
          count_of(theta, "&#x25bc;"));
    /* maxima at pi / 2 and 5 pi / 2: the thin disk's and mujoco's two, ode's first (its
     * window ends at 6 s), and the legend's two triangles */
    CHECK(count_of(theta, "&#x25b2;") == 7, "theta.svg: %d maxima marked, want 7",
          count_of(theta, "&#x25b2;"));
  }
  for (const char *const *name = dv_report_plot_files; *name; name++) {
    char *svg = plot_text(dir, *name);
    double data[4] = {0}, legend[4] = {0};
    const int drawn = svg && svg_lines(svg, "", 2, 0.0, 1.0, data) > 0;
    const int boxed = svg && svg_legend_box(svg, legend);
    CHECK(drawn && boxed, "%s: no data (%d) or no legend box (%d)", *name, drawn, boxed);
    if (drawn && boxed)
      CHECK(legend[0] > data[1] || legend[1] < data[0] || legend[2] > data[3] ||
                legend[3] < data[2],
            "%s: the legend [%g, %g] x [%g, %g] covers data [%g, %g] x [%g, %g]", *name,
            legend[0], legend[1], legend[2], legend[3], data[0], data[1], data[2], data[3]);
    CHECK(!boxed || legend[1] <= 960.0, "%s: the legend runs off the page at x %g", *name, legend[1]);
    free(svg);
  }
  free(err);
  free(theta);
  remove_dir(dir);
}

/* ---- what a newcomer reads ---- */

/* the labels of a linear axis are all distinct and their estimated boxes do
 * not overlap: along an axis 150 character heights long (x: a frame of about
 * 700 of the page's 960 px, at 5.15 mm per character height of its 339 mm),
 * across one 60 long (y) */
static void test_ticks(void) {
  static const double ranges[][2] = {{1.2 - 5e-11, 1.2 + 5e-11}, {-2.5e-5, 0.0}, {0.0, 7000.0},
                                     {-1.0, 1.0}, {1.19965, 1.20002}, {1e6, 1e6 + 3.0}};
  for (size_t r = 0; r < sizeof ranges / sizeof ranges[0]; r++)
    for (int along = 0; along <= 1; along++) {
      const double lo = ranges[r][0], hi = ranges[r][1], length = along ? 150.0 : 60.0;
      dvp_ticks t;
      dvp_linear_ticks(lo, hi, length, along, &t);
      char label[16][64];
      int n = 0;
      for (double i = ceil(lo / t.step - 1e-9); i * t.step <= hi + 1e-9 * t.step && n < 16; i++)
        dvp_tick_label(&t, i * t.step, label[n++], sizeof label[0]);
      CHECK(n >= 2, "[%g, %g]: %d ticks", lo, hi, n);
      for (int a = 0; a < n; a++)
        for (int b = a + 1; b < n; b++)
          CHECK(strcmp(label[a], label[b]) != 0, "[%g, %g]: two ticks read %s", lo, hi, label[a]);
      /* a label's box: its width (DVP_TICK_CHAR_WIDTH per character) along, one character across */
      const double pitch = t.step / (hi - lo) * length;
      for (int a = 0; a < n; a++) {
        const double size = along ? DVP_TICK_CHAR_WIDTH * (double)strlen(label[a]) : 1.0;
        CHECK(pitch > size, "[%g, %g] %s: labels %g apart, %s is %g wide", lo, hi,
              along ? "x" : "y", pitch, label[a], size);
      }
    }
}

/* the longest labels the report writes: every legend box lies within the page */
static void test_long_labels(const dv_traj *ref, const dv_traj *a, const dv_traj *b) {
  char dir[] = "/tmp/test_plot_long.XXXXXX";
  dv_plot_input in = {.title = "euro_coin_with_a_long_name", .thin = ref, .window_end = 6.0};
  const char *const names[] = {"adapter-rapier3d-compat", "adapter-cannon-es-physics", "mujoco",
                               "ode", "bullet", "dart", "simbody"};
  for (size_t k = 0; k < 7; k++)
    in.series[in.nseries++] = (dv_plot_series){names[k], k % 2 ? a : b, b, 6.0, 3.0,
                                               0.01 * (double)(k + 1), 0};
  in.series[in.nseries++] =
      (dv_plot_series){"reference (matched, thickness 2.2 mm)", b, NULL, 6.0, INFINITY, NAN, 0};
  plot_into(dir, &in);
  for (const char *const *name = dv_report_plot_files; *name; name++) {
    char *svg = plot_text(dir, *name);
    double box[4] = {0};
    const int boxed = svg && svg_legend_box(svg, box);
    CHECK(boxed, "%s: no legend box", *name);
    CHECK(!boxed || (box[0] >= 0.0 && box[1] <= 960.0 && box[2] >= 0.0 && box[3] <= 500.0),
          "%s: the legend [%g, %g] x [%g, %g] leaves the page 960 x 500", *name, box[0], box[1],
          box[2], box[3]);
    free(svg);
  }
  remove_dir(dir);
  /* and an x-y plot's, with two columns of them */
  char xydir[] = "/tmp/test_plot_long.XXXXXX", path[PATH_MAX];
  CHECK(mkdtemp(xydir) != NULL, "mkdtemp failed");
  snprintf(path, sizeof path, "%s/phase.svg", xydir);
  double x[2] = {1.2, 1.2 + 1e-10}, y[2] = {-8e-10, 8e-10};
  dv_plot_curve c[12];
  for (int k = 0; k < 12; k++)
    c[k] = (dv_plot_curve){k ? names[k % 7] : "reference (matched, the level set E)", 2, x, y, NULL,
                           DV_CURVE_LINE, k};
  dv_error err = {{0}};
  CHECK(dv_report_plot_xy(path, "phase", "#gh", "p", c, 12, 0, &err) == DV_OK, "%s", err.msg);
  char *svg = plot_text(xydir, "phase.svg");
  double box[4] = {0};
  const int boxed = svg && svg_legend_box(svg, box);
  CHECK(boxed && box[0] >= 0.0 && box[1] <= 960.0 && box[2] >= 0.0 && box[3] <= 500.0,
        "phase.svg: the legend [%g, %g] x [%g, %g] leaves the page", box[0], box[1], box[2],
        box[3]);
  free(svg);
  unlink(path);
  rmdir(xydir);
}

/* a thick scene: every engine judged against the matched reference; the thin
 * reference judged none: faint throughout, no turning points, out of the ranges */
static void test_thin_not_compared(const dv_traj *thin, const dv_traj *matched,
                                   const dv_traj *engine) {
  char dir[] = "/tmp/test_plot_thick.XXXXXX";
  dv_plot_input in = {.title = "coin", .thin = thin, .nseries = 2, .window_end = 10.0};
  in.series[0] = (dv_plot_series){"ode", engine, matched, 10.0, INFINITY, 0.01, 1};
  in.series[1] = (dv_plot_series){"reference (matched)", matched, NULL, 10.0, INFINITY, NAN, 0};
  plot_into(dir, &in);
  char *theta = plot_text(dir, "theta.svg");
  double strong[4] = {0}, faint[4] = {0};
  CHECK(theta && svg_lines(theta, "#000000", 10, 0.99, 1.0, strong) == 0,
        "the thin reference, which judged nothing, is drawn strongly");
  CHECK(theta && svg_lines(theta, "#000000", 10, 0.0, 0.5, faint) > 0,
        "the thin reference is not drawn faintly");
  /* (the frame and the legend box are black polylines of 5 points) ode's turns are not judged: the matched reference's not marked either */
  CHECK(theta && count_of(theta, "&#x25bc;") == 0 && count_of(theta, "&#x25b2;") == 0,
        "turning points marked where theta_turning_err was not judged");
  free(theta);
  remove_dir(dir);
}

int main(int argc, char **argv) {
  dv_traj ref = {0}, close_by = {0}, holed = {0}, empty = {0}, flat = {0};
  CHECK(make_traj(&ref, N, 0.0) == 0 && make_traj(&close_by, N, 1e-6) == 0 &&
            make_traj(&holed, N, 1e-3) == 0,
        "out of memory");
  for (size_t i = 0; i < 5; i++) { /* a constant tilt: a collapsed range of its own */
    dv_sample s = sample((double)i, 0.0);
    s.y[RED_TH] = 1.0;
    s.energy = 0.0;
    CHECK(dv_run_traj_push(&flat, &s) == 0, "out of memory");
  }
  holed.s[50].y[RED_TH] = NAN; /* a hole in every plot */
  holed.s[50].contact[0] = INFINITY;
  holed.s[50].energy = NAN;
  holed.s[51].y[RED_TH] = NAN;

  dv_plot_input in = {.title = "synthetic #1", .thin = &ref, .nseries = 4, .window_end = INFINITY};
  in.series[0] = whole_run("close (1e-6)", &close_by, &ref);
  in.series[1] = whole_run("holed", &holed, &ref);
  in.series[2] = whole_run("empty", &empty, &ref);
  in.series[3] = whole_run("flat", &flat, &flat);

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
  none.series[0] = whole_run("empty", &empty, &empty);
  char dir2[] = "/tmp/test_plot.XXXXXX";
  CHECK(mkdtemp(dir2) != NULL, "mkdtemp failed");
  CHECK(dv_report_plot_scenario(dir2, &none, &err) == DV_OK, "empty input: %s", err.msg);
  check_dir(dir2);
  if (argc > 1)
    printf("empty plots kept in %s\n", dir2);
  else
    remove_dir(dir2);

  /* a missing directory: an error, no crash */
  char missing[PATH_MAX];
  snprintf(missing, sizeof missing, "%s/no/such/dir", dir);
  err.msg[0] = '\0';
  CHECK(dv_report_plot_scenario(missing, &in, &err) == DV_ESYSTEM, "missing dir accepted");
  CHECK(err.msg[0] != '\0', "missing dir: no message");

  if (argc > 1)
    printf("plots kept in %s\n", dir);
  else
    remove_dir(dir);
  test_engine_plots(&ref, &close_by, &holed, &empty);
  test_verdict_marks(&ref, &close_by, &holed);
  test_ticks();
  test_long_labels(&ref, &close_by, &holed);
  test_thin_not_compared(&ref, &close_by, &holed);
  dv_run_traj_free(&ref);
  dv_run_traj_free(&close_by);
  dv_run_traj_free(&holed);
  dv_run_traj_free(&empty);
  dv_run_traj_free(&flat);
  test_xy(argc > 1);
  return TEST_RESULT();
}
