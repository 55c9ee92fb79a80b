/* engine_module: a contact engine's code as a shared module (engines/NAME/ builds
 * engine_NAME.so), opened with dlopen the first time the engine runs, so a process
 * that runs none maps none of the engines' libraries, and a module missing or
 * broken disables its engine only ("NAME: not available: PATH: why").
 *
 * The engine's table (dv_engine_NAME: its name, settings, search and contact
 * knobs) stays linked in; its calls (version, alloc, reset, advance, stats,
 * free) go through DV_ENGINE_MODULE_CALLS to the module's dv_engine_module.
 * Each module links its own hidden copy of the layers below the registry
 * (libdiskval hides dv_*, so a module cannot take them from its host).
 *
 * Modules are looked for in $DISKVAL_ENGINE_DIR alone where it is set, else
 * in the build tree's folder, then in the installed LIBDIR/diskval. Opened
 * once per process and never closed.
 */
#ifndef DV_ENGINE_MODULE_H
#define DV_ENGINE_MODULE_H

#include "dv_engine.h"

#define DV_ENGINE_MODULE_ABI 1
#define DV_ENGINE_MODULE_SYMBOL "dv_engine_module"

/* what a module exports, as the symbol dv_engine_module */
typedef struct dv_module_calls {
  int abi; /* DV_ENGINE_MODULE_ABI */
  /* the structures it was built with: another build's module is refused */
  size_t scenario_size, sample_size, stats_size, error_size;
  const char *(*version)(void);
  void *(*alloc)(const dv_scenario *sc, dv_error *err);
  int (*reset)(void *engine, const double state[RED_NSTATE], dv_error *err);
  int (*advance)(void *engine, double t, dv_sample *out, dv_error *err);
  void (*stats)(const void *engine, dv_engine_stats *out);
  void (*free)(void *engine);
} dv_module_calls;

/* a const's external linkage: C++ gives it internal linkage unless extern */
#ifdef __cplusplus
#define DV_MODULE_LINKAGE extern
#else
#define DV_MODULE_LINKAGE
#endif

/* in a module: its export, from its functions */
#define DV_ENGINE_MODULE_EXPORT(version_, alloc_, reset_, advance_, stats_, free_)            \
  __attribute__((visibility("default"))) DV_MODULE_LINKAGE const dv_module_calls          \
      dv_engine_module = {                                                                 \
      DV_ENGINE_MODULE_ABI, sizeof(dv_scenario), sizeof(dv_sample), sizeof(dv_engine_stats), \
      sizeof(dv_error),     version_,            alloc_,            reset_,                  \
      advance_,             stats_,              free_}

/* engine name's module, opened once; NULL with err "NAME: not available: PATH: why" */
const dv_module_calls *dv_engine_module_open(const char *name, dv_error *err);

/* a further symbol of engine name's module (a test's entry), or NULL with err */
void *dv_engine_module_symbol(const char *name, const char *symbol, dv_error *err);

/* the table's calls, through the module of the engine called name */
const char *dv_engine_module_version(const char *name);
void *dv_engine_module_alloc(const char *name, const dv_scenario *sc, dv_error *err);
int dv_engine_module_reset(void *engine, const double state[RED_NSTATE], dv_error *err);
int dv_engine_module_advance(void *engine, double t, dv_sample *out, dv_error *err);
void dv_engine_module_stats(const void *engine, dv_engine_stats *out);
void dv_engine_module_free(void *engine);

/* in an engine's table file: its calls, named NAME_version and NAME_alloc, to
 * its module */
#define DV_ENGINE_MODULE_PROXY(NAME)                                                   \
  static const char *NAME##_version(void) { return dv_engine_module_version(#NAME); } \
  static void *NAME##_alloc(const dv_scenario *sc, dv_error *err) {                   \
    return dv_engine_module_alloc(#NAME, sc, err);                                     \
  }

/* ...and the table's fields for them */
#define DV_ENGINE_MODULE_CALLS(NAME)                                                        \
  .version = NAME##_version, .alloc = NAME##_alloc, .reset = dv_engine_module_reset,      \
  .advance = dv_engine_module_advance, .stats = dv_engine_module_stats,                   \
  .free = dv_engine_module_free, .module = 1

#endif
