/* dv_report_plot_xy: one generic x-y plot (see dv_plot.h), drawn with PLplot into
 * an SVG file through dvp_write_svg (dv_plot.c): own stream, temporary file,
 * validation, rename, no output.
 *
 * Coordinates are transformed once (log10 on a log axis); a point that cannot
 * be drawn becomes NaN there, which breaks lines and is skipped everywhere.
 * Dots and stars are UTF-8 glyphs drawn with plstring, as the legend draws
 * its symbols.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "report_plot.h"
#include "report_plot_internal.h"
#include "report_plot_ticks.h"

#define DOT "\xe2\x97\x8f"          /* U+25CF black circle: a point */
#define STAR "\xe2\x98\x85"         /* U+2605 black star: a marked point */
#define STAR_OUTLINE "\xe2\x98\x86" /* U+2606 white star: its outline */
#define MARK_TEXT "Pareto-optimal"  /* the legend entry of marked points */
#define DOT_SCALE 0.5               /* of the default character height */
#define LONE_SCALE 1.2              /* a line that is one point */
#define STAR_SCALE 1.4
#define CHUNK 65536 /* points per plstring call */

typedef struct xy_curve {
  double *x, *y;     /* plotted coordinates, NaN where a point is skipped */
  const int *marked; /* the caller's, or NULL */
  size_t n;
  int style, any;  /* any: a point to draw */
  int zeros;       /* every y is 0: on a log axis, below it rather than missing */
  PLINT colour;    /* cmap0 index */
  PLINT pattern;   /* line style (pllsty): 1 solid, dashed for colour numbers past the palette */
  char label[128]; /* PLplot-escaped */
} xy_curve;

typedef struct xy_figure {
  const char *xlabel, *ylabel;
  char title[768];  /* the caller's, then "(no data: ...)" naming the curves left out */
  int flags, marks; /* marks: a drawn point is marked */
  size_t n;
  xy_curve c[DV_PLOT_MAX_CURVES];
} xy_figure;

/* v on an axis (log10 if log), NaN when it cannot be drawn there */
static double axis_value(double v, int log) {
  if (!dvp_plottable(v) || (log && !(v > 0))) return NAN;
  return log ? log10(v) : v;
}

/* whether point i of c is drawn */
static int point_ok(const xy_curve *c, size_t i) {
  return !isnan(c->x[i]) && !isnan(c->y[i]);
}

/* whether point i of c is drawn and marked */
static int point_marked(const xy_curve *c, size_t i) {
  return c->marked && c->marked[i] && point_ok(c, i);
}

/* transform curve in into c; -1 out of memory */
static int fill_curve(xy_curve *c, const dv_plot_curve *in, int flags) {
  c->n = in->n;
  c->style = in->style;
  c->marked = in->marked;
  dvp_colour_style(in->colour, &c->colour, &c->pattern);
  if (c->n > 0) {
    c->x = malloc(c->n * sizeof *c->x);
    c->y = malloc(c->n * sizeof *c->y);
    if (!c->x || !c->y) return -1;
  }
  c->zeros = c->n > 0 && (flags & DV_PLOT_LOGY);
  for (size_t i = 0; i < c->n; i++) {
    c->x[i] = axis_value(in->x[i], flags & DV_PLOT_LOGX);
    c->y[i] = axis_value(in->y[i], flags & DV_PLOT_LOGY);
    c->any |= point_ok(c, i);
    c->zeros &= in->y[i] == 0.0;
  }
  dvp_escape(c->label, sizeof c->label, in->label, "");
  return 0;
}

/* bounds of every drawn point; 0 when there is none */
static int data_range(const xy_figure *f, double r[4]) {
  int any = 0;
  for (size_t k = 0; k < f->n; k++) dvp_extend_range(f->c[k].x, f->c[k].y, f->c[k].n, r, &any);
  return any;
}

/* pad [lo, hi]; on a log axis (decades) widen to whole decades unless two are inside */
static void axis_range(double *lo, double *hi, int log) {
  dvp_pad_range(lo, hi, 0.05, log ? 1.0 : 0.0);
  if (log && floor(*hi) - ceil(*lo) < 1.0) {
    *lo = floor(*lo);
    *hi = ceil(*hi);
  }
}

/* glyph at the points [a, b) of c, which are all drawn */
static void glyphs(const xy_curve *c, size_t a, size_t b, const char *glyph) {
  for (; a < b; a += CHUNK) {
    const size_t m = b - a < CHUNK ? b - a : CHUNK;
    plstring((PLINT)m, &c->x[a], &c->y[a], glyph);
  }
}

/* whether the points [a, b) of c, all drawn, are one point to 1e-9 of its
 * coordinates (a steady motion's U(theta), theta still to 1e-14 rad) */
