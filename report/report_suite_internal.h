/* report_suite_internal: what the suite's writers and the pages share (not public API).
 *
 * A suite's scenarios as read back from their report.json (schema in
 * report_format.h), and the accessors that tolerate any member missing.
 */
#ifndef DV_REPORT_SUITE_INTERNAL_H
#define DV_REPORT_SUITE_INTERNAL_H

#include <cjson/cJSON.h>
#include <stddef.h>
#include <stdio.h>

#include "dv_error.h"

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

/* read and parse out_dir/dir/report.json into e; failures are recorded in e->error */
void dvs_load_entry(const char *out_dir, const char *dir, dvs_entry *e);

/* the suite's index.html: its summary and the scenario x engine matrix */
void dvs_write_matrix(FILE *fp, const char *out_dir, const dvs_entry *es, size_t n, int pass);

/* out_dir/e->dir/index.html, the scenario's own page (written atomically) */
int dvs_write_page(const char *out_dir, const dvs_entry *e, dv_error *err);

/* a verdict as a person reads it: the colour of a cell, a count in the summary */
typedef enum dvs_class { DVS_PASS, DVS_FAIL, DVS_NOT_JUDGED, DVS_ERROR, DVS_NCLASSES } dvs_class;
extern const char *const dvs_class_names[DVS_NCLASSES]; /* "pass", "fail", "not judged", "error" */
extern const char *const dvs_class_css[DVS_NCLASSES];   /* the pages' CSS class of each */

/* engine eng's class: not judged by its outcome, else pass or fail by its "pass" */
dvs_class dvs_class_of(const cJSON *eng);

/* the limit of eng that decided: the judged metric nearest (or furthest over)
 * its limit, the largest value / limit of its "limits"; NULL when none has one */
const cJSON *dvs_deciding_limit(const cJSON *eng);

/* the verdict in a few words: "fails: theta_turning_err 0.043 > 0.01",
 * "passes: path_max_err 0.0003 <= 0.01", "fails: diverged", "not judged" */
void dvs_put_verdict_words(FILE *fp, const cJSON *eng);

/* pre, number v with %.3g (an en dash when absent or not finite), post */
void dvs_put_num(FILE *fp, const char *pre, const cJSON *v, const char *post);

/* pre, the relative URL dir/name (name alone for a NULL dir) percent-encoded ('/' kept), post */
void dvs_put_url(FILE *fp, const char *pre, const char *dir, const char *name, const char *post);

/* a file name that stays inside its scenario dir */
int dvs_safe_name(const char *s);

/* out_dir/dir/name is a regular file (name a safe one) */
int dvs_file_exists(const char *out_dir, const char *dir, const char *name);

#endif
