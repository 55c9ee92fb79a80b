/* dv_report_plot_engine_colour: one colour per engine in every plot.
 *
 * The thin-disk reference is black; the other engines of the registry
 * (dv_engine_list()) take the palette's colours in turn, contact engines first,
 * then the other references; a name the registry does not know gets one of
 * the colours after those, by a hash of its name.
 *
 * dv_report_plot_distinct_colours keeps the curves of one plot apart where
 * those colours meet (names the hash puts together, more engines than the
 * palette has colours), and dvp_colour_style draws a colour number.
 */
#include <stddef.h>
#include <string.h>

#include "dv_engine.h"
#include "report_plot.h"
#include "report_plot_internal.h"

/* the palette slot of engine e among the registry's coloured engines, or -1 */
static int registry_slot(const dv_engine_type *e, int *ncoloured) {
  int slot = -1, k = 0;
  for (int contact = 1; contact >= 0; contact--)
    for (const dv_engine_type *const *t = dv_engine_list(); *t; t++) {
      if ((*t)->role == DV_ENGINE_THIN_REFERENCE || ((*t)->role == DV_ENGINE_CONTACT) != contact)
        continue;
      if (*t == e) slot = k;
      k++;
    }
  *ncoloured = k;
  return slot;
}

int dv_report_plot_engine_colour(const char *name) {
  const dv_engine_type *e = name ? dv_engine_find(name) : NULL;
  if (e && e->role == DV_ENGINE_THIN_REFERENCE) return 0;
  int ncoloured;
  const int slot = registry_slot(e, &ncoloured);
  if (slot >= 0) return 1 + slot;
  unsigned hash = 5381; /* djb2 */
  for (const char *p = name ? name : ""; *p; p++) hash = hash * 33u + (unsigned char)*p;
  const int spare = DVP_NPALETTE > ncoloured ? DVP_NPALETTE - ncoloured : DVP_NPALETTE;
  return 1 + (DVP_NPALETTE > ncoloured ? ncoloured : 0) + (int)(hash % (unsigned)spare);
}

/* whether one of the n colours is c */
static int used(const int *colour, size_t n, int c) {
  for (size_t j = 0; j < n; j++)
    if (colour[j] == c) return 1;
  return 0;
}

void dv_report_plot_distinct_colours(const int *want, size_t n, int *colour) {
  for (size_t k = 0; k < n; k++) /* the first to ask for a colour keeps it */
    colour[k] = want[k] >= 1 && !used(colour, k, want[k]) ? want[k] : 0;
  for (size_t k = 0; k < n; k++) {
    if (colour[k]) continue;
    for (int c = 1; c <= DVP_NPALETTE && !colour[k]; c++) /* a colour nobody has */
      if (!used(colour, n, c)) colour[k] = c;
    /* none left: its own colour with a pattern no curve of it has (n + 1 tries always find one) */
    const int base = want[k] >= 1 ? 1 + (want[k] - 1) % DVP_NPALETTE : 1;
    for (size_t d = 1; !colour[k] && d <= n + 1; d++)
      if (!used(colour, n, base + (int)d * DVP_NPALETTE)) colour[k] = base + (int)d * DVP_NPALETTE;
  }
}

void dv_report_plot_series_colours(const dv_plot_input *in, int *colour) {
  int want[DV_PLOT_MAX_SERIES];
  const size_t n = in->nseries < DV_PLOT_MAX_SERIES ? in->nseries : DV_PLOT_MAX_SERIES;
  for (size_t k = 0; k < n; k++) want[k] = dv_report_plot_engine_colour(in->series[k].label);
  dv_report_plot_distinct_colours(want, n, colour);
}

void dvp_colour_style(int c, PLINT *colour, PLINT *style) {
  /* pllsty's patterns, those the marks do not use first (report_plot_marks.c: 2 limit,
   * 3 horizon, 4 window end): 5 dash-dot, 6 dash-dash-dot, 7 and 8 dashes lengthening */
  static const PLINT patterns[DVP_NDASHES] = {1, 5, 6, 7, 8, 2, 3, 4};
  if (c < 1) {
    *colour = DVP_COL_FG;
    *style = 1;
    return;
  }
  *colour = (PLINT)(DVP_COL_SERIES + (c - 1) % DVP_NPALETTE);
  *style = patterns[(c - 1) / DVP_NPALETTE % DVP_NDASHES];
}
