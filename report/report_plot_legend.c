/* dvp_viewport_beside_legend: the frame, and room right of it for the legend.
 *
 * A legend inside the frame hides data wherever it goes (a steel Euler
 * disk's energy curves fill every corner), so it sits outside, right of the
 * frame; the frame is as wide as that leaves. The legend's width is estimated
 * from PLplot's character height and the layout pllegend is given
 * (DVP_LEGEND_*): each column a line sample plus its longest text.
 */
#include <math.h>

#include "report_plot_internal.h"

/* pllegend's box as it draws it on the SVG page (measured: its returned width
 * for 1 to 17 lines, labels of 3 to 25 characters, came within 10%) */
#define CHAR_WIDTH 0.6  /* per character of the longest text, in character heights */
#define TEXT_LEAD 3.0   /* the text's offset and the box's padding, in character heights */
#define MARGIN 1.1      /* what the fit missed, and a little air */
#define PAGE_RIGHT 0.99 /* of the page: the legend's right edge at most */
#define FRAME_MIN 0.45  /* of the page: the frame's width at least (long labels are cut) */

PLINT dvp_faint(PLINT c) {
  if (c == DVP_COL_FG) return DVP_COL_FAINT_FG;
  if (c >= DVP_COL_SERIES && c < DVP_COL_SERIES + DVP_NPALETTE)
    return DVP_COL_FAINT + (c - DVP_COL_SERIES);
  return c;
}

void dvp_viewport_beside_legend(int nlines, int ncolumns, size_t longest, double *line) {
  PLFLT def, ht, sx0, sx1, sy0, sy1;
  plgchr(&def, &ht);              /* mm */
  plgspa(&sx0, &sx1, &sy0, &sy1); /* subpage, mm */
  const double page_w = sx1 - sx0;
  const double col_mm = DVP_LEGEND_LINE_MM +
                        (TEXT_LEAD + CHAR_WIDTH * (double)longest) * DVP_LEGEND_SCALE * ht;
  double legend = nlines > 0 ? MARGIN * ncolumns * col_mm / page_w : 0.0;
  double right = PAGE_RIGHT - legend - (nlines > 0 ? 0.02 : 0.0);
  if (right < DVP_VIEWPORT_LEFT + FRAME_MIN) right = DVP_VIEWPORT_LEFT + FRAME_MIN;
  plvpor(DVP_VIEWPORT_LEFT, right, 0.12, 0.88);
  *line = DVP_LEGEND_LINE_MM / ((right - DVP_VIEWPORT_LEFT) * page_w);
}
