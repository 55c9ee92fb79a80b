/* dvp_draw_marks: what the verdict used, marked on a scenario's plot.
 *
 * Over time: the latest compared window's end (black, dash-dotted) when the
 * runs go on after it, an engine's own window end where it stops earlier
 * (dash-dotted, its colour), each engine's horizon before that (dotted, its
 * colour, labelled along the line); on the error plot each engine's own theta
 * limit (dashed, its colour, labelled), or one black line when all agree (with
 * more than LIMIT_LABELS engines, one line per value, black where engines
 * share it, so that labels do not pile up); on theta.svg the turning points
 * theta_turning_err compared (triangles). On the path, a diamond at the
 * reference's contact point where the window ends.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report_plot_figure.h"
#include "report_plot_internal.h"

#define UP "\xe2\x96\xb2"   /* U+25B2: a maximum of theta */
#define DOWN "\xe2\x96\xbc" /* U+25BC: a minimum */
#define TURN_SCALE 0.7      /* of the default character height */
#define LABEL_SCALE 0.7
#define LABEL_BESIDE 0.012 /* a label along a vertical line: its middle this far off, of the range */
#define LIMIT_LABELS 3  /* engines' limits labelled each with its name, at most */
#define STYLE_LIMIT 2   /* pllsty: dashed */
#define STYLE_HORIZON 3 /* dotted */
#define STYLE_WINDOW 4  /* dash-dotted */

/* whether t is inside the window's time span and before the run's end */
static int in_time(double t, const double r[4], double t_last) {
  return isfinite(t) && t > r[0] && t < t_last - 1e-9 * fabs(t_last);
}

/* the engines' own window ends drawn: one ends before the latest */
static int own_window_marked(const dvp_curve *c, const dvp_figure *f, const double r[4],
                             double t_last) {
  const double latest = isfinite(f->window_end) ? f->window_end : t_last;
  return f->kind != DVP_PATH && c->judged && in_time(c->window_end, r, t_last) &&
         c->window_end < latest - 1e-9 * fabs(latest);
}

/* its horizon is marked: on the tilt and error plots, before its window's end */
static int horizon_marked(const dvp_curve *c, const dvp_figure *f, const double r[4],
                          double t_last) {
  return (f->kind == DVP_THETA || f->kind == DVP_ERROR) && c->judged &&
         in_time(c->horizon, r, t_last + 1.0) &&
         c->horizon < c->window_end - 1e-9 * fabs(c->window_end);
}

int dvp_limits_differ(const dvp_figure *f, double *one) {
  *one = NAN;
  for (size_t k = 0; k < f->ncurves; k++) {
    const double l = f->c[k].limit;
    if (!isfinite(l)) continue;
    if (isfinite(*one) && fabs(l - *one) > 1e-9) return 1;
    *one = l;
  }
  return 0;
}

/* a vertical line at t in style over the window, in colour */
static void vline(double t, const double r[4], PLINT style, PLINT colour) {
  plcol0(colour);
  pllsty(style);
  pljoin(t, r[2], t, r[3]);
  pllsty(1);
}

/* whether log10 limits a and b read the same in a label (%.3g rad) */
static int reads_as(double a, double b) {
  char ta[32], tb[32];
  snprintf(ta, sizeof ta, "%.3g", pow(10.0, a));
  snprintf(tb, sizeof tb, "%.3g", pow(10.0, b));
  return !strcmp(ta, tb);
}

/* the engines of f whose limit reads as limit; the first of them into *first */
static int sharing(const dvp_figure *f, double limit, size_t *first) {
  int n = 0;
  for (size_t k = 0; k < f->ncurves; k++)
    if (isfinite(f->c[k].limit) && reads_as(f->c[k].limit, limit) && !n++) *first = k;
  return n;
}

/* a horizontal limit line at log10 limit, dashed, in colour, its text staggered along it by nth */
static void limit_line(double limit, PLINT colour, const char *text, int nth, const double r[4]) {
  const double dx = r[1] - r[0], dy = r[3] - r[2];
  plcol0(colour);
  pllsty(STYLE_LIMIT);
  pljoin(r[0], limit, r[1], limit);
  pllsty(1);
  /* labels staggered along the line, so equal-looking limits stay apart */
  plptex(r[1] - (0.02 + 0.3 * (nth % 3)) * dx, limit + 0.04 * dy, 1, 0, 1, text);
}

/* the error plot's limits: one labelled black line when all agree; else one
 * per engine in its colour, labelled with its name, where at most
 * LIMIT_LABELS engines have one; else one per value as its label reads it,
 * black where engines share it, labelled with how many */
