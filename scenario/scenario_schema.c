/* scenario_schema: reading, checking and storing one setting by its spec. */
#include "scenario_schema.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_format.h"
#include "scenario_number.h"

const char *dv_setting_choice(const dv_setting_spec *spec, size_t i) {
  if (spec->choice_at) return spec->choice_at(i);
  if (!spec->choices) return NULL;
  for (size_t k = 0; k < i; k++)
    if (!spec->choices[k]) return NULL;
  return spec->choices[i];
}

const dv_setting_spec *dv_settings_find(const dv_settings_section *section, const char *key) {
  for (size_t i = 0; i < section->nspecs; i++)
    if (!strcmp(section->specs[i].key, key)) return &section->specs[i];
  return NULL;
}

/* every digit that tells two bounds or a value and its bound apart */
void dv_setting_range_text(const dv_setting_spec *spec, char *buf, size_t size) {
  char lo[DV_FORMAT_SIZE], hi[DV_FORMAT_SIZE];
  dv_format_double(spec->lo, lo, sizeof lo);
  dv_format_double(spec->hi, hi, sizeof hi);
  snprintf(buf, size, "%s%s, %s%s", spec->flags & DV_SETTING_OPEN_LO ? "(" : "[", lo, hi,
           spec->flags & DV_SETTING_OPEN_HI ? ")" : "]");
}

int dv_setting_store(const dv_setting_spec *spec, double v, void *block, char *what, size_t size) {
  char range[96];
  const int ok_lo = spec->flags & DV_SETTING_OPEN_LO ? v > spec->lo : v >= spec->lo;
  const int ok_hi = spec->flags & DV_SETTING_OPEN_HI ? v < spec->hi : v <= spec->hi;
  if (spec->type == DV_SETTING_TEXT) return snprintf(what, size, "not a number"), -1;
  if (spec->type != DV_SETTING_REAL && v != floor(v))
    return snprintf(what, size, "%g is not a whole number", v), -1;
  if (spec->type == DV_SETTING_CHOICE && !(v >= 0.0 && dv_setting_choice(spec, (size_t)v)))
    return snprintf(what, size, "%g is not the index of a choice", v), -1;
  if (spec->type != DV_SETTING_CHOICE && (!ok_lo || !ok_hi)) {
    char value[DV_FORMAT_SIZE];
    dv_setting_range_text(spec, range, sizeof range);
    dv_format_double(v, value, sizeof value);
    return snprintf(what, size, "%s is outside %s", value, range), -1;
  }
  char *field = (char *)block + spec->offset;
  if (spec->type == DV_SETTING_REAL)
    *(double *)field = v;
  else
    *(int *)field = (int)v;
  return 0;
}

int dv_setting_parse(const dv_setting_spec *spec, const char *text, void *block, char *what,
                     size_t size) {
  double v;
  if (spec->type == DV_SETTING_TEXT) {
    if (strlen(text) >= spec->size)
      return snprintf(what, size, "longer than %zu characters", spec->size - 1), -1;
    memcpy((char *)block + spec->offset, text, strlen(text) + 1);
    return 0;
  }
  if (spec->type == DV_SETTING_CHOICE) {
    const char *name;
    for (size_t i = 0; (name = dv_setting_choice(spec, i)); i++)
      if (!strcmp(name, text)) return dv_setting_store(spec, (double)i, block, what, size);
    int n = snprintf(what, size, "'%.60s' is not one of ", text);
    for (size_t i = 0; (name = dv_setting_choice(spec, i)) && n > 0 && (size_t)n < size; i++)
      n += snprintf(what + n, size - (size_t)n, "%s%s", i ? ", " : "", name);
    return -1;
  }
  if (dv_scenario_parse_number(text, &v))
    return snprintf(what, size,
                    "not a number: '%.60s' (a finite number, or [NUMBER *] pi [/ NUMBER])", text),
           -1;
  return dv_setting_store(spec, v, block, what, size);
}

double dv_setting_value(const dv_setting_spec *spec, const void *block) {
  const char *field = (const char *)block + spec->offset;
  switch (spec->type) {
    case DV_SETTING_REAL:
      return *(const double *)field;
    case DV_SETTING_INT:
    case DV_SETTING_CHOICE:
      return *(const int *)field;
    default:
      return NAN;
  }
}

void dv_settings_defaults(const dv_settings_section *section, void *block) {
  for (size_t i = 0; i < section->nspecs; i++) {
    const dv_setting_spec *sp = &section->specs[i];
    char *field = (char *)block + sp->offset;
    if (sp->type == DV_SETTING_TEXT)
      field[0] = '\0';
    else if (sp->type == DV_SETTING_REAL)
      *(double *)field = sp->def;
    else /* a whole number derived from the scene (NAN): 0 until derived */
      *(int *)field = isnan(sp->def) ? 0 : (int)sp->def;
  }
}
