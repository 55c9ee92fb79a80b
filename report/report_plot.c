/* dv_plot: the four SVG plots of one scenario, drawn with PLplot.
 *
 * Each file is drawn on a stream of its own (plmkstrm ... plend1), so the
 * caller's PLplot stream, if any, is left alone and consecutive calls work;
 * PLplot's state is global, so this is not thread-safe. Each file is written
 * as dv_io_open writes (io_file.h: a temporary in dir, created first so
 * PLplot never has to prompt or give up on an unwritable path, removed on
 * failure or a signal), checked to be a complete SVG document, then renamed
 * by dv_io_commit. PLplot's recoverable errors (plabort) are caught
 * per stream with plsError instead of printed. Non-finite samples break a
 * curve; a plot without any finite point still gets axes and "no data".
 */
#include "report_plot.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <plplot.h>

#include "io_file.h"
#include "report_plot_internal.h"

const char *const dv_report_plot_files[] = {"theta.svg", "theta_error.svg", "path.svg",
                                            "energy.svg", NULL};

/* the plots, in the order of dv_report_plot_files */
typedef enum plot_kind { PLOT_THETA = 0, PLOT_ERROR, PLOT_PATH, PLOT_ENERGY, NPLOTS } plot_kind;

static const struct {
  const char *what, *xlabel, *ylabel;
} kinds[NPLOTS] = {
    {"tilt angle", "time t (s)", "tilt #gh (rad)"},
    {"tilt error against its reference", "time t (s)", "|#gh - #gh#dref#u| (rad)"},
    {"contact paths (o start, x end)", "contact point x (m)", "contact point y (m)"},
    {"relative energy drift", "time t (s)", "(E - E#d0#u) / |E#d0#u|"},
};

/* cmap0: background, foreground (axes and the thin reference), grid, series */
enum {
  COL_BG = DVP_COL_BG,
  COL_FG = DVP_COL_FG,
  COL_GRID = DVP_COL_GRID,
  COL_SERIES = DVP_COL_SERIES
};
_Static_assert(DV_PLOT_MAX_SERIES <= DVP_NPALETTE, "a palette colour per series");
static const PLINT red[DVP_NCOLOURS] = {255, 0,   225, 31, 255, 44,  214, 148, 140, 227,
                                        127, 188, 23,  0,  0,   204, 128, 200, 0};
static const PLINT green[DVP_NCOLOURS] = {255, 0,   225, 119, 127, 160, 39, 103, 86, 119,
                                          127, 189, 190, 0,   100, 153, 0,  0,   128};
static const PLINT blue[DVP_NCOLOURS] = {255, 0,  225, 180, 14, 44, 40, 189, 75, 194,
                                         127, 34, 207, 140, 0,  0,  0,  200, 128};

#define ERR_FLOOR 1e-16  /* smallest error drawn on the log axis, rad */
#define LINE_CHUNK 65536 /* points per plline call */

/* one curve: a NaN in x or y breaks the line */
typedef struct curve {
  double *x, *y;
  size_t n;
  PLINT colour;
  char label[128]; /* legend text, PLplot-escaped */
} curve;

/* one plot: its title and curves, the thin reference first */
typedef struct figure {
  plot_kind kind;
  char title[512];
  size_t ncurves;
  curve c[DV_PLOT_MAX_SERIES + 1];
  double limit;        /* error plot: the theta limit, log10 (NAN: none) */
  double horizon;      /* error plot: the horizon, s (NAN: none) */
  double window_end;   /* s, where the comparison stopped (NAN: none) */
  double window_at[2]; /* path plot: the reference's contact point there (NAN: none) */
} figure;

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

/* whether point i of c can be drawn */
static int point_ok(const curve *c, size_t i) {
  return dvp_plottable(c->x[i]) && dvp_plottable(c->y[i]);
}

/* samples of tr at the same times as ref's, from the start */
static size_t matched_prefix(const dv_traj *tr, const dv_traj *ref) {
  if (!tr || !ref) return 0;
  const size_t n = tr->n < ref->n ? tr->n : ref->n;
  size_t i = 0;
  while (i < n && tr->s[i].t == ref->s[i].t) i++;
  return i;
}

