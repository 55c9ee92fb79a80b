/* test_plot_many: as many series as a comparison holds. dv_report_plot_scenario
 * draws DV_PLOT_MAX_SERIES series (DV_MAX_ENGINES engines and the matched
 * reference) and the thin reference: in every plot each series is in the
 * legend, by its label, and drawn; no two in the same colour and line pattern
 * (the palette's colours, then a dashed line); the legend lies within the page
 * and off the frame, its text no smaller than the layout allows; their theta
 * limits labelled once per value. One series
 * more is refused with a one-line error and nothing written.
 * dv_report_plot_distinct_colours keeps the colours asked for where they are
 * apart, and otherwise gives free palette colours before dashed ones.
 * usage: test_plot_many [KEEP] (with an argument, the plots are kept to look at) */
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

#define NSERIES DV_PLOT_MAX_SERIES
#define PALETTE 16 /* dv_plot_curve's colours 1 to 16 (report_plot.h) */
#define PAGE_W 960.0
#define PAGE_H 500.0

/* the labels: engines with names no registry knows (their colours collide by
 * the hash), then the matched reference as the report labels it */
static void make_labels(char label[NSERIES][64]) {
  for (int k = 0; k < NSERIES - 1; k++) snprintf(label[k], 64, "engine %02d", k + 1);
  snprintf(label[NSERIES - 1], 64, "reference (matched, thickness 2.2 mm)");
}

/* whether a text element of svg reads exactly text */
static int has_text(const char *svg, const char *text) {
  char line[512];
  for (const char *p = svg; (p = strstr(p, "<text")); p++) {
    pt_decode_text(p, line, sizeof line);
    if (!strcmp(line, text)) return 1;
  }
  return 0;
}

/* the distinct stroke colours of the opaque polylines of svg but black,
 * white and the grid's; their count */
static int opaque_colours(const char *svg, char out[][8], int max) {
  int n = 0;
  for (const char *p = svg; (p = strstr(p, "<polyline")); p++) {
    char c[8], op[32];
    if (!pt_attr_of(p, "stroke=\"", c, sizeof c) ||
        !pt_attr_of(p, "stroke-opacity=\"", op, sizeof op) || atof(op) < 0.99 ||
        !strcmp(c, "#000000") || !strcmp(c, "#FFFFFF") || !strcmp(c, "#E1E1E1"))
      continue;
    int seen = 0;
    for (int i = 0; i < n; i++) seen |= !strcmp(out[i], c);
    if (!seen && n < max) snprintf(out[n++], 8, "%s", c);
  }
  return n;
}

/* the polylines of svg in colour with exactly two points, not vertical: a
 * curve's dashes, or a legend's line sample (not a window end's or horizon's mark) */
static int short_lines(const char *svg, const char *colour) {
  int n = 0;
  for (const char *p = svg; (p = strstr(p, "<polyline")); p++) {
    char c[8], pts[256];
    double x0, y0, x1, y1, x2, y2;
    if (pt_attr_of(p, "stroke=\"", c, sizeof c) && !strcmp(c, colour) &&
        pt_attr_of(p, "points=\"", pts, sizeof pts) &&
        sscanf(pts, "%lf,%lf %lf,%lf %lf,%lf", &x0, &y0, &x1, &y1, &x2, &y2) == 4 && x0 != x1)
      n++;
  }
  return n;
}

/* the smallest font size of the text elements reading one of the n labels, or
 * the title when n is 0 (the page's units) */
static double label_font(const char *svg, char label[][64], int n) {
  double least = INFINITY;
  char line[512], size[32];
  for (const char *p = svg; (p = strstr(p, "<text")); p++) {
    pt_decode_text(p, line, sizeof line);
    int is = n == 0 && !strncmp(line, "many: ", 6);
    for (int k = 0; k < n; k++) is |= !strcmp(line, label[k]);
    if (is && pt_attr_of(p, "font-size=\"", size, sizeof size)) least = fmin(least, atof(size));
  }
  return least;
}

/* every plot of dir: every label of the series it draws in its legend and drawn,
 * each in its own colour and pattern, the legend on the page and off the frame
 * (theta.svg's has 22 lines: the thin reference, the series, "not compared",
 * "window end", "horizon" and "turning points") */
