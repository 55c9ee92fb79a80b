/* dvs_write_junit: the suite's JUnit XML from the scenarios' report.json.
 *
 * One <testsuite> per scenario inside <testsuites>; per engine a <testcase>
 * whose <properties> carry every metric with its limit, margin and where the
 * limit came from, and the reference it was compared with, passing or not.
 * Times are real wall-clock seconds: a test case is its engine's run, a
 * scenario also counts its reference runs. Properties come first in a test
 * case, then <failure>, as pytest and Testmo write them; GitLab and Jenkins
 * read the rest and skip what they do not know.
 */
#include <math.h>
#include <string.h>

#include "report_escape.h"
#include "report_suite_internal.h"

/* a number or 0: what a missing timing field counts */
static double seconds(const cJSON *v) {
  return cJSON_IsNumber(v) && isfinite(v->valuedouble) && v->valuedouble > 0 ? v->valuedouble : 0.0;
}

/* wall-clock seconds of engine eng's run; reports without "wall_s": rate x window */
static double engine_seconds(const cJSON *report, const cJSON *eng) {
  if (item(eng, "wall_s")) return seconds(item(eng, "wall_s"));
  const cJSON *span = item(eng, "window_end");
  if (!cJSON_IsNumber(span)) span = item(report, "duration");
  const double w = seconds(item(eng, "wall_per_sim_s")) * seconds(span);
  return isfinite(w) ? w : 0.0;
}

/* wall-clock seconds of scenario e: its reference runs and every engine's */
static double scenario_seconds(const dvs_entry *e) {
  const cJSON *ref = item(e->report, "reference"), *eng;
  double t = seconds(item(ref, "wall_s")) + seconds(item(ref, "horizon_wall_s"));
  cJSON_ArrayForEach(eng, e->engines) {
    t += engine_seconds(e->report, eng);
    t += seconds(item(item(eng, "reference"), "wall_s")); /* its matched reference */
  }
  return t;
}

/* <property name="NAME" value="VALUE" /> */
static void put_property(FILE *fp, const char *name, const char *value) {
  dv_report_escape_put(fp, "        <property name=\"", name, 1, "\"");
  dv_report_escape_put(fp, " value=\"", value, 1, "\" />\n");
}

/* a number property (%.6g), "none" when absent: a limit that does not judge */
static void put_number(FILE *fp, const char *name, const cJSON *v) {
  char text[40] = "none";
  if (cJSON_IsNumber(v)) snprintf(text, sizeof text, "%.6g", v->valuedouble);
  put_property(fp, name, text);
}

/* the reference engine eng was compared with, in words */
static void reference_text(const cJSON *report, const cJSON *eng, char *out, size_t size) {
  const cJSON *ref = item(eng, "reference"), *top = item(report, "reference");
  const cJSON *h = item(ref ? ref : eng, ref ? "half_thickness" : "reference_half_thickness");
  if (!ref) ref = top; /* a report from before per-engine references: the thin one's engine */
  int k = snprintf(out, size, "%s", *text(ref, "engine") ? text(ref, "engine") : "?");
  if (k >= 0 && (size_t)k < size && cJSON_IsNumber(h) && h->valuedouble > 0)
    k += snprintf(out + k, size - (size_t)k, ", half-thickness %g m", h->valuedouble);
  else if (k >= 0 && (size_t)k < size)
    k += snprintf(out + k, size - (size_t)k, ", thin disk");
  if (k >= 0 && (size_t)k < size && *text(ref, "integrator"))
    snprintf(out + k, size - (size_t)k, ", %s rtol %g", text(ref, "integrator"),
             cJSON_IsNumber(item(ref, "rtol")) ? item(ref, "rtol")->valuedouble : NAN);
}

/* every metric of eng: value, limit, margin and its source; older reports: tolerances */
static void put_metrics(FILE *fp, const cJSON *eng) {
  const cJSON *limits = item(eng, "limits"), *l;
  char name[160];
  if (!cJSON_IsObject(limits)) {
    cJSON_ArrayForEach(l, item(eng, "tolerances")) {
      const cJSON *v = item(eng, l->string);
      put_number(fp, l->string, v);
      snprintf(name, sizeof name, "%s.limit", l->string);
      put_number(fp, name, l);
    }
    return;
  }
  cJSON_ArrayForEach(l, limits) {
    static const char *const parts[] = {"limit", "margin"};
    put_number(fp, l->string, item(l, "value"));
    for (size_t k = 0; k < 2; k++) {
      snprintf(name, sizeof name, "%s.%s", l->string, parts[k]);
      put_number(fp, name, item(l, parts[k]));
    }
    snprintf(name, sizeof name, "%s.limit_from", l->string);
    put_property(fp, name, text(l, "from"));
  }
}

