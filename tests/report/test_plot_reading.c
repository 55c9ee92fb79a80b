/* test_plot_reading: what a newcomer reads in the plots dv_plot writes. The
 * labels of a linear axis are all distinct and their estimated boxes do not
 * overlap; with the longest labels the report writes, every legend box lies
 * within the page (the scenario plots' and an x-y plot's); in a thick scene,
 * every engine judged against the matched reference, the thin reference judged
 * none: faint throughout, no turning points, out of the ranges. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_test.h"
#include "plot_svg.h"
#include "report_plot.h"
#include "report_plot_ticks.h"

/* the four plots of in into a new directory (its name left in dir) */
static void plot_into(char *dir, const dv_plot_input *in) {
  dv_error err = {{0}};
  CHECK(mkdtemp(dir) != NULL, "mkdtemp failed");
  CHECK(dv_report_plot_scenario(dir, in, &err) == DV_OK, "%s: %s", in->title, err.msg);
}

/* ---- what a newcomer reads ---- */

/* the labels of a linear axis are all distinct and their estimated boxes do
 * not overlap: along an axis 150 character heights long (x: a frame of about
 * 700 of the page's 960 px, at 5.15 mm per character height of its 339 mm),
 * across one 60 long (y) */
static void test_ticks(void) {
  static const double ranges[][2] = {
      {1.2 - 5e-11, 1.2 + 5e-11}, {-2.5e-5, 0.0},  {0.0, 7000.0}, {-1.0, 1.0},
      {1.19965, 1.20002},         {1e6, 1e6 + 3.0}};
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
  const char *const names[] = {"adapter-rapier3d-compat",
                               "adapter-cannon-es-physics",
                               "mujoco",
                               "ode",
                               "bullet",
                               "dart",
                               "simbody"};
  for (size_t k = 0; k < 7; k++)
    in.series[in.nseries++] =
        (dv_plot_series){names[k], k % 2 ? a : b, b, 6.0, 3.0, 0.01 * (double)(k + 1), 0};
  in.series[in.nseries++] =
      (dv_plot_series){"reference (matched, thickness 2.2 mm)", b, NULL, 6.0, INFINITY, NAN, 0};
  plot_into(dir, &in);
  for (const char *const *name = dv_report_plot_files; *name; name++) {
    char *svg = pt_plot_text(dir, *name);
    double box[4] = {0};
    const int boxed = svg && pt_svg_legend_box(svg, box);
    CHECK(boxed, "%s: no legend box", *name);
    CHECK(!boxed || (box[0] >= 0.0 && box[1] <= 960.0 && box[2] >= 0.0 && box[3] <= 500.0),
          "%s: the legend [%g, %g] x [%g, %g] leaves the page 960 x 500", *name, box[0], box[1],
          box[2], box[3]);
    free(svg);
  }
  pt_remove_dir(dir);
  /* and an x-y plot's, with two columns of them */
  char xydir[] = "/tmp/test_plot_long.XXXXXX", path[PATH_MAX];
  CHECK(mkdtemp(xydir) != NULL, "mkdtemp failed");
  snprintf(path, sizeof path, "%s/phase.svg", xydir);
  double x[2] = {1.2, 1.2 + 1e-10}, y[2] = {-8e-10, 8e-10};
  dv_plot_curve c[12];
  for (int k = 0; k < 12; k++)
    c[k] = (dv_plot_curve){
        k ? names[k % 7] : "reference (matched, the level set E)", 2, x, y, NULL, DV_CURVE_LINE, k};
  dv_error err = {{0}};
  CHECK(dv_report_plot_xy(path, "phase", "#gh", "p", c, 12, 0, &err) == DV_OK, "%s", err.msg);
  char *svg = pt_plot_text(xydir, "phase.svg");
  double box[4] = {0};
  const int boxed = svg && pt_svg_legend_box(svg, box);
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
  char *theta = pt_plot_text(dir, "theta.svg");
  double strong[4] = {0}, faint[4] = {0};
  CHECK(theta && pt_svg_lines(theta, "#000000", 10, 0.99, 1.0, strong) == 0,
        "the thin reference, which judged nothing, is drawn strongly");
  CHECK(theta && pt_svg_lines(theta, "#000000", 10, 0.0, 0.5, faint) > 0,
        "the thin reference is not drawn faintly");
  /* (the frame and the legend box are black polylines of 5 points) ode's turns are not judged: the
   * matched reference's not marked either */
  CHECK(theta && pt_count_of(theta, "&#x25bc;") == 0 && pt_count_of(theta, "&#x25b2;") == 0,
        "turning points marked where theta_turning_err was not judged");
  free(theta);
  pt_remove_dir(dir);
}

int main(void) {
  dv_traj ref = {0}, close_by = {0}, holed = {0};
  CHECK(pt_make_runs(&ref, &close_by, &holed) == 0, "out of memory");
  test_ticks();
  test_long_labels(&ref, &close_by, &holed);
  test_thin_not_compared(&ref, &close_by, &holed);
  dv_run_traj_free(&ref);
  dv_run_traj_free(&close_by);
  dv_run_traj_free(&holed);
  return TEST_RESULT();
}