static void check_plots(const char *dir, char label[NSERIES][64]) {
  for (const char *const *name = dv_report_plot_files; *name; name++) {
    char *svg = pt_plot_text(dir, *name);
    CHECK(svg != NULL, "%s: not written", *name);
    if (!svg) continue;
    /* the error plot draws the engines (against their reference), the others every series */
    const int error = !strcmp(*name, "theta_error.svg"), n = error ? NSERIES - 1 : NSERIES;
    for (int k = 0; k < n; k++)
      CHECK(has_text(svg, label[k]), "%s: %s is not in the legend", *name, label[k]);
    CHECK(error || has_text(svg, "reference (thin disk)"), "%s: no thin reference", *name);
    char *text = pt_svg_text(svg);
    CHECK(text && !strstr(text, "no data"), "%s: a series left out: %s", *name,
          text ? text : "(unreadable)");
    /* sixteen engines' limits, two values: one labelled line each, not sixteen piled up */
    CHECK(!error || (text && strstr(text, "limit 0.02 rad (3 engines)") &&
                     strstr(text, "limit 0.01 rad (13 engines)") && !strstr(text, "01 limit")),
          "%s: the limits are not labelled once per value: %s", *name,
          text ? text : "(unreadable)");
    free(text);
    /* n series in at most 16 colours: all 16 used, and n - 16 of them dashed as well */
    char colours[2 * PALETTE][8];
    const int ncolours = opaque_colours(svg, colours, 2 * PALETTE);
    CHECK(ncolours == (n < PALETTE ? n : PALETTE), "%s: %d colours for %d series", *name, ncolours,
          n);
    int dashed = 0;
    /* a solid curve is one polyline of its samples and its legend's sample one line; a
     * dashed one (pllsty 5: 2.5 mm, 1 mm, 1 mm, 1 mm) breaks into dashes: 4 in its
     * legend's 10 mm sample, dozens along the frame (measured 263 on theta.svg, 200
     * on energy.svg): more than 20, whatever the legend draws */
    for (int i = 0; i < ncolours; i++) dashed += short_lines(svg, colours[i]) > 20;
    CHECK(dashed == n - PALETTE, "%s: %d colours with dashes, want %d", *name, dashed, n - PALETTE);
    double legend[4] = {0}, data[4] = {0};
    const int boxed = pt_svg_legend_box(svg, legend);
    const int drawn = pt_svg_lines(svg, "", 150, 0.99, 1.0, data) > 0;
    CHECK(boxed && drawn, "%s: no legend box (%d) or no curve (%d)", *name, boxed, drawn);
    if (boxed && drawn) {
      CHECK(legend[0] >= 0.0 && legend[1] <= PAGE_W && legend[2] >= 0.0 && legend[3] <= PAGE_H,
            "%s: the legend [%g, %g] x [%g, %g] leaves the %g x %g page", *name, legend[0],
            legend[1], legend[2], legend[3], PAGE_W, PAGE_H);
      CHECK(legend[0] > data[1] || legend[3] < data[2],
            "%s: the legend [%g, %g] x [%g, %g] is not beside or below the curves [%g, %g] x "
            "[%g, %g]",
            *name, legend[0], legend[1], legend[2], legend[3], data[0], data[1], data[2], data[3]);
    }
    /* legend text no smaller than the layout's least, 0.45 of the title's (its
     * SCALE_MIN; PLplot writes whole units, so 1 less; measured: title 19, the
     * legend 11 on theta.svg, 0.8 * 0.85^2 of it) */
    const double font = label_font(svg, label, n), title = label_font(svg, label, 0);
    CHECK(isfinite(font) && font >= 0.45 * title - 1.0, "%s: legend text %g high, the title %g",
          *name, font, title);
    free(svg);
  }
}

/* dir holds no file */
static void check_empty(const char *dir) {
  DIR *d = opendir(dir);
  CHECK(d != NULL, "%s: cannot list", dir);
  if (!d) return;
  int files = 0;
  for (struct dirent *e; (e = readdir(d)) != NULL;)
    files += strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
  closedir(d);
  CHECK(files == 0, "%s: %d files written by a refused call", dir, files);
}

