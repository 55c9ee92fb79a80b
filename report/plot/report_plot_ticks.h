/* report_plot_ticks: the labelled ticks of a linear axis, readable for any
 * range (not public API).
 *
 * The step is 1, 2 or 5 times a power of ten, the smallest whose labels do
 * not crowd: along an axis (x) each label's estimated width plus a gap fits
 * between ticks; across it (y, labels written horizontally) two character
 * heights do. Labels have exactly the digits the step needs. A range whose
 * labels would need more than DVP_TICK_DIGITS significant digits is shown
 * scaled: the labels are (v - offset) / 10^exponent and the axis title says
 * so ("- 1.2, x10^-11"); e.g. a 1e-10 wide range around 1.2 reads -4 ... 4
 * (x10^-11, offset 1.2), -2.5e-5 .. 0 reads -2.5 ... 0.0 (x10^-5).
 */
#ifndef DV_REPORT_PLOT_TICKS_H
#define DV_REPORT_PLOT_TICKS_H

#include <stddef.h>


#define DVP_TICK_DIGITS 5        /* significant digits a label may show */
#define DVP_TICK_CHAR_WIDTH 0.8  /* a label's character, in character heights (a browser's
                                    sans-serif digit is 0.56 em, its em 1.3 character heights) */

typedef struct dvp_ticks {
  double step;   /* between labelled ticks, axis units */
  double offset; /* subtracted from a value before it is scaled (0: none) */
  int exponent;  /* a label is (v - offset) / 10^exponent */
  int decimals;  /* digits after the point */
  int width;     /* characters of the longest label */
} dvp_ticks;

/* ticks of [lo, hi] (lo < hi) on an axis length character heights long;
 * along: the labels are written along the axis (else across it) */
void dvp_linear_ticks(double lo, double hi, double length, int along, dvp_ticks *t);

/* the label of value v on t's axis */
void dvp_tick_label(const dvp_ticks *t, double v, char *out, size_t size);

/* the axis title's note for t (PLplot text): "", ", x10^-5" or " - 1.2, x10^-11" */
void dvp_ticks_note(const dvp_ticks *t, char *out, size_t size);

/* the estimated width of t's widest label, in character heights */
double dvp_ticks_width(const dvp_ticks *t);

/* the axes of a frame: whether each (x, y) is log10, a linear one's ticks */
typedef struct dvp_axes {
  int log[2];
  dvp_ticks t[2];
} dvp_axes;

/* the estimated width (character heights) of the y labels of [lo, hi], on a frame
 * of the usual height, for the margin left of it */
double dvp_ylabels_width(double lo, double hi, int log);

/* frame, grid, ticks and labels of the current viewport and window r (x0, x1, y0,
 * y1) into ax: linear axes labelled by their dvp_ticks, log axes by decades (every
 * few, as 10^k, where there are more than 8) */
void dvp_draw_axes(const double r[4], int logx, int logy, dvp_axes *ax);

/* the axis titles with ax's notes: xlabel under the frame, ylabel disp character
 * heights left of it, title above */
void dvp_axis_titles(const dvp_axes *ax, const char *xlabel, const char *ylabel, double disp,
                     const char *title);

#endif
