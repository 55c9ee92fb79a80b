/* dvp_viewport_beside_legend: the frame, room right of it for the legend,
 * and left of it for the y axis's labels.
 *
 * A legend inside the frame hides data wherever it goes (a steel Euler
 * disk's energy curves fill every corner), so it sits outside, right of the
 * frame; the frame is as wide as that leaves. The legend's width is estimated
 * from PLplot's character height at the legend's scale and the layout
 * pllegend is given (DVP_LEGEND_*): each column a line sample plus its
 * longest text.
 */
#include <math.h>
#include <string.h>

#include "report_plot_internal.h"

#define CHAR_WIDTH 0.6  /* per character of the longest text, in character heights */
#define TEXT_LEAD 6.5   /* the text's offset and the box's padding, in character heights (fit
                           to the widths pllegend returned for 12- and 21-character texts) */
#define MARGIN 1.05     /* what the estimate missed, and a little air */
#define PAGE_RIGHT 0.99 /* of the page: the legend's right edge at most */
#define FRAME_MIN 0.45  /* of the page: the frame's width at least (long labels are cut) */

PLINT dvp_faint(PLINT c) {
  if (c == DVP_COL_FG) return DVP_COL_FAINT_FG;
  if (c >= DVP_COL_SERIES && c < DVP_COL_SERIES + DVP_NPALETTE)
    return DVP_COL_FAINT + (c - DVP_COL_SERIES);
  return c;
}

void dvp_viewport_beside_legend(const char *const *text, int nlines, int ncolumns, double *line) {
  PLFLT def, ht, sx0, sx1, sy0, sy1;
  plgspa(&sx0, &sx1, &sy0, &sy1); /* subpage, mm */
  plschr(0, DVP_LEGEND_SCALE);
  plgchr(&def, &ht); /* mm */
  size_t longest = 0;
  for (int k = 0; k < nlines; k++) longest = strlen(text[k]) > longest ? strlen(text[k]) : longest;
  plschr(0, 1.0);
  const double page_w = sx1 - sx0;
  const double col_mm = DVP_LEGEND_LINE_MM + (TEXT_LEAD + CHAR_WIDTH * (double)longest) * ht;
  double legend = nlines > 0 ? MARGIN * ncolumns * col_mm / page_w : 0.0;
  double right = PAGE_RIGHT - legend - (nlines > 0 ? 0.02 : 0.0);
  if (right < DVP_VIEWPORT_LEFT + FRAME_MIN) right = DVP_VIEWPORT_LEFT + FRAME_MIN;
  plvpor(DVP_VIEWPORT_LEFT, right, 0.12, 0.88);
  *line = DVP_LEGEND_LINE_MM / ((right - DVP_VIEWPORT_LEFT) * page_w);
}

const char *dvp_yaxis_opts(int log, int own_decades) {
  return !log ? "bcnst" : own_decades ? "bcnotv" : "bcnstlv";
}

double dvp_ylabel_disp(int log) {
  return log ? 5.5 : 4.0; /* "10^-16" across the axis is about 4.5 characters wide */
}
