/* scenario_schema: one table per section describes every key a scenario
 * file may hold: the core sections ([scenario], [disk], [initial]) here, and
 * each engine's [engines.NAME] in that engine's own file. The same tables
 * drive parsing, validation, defaults, --set, `diskval engines` and the
 * settings written beside every run.
 */
#ifndef DV_SCENARIO_SCHEMA_H
#define DV_SCENARIO_SCHEMA_H

#include <stddef.h>

#include "dv_error.h"

typedef enum dv_setting_type {
  DV_SETTING_REAL = 0, /* double */
  DV_SETTING_INT,      /* int, a whole number in range */
  DV_SETTING_CHOICE,   /* int: the index of one of the names */
  DV_SETTING_TEXT,     /* char[size] */
} dv_setting_type;

enum {
  DV_SETTING_REQUIRED = 1, /* no default: the file must give it */
  DV_SETTING_OPEN_LO = 2,  /* lo < value, not lo <= value */
  DV_SETTING_OPEN_HI = 4,  /* value < hi, not value <= hi */
};

typedef struct dv_setting_spec {
  const char *key;
  dv_setting_type type;
  size_t offset;                      /* of the value in its section's block */
  size_t size;                        /* DV_SETTING_TEXT: the buffer's size */
  int flags;                          /* DV_SETTING_* */
  double def, lo, hi;                 /* default (NAN: the section's check computes it) and range */
  const char *const *choices;         /* DV_SETTING_CHOICE: NULL-terminated names */
  const char *(*choice_at)(size_t i); /* or names kept by another module (NULL past the end) */
  const char *unit;                   /* "s", "m", "N", "" */
  const char *doc;                    /* one line */
} dv_setting_spec;

struct dv_scenario;

/* a problem found by a section's check: the key it is reported at */
typedef struct dv_setting_issue {
  const char *section; /* "initial", or an engine's name for [engines.NAME] */
  const char *key;
  char what[300];
} dv_setting_issue;

typedef struct dv_settings_section {
  const char *name; /* "disk"; for an engine, its name: the section is [engines.NAME] */
  const dv_setting_spec *specs;
  size_t nspecs;
  size_t size; /* of the block the values live in (an engine's settings struct) */
  /* after every section is read: derived values and checks across keys;
   * 0, or -1 with issue filled in. NULL: none. */
  int (*check)(struct dv_scenario *sc, void *block, dv_setting_issue *issue);
} dv_settings_section;

/* the name of choice i of spec, or NULL past the last */
const char *dv_setting_choice(const dv_setting_spec *spec, size_t i);

/* the spec of key in section, or NULL */
const dv_setting_spec *dv_settings_find(const dv_settings_section *section, const char *key);

/* parse text as the value of spec into its place in block: strict numbers
 * (the whole text, finite, in range), whole numbers for DV_SETTING_INT, a
 * listed name for a choice. 0, or -1 with what describing the problem. */
int dv_setting_parse(const dv_setting_spec *spec, const char *text, void *block, char *what,
                     size_t size);

/* store v (a choice's index for DV_SETTING_CHOICE) after the same checks */
int dv_setting_store(const dv_setting_spec *spec, double v, void *block, char *what, size_t size);

/* the value in block as a number (a choice's index); NAN for text */
double dv_setting_value(const dv_setting_spec *spec, const void *block);

/* every key of section at its default (text empty, computed ones NAN) */
void dv_settings_defaults(const dv_settings_section *section, void *block);

/* "[lo, hi]", "(lo, hi)", ... for messages and documentation */
void dv_setting_range_text(const dv_setting_spec *spec, char *buf, size_t size);

#endif
