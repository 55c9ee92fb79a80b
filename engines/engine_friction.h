/* engine_friction: the friction coefficient an engine uses, from the scene.
 *
 * A real disk has one coefficient against its table: [disk] friction
 * (scenario.h). Every engine takes it, and so does the validity window of
 * the references ([engines.matched] friction), unless the engine's own
 * friction key is given (file, --set, code), which wins.
 */
#ifndef DV_ENGINE_FRICTION_H
#define DV_ENGINE_FRICTION_H

#include <stddef.h>

#include "scenario.h"

/* *value as engine's friction key (its [engines.NAME] key) in sc: left as
 * given, else [disk] friction times scale (1 for a coefficient; m g for a
 * force limit, unit "N"). why (may be NULL): "; "-appended "friction 2:
 * [disk] friction" or "friction 5: [engines.ode] friction"; keys (may be
 * NULL): a NULL-terminated list the key is appended to when derived (room
 * for 1 more). */
void dv_engine_derive_friction(const dv_scenario *sc, const char *engine, const char *key,
                               double scale, const char *unit, double *value, char *why,
                               size_t size, const char **keys);

#endif
