/* dv_report_plot_cells: a map of classified grid cells (SVG, PLplot).
 *
 * Every cell of an nx by ny grid is a filled rectangle in its class's
 * colour, reaching halfway to its neighbours' centres (on a log axis, in
 * log10), and each row's and column's value is written beside it; marked cells get a black cross
 * (e.g. where an engine's class differs from the reference's); an optional black curve is drawn
 * over the cells. The legend, right of the plot, lists the classes that occur, the curve and the
 * mark. Written like dv_report_plot_xy: a temporary file renamed when complete; DV_EINPUT for bad
 * arguments, DV_ESYSTEM when the file cannot be written. PLplot's state is global: not thread-safe.
 */
#ifndef DV_REPORT_PLOT_CELLS_H
#define DV_REPORT_PLOT_CELLS_H

#include <stddef.h>

#include "dv_error.h"

#define DV_CELLS_MAX_CLASSES 8

typedef struct dv_cell_map {
  const char *title, *xlabel, *ylabel; /* PLplot text, as dv_report_plot_xy's */
  size_t nx, ny;
  const double *x, *y; /* the cells' centres, nx and ny, increasing (> 0 on a log axis) */
  int logx, logy;      /* x, y on a log10 axis */
  const int *cls;      /* nx * ny classes, cell (i, j) at i * ny + j, in [0, nclasses) */
  size_t nclasses;
  const char *const *class_names; /* legend text */
  const int *class_colours;       /* dv_report_plot_xy's palette numbers, >= 1 */
  const int *marked;              /* optional, nx * ny: crossed cells */
  const char *marked_label;       /* the legend text of the cross */
  size_t ncurve;                  /* an optional black curve over the cells */
  const double *curve_x, *curve_y;
  const char *curve_label;
} dv_cell_map;

int dv_report_plot_cells(const char *path, const dv_cell_map *m, dv_error *err);

#endif