/* colours asked for: kept where apart; then free palette colours, then dashed ones */
static void test_distinct(void) {
  int want[3 * PALETTE], got[3 * PALETTE];
  for (int k = 0; k < PALETTE; k++) want[k] = PALETTE - k;
  dv_report_plot_distinct_colours(want, PALETTE, got);
  for (int k = 0; k < PALETTE; k++)
    CHECK(got[k] == want[k], "curve %d asked for %d, got %d", k, want[k], got[k]);
  for (int k = 0; k < 3 * PALETTE; k++) want[k] = 3; /* all the same, 3 * PALETTE of them */
  dv_report_plot_distinct_colours(want, 3 * PALETTE, got);
  CHECK(got[0] == 3, "the first to ask for 3 got %d", got[0]);
  for (int k = 1; k < 3 * PALETTE; k++) {
    /* the palette's other 15 colours in order, then 3 with one dash after another */
    const int expect = k < 3 ? k : k < PALETTE ? k + 1 : 3 + (k - PALETTE + 1) * PALETTE;
    CHECK(got[k] == expect, "curve %d: colour %d, want %d", k, got[k], expect);
  }
  const int none[3] = {0, 2, 0}; /* no preference (the thin reference's name: 0) */
  dv_report_plot_distinct_colours(none, 3, got);
  CHECK(got[0] == 1 && got[1] == 2 && got[2] == 3, "no preference: %d, %d, %d", got[0], got[1],
        got[2]);
}

int main(int argc, char **argv) {
  dv_traj ref = {0}, close_by = {0}, holed = {0}, run[NSERIES] = {{0}};
  CHECK(pt_make_runs(&ref, &close_by, &holed) == 0, "out of memory");
  char label[NSERIES][64];
  make_labels(label);
  dv_plot_input in = {.title = "many", .thin = &ref, .nseries = NSERIES, .window_end = INFINITY};
  for (int k = 0; k < NSERIES; k++) {
    for (int i = 0; i < PT_N; i++) { /* each its own offset: 2 mrad apart in every plot */
      const dv_sample s = pt_sample(10.0 * i / (PT_N - 1), 0.002 * (k + 1));
      CHECK(dv_run_traj_push(&run[k], &s) == 0, "out of memory");
    }
    /* a thick scene's: the engines judged against the matched reference, the last series */
    in.series[k] = pt_whole_run(label[k], &run[k], k < NSERIES - 1 ? &run[NSERIES - 1] : NULL);
    in.series[k].window_end = 8.0; /* of their 10 s: every mark in the legend as well */
    in.series[k].theta_limit = k < 3 ? 0.02 : 0.01;
  }
  in.series[0].horizon = 5.0;
  in.window_end = 8.0;
  char dir[] = "/tmp/test_plot_many.XXXXXX";
  CHECK(mkdtemp(dir) != NULL, "mkdtemp failed");
  dv_error err = {{0}};
  CHECK(dv_report_plot_scenario(dir, &in, &err) == DV_OK, "%d series: %s", NSERIES, err.msg);
  check_plots(dir, label);

  /* one series more than a plot holds: refused in one line, nothing written */
  char full[] = "/tmp/test_plot_many.XXXXXX";
  CHECK(mkdtemp(full) != NULL, "mkdtemp failed");
  in.nseries = NSERIES + 1;
  err.msg[0] = '\0';
  CHECK(dv_report_plot_scenario(full, &in, &err) == DV_EINPUT, "%d series accepted", NSERIES + 1);
  CHECK(err.msg[0] && !strchr(err.msg, '\n') && strstr(err.msg, "series"),
        "the refusal does not say why in one line: '%s'", err.msg);
  check_empty(full);
  rmdir(full);
  test_distinct();

  if (argc > 1)
    printf("plots kept in %s\n", dir);
  else
    pt_remove_dir(dir);
  dv_run_traj_free(&ref);
  dv_run_traj_free(&close_by);
  dv_run_traj_free(&holed);
  for (int k = 0; k < NSERIES; k++) dv_run_traj_free(&run[k]);
  return TEST_RESULT();
}
