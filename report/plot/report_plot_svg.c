/* the helpers dv_report_plot_scenario and dv_report_plot_xy share
 * (report_plot_internal.h): the palette, ranges, lines, and dvp_write_svg.
 *
 * Each file is drawn on a stream of its own (plmkstrm ... plend1), so the
 * caller's PLplot stream, if any, is left alone and consecutive calls work;
 * PLplot's state is global, so this is not thread-safe. Each file is written
 * as dv_io_open writes (io_file.h: a temporary in dir, created first so
 * PLplot never has to prompt or give up on an unwritable path, removed on
 * failure or a signal), checked to be a complete SVG document, then renamed
 * by dv_io_commit. PLplot's recoverable errors (plabort) are caught
 * per stream with plsError instead of printed.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <plplot.h>

#include "io_file.h"
#include "report_plot_internal.h"

#define LINE_CHUNK 65536 /* points per plline call */

/* cmap0: background, foreground (axes and the thin reference), grid, series; then translucent */
enum { NSOLID = DVP_COL_FAINT_FG };
static const PLINT red[NSOLID] = {255, 0,   225, 31, 255, 44,  214, 148, 140, 227,
                                        127, 188, 23,  0,  0,   204, 128, 200, 0};
static const PLINT green[NSOLID] = {255, 0,   225, 119, 127, 160, 39, 103, 86, 119,
                                          127, 189, 190, 0,   100, 153, 0,  0,   128};
static const PLINT blue[NSOLID] = {255, 0,  225, 180, 14, 44, 40, 189, 75, 194,
                                         127, 34, 207, 140, 0,  0,  0,  200, 128};


/* the solid colours, then the foreground and the series colours translucent */
static void set_palette(void) {
  PLINT r[DVP_NCOLOURS], g[DVP_NCOLOURS], b[DVP_NCOLOURS];
  PLFLT a[DVP_NCOLOURS];
  for (int k = 0; k < DVP_NCOLOURS; k++) {
    const int from = k < NSOLID ? k : k == DVP_COL_FAINT_FG ? DVP_COL_FG : DVP_COL_SERIES + k - DVP_COL_FAINT;
    r[k] = red[from], g[k] = green[from], b[k] = blue[from];
    a[k] = k < NSOLID ? 1.0 : DVP_FAINT_ALPHA;
  }
  plscmap0n(DVP_NCOLOURS);
  plscmap0a(r, g, b, a, DVP_NCOLOURS);
}

void dvp_escape(char *out, size_t size, const char *text, const char *suffix) {
  size_t k = 0;
  for (const char *p = text ? text : "?"; *p && k + 3 < size; p++) {
    if (*p == '#') out[k++] = '#';
    out[k++] = *p;
  }
  out[k] = '\0';
  snprintf(out + k, size - k, "%s", suffix);
}

int dvp_plottable(double v) {
  return isfinite(v) && fabs(v) < DVP_PLOT_LIMIT;
}

void dvp_extend_range(const double *x, const double *y, size_t n, double r[4], int *any) {
  for (size_t i = 0; i < n; i++) {
    if (!dvp_plottable(x[i]) || !dvp_plottable(y[i])) continue;
    if (!*any || x[i] < r[0]) r[0] = x[i];
    if (!*any || x[i] > r[1]) r[1] = x[i];
    if (!*any || y[i] < r[2]) r[2] = y[i];
    if (!*any || y[i] > r[3]) r[3] = y[i];
    *any = 1;
  }
}

void dvp_pad_range(double *lo, double *hi, double margin, double min_pad) {
  const double span = *hi - *lo, mag = fmax(fabs(*lo), fabs(*hi));
  if (!(span > 1e-300) || span < 1e-6 * mag) {
    const double mid = 0.5 * (*lo + *hi), p = fmax(mag > 0 ? 0.05 * mag : 1.0, min_pad);
    *lo = mid - p;
    *hi = mid + p;
  } else {
    *lo -= margin * span;
    *hi += margin * span;
  }
}