/* fill c with the plotted values of tr (ref: the error plot's reference); -1 out of memory */
static int fill_curve(curve *c, plot_kind kind, const dv_traj *tr, const dv_traj *ref) {
  const size_t n = kind == PLOT_ERROR ? matched_prefix(tr, ref) : (tr ? tr->n : 0);
  if (n == 0) return 0;
  c->x = malloc(n * sizeof *c->x);
  c->y = malloc(n * sizeof *c->y);
  if (!c->x || !c->y) return -1;
  const double e0 = tr->s[0].energy;
  for (size_t i = 0; i < n; i++) {
    const dv_sample *s = &tr->s[i];
    double x = s->t, y = NAN;
    if (kind == PLOT_THETA) {
      y = s->y[RED_TH];
    } else if (kind == PLOT_ERROR) {
      const double d = fabs(s->y[RED_TH] - ref->s[i].y[RED_TH]); /* NaN stays NaN */
      if (isfinite(d)) y = log10(fmax(d, ERR_FLOOR));
    } else if (kind == PLOT_PATH) {
      x = s->contact[0];
      y = s->contact[1];
    } else {
      y = (s->energy - e0) / fabs(e0); /* E(0) = 0 or NaN: nothing drawn */
    }
    c->x[c->n] = x;
    c->y[c->n++] = y;
  }
  return 0;
}

/* whether c has a point to draw */
static int curve_has_data(const curve *c) {
  for (size_t i = 0; i < c->n; i++)
    if (point_ok(c, i)) return 1;
  return 0;
}

/* the thin reference's contact point at the end of the window, on the path
 * plot, when its run goes on after it */
static void window_point(figure *f, const dv_traj *thin) {
  f->window_at[0] = f->window_at[1] = NAN;
  if (!thin || thin->n == 0 || !(f->window_end < thin->s[thin->n - 1].t)) return;
  for (size_t i = 0; i < thin->n && thin->s[i].t <= f->window_end; i++) {
    f->window_at[0] = thin->s[i].contact[0];
    f->window_at[1] = thin->s[i].contact[1];
  }
}

/* set up the curves of one plot, leaving out those without data (the title
 * names them); -1 out of memory */
static int build_figure(figure *f, plot_kind kind, const dv_plot_input *in) {
  memset(f, 0, sizeof *f);
  f->kind = kind;
  f->limit = kind == PLOT_ERROR && in->theta_limit > 0.0 ? log10(in->theta_limit) : NAN;
  f->horizon = kind == PLOT_ERROR && isfinite(in->horizon) ? in->horizon : NAN;
  f->window_end = in->window_end > 0.0 && isfinite(in->window_end) ? in->window_end : NAN;
  if (kind == PLOT_PATH) window_point(f, in->thin);
  char name[160], missing[256] = "";
  dvp_escape(name, sizeof name, in->title, "");
  for (size_t k = 0; k <= in->nseries; k++) {
    const dv_plot_series *s = k ? &in->series[k - 1] : NULL;
    if (kind == PLOT_ERROR && !(s && s->reference)) continue; /* a reference has no error */
    curve *c = &f->c[f->ncurves];
    c->colour =
        s ? (PLINT)(COL_SERIES + (dv_report_plot_engine_colour(s->label) - 1) % DVP_NPALETTE)
          : COL_FG;
    if (fill_curve(c, kind, s ? s->traj : in->thin, s ? s->reference : NULL)) return -1;
    const char *label = s ? s->label : "reference (thin disk)";
    if (curve_has_data(c)) {
      dvp_escape(c->label, sizeof c->label, label, "");
      f->ncurves++;
      continue;
    }
    free(c->x), free(c->y);
    memset(c, 0, sizeof *c);
    const size_t used = strlen(missing);
    snprintf(missing + used, sizeof missing - used, "%s%s", used ? ", " : "", label);
  }
  char note[300] = "";
  if (missing[0]) dvp_escape(note, sizeof note, missing, ")");
  snprintf(f->title, sizeof f->title, "%s: %s%s%s", name, kinds[kind].what,
           note[0] ? " (no data: " : "", note);
  return 0;
}

