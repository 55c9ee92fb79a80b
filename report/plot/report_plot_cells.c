/* dv_report_plot_cells: filled cells, crossed cells and a curve over them,
 * drawn with PLplot into an SVG file through dvp_write_svg. */
#include "report_plot_cells.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "report_plot_internal.h"

#define CROSS "\xc3\x97" /* U+00D7 multiplication sign: the legend's mark */
#define INSET 0.2        /* a cross spans the cell less this share at each end */

/* the nv + 1 edges of cells centred at v (plot coordinates, increasing) */
static void cell_edges(const double *v, size_t nv, double *edge) {
  if (nv == 1) {
    const double half = fabs(v[0]) > 0.0 ? 0.05 * fabs(v[0]) : 0.5;
    edge[0] = v[0] - half;
    edge[1] = v[0] + half;
    return;
  }
  for (size_t i = 1; i < nv; i++) edge[i] = 0.5 * (v[i - 1] + v[i]);
  edge[0] = v[0] - 0.5 * (v[1] - v[0]);
  edge[nv] = v[nv - 1] + 0.5 * (v[nv - 1] - v[nv - 2]);
}

typedef struct cells_figure {
  const dv_cell_map *m;
  double *xe, *ye; /* cell edges, plot coordinates */
} cells_figure;

/* v on an axis: log10 on a log one */
static double axis(double v, int log) {
  return log ? log10(v) : v;
}

static PLINT palette(int colour) {
  return DVP_COL_SERIES + (colour - 1) % DVP_NPALETTE;
}

/* a rectangle [x0, x1] x [y0, y1]: filled, or outlined */
static void rectangle(double x0, double x1, double y0, double y1, int fill) {
  PLFLT x[5] = {x0, x1, x1, x0, x0}, y[5] = {y0, y0, y1, y1, y0};
  if (fill)
    plfill(4, x, y);
  else
    plline(5, x, y);
}

/* classes that occur, the curve, the cross: right of the plot */
static void draw_legend(const dv_cell_map *m, int crosses) {
  enum { M = DV_CELLS_MAX_CLASSES + 2 };
  PLINT opt[M], tcol[M], bcol[M], bpat[M], lcol[M], lsty[M], scol[M], snum[M];
  PLFLT bscale[M], bwidth[M], lwidth[M], sscale[M];
  const char *text[M], *sym[M];
  PLINT n = 0;
  for (size_t c = 0; c < m->nclasses; c++) {
    int used = 0;
    for (size_t k = 0; k < m->nx * m->ny && !used; k++) used = m->cls[k] == (int)c;
    if (!used) continue;
    opt[n] = PL_LEGEND_COLOR_BOX;
    bcol[n] = palette(m->class_colours[c]);
    text[n++] = m->class_names[c];
  }
  if (m->ncurve) {
    opt[n] = PL_LEGEND_LINE;
    lwidth[n] = 3.0;
    text[n++] = m->curve_label ? m->curve_label : "";
  }
  if (crosses) {
    opt[n] = PL_LEGEND_SYMBOL;
    text[n++] = m->marked_label ? m->marked_label : "";
  }
  for (PLINT i = 0; i < n; i++) {
    tcol[i] = lcol[i] = scol[i] = DVP_COL_FG;
    if (opt[i] != PL_LEGEND_COLOR_BOX) bcol[i] = DVP_COL_FG;
    if (opt[i] != PL_LEGEND_LINE) lwidth[i] = 1.0;
    bpat[i] = 0;
    bscale[i] = 0.8;
    bwidth[i] = 1.0;
    lsty[i] = 1;
    sscale[i] = 1.2;
    snum[i] = 1;
    sym[i] = CROSS;
  }
  if (n == 0) return;
  PLFLT w, h;
  pllegend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX,
           PL_POSITION_RIGHT | PL_POSITION_OUTSIDE, 0.02, 0.0, 0.05, DVP_COL_BG, DVP_COL_FG, 1, n,
           1, n, opt, 0.8, 0.8, 2.0, 0.0, tcol, text, bcol, bpat, bscale, bwidth, lcol, lsty,
           lwidth, scol, sscale, snum, sym);
}

