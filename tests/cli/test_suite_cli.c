/* test_suite_cli: diskval suite end to end on a small scenario set.
 *   - exit 0, summary.json parses back, one JUnit test case per scenario x
 *     engine, index.html references only files that exist;
 *   - the JUnit XML has a test suite per scenario, valid against
 *     tests/fixtures/junit.xsd; every test case, passing too, carries every
 *     metric of its report with its limit, margin and source and the
 *     reference; a scenario's time counts its reference runs, which are
 *     measured (report.json); summary.json has each run's limits and reference;
 *   - an impossible tolerance: exit 1, the JUnit failure names the scenario;
 *   - a broken scenario file: exit 2 and no output directory at all.
 * (The same inputs twice, identical reports: the test determinism.)
 * usage: test_suite_cli DISKVAL SCENARIO_DIR WORK_DIR (WORK_DIR is replaced) */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include "dv_test.h"

static const char *diskval, *scenarios, *work;

static char *slurp(const char *path) {
  FILE *fp = fopen(path, "rb");
  if (!fp) return NULL;
  fseek(fp, 0, SEEK_END);
  const long n = ftell(fp);
  rewind(fp);
  char *buf = malloc((size_t)n + 1);
  if (buf && fread(buf, 1, (size_t)n, fp) == (size_t)n) buf[n] = '\0';
  fclose(fp);
  return buf;
}

/* run a shell command; its exit status */
static int run(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static int run(const char *fmt, ...) {
  char cmd[4096];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(cmd, sizeof cmd, fmt, ap);
  va_end(ap);
  const int st = system(cmd);
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

static int exists(const char *path) {
  struct stat st;
  return stat(path, &st) == 0;
}

static size_t count(const char *text, const char *needle) {
  size_t n = 0;
  for (const char *p = text; p && (p = strstr(p, needle)); p++) n++;
  return n;
}

/* the number attribute name="..." of the first element at or after p */
static double attr_num(const char *p, const char *name) {
  char key[64];
  snprintf(key, sizeof key, " %s=\"", name);
  const char *a = p ? strstr(p, key) : NULL;
  return a ? atof(a + strlen(key)) : NAN;
}

/* the JUnit XML and summary.json of the good suite in out against its reports */
static void check_numbers(const char *out, const char *xml) {
  static const char *const names[] = {"falling", "upright_stable"};
  char path[2048], head[256];
  snprintf(path, sizeof path, "%s/summary.json", out);
  char *text = slurp(path);
  cJSON *summary = text ? cJSON_Parse(text) : NULL;
  CHECK(count(xml, "<testsuite ") == 2, "%zu test suites, want one per scenario",
        count(xml, "<testsuite "));
  for (int i = 0; i < 2; i++) {
    snprintf(path, sizeof path, "%s/%s/report.json", out, names[i]);
    char *rtext = slurp(path);
    cJSON *report = rtext ? cJSON_Parse(rtext) : NULL, *eng;
    const cJSON *ref = cJSON_GetObjectItem(report, "reference");
    const double ref_wall = cJSON_GetNumberValue(cJSON_GetObjectItem(ref, "wall_s"));
    CHECK(ref_wall > 0, "%s: the reference's wall time %g", names[i], ref_wall);
    snprintf(head, sizeof head, "<testsuite name=\"%s\"", names[i]);
    const char *suite = strstr(xml, head);
    double cases = 0;
    cJSON_ArrayForEach(eng, cJSON_GetObjectItem(report, "engines")) {
      snprintf(head, sizeof head, "<testcase classname=\"%s\" name=\"%s\"", names[i], eng->string);
      const char *tc = strstr(xml, head), *end = tc ? strstr(tc, "</testcase>") : NULL;
      CHECK(tc && end, "%s/%s: no test case with an end", names[i], eng->string);
      if (!tc || !end) continue;
      cases += attr_num(tc, "time");
      const cJSON *l;
      cJSON_ArrayForEach(l, cJSON_GetObjectItem(eng, "limits")) {
        char prop[160];
        for (int k = 0; k < 3; k++) {
          snprintf(prop, sizeof prop, "<property name=\"%s%s\" value=", l->string,
                   k == 0   ? ""
                   : k == 1 ? ".limit"
                            : ".margin");
          const char *at = strstr(tc, prop);
          CHECK(at && at < end, "%s/%s: no %s", names[i], eng->string, prop);
        }
      }
      CHECK(strstr(tc, "<property name=\"reference\" value=\"reduced, thin disk"),
            "%s/%s: the reference", names[i], eng->string);
      const cJSON *s = NULL, *e;
      cJSON_ArrayForEach(
          s, cJSON_GetObjectItem(
                 summary,
                 "scenarios")) if (!strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(s, "scenario")),
                                           names[i])) break;
      e = cJSON_GetObjectItem(cJSON_GetObjectItem(s, "engines"), eng->string);
      CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(e, "limits")) ==
                    cJSON_GetArraySize(cJSON_GetObjectItem(eng, "limits")) &&
                cJSON_IsObject(cJSON_GetObjectItem(e, "reference")),
            "summary.json: %s/%s lacks its limits or reference", names[i], eng->string);
    }
    /* the suite's time: its test cases and its reference runs (printed to 1e-6 s) */
    const double total = attr_num(suite, "time");
    CHECK(total >= cases + ref_wall - 1e-5, "%s: suite time %g < cases %g + reference %g", names[i],
          total, cases, ref_wall);
    cJSON_Delete(report);
    free(rtext);
  }
  cJSON_Delete(summary);
  free(text);
}