/* the <properties> of engine eng's test case */
static void put_case_properties(FILE *fp, const cJSON *report, const cJSON *eng) {
  char ref[256];
  reference_text(report, eng, ref, sizeof ref);
  fputs("      <properties>\n", fp);
  put_property(fp, "outcome", text(eng, "outcome"));
  put_property(fp, "reference", ref);
  char body[48];
  dvs_judged_words(eng, body, sizeof body);
  put_property(fp, "judged", body);
  if (item(eng, "ran_with")) put_property(fp, "ran_with", text(eng, "ran_with"));
  put_metrics(fp, eng);
  put_number(fp, "window_end", item(eng, "window_end"));
  put_number(fp, "pointwise_end", item(eng, "pointwise_end"));
  const cJSON *hz = item(eng, "horizon");
  if (hz) {
    put_number(fp, "horizon.early_error", item(hz, "early_error"));
    put_number(fp, "horizon.amplification", item(hz, "amplification"));
  }
  if (item(eng, "decided")) put_property(fp, "decided", text(eng, "decided"));
  if (item(eng, "decided_why")) put_property(fp, "decided_why", text(eng, "decided_why"));
  fputs("      </properties>\n", fp);
}

/* the <failure> of engine eng: its listed failures, else how it ended */
static void put_failure(FILE *fp, const dvs_entry *e, const cJSON *eng) {
  const cJSON *list = item(eng, "failures"), *first = NULL, *f;
  cJSON_ArrayForEach(f, list) if (!first && cJSON_IsString(f)) first = f;
  if (first) {
    dv_report_escape_put(fp, "      <failure message=\"", first->valuestring, 1, "\">");
    int nf = 0;
    cJSON_ArrayForEach(f, list) if (cJSON_IsString(f))
        dv_report_escape_put(fp, nf++ ? "\n" : "", f->valuestring, 0, "");
  } else {
    char why[1024];
    snprintf(why, sizeof why, "%s: %s: %s%s%s", e->name, eng->string,
             *text(eng, "outcome") ? text(eng, "outcome") : "failed",
             *text(eng, "detail") ? ": " : "", text(eng, "detail"));
    dv_report_escape_put(fp, "      <failure message=\"", why, 1, "\">");
    dv_report_escape(fp, why, 0);
  }
  fputs("</failure>\n", fp);
}

/* the <testsuite> of an errored scenario: one test case carrying <error> */
static void put_errored(FILE *fp, const dvs_entry *e) {
  dv_report_escape_put(fp, "  <testsuite name=\"", e->name, 1, "\"");
  fputs(" tests=\"1\" failures=\"0\" errors=\"1\" time=\"0.000000\">\n", fp);
  dv_report_escape_put(fp, "    <testcase classname=\"", e->name, 1, "\"");
  dv_report_escape_put(fp, " name=\"", e->dir, 1, "\" time=\"0.000000\">\n");
  dv_report_escape_put(fp, "      <error message=\"", e->error, 1, "\">");
  dv_report_escape_put(fp, "", e->error, 0, "</error>\n    </testcase>\n  </testsuite>\n");
}

/* the <testsuite> of scenario e: its reference, then a test case per engine */
static void put_scenario(FILE *fp, const dvs_entry *e) {
  const cJSON *ref = item(e->report, "reference"), *eng;
  int tests = 0, failures = 0, errors = 0;
  dvs_tally(e, 1, &tests, &failures, &errors);
  dv_report_escape_put(fp, "  <testsuite name=\"", e->name, 1, "\"");
  fprintf(fp, " tests=\"%d\" failures=\"%d\" errors=\"0\" time=\"%.6f\">\n", tests, failures,
          scenario_seconds(e));
  fputs("    <properties>\n", fp);
  put_property(fp, "file", text(e->report, "file"));
  put_property(fp, "reference", text(ref, "engine"));
  put_property(fp, "reference.integrator", text(ref, "integrator"));
  put_number(fp, "reference.rtol", item(ref, "rtol"));
  put_property(fp, "reference.outcome", text(ref, "outcome"));
  put_number(fp, "reference.t_end", item(ref, "t_end"));
  put_number(fp, "reference.horizon", item(ref, "horizon"));
  const cJSON *amp = item(ref, "amplification");
  if (amp) {
    put_property(fp, "reference.amplification", text(amp, "words"));
    put_number(fp, "reference.amplification.nudge", item(amp, "nudge"));
  }
  fputs("    </properties>\n", fp);
  cJSON_ArrayForEach(eng, e->engines) {
    dv_report_escape_put(fp, "    <testcase classname=\"", e->name, 1, "\"");
    dv_report_escape_put(fp, " name=\"", eng->string, 1, "\"");
    fprintf(fp, " time=\"%.6f\">\n", engine_seconds(e->report, eng));
    put_case_properties(fp, e->report, eng);
    if (!engine_pass(eng)) put_failure(fp, e, eng);
    fputs("    </testcase>\n", fp);
  }
  fputs("  </testsuite>\n", fp);
}

void dvs_write_junit(FILE *fp, const dvs_entry *es, size_t n) {
  int tests = 0, failures = 0, errors = 0;
  double total = 0.0;
  dvs_tally(es, n, &tests, &failures, &errors);
  tests += errors; /* an errored scenario is a test case of its own */
  for (size_t i = 0; i < n; i++) total += scenario_seconds(&es[i]);
  fprintf(fp,
          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"diskval\" tests=\"%d\" "
          "failures=\"%d\" errors=\"%d\" time=\"%.6f\">\n",
          tests, failures, errors, total);
  for (size_t i = 0; i < n; i++)
    if (es[i].error[0])
      put_errored(fp, &es[i]);
    else
      put_scenario(fp, &es[i]);
  fputs("</testsuites>\n", fp);
}
