/* report_plot_figure: one plot of dv_report_plot_scenario as report_plot.c
 * builds it and report_plot_marks.c marks what the verdict used on it (not
 * public API). */
#ifndef DV_REPORT_PLOT_FIGURE_H
#define DV_REPORT_PLOT_FIGURE_H

#include <stddef.h>

#include <plplot.h>

#include "report_plot.h"

/* the plots, in the order of dv_report_plot_files */
typedef enum dvp_kind { DVP_THETA = 0, DVP_ERROR, DVP_PATH, DVP_ENERGY, DVP_NPLOTS } dvp_kind;

/* one curve: a NaN in x or y breaks the line */
typedef struct dvp_curve {
  double *x, *y;
  size_t n;
  size_t nstrong;    /* its first nstrong points are what the verdict used: drawn strongly */
  PLINT colour;      /* cmap0 index */
  PLINT style;       /* line style (pllsty): 1 solid, else dashed where colours ran out */
  char label[128];   /* legend text, PLplot-escaped */
  int judged;        /* an engine's curve (not a reference's): its marks are drawn */
  int ranged;        /* its points set the axis ranges (a reference that judged nothing does not) */
  double window_end; /* s: its compared window's end (-INFINITY: nothing compared) */
  double horizon;    /* s: where its pointwise metrics stop (NAN: not marked) */
  double limit;      /* error plot: log10 of its theta limit (NAN: none) */
  size_t nturns;     /* theta plot: its compared turning points */
  double *turn_t, *turn_theta;
  int *turn_kind; /* +1 maximum, -1 minimum */
} dvp_curve;

/* one plot: its title and curves, the thin reference first */
typedef struct dvp_figure {
  dvp_kind kind;
  char title[512];
  size_t ncurves;
  dvp_curve c[DV_PLOT_MAX_SERIES + 1];
  double window_end;   /* s, where the comparison stopped (NAN: the whole run) */
  double window_at[2]; /* path plot: the reference's contact point there (NAN: none) */
} dvp_figure;

/* the legend entries of f's marks (line styles, triangles, faint) beyond its curves' */
typedef struct dvp_mark_legend {
  int n;
  const char *text[6];
  PLINT style[6]; /* line style; 0: a symbol */
  PLINT colour[6];
} dvp_mark_legend;

/* whether any engine's limit of f differs from another's; the one they share into *one */
int dvp_limits_differ(const dvp_figure *f, double *one);

/* draw f's marks over its curves: window ends, horizons, limits, turning points;
 * r is the window (x0, x1, y0, y1), t_last the latest time drawn */
void dvp_draw_marks(const dvp_figure *f, const double r[4], double t_last);

/* the legend entries for the marks dvp_draw_marks draws on f */
void dvp_mark_legend_of(const dvp_figure *f, const double r[4], double t_last,
                        dvp_mark_legend *out);

#endif
