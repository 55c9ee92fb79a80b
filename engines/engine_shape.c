/* engine_shape: a contact engine's body from [disk] thickness (engine_shape.h). */
#include "engine_shape.h"

#include <stdio.h>
#include <string.h>

#include "dv_format.h"

void dv_engine_derive_shape(const dv_scenario *sc, const dv_shape_keys *k, int *geom, double *half,
                            char *why, size_t size, const char **keys) {
  const double t = sc->thickness;
  const int derive_geom = !dv_scenario_is_given(sc, k->engine, k->geom_key);
  const int derive_half =
      !dv_scenario_is_given(sc, k->engine, k->half_key) && (derive_geom || *geom != k->thin);
  char what[96] = "", number[DV_FORMAT_SIZE];
  size_t nkeys = 0;
  if (!(t > 0.0) || !(derive_geom || derive_half)) return;
  if (derive_geom) *geom = k->cylinder;
  if (derive_half) *half = 0.5 * t;
  while (keys && keys[nkeys]) nkeys++;
  if (derive_geom) {
    snprintf(what, sizeof what, "%s cylinder", k->geom_key);
    if (keys) keys[nkeys++] = k->geom_key;
  }
  if (derive_half) {
    dv_format_double(*half, number, sizeof number);
    snprintf(what + strlen(what), sizeof what - strlen(what), "%s%s %s m", what[0] ? ", " : "",
             k->half_key, number);
    if (keys) keys[nkeys++] = k->half_key;
  }
  if (keys) keys[nkeys] = NULL;
  if (!why || !size) return;
  dv_format_double(t, number, sizeof number);
  const size_t n = strnlen(why, size);
  snprintf(why + n, size - n, "%s%s: [disk] thickness %s m", n ? "; " : "", what, number);
}