static int one_point(const xy_curve *c, size_t a, size_t b) {
  const double ex = 1e-9 * fabs(c->x[a]), ey = 1e-9 * fabs(c->y[a]);
  for (size_t i = a + 1; i < b; i++)
    if (fabs(c->x[i] - c->x[a]) > ex || fabs(c->y[i] - c->y[a]) > ey) return 0;
  return 1;
}

/* the runs of drawn points of c: lines (a lone point, or a run that stays at one: a
 * large dot) and/or dots */
static void draw_curve(const xy_curve *c) {
  const int line = c->style != DV_CURVE_POINTS, dots = c->style != DV_CURVE_LINE;
  size_t i = 0;
  while (i < c->n) {
    while (i < c->n && !point_ok(c, i)) i++;
    size_t j = i;
    while (j < c->n && point_ok(c, j)) j++;
    if (line && j > i && one_point(c, i, j)) {
      plschr(0, LONE_SCALE);
      glyphs(c, i, i + 1, DOT);
      plschr(0, 1.0);
    } else if (line) {
      pllsty(c->pattern);
      dvp_line(&c->x[i], &c->y[i], j - i);
      pllsty(1);
    }
    if (dots) {
      plschr(0, DOT_SCALE);
      glyphs(c, i, j, DOT);
      plschr(0, 1.0);
    }
    i = j;
  }
}

/* the marked points of c: a star in its colour, outlined black */
static void draw_marks(const xy_curve *c) {
  plschr(0, STAR_SCALE);
  for (size_t i = 0; i < c->n; i++) {
    if (!point_marked(c, i)) continue;
    plcol0(c->colour);
    plstring(1, &c->x[i], &c->y[i], STAR);
    plcol0(DVP_COL_FG);
    plstring(1, &c->x[i], &c->y[i], STAR_OUTLINE);
  }
  plschr(0, 1.0);
}

/* the legend's texts (labelled curves with data, then the marks' if any) into text; their count */
static int legend_texts(const xy_figure *f, const char **text) {
  int n = 0;
  for (size_t k = 0; k < f->n; k++)
    if (f->c[k].any && f->c[k].label[0]) text[n++] = f->c[k].label;
  if (f->marks) text[n++] = MARK_TEXT;
  return n;
}

/* a legend right of the frame: every labelled curve with data, then the marks if any */
static void draw_legend(const xy_figure *f, const dvp_layout *lay) {
  enum { M = DV_PLOT_MAX_CURVES + 1 };
  PLINT opt[M], tcol[M], lcol[M], lstyle[M], scol[M], snum[M];
  PLFLT lwidth[M], sscale[M];
  const char *text[M], *sym[M];
  PLINT n = 0;
  for (size_t k = 0; k < f->n; k++) {
    const xy_curve *c = &f->c[k];
    if (!c->any || !c->label[0]) continue;
    opt[n] = c->style == DV_CURVE_LINE     ? PL_LEGEND_LINE
             : c->style == DV_CURVE_POINTS ? PL_LEGEND_SYMBOL
                                           : PL_LEGEND_LINE | PL_LEGEND_SYMBOL;
    tcol[n] = DVP_COL_FG;
    lcol[n] = scol[n] = c->colour;
    lstyle[n] = c->pattern;
    lwidth[n] = c->colour == DVP_COL_FG ? 3.0 : 2.0;
    sscale[n] = DOT_SCALE;
    snum[n] = 3;
    sym[n] = DOT;
    text[n++] = c->label;
  }
  if (f->marks) {
    opt[n] = PL_LEGEND_SYMBOL;
    tcol[n] = lcol[n] = scol[n] = DVP_COL_FG;
    lstyle[n] = 1;
    lwidth[n] = 1.0;
    sscale[n] = STAR_SCALE;
    snum[n] = 1;
    sym[n] = STAR;
    text[n++] = MARK_TEXT;
  }
  if (n == 0) return;
  const PLINT columns = lay->columns, rows = (n + columns - 1) / columns;
  PLFLT w, h;
  pllegend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, lay->position, lay->x, lay->y,
           lay->line, DVP_COL_BG, DVP_COL_FG, 1, rows, columns, n, opt, DVP_LEGEND_TEXT_OFFSET,
           lay->scale, dvp_legend_spacing(lay->scale), 0.0, tcol, text, NULL, NULL, NULL, NULL,
           lcol, lstyle, lwidth, scol, sscale, snum, sym);
}

