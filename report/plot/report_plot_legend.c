/* dvp_viewport: the frame, room left of it for the y axis's labels and
 * title, and right of it (or below it) for the legend.
 *
 * A legend inside the frame hides data wherever it goes (a steel Euler
 * disk's energy curves fill every corner), so it sits outside, right of the
 * frame; the frame is as wide as that leaves, and a legend taller than the
 * page takes more columns there. Where that would leave the frame narrower
 * than FRAME_MIN (long labels), the legend goes below it, in as many columns
 * as fit the page, if the frame keeps FRAME_TALL of the page's height there.
 * A legend too large for either (many engines) goes beside the frame in
 * smaller text, down to SCALE_BESIDE of the default, or else below it, its
 * text shrinking down to SCALE_MIN while it would leave the frame less than
 * FRAME_MIN_H of the page. The legend's size is what pllegend
 * itself gives the texts, measured on a stream of the same page written to
 * /dev/null: PLplot's own estimate of its text, which is wider than a
 * browser draws it, so the box holds the text and the page holds the box.
 */
#include <math.h>
#include <string.h>

#include "report_plot.h"
#include "report_plot_internal.h"

#define PAGE_RIGHT 0.99 /* of the page: the legend's right edge at most */
#define FRAME_MIN 0.45  /* of the page: the frame's width at least, beside a legend */
#define FRAME_TOP 0.88  /* of the page: room for the title above */
#define XLABEL_ROOM 4.5 /* below the frame: the x tick labels and title, character heights */
#define MAX_BELOW_COLUMNS 4
#define MAX_BESIDE_COLUMNS 3
#define PAGE_FILL 0.96    /* of the page's height: a legend beside the frame at most */
#define FRAME_MIN_H 0.3   /* of the page: the frame's height at least, above a legend */
#define FRAME_TALL 0.5    /* ... above one in full-size text, rather than one beside in smaller */
#define SCALE_STEP 0.85   /* a legend that does not fit: its text this much smaller, */
#define SCALE_BESIDE 0.55 /* down to this beside the frame (of the default character height) */
#define SCALE_MIN 0.45    /* and this below it */

/* the size (mm) pllegend gives the nlines texts in ncolumns columns with
 * line_mm long line samples, at text scale; 0 when it cannot be measured */
static int legend_size(const char *const *text, int nlines, int ncolumns, double line_mm,
                       double scale, double *w, double *h) {
  enum { M = 64 };
  _Static_assert(DV_PLOT_MAX_SERIES + 1 + 6 <= M && DV_PLOT_MAX_CURVES + 1 <= M,
                 "every legend's lines can be measured");
  PLINT opt[M], tcol[M], cur = 0, strm = -1, code = 0;
  char msg[1024] = "";
  if (nlines > M) return 0;
  for (int k = 0; k < nlines; k++) opt[k] = PL_LEGEND_NONE, tcol[k] = 1;
  plgstrm(&cur);
  plmkstrm(&strm);
  if (strm < 0) return 0;
  plsError(&code, msg);
  plsdev("svg");
  plsfnam("/dev/null");
  plspage(0, 0, DVP_PAGE_W, DVP_PAGE_H, 0, 0);
  plinit();
  PLFLT lw = 0, lh = 0, sx0 = 0, sx1 = 1, sy0 = 0, sy1 = 1;
  if (!code) {
    pladv(0);
    plvpor(0, 1, 0, 1);
    plwind(0, 1, 0, 1);
    plgspa(&sx0, &sx1, &sy0, &sy1);
    const PLINT rows = (nlines + ncolumns - 1) / ncolumns;
    pllegend(&lw, &lh, 0,
             PL_POSITION_INSIDE | PL_POSITION_LEFT | PL_POSITION_TOP | PL_POSITION_VIEWPORT, 0, 0,
             line_mm / (sx1 - sx0), 0, 0, 1, rows, ncolumns, nlines, opt, DVP_LEGEND_TEXT_OFFSET,
             scale, dvp_legend_spacing(scale), 0.0, tcol, text, NULL, NULL, NULL, NULL, NULL, NULL,
             NULL, NULL, NULL, NULL, NULL);
  }
  plend1();
  plsstrm(cur);
  *w = lw * (sx1 - sx0);
  *h = lh * (sy1 - sy0);
  return !code && *w > 0;
}

double dvp_legend_spacing(double scale) {
  return DVP_LEGEND_SPACING * scale / DVP_LEGEND_SCALE;
}

PLINT dvp_faint(PLINT c) {
  if (c == DVP_COL_FG) return DVP_COL_FAINT_FG;
  if (c >= DVP_COL_SERIES && c < DVP_COL_SERIES + DVP_NPALETTE)
    return DVP_COL_FAINT + (c - DVP_COL_SERIES);
  return c;
}

/* beside the frame: the fewest columns from ncolumns whose legend fits the
 * page's height and leaves the frame FRAME_MIN wide; its right edge into
 * *right; 1 when one does, -1 when those that leave the frame wide enough are
 * too tall, 0 when none leaves it wide enough (or it cannot be measured) */
