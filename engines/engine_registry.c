/* engine_registry: the engines of a process (dv_engine.h): the linked ones, in
 * dv_engines.def's order, then the adapters found; their settings tables; and
 * the modules that hold the contact engines' code, opened on first use
 * (engine_module.h). */
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_engine.h"
#include "adapter.h"
#include "engine_module.h"

#define DV_ENGINE(name) &dv_engine_##name,
const dv_engine_type *const dv_engines_linked[] = {
#include "dv_engines.def"
    NULL};
#undef DV_ENGINE

static const dv_engine_type *registry[DV_MAX_REGISTERED + 1];
static pthread_once_t once = PTHREAD_ONCE_INIT;

/* the linked engines, then the adapters found (adapter.h) */
static void build(void) {
  size_t n = 0;
  const dv_adapter *const *a;
  for (const dv_engine_type *const *e = dv_engines_linked; *e; e++) registry[n++] = *e;
  const size_t na = dv_adapters(&a);
  for (size_t i = 0; i < na; i++) registry[n++] = &a[i]->type;
  registry[n] = NULL;
}

const dv_engine_type *const *dv_engine_list(void) {
  pthread_once(&once, build);
  return registry;
}

/* the linked engines first: a run of one of them reads no adapter's manifest
 * (an adapter never takes a linked engine's name, adapter_registry.c) */
const dv_engine_type *dv_engine_find(const char *name) {
  for (const dv_engine_type *const *e = dv_engines_linked; *e; e++)
    if (strcmp((*e)->name, name) == 0) return *e;
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++)
    if (strcmp((*e)->name, name) == 0) return *e;
  return NULL;
}

const dv_engine_type *dv_engine_of_role(dv_engine_role role) {
  for (const dv_engine_type *const *e = dv_engines_linked; *e; e++)
    if ((*e)->role == role) return *e;
  return NULL;
}

/* every engine's settings table, NULL-terminated */
static void tables(const dv_settings_section **out) {
  _Static_assert(DV_MAX_REGISTERED <= DV_MAX_ENGINE_SECTIONS,
                 "every engine's settings section fits");
  size_t n = 0;
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++)
    if ((*e)->settings) out[n++] = (*e)->settings;
  out[n] = NULL;
}

int dv_engine_load_scenario(const char *path, const char *const *overrides, size_t noverrides,
                            dv_scenario *sc, dv_error *err) {
  const dv_settings_section *t[DV_MAX_ENGINE_SECTIONS + 1];
  tables(t);
  return dv_scenario_load(t, path, overrides, noverrides, sc, err);
}

void dv_engine_init_scenario(dv_scenario *sc) {
  const dv_settings_section *t[DV_MAX_ENGINE_SECTIONS + 1];
  tables(t);
  dv_scenario_init(sc, t);
}

int dv_engine_derive_settings(dv_scenario *sc, dv_error *err) {
  for (size_t i = 0; i < sc->nsections; i++) {
    dv_setting_issue issue = {0};
    if (dv_scenario_check_engine(sc, i, &issue)) /* "initial.theta" is no engine's */
      return dv_fail(err, DV_EINPUT, "%s%s.%s: %s", dv_engine_find(issue.section) ? "engines." : "",
                     issue.section, issue.key, issue.what);
  }
  return DV_OK;
}

int dv_engine_parse_list(const char *list, const dv_engine_type **engines, size_t max,
                         dv_error *err) {
  char buf[256];
  size_t n = 0;
  snprintf(buf, sizeof buf, "%s", list);
  for (char *save = NULL, *tok = strtok_r(buf, ", ", &save); tok;
       tok = strtok_r(NULL, ", ", &save)) {
    const dv_engine_type *e = dv_engine_find(tok);
    if (!e) {
      char names[256] = "";
      for (const dv_engine_type *const *k = dv_engine_list(); *k; k++)
        snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s",
                 k == dv_engine_list() ? "" : ", ", (*k)->name);
      return dv_fail(err, DV_EINPUT, "unknown engine '%s' (one of: %s)", tok, names);
    }
    const char *why = e->module ? dv_engine_unavailable(e) : NULL;
    if (why) return dv_fail(err, DV_EINPUT, "%s: not available: %s", tok, why);
    for (size_t k = 0; k < n; k++) /* a report holds one result per engine */
      if (engines[k] == e) return dv_fail(err, DV_EINPUT, "engine '%s' listed twice", tok);
    if (n + 1 >= max) return dv_fail(err, DV_EINPUT, "too many engines");
    engines[n++] = e;
  }
  if (!n) return dv_fail(err, DV_EINPUT, "no engine in '%s'", list);
  engines[n] = NULL;
  return DV_OK;
}


/* one module: opened at most once; ops or why not */
typedef struct module_slot {
  const char *name;
  int tried;
  void *handle;
  const dv_module_calls *ops;
  char why[1200];
} module_slot;