/* draw figure f (an xy_figure *) on the current, initialised stream */
static void draw_figure(const void *arg) {
  const xy_figure *f = arg;
  const int logx = f->flags & DV_PLOT_LOGX, logy = f->flags & DV_PLOT_LOGY;
  double r[4] = {logx ? -1 : 0, 1, logy ? -1 : 0, 1}; /* without data: 0.1 .. 10 on a log axis */
  const int any = data_range(f, r);
  if (any) {
    axis_range(&r[0], &r[1], logx);
    axis_range(&r[2], &r[3], logy);
  }
  pladv(0);
  plsyax(8, 0);
  const char *text[DV_PLOT_MAX_CURVES + 1];
  const int nlines = legend_texts(f, text);
  const double disp = dvp_ylabel_disp(logy, dvp_ylabels_width(r[2], r[3], logy));
  dvp_layout lay;
  dvp_viewport(text, nlines, 1, disp, &lay); /* more columns where the page needs them */
  if (f->flags & DV_PLOT_EQUAL) dvp_equal_aspect(r);
  plwind(r[0], r[1], r[2], r[3]);
  dvp_axes ax;
  dvp_draw_axes(r, logx, logy, &ax);
  dvp_axis_titles(&ax, f->xlabel, f->ylabel, disp, f->title);
  for (int black = 1; black >= 0; black--) /* black references wide, underneath */
    for (size_t k = 0; k < f->n; k++) {
      const xy_curve *c = &f->c[k];
      if ((c->colour == DVP_COL_FG) != black) continue;
      plwidth(black ? 3.0 : 1.5);
      plcol0(c->colour);
      draw_curve(c);
    }
  plwidth(1.0);
  for (size_t k = 0; k < f->n; k++) draw_marks(&f->c[k]);
  plcol0(DVP_COL_FG);
  if (!any) plptex(0.5 * (r[0] + r[1]), 0.5 * (r[2] + r[3]), 1, 0, 0.5, "no data");
  draw_legend(f, &lay);
}

/* f's title: title, then "(zero at every point: ...)" and "(no data: ...)"
 * naming the labelled curves without a drawable point */
static void title_with_missing(xy_figure *f, const char *title) {
  size_t k = (size_t)snprintf(f->title, sizeof f->title, "%s", title ? title : "");
  for (int zeros = 1; zeros >= 0; zeros--) {
    int named = 0;
    for (size_t i = 0; i < f->n && k < sizeof f->title; i++) {
      if (f->c[i].any || !f->c[i].label[0] || f->c[i].zeros != zeros) continue;
      k += (size_t)snprintf(f->title + k, sizeof f->title - k, "%s%s",
                            named++ ? ", " : zeros ? " (zero at every point: " : " (no data: ",
                            f->c[i].label);
    }
    if (named && k < sizeof f->title) k += (size_t)snprintf(f->title + k, sizeof f->title - k, ")");
  }
}

/* free the coordinates of f */
static void free_figure(xy_figure *f) {
  for (size_t k = 0; k < f->n; k++) {
    free(f->c[k].x);
    free(f->c[k].y);
  }
}

int dv_report_plot_xy(const char *path, const char *title, const char *xlabel, const char *ylabel,
                      const dv_plot_curve *curves, size_t n, int flags, dv_error *err) {
  if (!path || (n > 0 && !curves) || n > DV_PLOT_MAX_CURVES)
    return dv_fail(err, DV_EINPUT, "dv_report_plot_xy: bad arguments");
  if (flags & ~(DV_PLOT_LOGX | DV_PLOT_LOGY | DV_PLOT_EQUAL))
    return dv_fail(err, DV_EINPUT, "%s: unknown plot flags %#x", path, (unsigned)flags);
  for (size_t k = 0; k < n; k++) {
    const dv_plot_curve *c = &curves[k];
    if (c->n > 0 && (!c->x || !c->y))
      return dv_fail(err, DV_EINPUT, "%s: curve %zu has no coordinates", path, k);
    if (c->style < DV_CURVE_LINE || c->style > DV_CURVE_LINE_POINTS || c->colour < 0)
      return dv_fail(err, DV_EINPUT, "%s: curve %zu: bad style %d or colour %d", path, k, c->style,
                     c->colour);
  }
  if (!dvp_have_svg()) return dv_fail(err, DV_ESYSTEM, "PLplot has no svg driver");
  xy_figure *f = calloc(1, sizeof *f);
  if (!f) return dv_fail(err, DV_ESYSTEM, "%s: out of memory", path);
  f->xlabel = xlabel;
  f->ylabel = ylabel;
  f->flags = flags;
  int status = DV_OK;
  for (size_t k = 0; k < n && status == DV_OK; k++) {
    xy_curve *c = &f->c[f->n++];
    if (fill_curve(c, &curves[k], flags) != 0)
      status = dv_fail(err, DV_ESYSTEM, "%s: out of memory", path);
    else
      for (size_t i = 0; i < c->n && !f->marks; i++) f->marks = point_marked(c, i);
  }
  if (status == DV_OK) title_with_missing(f, title);
  if (status == DV_OK) status = dvp_write_svg(path, draw_figure, f, err);
  free_figure(f);
  free(f);
  return status;
}