static void check_good_suite(void) {
  char out[1024], path[2048];
  snprintf(out, sizeof out, "%s/good", work);
  int code = run("%s suite %s/falling.ini %s/upright_stable.ini --out %s --jobs 2 >/dev/null",
                 diskval, scenarios, scenarios, out);
  CHECK(code == 0, "suite exit %d", code);
  snprintf(path, sizeof path, "%s/summary.json", out);
  char *text = slurp(path);
  cJSON *summary = text ? cJSON_Parse(text) : NULL;
  CHECK(summary && cJSON_IsTrue(cJSON_GetObjectItem(summary, "pass")), "summary.json: %s", path);
  const cJSON *scenes = cJSON_GetObjectItem(summary, "scenarios");
  CHECK(cJSON_GetArraySize(scenes) == 2, "two scenarios");
  /* a test case for each engine run of each scene, every contact engine by default */
  int runs = 0;
  for (int k = 0; k < cJSON_GetArraySize(scenes); k++)
    runs += cJSON_GetArraySize(cJSON_GetObjectItem(cJSON_GetArrayItem(scenes, k), "engines"));
  CHECK(runs >= 4, "%d engine runs in two scenes", runs);
  cJSON_Delete(summary);
  free(text);
  snprintf(path, sizeof path, "%s/junit.xml", out);
  text = slurp(path);
  CHECK(text && count(text, "<testcase ") == (size_t)runs && !strstr(text, "<failure"), "junit: %s", path);
  CHECK(run("command -v xmllint >/dev/null") != 0 ||
            run("xmllint --noout --schema %s/../tests/fixtures/junit.xsd %s", scenarios, path) == 0,
        "xmllint rejects %s", path);
  if (text) check_numbers(out, text);
  free(text);
  /* the matrix links each scenario's page; every src= of those pages exists */
  snprintf(path, sizeof path, "%s/index.html", out);
  text = slurp(path);
  size_t images = 0, pages = 0;
  char last[1024] = ""; /* a row links its page from every cell: each page once */
  for (const char *p = text; p && (p = strstr(p, "href=\"")); p += 6) {
    char page[1024], full[4096];
    const char *end = strchr(p + 6, '"');
    snprintf(page, sizeof page, "%.*s", end ? (int)(end - p - 6) : 0, p + 6);
    const size_t len = strlen(page);
    if (len < 11 || strcmp(page + len - 11, "/index.html") || !strcmp(page, last)) continue;
    snprintf(last, sizeof last, "%s", page);
    snprintf(full, sizeof full, "%s/%s", out, page);
    char *html = slurp(full);
    CHECK(html, "index.html links a missing page %s", page);
    pages++;
    page[len - 11] = '\0';
    for (const char *q = html; q && (q = strstr(q, "src=\"")); q += 5) {
      char file[1024];
      const char *qend = strchr(q + 5, '"');
      snprintf(file, sizeof file, "%.*s", qend ? (int)(qend - q - 5) : 0, q + 5);
      snprintf(full, sizeof full, "%s/%s/%s", out, page, file);
      CHECK(exists(full), "%s/index.html shows a missing file %s", page, file);
      images++;
    }
    free(html);
  }
  CHECK(pages >= 2 && images >= 8, "index.html links %zu pages showing %zu images", pages, images);
  free(text);
  /* the same inputs twice give identical reports: check_determinism.sh, over every
   * shipped scene (a second run of these two here doubled this test's 100 s) */
}

static void check_failing_suite(void) {
  char out[1024], scn[1024], path[2048];
  snprintf(scn, sizeof scn, "%s/impossible.ini", work);
  FILE *fp = fopen(scn, "w");
  if (fp) {
    fputs(
        "[scenario]\nname = impossible\nduration = 0.2\noutput_dt = 0.01\n"
        "[disk]\nradius = 0.1\nmass = 1\n[initial]\ntheta = 1.2\nphi_dot = 2\n"
        "[tolerance]\ntheta_max_err = 1e-30\n",
        fp);
    fclose(fp);
  }
  snprintf(out, sizeof out, "%s/failing", work);
  const int code = run("%s suite %s --out %s >/dev/null", diskval, scn, out);
  CHECK(code == 1, "impossible tolerance: exit %d, want 1", code);
  snprintf(path, sizeof path, "%s/junit.xml", out);
  char *text = slurp(path);
  CHECK(text && count(text, "<failure") >= 1 && strstr(text, "impossible") &&
            strstr(text, "theta_max_err"),
        "the JUnit XML does not name the failure");
  free(text);
}

static void check_broken_suite(void) {
  char out[1024], scn[1024];
  snprintf(scn, sizeof scn, "%s/broken.ini", work);
  run("sed 's/^mass = 1.0$/mass = -1/' %s/falling.ini > %s", scenarios, scn);
  snprintf(out, sizeof out, "%s/broken-out", work);
  const int code =
      run("%s suite %s/upright_stable.ini %s --out %s 2>/dev/null", diskval, scenarios, scn, out);
  CHECK(code == 2, "broken scenario: exit %d, want 2", code);
  CHECK(!exists(out), "a broken scenario left an output directory %s", out);
}

int main(int argc, char **argv) {
  if (argc != 4) return fprintf(stderr, "usage: test_suite_cli DISKVAL SCENARIO_DIR WORK_DIR\n"), 2;
  diskval = argv[1];
  scenarios = argv[2];
  work = argv[3];
  run("rm -rf %s && mkdir -p %s", work, work);
  check_good_suite();
  check_failing_suite();
  check_broken_suite();
  return TEST_RESULT();
}