static module_slot slots[DV_NENGINES];
static pthread_mutex_t slots_lock = PTHREAD_MUTEX_INITIALIZER;

/* the folders searched, in order, NULL-terminated */
static void module_dirs(const char **dirs) {
  const char *env = getenv("DISKVAL_ENGINE_DIR");
  size_t n = 0;
  if (env && env[0]) {
    dirs[n++] = env;
  } else {
    dirs[n++] = DV_ENGINE_BUILD_DIR;
    dirs[n++] = DV_ENGINE_INSTALL_DIR;
  }
  dirs[n] = NULL;
}

/* open name's module into slot: the first folder holding one, else the last folder's dlerror */
static void module_load(module_slot *slot) {
  const char *dirs[3];
  char path[1100];
  void *handle = NULL;
  module_dirs(dirs);
  for (const char *const *d = dirs; *d; d++) {
    snprintf(path, sizeof path, "%s/engine_%s.so", *d, slot->name);
    if (access(path, F_OK) == 0 || !d[1]) break;
  }
  handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    snprintf(slot->why, sizeof slot->why, "%s", dlerror());
    return;
  }
  const dv_module_calls *m = dlsym(handle, DV_ENGINE_MODULE_SYMBOL);
  if (!m)
    snprintf(slot->why, sizeof slot->why, "%s", dlerror());
  else if (m->abi != DV_ENGINE_MODULE_ABI || m->scenario_size != sizeof(dv_scenario) ||
           m->sample_size != sizeof(dv_sample) || m->stats_size != sizeof(dv_engine_stats) ||
           m->error_size != sizeof(dv_error))
    snprintf(slot->why, sizeof slot->why, "%s: built by another version of diskval", path);
  else
    slot->ops = m; /* never closed: its code and data live as long as the process */
  slot->handle = handle;
}

static module_slot *module_slot_of(const char *name) {
  pthread_mutex_lock(&slots_lock);
  module_slot *slot = NULL;
  for (size_t i = 0; i < DV_NENGINES && !slot; i++) {
    if (!slots[i].name) slots[i].name = name;
    if (strcmp(slots[i].name, name) == 0) slot = &slots[i];
  }
  if (slot && !slot->tried) {
    slot->tried = 1;
    module_load(slot);
  }
  pthread_mutex_unlock(&slots_lock);
  return slot;
}

const dv_module_calls *dv_engine_module_open(const char *name, dv_error *err) {
  const module_slot *slot = module_slot_of(name);
  if (slot && slot->ops) return slot->ops;
  dv_fail(err, DV_EINPUT, "%s: not available: %s", name, slot ? slot->why : "no such engine");
  return NULL;
}

const char *dv_engine_unavailable(const dv_engine_type *engine) {
  const dv_adapter *a = dv_adapter_of(engine);
  if (a) return a->missing[0] ? a->missing : NULL;
  if (!engine->module) return NULL;
  const module_slot *slot = module_slot_of(engine->name);
  return slot && slot->ops ? NULL : slot ? slot->why : "no such engine";
}

void *dv_engine_module_symbol(const char *name, const char *symbol, dv_error *err) {
  if (!dv_engine_module_open(name, err)) return NULL;
  void *found = dlsym(module_slot_of(name)->handle, symbol);
  if (!found) dv_fail(err, DV_EINPUT, "%s: no %s in its module", name, symbol);
  return found;
}

const char *dv_engine_module_version(const char *name) {
  dv_error err;
  const dv_module_calls *m = dv_engine_module_open(name, &err);
  return m ? m->version() : "not available";
}

/* an engine made by a module, with the module that made it */
typedef struct module_engine {
  const dv_module_calls *ops;
  void *engine;
} module_engine;

void *dv_engine_module_alloc(const char *name, const dv_scenario *sc, dv_error *err) {
  const dv_module_calls *m = dv_engine_module_open(name, err);
  if (!m) return NULL;
  module_engine *e = malloc(sizeof *e);
  if (!e) return dv_fail(err, DV_ESYSTEM, "out of memory"), NULL;
  e->ops = m;
  e->engine = m->alloc(sc, err);
  if (e->engine) return e;
  free(e);
  return NULL;
}

int dv_engine_module_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  module_engine *e = p;
  return e->ops->reset(e->engine, state, err);
}

int dv_engine_module_advance(void *p, double t, dv_sample *out, dv_error *err) {
  module_engine *e = p;
  return e->ops->advance(e->engine, t, out, err);
}

void dv_engine_module_stats(const void *p, dv_engine_stats *out) {
  const module_engine *e = p;
  e->ops->stats(e->engine, out);
}

void dv_engine_module_free(void *p) {
  module_engine *e = p;
  if (!e) return;
  e->ops->free(e->engine);
  free(e);
}
