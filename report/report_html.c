/* report_html: what the suite's matrix and a scenario's page both write (report_suite_internal.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "report_escape.h"
#include "report_suite_internal.h"
#include "run_verdict.h"

#define PATH_CAP 4096

void dvs_put_num(FILE *fp, const char *pre, const cJSON *v, const char *post) {
  if (cJSON_IsNumber(v) && isfinite(v->valuedouble))
    fprintf(fp, "%s%.3g%s", pre, v->valuedouble, post);
  else
    fprintf(fp, "%s&#8211;%s", pre, post);
}

void dvs_put_url(FILE *fp, const char *pre, const char *dir, const char *name, const char *post) {
  char url[PATH_CAP];
  if (dir)
    snprintf(url, sizeof url, "%s/%s", dir, name);
  else
    snprintf(url, sizeof url, "%s", name);
  fputs(pre, fp);
  for (const unsigned char *p = (const unsigned char *)url; *p; p++) {
    const int plain = (*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') ||
                      (*p >= '0' && *p <= '9') || strchr("-._~/", *p);
    fprintf(fp, plain ? "%c" : "%%%02X", *p);
  }
  fputs(post, fp);
}

int dvs_safe_name(const char *s) {
  return s && *s && !strchr(s, '/') && strcmp(s, ".") && strcmp(s, "..");
}

int dvs_file_exists(const char *out_dir, const char *dir, const char *name) {
  char path[PATH_CAP];
  struct stat st;
  if (!dvs_safe_name(name)) return 0;
  if (snprintf(path, sizeof path, "%s/%s/%s", out_dir, dir, name) >= (int)sizeof path) return 0;
  return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

const cJSON *dvs_deciding_limit(const cJSON *eng) {
  const cJSON *l, *worst = NULL;
  cJSON_ArrayForEach(l, item(eng, "limits")) {
    const cJSON *m = item(l, "margin");
    if (cJSON_IsNumber(m) && isfinite(m->valuedouble) &&
        (!worst || m->valuedouble > item(worst, "margin")->valuedouble))
      worst = l;
  }
  return worst;
}

dvs_class dvs_class_of(const cJSON *eng) {
  const char *outcome = text(eng, "outcome");
  if (!strcmp(outcome, dv_run_verdict_name(DV_VERDICT_NOT_JUDGED)) ||
      !strcmp(outcome, dv_run_verdict_name(DV_VERDICT_OUTSIDE_VALIDITY)))
    return DVS_NOT_JUDGED;
  return engine_pass(eng) ? DVS_PASS : DVS_FAIL;
}

const char *const dvs_class_names[DVS_NCLASSES] = {
    [DVS_PASS] = "pass", [DVS_FAIL] = "fail", [DVS_NOT_JUDGED] = "not judged",
    [DVS_ERROR] = "error"};

/* the CSS class of each verdict class */
const char *const dvs_class_css[DVS_NCLASSES] = {
    [DVS_PASS] = "pass", [DVS_FAIL] = "fail", [DVS_NOT_JUDGED] = "nj", [DVS_ERROR] = "err"};

void dvs_put_verdict_words(FILE *fp, const cJSON *eng) {
  const dvs_class k = dvs_class_of(eng);
  const cJSON *worst = dvs_deciding_limit(eng);
  const char *outcome = text(eng, "outcome");
  if (worst && (k == DVS_PASS || (k == DVS_FAIL && !strcmp(outcome, "exceeds tolerance")))) {
    fputs(k == DVS_PASS ? "passes" : "fails", fp);
    const cJSON *v = item(worst, "value"), *lim = item(worst, "limit");
    dv_report_escape_put(fp, ": ", worst->string, 0, " ");
    dvs_put_num(fp, "", v, k == DVS_PASS ? " &#8804; " : " &gt; ");
    dvs_put_num(fp, "", lim, "");
  } else {
    fputs(k == DVS_PASS ? "passes: " : k == DVS_FAIL ? "fails: " : "", fp);
    dv_report_escape(fp, *outcome ? outcome : "no outcome", 0);
  }
}