static void draw_limits(const dvp_figure *f, const double r[4]) {
  double one;
  const int differ = dvp_limits_differ(f, &one);
  if (!isfinite(one)) return;
  plschr(0, LABEL_SCALE);
  int nth = 0, limited = 0;
  for (size_t k = 0; k < f->ncurves; k++) limited += isfinite(f->c[k].limit);
  for (size_t k = 0; k < f->ncurves && differ; k++) {
    const dvp_curve *c = &f->c[k];
    size_t first = k;
    if (!isfinite(c->limit)) continue;
    const int n = limited > LIMIT_LABELS ? sharing(f, c->limit, &first) : 1;
    if (first != k) continue; /* its value is drawn */
    char text[160];
    if (n > 1)
      snprintf(text, sizeof text, "limit %.3g rad (%d engines)", pow(10.0, c->limit), n);
    else
      snprintf(text, sizeof text, "%s limit %.3g rad", c->label, pow(10.0, c->limit));
    limit_line(c->limit, n > 1 ? DVP_COL_FG : c->colour, text, nth++, r);
  }
  if (!differ) {
    char text[64];
    snprintf(text, sizeof text, "limit %.3g rad", pow(10.0, one));
    limit_line(one, DVP_COL_FG, text, 0, r);
  }
  plschr(0, 1.0);
}

/* a curve's compared turning points: triangles up at maxima, down at minima */
static void draw_turns(const dvp_curve *c) {
  plcol0(c->colour);
  plschr(0, TURN_SCALE);
  for (size_t i = 0; i < c->nturns; i++)
    if (dvp_plottable(c->turn_t[i]) && dvp_plottable(c->turn_theta[i]))
      plstring(1, &c->turn_t[i], &c->turn_theta[i], c->turn_kind[i] > 0 ? UP : DOWN);
  plschr(0, 1.0);
}

/* the latest window's end: a diamond on the reference's path, or a black line over time */
static void draw_window_end(const dvp_figure *f, const double r[4], double t_last) {
  if (f->kind == DVP_PATH) {
    if (!dvp_plottable(f->window_at[0]) || !dvp_plottable(f->window_at[1])) return;
    plcol0(DVP_COL_FG);
    plstring(1, &f->window_at[0], &f->window_at[1], DVP_DIAMOND);
    const int left = f->window_at[0] > 0.5 * (r[0] + r[1]); /* the label stays in the frame */
    const double gap = (left ? -0.02 : 0.02) * (r[1] - r[0]);
    plptex(f->window_at[0] + gap, f->window_at[1] - 0.04 * (r[3] - r[2]), 1, 0, left ? 1.0 : 0.0,
           DVP_WINDOW_END);
    return;
  }
  if (!in_time(f->window_end, r, t_last)) return;
  vline(f->window_end, r, STYLE_WINDOW, DVP_COL_FG);
  /* beside the line, not on it: on the side with more room */
  const double side = f->window_end > 0.5 * (r[0] + r[1]) ? -1.0 : 1.0;
  plptex(f->window_end + side * LABEL_BESIDE * (r[1] - r[0]), r[2] + 0.05 * (r[3] - r[2]), 0, 1,
         -0.05, DVP_WINDOW_END);
}

void dvp_draw_marks(const dvp_figure *f, const double r[4], double t_last) {
  plwidth(1.0);
  draw_window_end(f, r, t_last);
  for (size_t k = 0; k < f->ncurves; k++) {
    const dvp_curve *c = &f->c[k];
    if (own_window_marked(c, f, r, t_last)) vline(c->window_end, r, STYLE_WINDOW, c->colour);
    if (horizon_marked(c, f, r, t_last)) {
      char text[160];
      snprintf(text, sizeof text, "%s horizon %.3g s", c->label, c->horizon);
      vline(c->horizon, r, STYLE_HORIZON, c->colour);
      plschr(0, LABEL_SCALE);
      plptex(c->horizon + LABEL_BESIDE * (r[1] - r[0]), r[3] - 0.03 * (r[3] - r[2]), 0, -1, 0,
             text); /* down beside the line */
      plschr(0, 1.0);
    }
    if (f->kind == DVP_THETA) draw_turns(c);
  }
  if (f->kind == DVP_ERROR) draw_limits(f, r);
  plcol0(DVP_COL_FG);
}

/* add an entry to out */
static void entry(dvp_mark_legend *out, const char *text, PLINT style, PLINT colour) {
  out->text[out->n] = text;
  out->style[out->n] = style;
  out->colour[out->n++] = colour;
}

void dvp_mark_legend_of(const dvp_figure *f, const double r[4], double t_last,
                        dvp_mark_legend *out) {
  out->n = 0;
  int faint = 0, window = f->kind != DVP_PATH && in_time(f->window_end, r, t_last);
  int horizon = 0, turns = 0;
  for (size_t k = 0; k < f->ncurves; k++) {
    const dvp_curve *c = &f->c[k];
    faint |= c->nstrong < c->n;
    window |= own_window_marked(c, f, r, t_last);
    horizon |= horizon_marked(c, f, r, t_last);
    turns |= f->kind == DVP_THETA && c->nturns > 0;
  }
  if (faint) entry(out, "not compared", 1, DVP_COL_FAINT_FG);
  if (window) entry(out, "window end", STYLE_WINDOW, DVP_COL_FG);
  if (horizon) entry(out, "horizon", STYLE_HORIZON, DVP_COL_FG);
  double one;
  if (f->kind == DVP_ERROR && (dvp_limits_differ(f, &one) || isfinite(one)))
    entry(out, "theta limit", STYLE_LIMIT, DVP_COL_FG);
  if (turns) entry(out, "turning points", 0, DVP_COL_FG);
}
