/* dv_report_plot_scenario: the four SVG plots of one scenario, drawn with
 * PLplot (report_plot.h), what the verdict used drawn strongly and marked
 * (report_plot_marks.c), the rest faint. Written through dvp_write_svg
 * (report_plot_svg.c). Non-finite samples break a curve; a plot without any
 * finite point still gets axes and "no data".
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

#include "report_plot_figure.h"
#include "report_plot_internal.h"
#include "report_plot_ticks.h"
#include "run_turning.h"

const char *const dv_report_plot_files[] = {"theta.svg", "theta_error.svg", "path.svg",
                                            "energy.svg", NULL};

_Static_assert(DV_PLOT_MAX_SERIES <= DVP_NPALETTE * DVP_NDASHES,
               "a palette colour and line pattern of its own per series");

static const struct {
  const char *what, *xlabel, *ylabel;
} kinds[DVP_NPLOTS] = {
    {"tilt angle", "time t (s)", "tilt #gh (rad)"},
    {"tilt error against its reference", "time t (s)", "|#gh - #gh#dref#u| (rad)"},
    {"contact paths (o start, x end)", "contact point x (m)", "contact point y (m)"},
    {"relative energy drift", "time t (s)", "(E - E#d0#u) / |E#d0#u|"},
};

#define ERR_FLOOR 1e-16 /* smallest error drawn on the log axis, rad */
#define STRONG_WIDTH 1.5
#define FAINT_WIDTH 1.0

