/* dv_engines: the registry of engines. */
#include <string.h>

#include "dv_engine.h"

const dv_engine_type *const dv_engines[] = {&dv_engine_reduced, NULL};

const dv_engine_type *dv_engine_find(const char *name) {
  for (const dv_engine_type *const *e = dv_engines; *e; e++)
    if (strcmp((*e)->name, name) == 0) return *e;
  return NULL;
}
