/* dvp_legend_corner: where a legend inside the frame hides the least.
 *
 * The legend's size is estimated from PLplot's character height and the
 * layout pllegend is given (DVP_LEGEND_*): each line is DVP_LEGEND_SPACING
 * character heights high, each column a line sample plus its longest text. The four corners are
 * tried in the order top right, top left, bottom right, bottom left; the first with the fewest
 * points under the legend wins. When every corner would hide a point, dvp_legend_make_room raises
 * the top of the window so a band free of points holds the legend.
 */
#include <math.h>

#include "report_plot_internal.h"

/* pllegend's box as it draws it on the SVG page (measured: its returned width
 * and height for 1 to 17 lines, labels of 3 to 25 characters, came within 10%) */
#define CHAR_WIDTH 0.6 /* per character of the longest text, in character heights */
#define TEXT_LEAD 3.0  /* the text's offset and the box's padding, in character heights */
#define MARGIN 1.1     /* what the fit missed, and a little air */

/* points of pts inside the box x0 <= x <= x1, y0 <= y <= y1 */
static size_t count_in(const dvp_points *pts, size_t npts, double x0, double x1, double y0,
                       double y1) {
  size_t n = 0;
  for (size_t k = 0; k < npts; k++)
    for (size_t i = 0; i < pts[k].n; i++) {
      const double x = pts[k].x[i], y = pts[k].y[i];
      n += x >= x0 && x <= x1 && y >= y0 && y <= y1; /* NaN: never inside */
    }
  return n;
}

/* the legend's width and height, as fractions of the viewport */
static void legend_size(int nlines, int ncolumns, size_t longest, double *w, double *h) {
  PLFLT def, ht, sx0, sx1, sy0, sy1, vx0, vx1, vy0, vy1;
  plgchr(&def, &ht);              /* mm */
  plgspa(&sx0, &sx1, &sy0, &sy1); /* subpage, mm */
  plgvpd(&vx0, &vx1, &vy0, &vy1); /* viewport, fraction of the subpage */
  const double w_mm = (vx1 - vx0) * (sx1 - sx0), h_mm = (vy1 - vy0) * (sy1 - sy0);
  const double line = DVP_LEGEND_SPACING * ht;
  const int rows = (nlines + ncolumns - 1) / ncolumns;
  *h = fmin(1.0, DVP_LEGEND_OFFSET + MARGIN * rows * line / h_mm);
  const double col = DVP_LEGEND_LINE + (TEXT_LEAD + CHAR_WIDTH * (double)longest) * ht / w_mm;
  *w = fmin(1.0, DVP_LEGEND_OFFSET + MARGIN * ncolumns * col);
}

/* the corner (PL_POSITION_*) where a w x h legend hides the fewest points; that count */
static size_t best_corner(const dvp_points *pts, size_t npts, const double r[4], double w, double h,
                          PLINT *best) {
  static const PLINT corners[4] = {
      PL_POSITION_TOP | PL_POSITION_RIGHT, PL_POSITION_TOP | PL_POSITION_LEFT,
      PL_POSITION_BOTTOM | PL_POSITION_RIGHT, PL_POSITION_BOTTOM | PL_POSITION_LEFT};
  const double dx = r[1] - r[0], dy = r[3] - r[2];
  size_t fewest = (size_t)-1;
  *best = corners[0];
  for (int k = 0; k < 4; k++) {
    const int right = corners[k] & PL_POSITION_RIGHT, top = corners[k] & PL_POSITION_TOP;
    const double x0 = right ? r[1] - w * dx : r[0], y0 = top ? r[3] - h * dy : r[2];
    const size_t n = count_in(pts, npts, x0, x0 + w * dx, y0, y0 + h * dy);
    if (n < fewest) fewest = n, *best = corners[k];
  }
  return fewest;
}

void dvp_legend_make_room(const dvp_points *pts, size_t npts, double r[4], int nlines, int ncolumns,
                          size_t longest) {
  double w, h;
  PLINT corner;
  if (nlines == 0) return;
  legend_size(nlines, ncolumns, longest, &w, &h);
  if (h > 0.5 || best_corner(pts, npts, r, w, h, &corner) == 0) return;
  r[3] = (r[3] - h * r[2]) / (1.0 - h); /* the top band of height h now starts above r[3] */
}

PLINT dvp_legend_corner(const dvp_points *pts, size_t npts, const double r[4], int nlines,
                        int ncolumns, size_t longest) {
  double w, h;
  PLINT corner;
  legend_size(nlines, ncolumns, longest, &w, &h);
  best_corner(pts, npts, r, w, h, &corner);
  return corner | PL_POSITION_INSIDE | PL_POSITION_VIEWPORT;
}