/* free the curves of f */
static void free_figure(figure *f) {
  for (size_t k = 0; k < f->ncurves; k++) {
    free(f->c[k].x);
    free(f->c[k].y);
  }
  f->ncurves = 0;
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

/* bounds of every drawable point; 0 when there is none */
static int data_range(const figure *f, double r[4]) {
  int any = 0;
  for (size_t k = 0; k < f->ncurves; k++)
    dvp_extend_range(f->c[k].x, f->c[k].y, f->c[k].n, r, &any);
  return any;
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

/* draw the drawable runs of c as lines, a lone point as a dot */
static void draw_curve(const curve *c) {
  size_t i = 0;
  while (i < c->n) {
    while (i < c->n && !point_ok(c, i)) i++;
    size_t j = i;
    while (j < c->n && point_ok(c, j)) j++;
    if (j - i == 1) plpoin(1, &c->x[i], &c->y[i], 17);
    dvp_line(&c->x[i], &c->y[i], j - i);
    i = j;
  }
}

/* mark the first drawable point of c with a circle and the last with a cross */
static void draw_ends(const curve *c) {
  size_t first = c->n, last = c->n;
  for (size_t i = 0; i < c->n; i++) {
    if (!point_ok(c, i)) continue;
    if (first == c->n) first = i;
    last = i;
  }
  if (first == c->n) return;
  plpoin(1, &c->x[first], &c->y[first], 4);
  plpoin(1, &c->x[last], &c->y[last], 5);
}

/* the points of f's curves, for placing its legend; the longest label's length */
static size_t legend_points(const figure *f, dvp_points *pts) {
  size_t longest = 0;
  for (size_t k = 0; k < f->ncurves; k++) {
    pts[k] = (dvp_points){f->c[k].x, f->c[k].y, f->c[k].n};
    if (strlen(f->c[k].label) > longest) longest = strlen(f->c[k].label);
  }
  return longest;
}

/* a legend inside the viewport, one line per curve, where it hides the fewest points */
static void draw_legend(const figure *f, const double r[4]) {
  PLINT opt[DV_PLOT_MAX_SERIES + 1], tcol[DV_PLOT_MAX_SERIES + 1], lcol[DV_PLOT_MAX_SERIES + 1];
  PLINT lstyle[DV_PLOT_MAX_SERIES + 1];
  PLFLT lwidth[DV_PLOT_MAX_SERIES + 1];
  const char *text[DV_PLOT_MAX_SERIES + 1];
  const PLINT n = (PLINT)f->ncurves;
  if (n == 0) return;
  dvp_points pts[DV_PLOT_MAX_SERIES + 1];
  const size_t longest = legend_points(f, pts);
  for (PLINT k = 0; k < n; k++) {
    opt[k] = PL_LEGEND_LINE;
    tcol[k] = COL_FG;
    lcol[k] = f->c[k].colour;
    lstyle[k] = 1;
    lwidth[k] = 2.0;
    text[k] = f->c[k].label;
  }
  PLFLT w, h;
  const PLINT where = dvp_legend_corner(pts, (size_t)n, r, n, 1, longest);
  pllegend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, where, DVP_LEGEND_OFFSET,
           DVP_LEGEND_OFFSET, DVP_LEGEND_LINE, COL_BG, COL_FG, 1, n, 1, n, opt, 0.8,
           DVP_LEGEND_SCALE, DVP_LEGEND_SPACING, 0.0, tcol, text, NULL, NULL, NULL, NULL, lcol,
           lstyle, lwidth, NULL, NULL, NULL, NULL);
}

void dvp_decade_label(PLINT axis, PLFLT value, char *label, PLINT length, PLPointer data) {
  snprintf(label, (size_t)length, "10#u%d#d", (int)lround(value));
}

/* the error plot's theta limit (dashed) and the reference's horizon (dotted), labelled */
static void draw_limits(const figure *f, const double r[4]) {
  if (isfinite(f->limit)) {
    pllsty(2);
    pljoin(r[0], f->limit, r[1], f->limit);
    plptex(r[1] - 0.02 * (r[1] - r[0]), f->limit + 0.02 * (r[3] - r[2]), 1, 0, 1, "limit");
  }
  if (isfinite(f->horizon) && f->horizon > r[0] && f->horizon < r[1]) {
    pllsty(3);
    pljoin(f->horizon, r[2], f->horizon, r[3]);
    plptex(f->horizon, r[3] - 0.05 * (r[3] - r[2]), 0, 1, 1.05, "horizon");
  }
  pllsty(1);
}

/* where the comparison stopped, when the run goes on after it: a dash-dotted
 * line over time (labelled at the bottom), a diamond on the reference's path */
static void draw_window_end(const figure *f, const double r[4], double t_last) {
  if (f->kind == PLOT_PATH) {
    if (!dvp_plottable(f->window_at[0]) || !dvp_plottable(f->window_at[1])) return;
    plstring(1, &f->window_at[0], &f->window_at[1], DVP_DIAMOND);
    const int left = f->window_at[0] > 0.5 * (r[0] + r[1]); /* the label stays in the frame */
    const double gap = (left ? -0.02 : 0.02) * (r[1] - r[0]);
    plptex(f->window_at[0] + gap, f->window_at[1] - 0.04 * (r[3] - r[2]), 1, 0, left ? 1.0 : 0.0,
           DVP_WINDOW_END);
    return;
  }
  if (!(f->window_end > r[0] && f->window_end < t_last - 1e-9 * fabs(t_last))) return;
  pllsty(4);
  pljoin(f->window_end, r[2], f->window_end, r[3]);
  pllsty(1);
  plptex(f->window_end, r[2] + 0.05 * (r[3] - r[2]), 0, 1, -0.05, DVP_WINDOW_END);
}

/* the latest time drawn: the end of the run */
static double last_time(const figure *f) {
  double t = -INFINITY;
  for (size_t k = 0; k < f->ncurves; k++)
    for (size_t i = 0; i < f->c[k].n; i++)
      if (point_ok(&f->c[k], i)) t = fmax(t, f->c[k].x[i]);
  return t;
}

/* draw figure f (a figure *) on the current, initialised stream */
static void draw_figure(const void *arg) {
  const figure *f = arg;
  const int logy = f->kind == PLOT_ERROR;
  double r[4];
  const int any = data_range(f, r);
  const double t_last = last_time(f); /* the path plot's x is no time: unused there */
  if (!any) {
    r[0] = 0, r[1] = 1;
    r[2] = logy ? -16 : 0, r[3] = logy ? 0 : 1;
  }
  if (isfinite(f->limit)) r[3] = fmax(r[3], f->limit); /* the limit stays in view */
  dvp_pad_range(&r[0], &r[1], f->kind == PLOT_PATH ? 0.05 : 0.0, 0.0);
  dvp_pad_range(&r[2], &r[3], 0.05, logy ? 1.0 : 0.0);
  if (logy) { /* whole decades, so that at least two are labelled */
    r[2] = floor(r[2]);
    r[3] = ceil(r[3]);
  }
  /* small variations about a large value need long tick labels: more room */
  const int narrow = !logy && r[3] - r[2] < 1e-3 * fmax(fabs(r[2]), fabs(r[3]));
  pladv(0);
  plvpor(narrow ? 0.16 : 0.12, DVP_VIEWPORT_RIGHT, 0.12, 0.88);
  plsyax(8, 0);
  dvp_points pts[DV_PLOT_MAX_SERIES + 1];
  const size_t longest = legend_points(f, pts);
  dvp_legend_make_room(pts, f->ncurves, r, (int)f->ncurves, 1, longest);
  if (f->kind == PLOT_PATH) dvp_equal_aspect(r);
  plwind(r[0], r[1], r[2], r[3]);
  plcol0(COL_GRID);
  plwidth(1.0);
  plbox("g", 0, 0, logy ? "gl" : "g", 0, 0);
  plcol0(COL_FG);
  /* a log axis labels every decade (PLplot's "l"), or every few with labels of our own */
  const double ystep = logy ? ceil((r[3] - r[2]) / 8.0) : 0.0;
  if (ystep > 1) plslabelfunc(dvp_decade_label, NULL);
  plbox("bcnst", 0, 0, !logy ? "bcnstv" : ystep > 1 ? "bcnotv" : "bcnstlv", ystep, 0);
  pllab(kinds[f->kind].xlabel, "", f->title);
  plmtex("l", narrow ? 8.0 : logy ? 5.5 : 5.0, 0.5, 0.5, kinds[f->kind].ylabel);
  for (size_t k = 0; k < f->ncurves; k++) { /* the thin reference wide, underneath */
    plwidth(f->c[k].colour == COL_FG ? 3.0 : 1.5);
    plcol0(f->c[k].colour);
    draw_curve(&f->c[k]);
    if (f->kind == PLOT_PATH) draw_ends(&f->c[k]);
  }
  plwidth(1.0);
  plcol0(COL_FG);
  draw_limits(f, r);
  draw_window_end(f, r, t_last);
  if (!any) plptex(0.5 * (r[0] + r[1]), 0.5 * (r[2] + r[3]), 1, 0, 0.5, "no data");
  draw_legend(f, r);
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
  plscmap0n(DVP_NCOLOURS);
  plscmap0(red, green, blue, DVP_NCOLOURS);
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

int dv_report_plot_scenario(const char *dir, const dv_plot_input *in, dv_error *err) {
  if (!dir || !in || in->nseries > DV_PLOT_MAX_SERIES)
    return dv_fail(err, DV_EINPUT, "dv_report_plot_scenario: bad arguments");
  struct stat st;
  if (stat(dir, &st) != 0) return dv_fail(err, DV_ESYSTEM, "%s: %s", dir, strerror(errno));
  if (!S_ISDIR(st.st_mode)) return dv_fail(err, DV_ESYSTEM, "%s: not a directory", dir);
  if (!dvp_have_svg()) return dv_fail(err, DV_ESYSTEM, "PLplot has no svg driver");
  int status = DV_OK;
  figure f = {0};
  for (int k = 0; k < NPLOTS && status == DV_OK; k++) {
    char path[PATH_MAX];
    if (snprintf(path, sizeof path, "%s/%s", dir, dv_report_plot_files[k]) >= (int)sizeof path)
      status = dv_fail(err, DV_ESYSTEM, "%s: path too long", dir);
    else if (build_figure(&f, (plot_kind)k, in) != 0)
      status = dv_fail(err, DV_ESYSTEM, "%s: out of memory", dv_report_plot_files[k]);
    else
      status = dvp_write_svg(path, draw_figure, &f, err);
    free_figure(&f);
  }
  return status;
}
