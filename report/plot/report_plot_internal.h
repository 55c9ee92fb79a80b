/* dv_plot_internal: what dv_plot.c shares with dv_report_plot_xy.c (not public API).
 *
 * The palette (cmap0) is set on every stream dvp_write_svg opens: background,
 * foreground (axes, text, black references), grid, then DVP_NPALETTE series
 * colours, then the foreground and the series colours again, translucent. Series k of dv_report_plot_scenario and curve colour k + 1 of dv_report_plot_xy
 * are the same colour.
 */
#ifndef DV_PLOT_INTERNAL_H
#define DV_PLOT_INTERNAL_H

#include <stddef.h>

#include <plplot.h>

#include "dv_error.h"

enum {
  DVP_COL_BG = 0,
  DVP_COL_FG,
  DVP_COL_GRID,
  DVP_COL_SERIES,
  DVP_NPALETTE = 16,
  DVP_COL_FAINT_FG = DVP_COL_SERIES + DVP_NPALETTE, /* the foreground, translucent */
  DVP_COL_FAINT,                                    /* the series colours, translucent */
  DVP_NCOLOURS = DVP_COL_FAINT + DVP_NPALETTE
};

#define DVP_NDASHES 8 /* line patterns: solid, then PLplot's seven dashed ones */

#define DVP_PAGE_W 960       /* px */
#define DVP_PAGE_H 500       /* px */
#define DVP_PLOT_LIMIT 1e150 /* larger magnitudes are not drawn */
#define DVP_FAINT_ALPHA 0.3  /* opacity of what the verdict did not use */

#define DVP_LEGEND_LINE_MM 10.0     /* length of a legend's line sample */
#define DVP_LEGEND_SCALE 0.8        /* legend text, of the default character height */
#define DVP_LEGEND_SPACING 2.0      /* between legend lines, in character heights */
#define DVP_DIAMOND "\xe2\x97\x86"  /* U+25C6 black diamond: the window's end on a path */
#define DVP_WINDOW_END "window end" /* the label of where the comparison stopped */

/* the y axis's title from the frame, in character heights, for labels labels
 * character heights wide (a linear axis's) */
double dvp_ylabel_disp(int log, double labels);

/* the translucent version of cmap0 colour c (foreground or series), c itself otherwise */
PLINT dvp_faint(PLINT c);

/* the cmap0 colour and line style (pllsty) of colour number c of a
 * dv_plot_curve: 0 the foreground; c >= 1 palette colour (c - 1) % DVP_NPALETTE,
 * pattern (c - 1) / DVP_NPALETTE (0 solid) of DVP_NDASHES in turn */
void dvp_colour_style(int c, PLINT *colour, PLINT *style);

/* the points of one curve, in plot coordinates */
typedef struct dvp_points {
  const double *x, *y;
  size_t n;
} dvp_points;

/* where dvp_viewport put the legend: pllegend's position, offsets, columns,
 * line sample's length (plot_width) and text size (text_scale) */
typedef struct dvp_layout {
  PLINT position;
  double x, y;
  int columns;
  double line;
  double scale;
} dvp_layout;

/* pllegend's text_spacing for text at scale: DVP_LEGEND_SPACING at DVP_LEGEND_SCALE,
 * proportionally closer for smaller text (pllegend spaces by the default height) */
double dvp_legend_spacing(double scale);

/* set the viewport (after pladv): left_chars character heights left of the
 * frame for the y axis's labels and title, room right of it for a legend of
 * the nlines texts (PLplot text) in ncolumns columns or more, as its height
 * needs, or below it when the frame would be too narrow beside it; a legend
 * too large for either in smaller text (report_plot_legend.c; none: nlines 0) */
void dvp_viewport(const char *const *text, int nlines, int ncolumns, double left_chars,
                  dvp_layout *out);

/* pllegend's position and offsets for a legend beside the frame: outside, right of it, centred */
#define DVP_LEGEND_POSITION (PL_POSITION_OUTSIDE | PL_POSITION_RIGHT | PL_POSITION_VIEWPORT)
#define DVP_LEGEND_X 0.015 /* gap between the frame and the legend, of the viewport */
#define DVP_LEGEND_TEXT_OFFSET 0.8 /* pllegend's text_offset */

/* copy text into out with PLplot's escape character doubled, then suffix */
void dvp_escape(char *out, size_t size, const char *text, const char *suffix);

/* whether v can be drawn */
int dvp_plottable(double v);

/* widen the bounds r (x0, x1, y0, y1) to the points of x, y (n each) that can
 * be drawn; *any says whether r holds a point yet, and is set once it does */
void dvp_extend_range(const double *x, const double *y, size_t n, double r[4], int *any);

/* a line through the n points of x, y, all drawable, in calls PLplot can take */
void dvp_line(const double *x, const double *y, size_t n);

/* widen [lo, hi] by margin of its span, or pad it around its middle when it collapses */
void dvp_pad_range(double *lo, double *hi, double margin, double min_pad);

/* widen the narrower range of r (x0, x1, y0, y1) so a unit is as long on both
 * axes of the current viewport */
void dvp_equal_aspect(double r[4]);

/* plslabelfunc callback: the label 10^value of a log10 axis */
void dvp_decade_label(PLINT axis, PLFLT value, char *label, PLINT length, PLPointer data);

/* whether PLplot can load its svg driver (plinit would exit the process otherwise) */
int dvp_have_svg(void);

/* draw(arg) on a fresh PLplot stream writing a temporary file next to path,
 * check that it is a complete SVG document, rename it to path */
typedef void (*dvp_draw_fn)(const void *arg);
int dvp_write_svg(const char *path, dvp_draw_fn draw, const void *arg, dv_error *err);

#endif