static int beside(const char *const *text, int nlines, int ncolumns, double left, double page_w,
                  double page_h, dvp_layout *out, double *right) {
  int tall = 0;
  for (int c = ncolumns; c <= MAX_BESIDE_COLUMNS; c++) {
    double w, h;
    if (!legend_size(text, nlines, c, DVP_LEGEND_LINE_MM, out->scale, &w, &h)) return 0;
    /* the legend's left edge is DVP_LEGEND_X of the frame right of it */
    *right = (PAGE_RIGHT - w / page_w + DVP_LEGEND_X * left) / (1.0 + DVP_LEGEND_X);
    if (*right - left < FRAME_MIN) break; /* more columns are wider still */
    if (h <= PAGE_FILL * page_h) {
      out->columns = c;
      return 1;
    }
    tall = 1;
  }
  return tall ? -1 : 0;
}

/* below the frame, in the most columns that fit the page's width: the
 * frame's bottom into *bottom; 1 when it leaves the frame FRAME_MIN_H of the
 * page, 0 when not (*bottom then leaves it that), -1 when it cannot be measured */
static int below(const char *const *text, int nlines, double left, double right, double ht,
                 double page_w, double page_h, dvp_layout *out, double *bottom) {
  double w = 0, h = 0;
  int any = 0;
  for (int c = MAX_BELOW_COLUMNS; c >= 1; c--) {
    double wc, hc;
    if (!legend_size(text, nlines, c, DVP_LEGEND_LINE_MM, out->scale, &wc, &hc)) continue;
    out->columns = c, w = wc, h = hc, any = 1;
    if (wc <= PAGE_RIGHT * page_w) break;
  }
  const double want = (XLABEL_ROOM + 0.5) * ht / page_h + h / page_h;
  *bottom = fmin(want, FRAME_TOP - FRAME_MIN_H);
  out->position = PL_POSITION_OUTSIDE | PL_POSITION_BOTTOM | PL_POSITION_VIEWPORT;
  /* centred under the frame, moved over as far as the page needs */
  const double half = 0.5 * w / page_w, mid = 0.5 * (left + right);
  const double at = fmax(fmin(mid, PAGE_RIGHT - half), 1.0 - PAGE_RIGHT + half);
  out->x = (at - mid) / (right - left);
  out->y = XLABEL_ROOM * ht / ((FRAME_TOP - *bottom) * page_h);
  return !any ? -1 : want <= FRAME_TOP - FRAME_MIN_H;
}

/* a legend too large for full-size text: beside the frame in smaller text,
 * down to SCALE_BESIDE, or else below it, its text shrinking down to SCALE_MIN
 * while the frame would be lower than FRAME_MIN_H; its right and bottom edges
 * into *right, *bottom */
static void place_small(const char *const *text, int nlines, int ncolumns, double left, double ht,
                        double page_w, double page_h, dvp_layout *out, double *right,
                        double *bottom) {
  *bottom = 0.12;
  for (out->scale = DVP_LEGEND_SCALE * SCALE_STEP; out->scale >= SCALE_BESIDE;
       out->scale *= SCALE_STEP) {
    out->position = DVP_LEGEND_POSITION, out->x = DVP_LEGEND_X, out->y = 0.0;
    if (beside(text, nlines, ncolumns, left, page_w, page_h, out, right) == 1) return;
  }
  *right = PAGE_RIGHT - 0.02;
  out->scale = DVP_LEGEND_SCALE;
  while (!below(text, nlines, left, *right, ht, page_w, page_h, out, bottom) &&
         out->scale * SCALE_STEP >= SCALE_MIN)
    out->scale *= SCALE_STEP;
}

void dvp_viewport(const char *const *text, int nlines, int ncolumns, double left_chars,
                  dvp_layout *out) {
  PLFLT def, ht, sx0, sx1, sy0, sy1;
  plgspa(&sx0, &sx1, &sy0, &sy1); /* subpage, mm */
  plgchr(&def, &ht);              /* mm */
  const double page_w = sx1 - sx0, page_h = sy1 - sy0;
  const double left = (left_chars + 1.5) * ht / page_w;
  double right = PAGE_RIGHT - 0.02, bottom = 0.12;
  out->columns = ncolumns;
  out->position = DVP_LEGEND_POSITION;
  out->x = DVP_LEGEND_X;
  out->y = 0.0;
  out->scale = DVP_LEGEND_SCALE;
  if (nlines > 0 && beside(text, nlines, ncolumns, left, page_w, page_h, out, &right) != 1) {
    dvp_layout under = *out;
    const double full = PAGE_RIGHT - 0.02;
    const int fits = below(text, nlines, left, full, ht, page_w, page_h, &under, &bottom);
    if (fits != 1 || FRAME_TOP - bottom < FRAME_TALL) /* the frame too low: smaller text */
      place_small(text, nlines, ncolumns, left, ht, page_w, page_h, out, &right, &bottom);
    else
      *out = under, right = full;
  }
  plvpor(left, right, bottom, FRAME_TOP);
  out->line = DVP_LEGEND_LINE_MM / ((right - left) * page_w);
}

double dvp_ylabel_disp(int log, double labels) {
  /* "10^-16" across the axis is about 4.5 characters wide */
  return log ? 5.5 : labels + 2.0;
}
