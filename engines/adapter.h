/* adapter: an engine outside diskval's build, run as a child process
 * (docs/adapters.md; DESIGN section 8).
 *
 * An adapter's folder holds manifest.ini; dv_adapter_load reads it into a
 * dv_adapter, whose tables (settings, search, contact knobs, step models) make
 * it an engine like the linked ones. The registry (dv_engine.c) loads every
 * adapter it finds once per process; engine_adapter.c runs them.
 */
#ifndef DV_ADAPTER_H
#define DV_ADAPTER_H

#include <stddef.h>

#include "dv_engine.h"
#include "engine_choose.h"

#define DV_ADAPTER_MAX_SETTINGS 24 /* 8 bytes a value: within DV_SETTINGS_BYTES */
#define DV_ADAPTER_MAX_CHOICES 8
#define DV_ADAPTER_MAX_EXTRA 6
#define DV_ADAPTER_NAME 32
#define DV_ADAPTER_PROTOCOL 1
#define DV_ADAPTER_HALF_KEY "half_thickness"

/* one setting as the manifest declares it */
typedef struct dv_adapter_setting {
  char key[DV_ADAPTER_NAME];
  char unit[16];
  char doc[320];
  char names[DV_ADAPTER_MAX_CHOICES][DV_ADAPTER_NAME]; /* a choice's values */
  const char *choices[DV_ADAPTER_MAX_CHOICES + 1];
} dv_adapter_setting;

typedef struct dv_adapter {
  char name[DV_ADAPTER_NAME];
  char description[200];
  char dir[1024];     /* the adapter's folder, absolute */
  char command[256];  /* words: the first is looked up on PATH */
  char requires[512]; /* paths relative to dir that must exist */
  double timeout;     /* s without an answer: hung */
  double stand_in;    /* m: the half-thickness modelled for a thin scene */
  char missing[256];  /* "": available; else why not */
  /* roles */
  char step_key[DV_ADAPTER_NAME], friction_key[DV_ADAPTER_NAME];
  char choice_key[DV_ADAPTER_NAME], softness_key[DV_ADAPTER_NAME];
  /* the settings, each 8 bytes of the block at its index */
  size_t nsettings;
  dv_adapter_setting setting[DV_ADAPTER_MAX_SETTINGS];
  dv_setting_spec specs[DV_ADAPTER_MAX_SETTINGS];
  /* step models, by the choice key's value (one where there is none) */
  dv_step_model models[DV_ADAPTER_MAX_CHOICES + 1];
  unsigned model_given; /* bit v: [model.VALUE] was given */
  /* attribution's further knobs */
  size_t nextra;
  char extra_what[DV_ADAPTER_MAX_EXTRA][128];
  char extra_key[DV_ADAPTER_MAX_EXTRA][DV_ADAPTER_NAME];
  char extra_value[DV_ADAPTER_MAX_EXTRA][DV_ADAPTER_NAME];
  dv_engine_extra_knob extra[DV_ADAPTER_MAX_EXTRA];
  /* the tables it is an engine by */
  dv_settings_section section;
  dv_engine_search search;
  dv_engine_contact contact;
  dv_engine_knobs knobs;
  dv_engine_type type;
  char version[160]; /* the engine's own words, once asked */
} dv_adapter;

/* read dir/manifest.ini into a (dir absolute). 0, or -1 with err "FILE:LINE: key: what" */
int dv_adapter_load(const char *dir, dv_adapter *a, dv_error *err);

/* every adapter found (the source tree's adapters/, then DISKVAL_ADAPTERS'
 * folders), each with its type filled; a manifest that cannot be read is left
 * out, its error kept for dv_adapter_problems. Loaded once per process. */
size_t dv_adapters(const dv_adapter *const **out);

/* the manifests that could not be read, one line each ("" when none) */
const char *dv_adapter_problems(void);

/* the adapter behind engine type t, or NULL for a linked engine */
const dv_adapter *dv_adapter_of(const dv_engine_type *t);

/* the scene's lines for a's run of sc (up to and including "start") into
 * buf; 0, or -1 with err (the text did not fit, or a setting is missing) */
int dv_adapter_scene_text(const dv_adapter *a, const dv_scenario *sc, const double *state,
                          char *buf, size_t size, dv_error *err);

/* [engines.NAME]'s check: the step and choice from a probe (engine_choose.h),
 * the half-thickness and friction from the scene, each with its reason */
int dv_adapter_check(const dv_adapter *a, dv_scenario *sc, void *block, dv_setting_issue *issue);

/* fill a's type from its tables and the methods of slot i (engine_adapter.c) */
void dv_adapter_make_type(dv_adapter *a, size_t i);

#endif