/* whether point i of c can be drawn */
static int point_ok(const dvp_curve *c, size_t i) {
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

/* fill c with the plotted values of tr (ref: the error plot's reference), the
 * first nstrong those up to strong_end; -1 out of memory */
static int fill_curve(dvp_curve *c, dvp_kind kind, const dv_traj *tr, const dv_traj *ref,
                      double strong_end) {
  const size_t n = kind == DVP_ERROR ? matched_prefix(tr, ref) : (tr ? tr->n : 0);
  if (n == 0) return 0;
  c->x = malloc(n * sizeof *c->x);
  c->y = malloc(n * sizeof *c->y);
  if (!c->x || !c->y) return -1;
  const double e0 = tr->s[0].energy;
  for (size_t i = 0; i < n; i++) {
    const dv_sample *s = &tr->s[i];
    double x = s->t, y = NAN;
    if (kind == DVP_THETA) {
      y = s->y[RED_TH];
    } else if (kind == DVP_ERROR) {
      const double d = fabs(s->y[RED_TH] - ref->s[i].y[RED_TH]); /* NaN stays NaN */
      if (isfinite(d)) y = log10(fmax(d, ERR_FLOOR));
    } else if (kind == DVP_PATH) {
      x = s->contact[0];
      y = s->contact[1];
    } else {
      y = (s->energy - e0) / fabs(e0); /* E(0) = 0 or NaN: nothing drawn */
    }
    if (s->t <= strong_end + 1e-9 * fabs(strong_end)) c->nstrong = i + 1;
    c->x[c->n] = x;
    c->y[c->n++] = y;
  }
  return 0;
}

/* the turning points of tr up to c's strong end, on the tilt plot; -1 out of memory */
static int fill_turns(dvp_curve *c, const dv_traj *tr) {
  if (c->nstrong < 2) return 0;
  c->turn_t = malloc(tr->n * sizeof *c->turn_t);
  c->turn_theta = malloc(tr->n * sizeof *c->turn_theta);
  c->turn_kind = malloc(tr->n * sizeof *c->turn_kind);
  if (!c->turn_t || !c->turn_theta || !c->turn_kind) return -1;
  c->nturns = dv_run_turning_points(tr, tr->s[c->nstrong - 1].t, c->turn_t, c->turn_theta,
                                    c->turn_kind);
  return 0;
}

/* whether c has a point to draw */
static int curve_has_data(const dvp_curve *c) {
  for (size_t i = 0; i < c->n; i++)
    if (point_ok(c, i)) return 1;
  return 0;
}

/* whether an engine of in is judged against the thin reference (thin 1) or
 * against a matched one (thin 0); turns: one whose theta_turning_err is */
static int judges(const dv_plot_input *in, int thin, int turns) {
  for (size_t k = 0; k < in->nseries; k++) {
    const dv_plot_series *s = &in->series[k];
    if (s->reference && (s->reference == in->thin) == thin && !(turns && s->turns_unjudged))
      return 1;
  }
  return 0;
}

/* whether series s (NULL: the thin reference) of in was compared: an engine,
 * a reference that judged one, or any when no engine is in */
static int compared(const dv_plot_input *in, const dv_plot_series *s) {
  return (s && s->reference) || (!judges(in, 0, 0) && !judges(in, 1, 0)) ||
         judges(in, !s, 0);
}

/* the reference the window's end is marked on: the thin one, or the first
 * matched one where the thin one judged nothing */
static const dv_traj *window_reference(const dv_plot_input *in) {
  if (compared(in, NULL)) return in->thin;
  for (size_t k = 0; k < in->nseries; k++)
    if (!in->series[k].reference) return in->series[k].traj;
  return NULL;
}

/* that reference's contact point at the end of the window, on the path
 * plot, when its run goes on after it */
static void window_point(dvp_figure *f, const dv_traj *thin) {
  f->window_at[0] = f->window_at[1] = NAN;
  if (!thin || thin->n == 0 || !(f->window_end < thin->s[thin->n - 1].t)) return;
  for (size_t i = 0; i < thin->n && thin->s[i].t <= f->window_end; i++) {
    f->window_at[0] = thin->s[i].contact[0];
    f->window_at[1] = thin->s[i].contact[1];
  }
}

/* free what c holds and clear it */
static void free_curve(dvp_curve *c) {
  free(c->x), free(c->y);
  free(c->turn_t), free(c->turn_theta), free(c->turn_kind);
  memset(c, 0, sizeof *c);
}

/* set up c from series s (NULL: the thin reference) in colour number colour
 * (dv_plot_curve's) for a plot of kind; -1 out of memory */
static int set_curve(dvp_curve *c, dvp_kind kind, const dv_plot_series *s, int colour,
                     const dv_plot_input *in) {
  dvp_colour_style(s ? colour : 0, &c->colour, &c->style);
  c->judged = s && s->reference;
  c->ranged = compared(in, s);
  c->window_end = !c->ranged ? -INFINITY : s ? s->window_end : in->window_end;
  if (isnan(c->window_end)) c->window_end = -INFINITY;
  c->horizon = c->judged && s->horizon < c->window_end ? s->horizon : NAN;
  c->limit = kind == DVP_ERROR && c->judged && s->theta_limit > 0.0 ? log10(s->theta_limit) : NAN;
  /* the error plot's pointwise metrics stop at the horizon */
  const double strong_end = kind == DVP_ERROR && isfinite(c->horizon) ? c->horizon : c->window_end;
  const dv_traj *tr = s ? s->traj : in->thin;
  if (fill_curve(c, kind, tr, s ? s->reference : NULL, strong_end)) return -1;
  const int turns = c->judged ? !s->turns_unjudged : judges(in, !s, 1);
  return kind == DVP_THETA && turns ? fill_turns(c, tr) : 0;
}

/* set up the curves of one plot, series k in colour number colour[k], leaving
 * out those without data (the title names them); -1 out of memory */
static int build_figure(dvp_figure *f, dvp_kind kind, const dv_plot_input *in, const int *colour) {
  memset(f, 0, sizeof *f);
  f->kind = kind;
  f->window_end = isfinite(in->window_end) ? in->window_end : NAN;
  if (kind == DVP_PATH) window_point(f, window_reference(in));
  char name[160], missing[256] = "";
  dvp_escape(name, sizeof name, in->title, "");
  for (size_t k = 0; k <= in->nseries; k++) {
    const dv_plot_series *s = k ? &in->series[k - 1] : NULL;
    if (kind == DVP_ERROR && !(s && s->reference)) continue; /* a reference has no error */
    dvp_curve *c = &f->c[f->ncurves];
    if (set_curve(c, kind, s, k ? colour[k - 1] : 0, in)) return -1;
    const char *label = s ? s->label : "reference (thin disk)";
    if (curve_has_data(c)) {
      dvp_escape(c->label, sizeof c->label, label, "");
      f->ncurves++;
      continue;
    }
    free_curve(c);
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
static void free_figure(dvp_figure *f) {
  for (size_t k = 0; k < f->ncurves; k++) free_curve(&f->c[k]);
  f->ncurves = 0;
}

/* bounds of every drawable point of the curves that set the ranges (of all
 * when those have none); 0 when there is none */
static int data_range(const dvp_figure *f, double r[4]) {
  int any = 0;
  for (int all = 0; all <= 1 && !any; all++)
    for (size_t k = 0; k < f->ncurves; k++)
      if (all || f->c[k].ranged) dvp_extend_range(f->c[k].x, f->c[k].y, f->c[k].n, r, &any);
  return any;
}

/* draw the drawable runs of c's points [from, to) as lines, a lone point as a dot */
static void draw_run(const dvp_curve *c, size_t from, size_t to) {
  size_t i = from;
  while (i < to) {
    while (i < to && !point_ok(c, i)) i++;
    size_t j = i;
    while (j < to && point_ok(c, j)) j++;
    if (j - i == 1) plpoin(1, &c->x[i], &c->y[i], 17);
    dvp_line(&c->x[i], &c->y[i], j - i);
    i = j;
  }
}

/* mark the first drawable point of c with a circle and the last with a cross */
static void draw_ends(const dvp_curve *c) {
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


/* c's points after its compared window faint and thin, those in it strong on top
 * (a window of fewer than two points draws nothing strongly) */
static void draw_curve(const dvp_curve *c) {
  const int strong = c->nstrong >= 2;
  pllsty(c->style);
  if (!strong || c->nstrong < c->n) {
    plwidth(FAINT_WIDTH);
    plcol0(dvp_faint(c->colour));
    draw_run(c, strong ? c->nstrong - 1 : 0, c->n); /* joined to the strong part */
  }
  if (strong) {
    plwidth(c->colour == DVP_COL_FG ? 3.0 : STRONG_WIDTH);
    plcol0(c->colour);
    draw_run(c, 0, c->nstrong);
  }
  pllsty(1);
}

/* the latest time drawn: the end of the run */
static double last_time(const dvp_figure *f) {
  double t = -INFINITY;
  for (size_t k = 0; k < f->ncurves; k++)
    for (size_t i = 0; i < f->c[k].n; i++)
      if (point_ok(&f->c[k], i)) t = fmax(t, f->c[k].x[i]);
  return t;
}

/* the legend's texts (curves, then marks) into text; their count */
static int legend_texts(const dvp_figure *f, const dvp_mark_legend *marks, const char **text) {
  int n = 0;
  for (size_t k = 0; k < f->ncurves; k++) text[n++] = f->c[k].label;
  for (int k = 0; k < marks->n; k++) text[n++] = marks->text[k];
  return n;
}

/* a legend right of the frame: one line per curve, then the marks' styles */
static void draw_legend(const dvp_figure *f, const dvp_mark_legend *marks, const dvp_layout *lay) {
  enum { M = DV_PLOT_MAX_SERIES + 1 + 6 };
  PLINT opt[M], tcol[M], lcol[M], lstyle[M], scol[M], snum[M];
  PLFLT lwidth[M], sscale[M];
  const char *text[M], *sym[M];
  PLINT n = 0;
  for (size_t k = 0; k < f->ncurves; k++, n++) {
    opt[n] = PL_LEGEND_LINE; /* faint where nothing of it was compared */
    lcol[n] = scol[n] = f->c[k].nstrong >= 2 ? f->c[k].colour : dvp_faint(f->c[k].colour);
    lstyle[n] = f->c[k].style;
    lwidth[n] = 2.0;
    text[n] = f->c[k].label;
  }
  for (int k = 0; k < marks->n; k++, n++) {
    opt[n] = marks->style[k] ? PL_LEGEND_LINE : PL_LEGEND_SYMBOL;
    lcol[n] = scol[n] = marks->colour[k];
    lstyle[n] = marks->style[k] ? marks->style[k] : 1;
    lwidth[n] = 1.0;
    text[n] = marks->text[k];
  }
  if (n == 0) return;
  for (PLINT k = 0; k < n; k++) {
    tcol[k] = DVP_COL_FG;
    sscale[k] = 0.7;
    snum[k] = 2;
    sym[k] = "\xe2\x96\xb2"; /* the turning points' triangle */
  }
  PLFLT w, h;
  const PLINT rows = (n + lay->columns - 1) / lay->columns;
  pllegend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX, lay->position, lay->x, lay->y,
           lay->line, DVP_COL_BG, DVP_COL_FG, 1, rows, lay->columns, n, opt, DVP_LEGEND_TEXT_OFFSET,
           lay->scale, dvp_legend_spacing(lay->scale), 0.0, tcol, text, NULL, NULL, NULL, NULL,
           lcol, lstyle, lwidth, scol, sscale, snum, sym);
}

/* the window: every drawn point (and every limit) with a margin; 0 when no point is drawn */
static int window_of(const dvp_figure *f, double r[4]) {
  const int logy = f->kind == DVP_ERROR;
  const int any = data_range(f, r);
  if (!any) {
    r[0] = 0, r[1] = 1;
    r[2] = logy ? -16 : 0, r[3] = logy ? 0 : 1;
  }
  for (size_t k = 0; k < f->ncurves; k++) /* every limit stays in view */
    if (isfinite(f->c[k].limit)) r[3] = fmax(r[3], f->c[k].limit);
  dvp_pad_range(&r[0], &r[1], f->kind == DVP_PATH ? 0.05 : 0.0, 0.0);
  dvp_pad_range(&r[2], &r[3], 0.05, logy ? 1.0 : 0.0);
  if (logy) { /* whole decades, so that at least two are labelled */
    r[2] = floor(r[2]);
    r[3] = ceil(r[3]);
  }
  return any;
}

/* draw figure f (a dvp_figure *) on the current, initialised stream */
static void draw_figure(const void *arg) {
  const dvp_figure *f = arg;
  const int logy = f->kind == DVP_ERROR;
  double r[4];
  const int any = window_of(f, r);
  const double t_last = last_time(f); /* the path plot's x is no time: unused there */
  dvp_mark_legend marks;
  dvp_mark_legend_of(f, r, t_last, &marks);
  const char *text[DV_PLOT_MAX_SERIES + 1 + 6];
  const int nlines = legend_texts(f, &marks, text);
  pladv(0);
  plsyax(8, 0);
  const double disp = dvp_ylabel_disp(logy, dvp_ylabels_width(r[2], r[3], logy));
  dvp_layout lay;
  dvp_viewport(text, nlines, 1, disp, &lay);
  if (f->kind == DVP_PATH) dvp_equal_aspect(r);
  plwind(r[0], r[1], r[2], r[3]);
  dvp_axes ax;
  dvp_draw_axes(r, 0, logy, &ax);
  dvp_axis_titles(&ax, kinds[f->kind].xlabel, kinds[f->kind].ylabel, disp, f->title);
  for (int judged = 0; judged <= 1; judged++) /* the references underneath the engines */
    for (size_t k = 0; k < f->ncurves; k++) {
      if (f->c[k].judged != judged) continue;
      draw_curve(&f->c[k]);
      if (f->kind == DVP_PATH) draw_ends(&f->c[k]);
    }
  dvp_draw_marks(f, r, t_last);
  if (!any) plptex(0.5 * (r[0] + r[1]), 0.5 * (r[2] + r[3]), 1, 0, 0.5, "no data");
  draw_legend(f, &marks, &lay);
}

int dv_report_plot_scenario(const char *dir, const dv_plot_input *in, dv_error *err) {
  if (!dir || !in) return dv_fail(err, DV_EINPUT, "dv_report_plot_scenario: bad arguments");
  if (in->nseries > DV_PLOT_MAX_SERIES)
    return dv_fail(err, DV_EINPUT, "%s: %zu series to plot, at most %d", dir, in->nseries,
                   DV_PLOT_MAX_SERIES);
  struct stat st;
  if (stat(dir, &st) != 0) return dv_fail(err, DV_ESYSTEM, "%s: %s", dir, strerror(errno));
  if (!S_ISDIR(st.st_mode)) return dv_fail(err, DV_ESYSTEM, "%s: not a directory", dir);
  if (!dvp_have_svg()) return dv_fail(err, DV_ESYSTEM, "PLplot has no svg driver");
  int colour[DV_PLOT_MAX_SERIES]; /* the same in every plot */
  dv_report_plot_series_colours(in, colour);
  int status = DV_OK;
  dvp_figure f = {0};
  for (int k = 0; k < DVP_NPLOTS && status == DV_OK; k++) {
    char path[PATH_MAX];
    if (snprintf(path, sizeof path, "%s/%s", dir, dv_report_plot_files[k]) >= (int)sizeof path)
      status = dv_fail(err, DV_ESYSTEM, "%s: path too long", dir);
    else if (build_figure(&f, (dvp_kind)k, in, colour) != 0)
      status = dv_fail(err, DV_ESYSTEM, "%s: out of memory", dv_report_plot_files[k]);
    else
      status = dvp_write_svg(path, draw_figure, &f, err);
    free_figure(&f);
  }
  return status;
}