/* draw the figure (a cells_figure *) on the current, initialised stream */
static void draw_cells(const void *arg) {
  const cells_figure *f = arg;
  const dv_cell_map *m = f->m;
  const double r[4] = {f->xe[0], f->xe[m->nx], f->ye[0], f->ye[m->ny]};
  pladv(0);
  plvpor(0.12, 0.68, 0.12, 0.88);
  plwind(r[0], r[1], r[2], r[3]);
  int crosses = 0;
  for (size_t i = 0; i < m->nx; i++)
    for (size_t j = 0; j < m->ny; j++) {
      plcol0(palette(m->class_colours[m->cls[i * m->ny + j]]));
      rectangle(f->xe[i], f->xe[i + 1], f->ye[j], f->ye[j + 1], 1);
    }
  plcol0(DVP_COL_BG); /* a thin gap between cells */
  plwidth(1.0);
  for (size_t i = 0; i < m->nx; i++)
    for (size_t j = 0; j < m->ny; j++) rectangle(f->xe[i], f->xe[i + 1], f->ye[j], f->ye[j + 1], 0);
  plcol0(DVP_COL_FG);
  plwidth(2.0);
  for (size_t i = 0; m->marked && i < m->nx; i++)
    for (size_t j = 0; j < m->ny; j++) {
      if (!m->marked[i * m->ny + j]) continue;
      crosses = 1;
      const double dx = INSET * (f->xe[i + 1] - f->xe[i]), dy = INSET * (f->ye[j + 1] - f->ye[j]);
      pljoin(f->xe[i] + dx, f->ye[j] + dy, f->xe[i + 1] - dx, f->ye[j + 1] - dy);
      pljoin(f->xe[i] + dx, f->ye[j + 1] - dy, f->xe[i + 1] - dx, f->ye[j] + dy);
    }
  plwidth(3.0);
  for (size_t k = 1; k < m->ncurve; k++) {
    const double x0 = axis(m->curve_x[k - 1], m->logx), x1 = axis(m->curve_x[k], m->logx);
    const double y0 = axis(m->curve_y[k - 1], m->logy), y1 = axis(m->curve_y[k], m->logy);
    if (isfinite(x0 + x1 + y0 + y1) && y0 >= r[2] && y0 <= r[3] && y1 >= r[2] && y1 <= r[3])
      pljoin(x0, y0, x1, y1);
  }
  plwidth(1.0);
  plbox(m->logx ? "bcstl" : "bcst", 0, 0, m->logy ? "bcstl" : "bcst", 0, 0);
  char text[32];
  for (size_t i = 0; i<m->nx; i += m->nx> 12 ? (m->nx + 11) / 12 : 1) { /* each column's value */
    snprintf(text, sizeof text, "%.3g", m->x[i]);
    plmtex("b", 1.5, (axis(m->x[i], m->logx) - r[0]) / (r[1] - r[0]), 0.5, text);
  }
  for (size_t j = 0; j<m->ny; j += m->ny> 16 ? (m->ny + 15) / 16 : 1) { /* each row's */
    snprintf(text, sizeof text, "%.3g", m->y[j]);
    plmtex("lv", 0.7, (axis(m->y[j], m->logy) - r[2]) / (r[3] - r[2]), 1.0, text);
  }
  pllab("", "", m->title ? m->title : "");
  plmtex("b", 3.2, 0.5, 0.5, m->xlabel ? m->xlabel : "");
  plmtex("l", m->logy ? 5.5 : 5.0, 0.5, 0.5, m->ylabel ? m->ylabel : "");
  draw_legend(m, crosses);
}

int dv_report_plot_cells(const char *path, const dv_cell_map *m, dv_error *err) {
  if (!path || !m || !m->nx || !m->ny || !m->x || !m->y || !m->cls || !m->nclasses ||
      m->nclasses > DV_CELLS_MAX_CLASSES || !m->class_names || !m->class_colours ||
      (m->ncurve && (!m->curve_x || !m->curve_y)))
    return dv_fail(err, DV_EINPUT, "dv_report_plot_cells: bad arguments");
  for (size_t k = 0; k < m->nx * m->ny; k++)
    if (m->cls[k] < 0 || (size_t)m->cls[k] >= m->nclasses)
      return dv_fail(err, DV_EINPUT, "%s: cell %zu: class %d", path, k, m->cls[k]);
  for (size_t c = 0; c < m->nclasses; c++)
    if (m->class_colours[c] < 1)
      return dv_fail(err, DV_EINPUT, "%s: class %zu: colour %d", path, c, m->class_colours[c]);
  for (size_t j = 0; j < m->ny; j++)
    if (!isfinite(m->y[j]) || (m->logy && !(m->y[j] > 0.0)) || (j && !(m->y[j] > m->y[j - 1])))
      return dv_fail(err, DV_EINPUT, "%s: the y centres must increase (> 0 on a log axis)", path);
  for (size_t i = 0; i < m->nx; i++)
    if (!isfinite(m->x[i]) || (m->logx && !(m->x[i] > 0.0)) || (i && !(m->x[i] > m->x[i - 1])))
      return dv_fail(err, DV_EINPUT, "%s: the x centres must increase (> 0 on a log axis)", path);
  if (!dvp_have_svg()) return dv_fail(err, DV_ESYSTEM, "PLplot has no svg driver");
  cells_figure f = {m, malloc((m->nx + 1) * sizeof *f.xe), malloc((m->ny + 1) * sizeof *f.ye)};
  double *lx = malloc((m->nx + m->ny) * sizeof *lx), *ly = lx ? lx + m->nx : NULL;
  int status = DV_OK;
  if (!f.xe || !f.ye || !lx) {
    status = dv_fail(err, DV_ESYSTEM, "%s: out of memory", path);
  } else {
    for (size_t i = 0; i < m->nx; i++) lx[i] = axis(m->x[i], m->logx);
    for (size_t j = 0; j < m->ny; j++) ly[j] = axis(m->y[j], m->logy);
    cell_edges(lx, m->nx, f.xe);
    cell_edges(ly, m->ny, f.ye);
    status = dvp_write_svg(path, draw_cells, &f, err);
  }
  free(f.xe);
  free(f.ye);
  free(lx);
  return status;
}
