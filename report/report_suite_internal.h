/* report_suite_internal: what report_suite.c shares with report_suite_junit.c (not public API).
 *
 * A suite's scenarios as read back from their report.json (schema in
 * report_format.h), and the accessors that tolerate any member missing.
 */
#ifndef DV_REPORT_SUITE_INTERNAL_H
#define DV_REPORT_SUITE_INTERNAL_H

#include <cjson/cJSON.h>
#include <stddef.h>
#include <stdio.h>

/* one scenario: its parsed report, or why it has none usable */
typedef struct dvs_entry {
  const char *dir;      /* relative to out_dir */
  const char *name;     /* the report's "scenario", else dir */
  cJSON *report;        /* parsed report.json (may be set even on error) */
  const cJSON *engines; /* its "engines" object, NULL on error */
  char error[768];      /* "" when the report is usable */
} dvs_entry;

/* member key of object o, NULL when absent or o is not an object */
static inline const cJSON *item(const cJSON *o, const char *key) {
  return cJSON_IsObject(o) ? cJSON_GetObjectItemCaseSensitive(o, key) : NULL;
}

/* string member key of o, "" when absent */
static inline const char *text(const cJSON *o, const char *key) {
  const cJSON *s = item(o, key);
  return cJSON_IsString(s) && s->valuestring ? s->valuestring : "";
}

/* an engine passed only when its report says "pass": true */
static inline int engine_pass(const cJSON *eng) {
  return cJSON_IsTrue(item(eng, "pass"));
}

/* add to *runs the engine runs of the n scenarios of es, to *failing those
 * that did not pass, to *errors the scenarios without a usable report */
void dvs_tally(const dvs_entry *es, size_t n, int *runs, int *failing, int *errors);

/* which body's reference judged engine eng ("vs cylinder h 1.165 mm", "vs
 * thin disk"): its "judged", else from its reference's half-thickness */
void dvs_judged_words(const cJSON *eng, char *out, size_t size);

/* the JUnit XML of the n scenarios of es */
void dvs_write_junit(FILE *fp, const dvs_entry *es, size_t n);

#endif
