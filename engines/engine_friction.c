/* engine_friction: an engine's friction from [disk] friction (engine_friction.h). */
#include "engine_friction.h"

#include <stdio.h>
#include <string.h>

#include "dv_format.h"

void dv_engine_derive_friction(const dv_scenario *sc, const char *engine, const char *key,
                               double scale, const char *unit, double *value, char *why,
                               size_t size, const char **keys) {
  const int given = dv_scenario_is_given(sc, engine, key);
  char number[DV_FORMAT_SIZE], mu[DV_FORMAT_SIZE];
  if (!given) *value = sc->friction * scale;
  if (keys && !given) {
    size_t n = 0;
    while (keys[n]) n++;
    keys[n++] = key;
    keys[n] = NULL;
  }
  if (!why || !size) return;
  dv_format_double(*value, number, sizeof number);
  dv_format_double(sc->friction, mu, sizeof mu);
  const size_t n = strnlen(why, size);
  if (given)
    snprintf(why + n, size - n, "%s%s %s%s%s: [engines.%s] %s", n ? "; " : "", key, number,
             unit[0] ? " " : "", unit, engine, key);
  else if (scale != 1.0)
    snprintf(why + n, size - n, "%s%s %s%s%s: [disk] friction %s x m g", n ? "; " : "", key, number,
             unit[0] ? " " : "", unit, mu);
  else
    snprintf(why + n, size - n, "%s%s %s: [disk] friction", n ? "; " : "", key, number);
}