void dvp_equal_aspect(double r[4]) {
  PLFLT sx0, sx1, sy0, sy1, vx0, vx1, vy0, vy1;
  plgspa(&sx0, &sx1, &sy0, &sy1); /* subpage, mm */
  plgvpd(&vx0, &vx1, &vy0, &vy1); /* viewport, fraction of the subpage */
  const double w = (vx1 - vx0) * (sx1 - sx0), h = (vy1 - vy0) * (sy1 - sy0);
  const double xs = r[1] - r[0], ys = r[3] - r[2];
  if (ys * w < xs * h) {
    const double mid = 0.5 * (r[2] + r[3]), half = 0.5 * xs * h / w;
    r[2] = mid - half;
    r[3] = mid + half;
  } else {
    const double mid = 0.5 * (r[0] + r[1]), half = 0.5 * ys * w / h;
    r[0] = mid - half;
    r[1] = mid + half;
  }
}

void dvp_line(const double *x, const double *y, size_t n) {
  for (size_t a = 0; n - a > 1; a += LINE_CHUNK - 1) { /* chunks share their end points */
    const size_t m = n - a < LINE_CHUNK ? n - a : LINE_CHUNK;
    plline((PLINT)m, &x[a], &y[a]);
    if (a + m == n) break;
  }
}

void dvp_decade_label(PLINT axis, PLFLT value, char *label, PLINT length, PLPointer data) {
  snprintf(label, (size_t)length, "10#u%d#d", (int)lround(value));
}

int dvp_have_svg(void) {
  const char *menu[128], *names[128], **pm = menu, **pn = names;
  int n = 128;
  plgDevs(&pm, &pn, &n);
  for (int i = 0; i < n; i++)
    if (names[i] && strcmp(names[i], "svg") == 0) return 1;
  return 0;
}

/* whether the file at path is a complete SVG document */
static int svg_complete(const char *path) {
  FILE *fp = fopen(path, "rb");
  if (!fp) return 0;
  char head[8] = "", tail[64] = "";
  const size_t nh = fread(head, 1, 5, fp);
  long size = fseek(fp, 0, SEEK_END) == 0 ? ftell(fp) : -1;
  const long back = size > (long)sizeof tail - 1 ? (long)sizeof tail - 1 : size;
  size_t nt = 0;
  if (back > 0 && fseek(fp, -back, SEEK_END) == 0) nt = fread(tail, 1, (size_t)back, fp);
  fclose(fp);
  tail[nt] = '\0';
  return nh == 5 && (memcmp(head, "<?xml", 5) == 0 || memcmp(head, "<svg", 4) == 0) &&
         strstr(tail, "</svg>") != NULL;
}

int dvp_write_svg(const char *path, dvp_draw_fn draw, const void *arg, dv_error *err) {
  char plmsg[1024] = "";
  PLINT plcode = 0, prev = 0, strm = -1;
  const char *slash = strrchr(path, '/');
  if (!*(slash ? slash + 1 : path)) return dv_fail(err, DV_EINPUT, "%s: no file name", path);
  dv_io_file out;
  int status = dv_io_open(&out, path, err);
  if (status != DV_OK) return status;
  /* PLplot writes the file by its name: the temporary, or a device in place */
  const char *name = out.direct ? out.path : out.tmp_path;
  if (out.fp == stdout) {
    status = dv_fail(err, DV_EINPUT, "%s: a plot needs a file", path);
    goto cleanup;
  }
  if (strstr(name, "%n")) { /* PLplot would read it as a file family pattern */
    status = dv_fail(err, DV_ESYSTEM, "%s: PLplot cannot write a path containing %%n", path);
    goto cleanup;
  }

  plgstrm(&prev);
  plmkstrm(&strm);
  if (strm < 0) {
    status = dv_fail(err, DV_ESYSTEM, "%s: no free PLplot stream", path);
    goto cleanup;
  }
  plsError(&plcode, plmsg); /* plabort fills these instead of printing */
  plsdev("svg");
  plsfnam(name);
  plspage(0, 0, DVP_PAGE_W, DVP_PAGE_H, 0, 0);
  set_palette();
  plinit();
  if (!plcode) draw(arg);
  plend1();
  plsstrm(prev);
  if (plcode) {
    plmsg[strcspn(plmsg, "\n")] = '\0';
    status = dv_fail(err, DV_ESYSTEM, "%s: PLplot: %s", path, plmsg[0] ? plmsg : "error");
    goto cleanup;
  }
  if (!out.direct && !svg_complete(name)) {
    status = dv_fail(err, DV_ESYSTEM, "%s: PLplot wrote an incomplete SVG file", path);
    goto cleanup;
  }
  return dv_io_commit(&out, err); /* renames the temporary over path */

cleanup:
  dv_io_abort(&out);
  return status;
}

