/* dv_report_plot_engine_colour: one colour per engine in every plot.
 *
 * The thin-disk reference is black; the other engines of the registry
 * (dv_engine_list()) take the palette's colours in turn, contact engines first,
 * then the other references; a name the registry does not know gets one of
 * the colours after those, by a hash of its name.
 */
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
