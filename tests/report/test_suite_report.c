/* test_suite_report: summary.json, index.html and the JUnit XML of a suite made of
 * hand-made reports: a passing scenario, a failing one, and three the harness
 * failed on (no report.json, a broken one, no directory at all).
 *
 * usage: test_suite_report FIXTURES_DIR [KEEP_OUT_DIR]
 * FIXTURES_DIR is tests/fixtures/suite; with KEEP_OUT_DIR the full suite's
 * output is written there and kept (e.g. for check_html_render.sh). */
#include <cjson/cJSON.h>
#include <dirent.h>
#include <errno.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "report_suite.h"
#include "dv_test.h"

/* the suite: fixture dirs, then two made here */
static const char *const all_dirs[] = {"rolling_pass", "falling_fail", "harness_failed", "garbage",
                                       "missing"};
enum { NALL = 5, NFIXTURES = 3, NERRORED = 3 };

/* the whole file at path as a string (caller frees), NULL if unreadable */
static char *slurp(const char *path) {
  FILE *fp = fopen(path, "rb");
  char *buf = NULL;
  long len;
  if (!fp) return NULL;
  if (fseek(fp, 0, SEEK_END) == 0 && (len = ftell(fp)) >= 0 && fseek(fp, 0, SEEK_SET) == 0 &&
      (buf = malloc((size_t)len + 1))) {
    if (fread(buf, 1, (size_t)len, fp) != (size_t)len) len = 0;
    buf[len] = '\0';
  }
  fclose(fp);
  return buf;
}

/* write text into path; 0 on success */
static int spit(const char *path, const char *text) {
  FILE *fp = fopen(path, "wb");
  if (!fp) return -1;
  const int bad = fputs(text, fp) < 0;
  return fclose(fp) || bad ? -1 : 0;
}

/* copy the regular files of directory src into new directory dst; 0 on success */
static int copy_dir(const char *src, const char *dst) {
  char from[4096], to[4096];
  DIR *d = opendir(src);
  struct dirent *de;
  int status = -1;
  if (!d || (mkdir(dst, 0777) && errno != EEXIST)) goto cleanup;
  while ((de = readdir(d))) {
    if (de->d_name[0] == '.') continue;
    snprintf(from, sizeof from, "%s/%s", src, de->d_name);
    snprintf(to, sizeof to, "%s/%s", dst, de->d_name);
    char *text = slurp(from);
    const int bad = !text || spit(to, text);
    free(text);
    if (bad) goto cleanup;
  }
  status = 0;
cleanup:
  if (d) closedir(d);
  return status;
}

/* the suite's out dir: the fixtures copied into dir, plus a broken report */
static int prepare(const char *fixtures, const char *dir) {
  char src[4096], dst[4096];
  for (int i = 0; i < NFIXTURES; i++) {
    snprintf(src, sizeof src, "%s/%s", fixtures, all_dirs[i]);
    snprintf(dst, sizeof dst, "%s/%s", dir, all_dirs[i]);
    if (copy_dir(src, dst)) return -1;
  }
  snprintf(dst, sizeof dst, "%s/garbage", dir);
  if (mkdir(dst, 0777) && errno != EEXIST) return -1;
  snprintf(dst, sizeof dst, "%s/garbage/report.json", dir);
  return spit(dst, "{\"scenario\": \"garbage\", \"engines\": {\"mujoco\": ");
}

static int ntemp; /* temporary files found by the walk below */

/* nftw visitor: count dv_io_file's leftovers (".diskval-tmp.PID.XXXXXX") */
static int find_temp(const char *path, const struct stat *st, int flag, struct FTW *ftw) {
  ntemp += strstr(path + ftw->base, ".diskval-tmp.") != NULL;
  return 0;
}

/* nftw visitor: remove everything, deepest first */
static int remove_one(const char *path, const struct stat *st, int flag, struct FTW *ftw) {
  return remove(path);
}

/* occurrences of needle in s */
static int count(const char *s, const char *needle) {
  int n = 0;
  for (const char *p = s; (p = strstr(p, needle)); p += strlen(needle)) n++;
  return n;
}

/* integer attribute attr of the first <tag ...>, -1 if absent */
static int attr_int(const char *s, const char *tag, const char *attr) {
  char key[64];
  const char *p = strstr(s, tag), *end = p ? strchr(p, '>') : NULL, *a;
  snprintf(key, sizeof key, " %s=\"", attr);
  if (!end || !(a = strstr(p, key)) || a > end) return -1;
  return atoi(a + strlen(key));
}

/* length of the XML entity at p ("&amp;", "&#39;", ...), 0 if not one */
static size_t entity_len(const char *p) {
  static const char *const named[] = {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"};
  for (size_t i = 0; i < sizeof named / sizeof *named; i++)
    if (!strncmp(p, named[i], strlen(named[i]))) return strlen(named[i]);
  size_t n = p[1] == '#' ? 2 : 0;
  while (n && p[n] >= '0' && p[n] <= '9') n++;
  return n > 2 && p[n] == ';' ? n + 1 : 0;
}

/* a tiny well-formedness check: balanced tags, quoted attributes, valid entities */
static int xml_ok(const char *s, const char *what) {
  char stack[32][32];
  int depth = 0;
  const char *p = s;
  while ((p = strpbrk(p, "<&"))) {
    if (*p == '&') {
      CHECK(entity_len(p), "%s: bad entity at byte %ld", what, (long)(p - s));
      p++;
      continue;
    }
    char quote = 0;
    const char *end = p + 1;
    for (; *end && (quote || *end != '>'); end++) {
      if (*end == '&' && !entity_len(end)) break;
      if (*end == '<') break;
      if (quote && *end == quote)
        quote = 0;
      else if (!quote && (*end == '"' || *end == '\''))
        quote = *end;
    }
    if (*end != '>') {
      CHECK(0, "%s: broken tag at byte %ld", what, (long)(p - s));
      return 0;
    }
    if (p[1] != '?' && p[1] != '!') {
      const int closing = p[1] == '/', empty = end[-1] == '/';
      const size_t len = strcspn(p + 1 + closing, " \t\n/>");
      char name[32];
      snprintf(name, sizeof name, "%.*s", (int)len, p + 1 + closing);
      if (closing) {
        if (!depth || strcmp(stack[depth - 1], name)) {
          CHECK(0, "%s: </%s> closes nothing open at byte %ld", what, name, (long)(p - s));
          return 0;
        }
        depth--;
      } else if (!empty) {
        if (depth == 32) return 0;
        snprintf(stack[depth++], sizeof stack[0], "%s", name);
      }
    }
    p = end + 1;
  }
  CHECK(depth == 0, "%s: <%s> left open", what, depth ? stack[depth - 1] : "");
  return depth == 0;
}

/* xmllint's verdict on path when it is installed, against schema unless NULL */
static void xmllint(const char *path, const char *schema) {
  char cmd[8400];
  if (strchr(path, '\'') || (schema && strchr(schema, '\'')) ||
      system("command -v xmllint >/dev/null 2>&1") != 0) {
    fprintf(stderr, "xmllint not run on %s\n", path);
    return;
  }
  snprintf(cmd, sizeof cmd, "xmllint --noout %s%s%s '%s'", schema ? "--schema '" : "",
           schema ? schema : "", schema ? "'" : "", path);
  CHECK(system(cmd) == 0, "xmllint rejects %s%s%s", path, schema ? " against " : "",
        schema ? schema : "");
}

/* the text from the test case of classname scenario, name engine to its end (caller frees) */
static char *junit_case(const char *xml, const char *scenario, const char *engine) {
  char head[256];
  snprintf(head, sizeof head, "<testcase classname=\"%s\" name=\"%s\"", scenario, engine);
  const char *p = strstr(xml, head), *end = p ? strstr(p, "</testcase>") : NULL;
  if (!end) return NULL;
  char *out = malloc((size_t)(end - p) + 1);
  if (out) snprintf(out, (size_t)(end - p) + 1, "%s", p);
  return out;
}

/* the JUnit XML of the full suite: a test suite per scenario, the numbers of every test case */
static void check_junit(const char *xml, const char *schema, const char *path, int engines,
                        int failing) {
  const int tests = engines + NERRORED;
  CHECK(attr_int(xml, "<testsuites ", "tests") == tests, "tests != %d", tests);
  CHECK(attr_int(xml, "<testsuites ", "failures") == failing, "failures != %d", failing);
  CHECK(attr_int(xml, "<testsuites ", "errors") == NERRORED, "errors != %d", NERRORED);
  CHECK(count(xml, "<testsuite ") == NALL, "%d test suites, want one per scenario",
        count(xml, "<testsuite "));
  CHECK(strstr(xml, "<testsuite name=\"steady_circle\" tests=\"2\" failures=\"0\" errors=\"0\""),
        "steady_circle's test suite");
  CHECK(strstr(xml, "<testsuite name=\"falling\" tests=\"2\" failures=\"1\" errors=\"0\""),
        "falling's test suite");
  CHECK(count(xml, "<testcase ") == tests, "%d test cases", count(xml, "<testcase "));
  CHECK(count(xml, "<failure ") == failing && count(xml, "<error ") == NERRORED, "verdicts");
  CHECK(strstr(xml, "name=\"harness_failed\"") && strstr(xml, "classname=\"falling\" name=\"ode\""),
        "test case names");
  CHECK(strstr(xml, "theta_max_err = 0.21 &gt; 0.05"), "failure text not escaped");
  CHECK(count(xml, "<property name=\"ran_with\" value=\"integrator implicit, timestep 8e-06 s\"") ==
            1,
        "the settings that ran, in the JUnit properties");
  /* real times: an engine's own run; a scenario's also counts its reference runs
   * (rolling_pass: reference 0.25 + horizon 0.5 + mujoco 0.1 and its matched
   * reference 0.05 + ode 0.25 s/s over its 2 s window, a report without wall_s) */
  CHECK(strstr(xml, "classname=\"steady_circle\" name=\"mujoco\" time=\"0.100000\""),
        "mujoco's own wall time");
  CHECK(strstr(xml,
               "name=\"steady_circle\" tests=\"2\" failures=\"0\" errors=\"0\" "
               "time=\"1.400000\""),
        "steady_circle's time leaves out its references");
  /* every engine's test case, passing or not, carries its numbers */
  static const char *const cases[][2] = {{"steady_circle", "mujoco"},
                                         {"steady_circle", "ode"},
                                         {"falling", "mujoco"},
                                         {"falling", "ode"}};
  for (size_t k = 0; k < 4; k++) {
    char *tc = junit_case(xml, cases[k][0], cases[k][1]);
    CHECK(tc && strstr(tc, "<properties>") &&
              strstr(tc, "<property name=\"theta_max_err\" value=") &&
              strstr(tc, "<property name=\"theta_max_err.limit\" value=") &&
              strstr(tc, "<property name=\"reference\" value="),
          "%s/%s: no metric, limit or reference property", cases[k][0], cases[k][1]);
    free(tc);
  }
  char *mj = junit_case(xml, "steady_circle", "mujoco");
  CHECK(
      mj && strstr(mj, "name=\"theta_max_err\" value=\"0.000123456\"") &&
          strstr(mj, "name=\"theta_max_err.limit\" value=\"0.01\"") &&
          strstr(mj, "name=\"theta_max_err.margin\" value=\"0.0123456\"") &&
          strstr(mj, "name=\"theta_max_err.limit_from\" value=\"default: 0.01 rad\"") &&
          strstr(mj, "name=\"path_max_err.limit_from\" value=\"[tolerance.mujoco] &lt;1%&gt;\"") &&
          strstr(mj, "name=\"path_hausdorff.limit\" value=\"none\"") &&
          strstr(mj,
                 "name=\"reference\" value=\"matched, half-thickness 0.005 m, cvode-bdf "
                 "rtol 1e-12\""),
      "steady_circle/mujoco: metric, limit, margin, source or reference wrong");
  CHECK(mj && strstr(mj, "<property name=\"outcome\" value=\"agrees\""),
        "steady_circle/mujoco: the outcome property");
  free(mj);
  char *fm = junit_case(xml, "falling", "mujoco"), *fo = junit_case(xml, "falling", "ode");
  CHECK(fm && strstr(fm, "<property name=\"outcome\" value=\"exceeds tolerance\""),
        "falling/mujoco: the outcome property");
  CHECK(fo && strstr(fo, "<property name=\"outcome\" value=\"ended by event\""),
        "falling/ode: the outcome property");
  free(fm);
  free(fo);
  char *od = junit_case(xml, "steady_circle", "ode");
  CHECK(od && strstr(od, "name=\"reference\" value=\"reduced, thin disk, cvode-bdf rtol 1e-12\"") &&
            strstr(od, "name=\"path_max_err.limit\" value=\"0.01\""),
        "steady_circle/ode: a report without limits or references");
  free(od);
  xml_ok(xml, "junit.xml");
  xmllint(path, schema);
}

/* every src= and href= of index.html in out names an existing file or anchor; returns #img */
static int check_refs(const char *out, const char *html) {
  int nimg = 0;
  for (const char *p = html; (p = strpbrk(p, "sh")); p++) {
    const int src = !strncmp(p, "src=\"", 5), href = !strncmp(p, "href=\"", 6);
    if (!src && !href) continue;
    const char *v = p + (src ? 5 : 6);
    char ref[1024], path[4096], id[1100];
    size_t n = 0;
    for (; *v && *v != '"' && n + 1 < sizeof ref; v++) {
      unsigned c;
      if (*v == '%' && sscanf(v + 1, "%2x", &c) == 1)
        ref[n++] = (char)c, v += 2;
      else
        ref[n++] = *v;
    }
    ref[n] = '\0';
    nimg += src;
    CHECK(!strstr(ref, "://") && strncmp(ref, "//", 2), "external reference %s", ref);
    if (ref[0] == '#') {
      snprintf(id, sizeof id, "id=\"%s\"", ref + 1);
      CHECK(strstr(html, id), "anchor %s has no target", ref);
      continue;
    }
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", out, ref);
    CHECK(stat(path, &st) == 0 && S_ISREG(st.st_mode), "index.html references missing %s", ref);
  }
  return nimg;
}

/* engines, failing engines and listed plots that exist in the fixture reports */
static void fixture_counts(const char *fixtures, int *engines, int *failing, int *plots) {
  char path[4096];
  struct stat st;
  *engines = *failing = *plots = 0;
  for (int i = 0; i < NFIXTURES; i++) {
    snprintf(path, sizeof path, "%s/%s/report.json", fixtures, all_dirs[i]);
    char *text = slurp(path);
    cJSON *r = text ? cJSON_Parse(text) : NULL, *eng;
    cJSON_ArrayForEach(eng, cJSON_GetObjectItem(r, "engines")) {
      ++*engines;
      *failing += !cJSON_IsTrue(cJSON_GetObjectItem(eng, "pass"));
    }
    cJSON_ArrayForEach(eng, cJSON_GetObjectItem(r, "plots")) {
      snprintf(path, sizeof path, "%s/%s/%s", fixtures, all_dirs[i], eng->valuestring);
      *plots += stat(path, &st) == 0;
    }
    cJSON_Delete(r);
    free(text);
  }
}

/* the full suite into out: counts, order, escaping, references, well-formedness */
static void check_full(const char *fixtures, const char *out) {
  char path[4096], junit[4096], schema[4096];
  dv_error err = {""};
  int engines, failing, plots;
  fixture_counts(fixtures, &engines, &failing, &plots);
  CHECK(engines == 4 && failing == 1 && plots == 6, "fixtures: %d engines, %d failing, %d plots",
        engines, failing, plots);
  snprintf(junit, sizeof junit, "%s/junit.xml", out);
  CHECK(dv_report_suite_write(out, all_dirs, NALL, junit, &err) == DV_OK, "%s", err.msg);

  snprintf(path, sizeof path, "%s/summary.json", out);
  char *text = slurp(path);
  cJSON *sum = text ? cJSON_Parse(text) : NULL;
  const cJSON *list = cJSON_GetObjectItem(sum, "scenarios");
  CHECK(cJSON_IsFalse(cJSON_GetObjectItem(sum, "pass")), "suite with a failure passes");
  CHECK(cJSON_GetArraySize(list) == NALL, "%d scenarios", cJSON_GetArraySize(list));
  for (int i = 0; i < NALL && i < cJSON_GetArraySize(list); i++) {
    const cJSON *s = cJSON_GetArrayItem(list, i);
    const cJSON *eng = cJSON_GetObjectItem(s, "engines");
    CHECK(!strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(s, "dir")), all_dirs[i]), "order %d", i);
    CHECK(cJSON_IsTrue(cJSON_GetObjectItem(s, "pass")) == (i == 0), "%s: pass", all_dirs[i]);
    CHECK(cJSON_IsString(cJSON_GetObjectItem(s, "error")) == (i >= 2), "%s: error", all_dirs[i]);
    CHECK(cJSON_IsObject(eng) && (cJSON_GetArraySize(eng) == 0) == (i >= 2), "%s", all_dirs[i]);
  }
  const cJSON *mj =
      cJSON_GetObjectItem(cJSON_GetObjectItem(cJSON_GetArrayItem(list, 1), "engines"), "mujoco");
  CHECK(cJSON_IsFalse(cJSON_GetObjectItem(mj, "pass")), "falling mujoco passes");
  CHECK(cJSON_GetArraySize(cJSON_GetObjectItem(mj, "failures")) == 2, "failures not copied");
  CHECK(cJSON_IsNumber(cJSON_GetObjectItem(mj, "theta_max_err")), "theta_max_err");
  /* each engine run: its limits and the reference it was compared with, as its report has them */
  const cJSON *rp =
      cJSON_GetObjectItem(cJSON_GetObjectItem(cJSON_GetArrayItem(list, 0), "engines"), "mujoco");
  const cJSON *lim = cJSON_GetObjectItem(cJSON_GetObjectItem(rp, "limits"), "theta_max_err");
  const cJSON *ref = cJSON_GetObjectItem(rp, "reference");
  CHECK(cJSON_GetNumberValue(cJSON_GetObjectItem(lim, "limit")) == 0.01 &&
            cJSON_GetNumberValue(cJSON_GetObjectItem(lim, "margin")) == 0.0123456 &&
            !strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(lim, "from")), "default: 0.01 rad"),
        "summary: steady_circle/mujoco's theta_max_err limit");
  CHECK(!strcmp(cJSON_GetStringValue(cJSON_GetObjectItem(ref, "engine")), "matched") &&
            cJSON_GetNumberValue(cJSON_GetObjectItem(ref, "half_thickness")) == 0.005,
        "summary: steady_circle/mujoco's reference");
  CHECK(cJSON_IsNull(cJSON_GetObjectItem(mj, "limits")) &&
            cJSON_IsNull(cJSON_GetObjectItem(mj, "reference")),
        "summary: a report without limits or reference gets null");
  cJSON_Delete(sum);
  free(text);

  char *xml = slurp(junit);
  CHECK(xml, "no %s", junit);
  snprintf(schema, sizeof schema, "%s/../junit.xsd", fixtures);
  if (xml) check_junit(xml, schema, junit, engines, failing);
  free(xml);

  snprintf(path, sizeof path, "%s/index.html", out);
  char *html = slurp(path);
  CHECK(html, "no index.html");
  if (html) {
    CHECK(check_refs(out, html) == 0, "the matrix shows images");
    /* a cell per engine run, a row per errored scenario; each links the scenario's page */
    CHECK(count(html, "<td class=\"pass\"") + count(html, "<td class=\"fail\"") == engines,
          "%d engine cells", engines);
    CHECK(count(html, "<td class=\"err\" colspan=") == NERRORED, "error rows");
    CHECK(strstr(html, "href=\"rolling_pass/index.html\"") &&
              strstr(html, "href=\"harness_failed/index.html\"") &&
              !strstr(html, "missing/index.html"),
          "the scenarios' pages: linked where they exist");
    /* the largest margin of steady_circle's mujoco: path 0.031 over theta 0.0123 (hausdorff null) */
    CHECK(strstr(html, "<span><b>0.031&#215;</b> path_max_err</span>"), "not the largest margin");
    CHECK(strstr(html, "<span>thin disk</span>"), "the reference judged against");
    CHECK(strstr(html, "<b class=\"pass\">3 pass</b>") && strstr(html, "1 fail</b>") &&
              strstr(html, "<li>fail: 1 exceeds tolerance</li>") &&
              strstr(html, "3 harness errors</b>"),
          "the summary's counts");
    CHECK(!strstr(html, "<script") && strstr(html, "<style>"), "scripts or no inline CSS");
    xml_ok(html, "index.html");
    xmllint(path, NULL);
  }
  free(html);
  /* the scenario pages: their plots, files, escaping and numbers; an error's page */
  int nimg = 0;
  for (int i = 0; i < NALL; i++) {
    char dir[2048];
    snprintf(dir, sizeof dir, "%s/%s", out, all_dirs[i]);
    snprintf(path, sizeof path, "%s/index.html", dir);
    html = slurp(path);
    CHECK((html != NULL) == (i < NALL - 1), "%s: a page", all_dirs[i]);
    if (!html) continue;
    nimg += check_refs(dir, html);
    CHECK((strstr(html, "<span class=\"err\">ERROR</span>") != NULL) == (i >= 2), "%s: error",
          all_dirs[i]);
    if (i == 0) {
      CHECK(!strstr(html, "<check>") && strstr(html, "&lt;check&gt; &amp; &quot;escape&quot;"),
            "description not escaped");
      CHECK(strstr(html, "\xce\xb8 = 1.2"), "UTF-8 text mangled");
      CHECK(strstr(html, "0.000123 / 0.01") && !strstr(html, "0.000123456"), "numbers not %%.3g");
      CHECK(strstr(html, "href=\"report.md\"") && strstr(html, "href=\"ode.csv\""), "links");
      CHECK(strstr(html, "integrator implicit, timestep 8e-06 s"), "the settings that ran");
      CHECK(strstr(html, "passes: path_max_err 0.00031 &#8804; 0.01"), "the verdict's words");
    }
    if (i == 1) CHECK(strstr(html, "fails: exceeds tolerance"), "falling_fail: its verdict");
    CHECK(!strstr(html, "<script") && strstr(html, "<style>"), "scripts or no inline CSS");
    xml_ok(html, path);
    xmllint(path, NULL);
    free(html);
  }
  CHECK(nimg == plots, "%d images, %d plots listed", nimg, plots);
}

/* same inputs, same bytes */
static void check_repeatable(const char *out) {
  static const char *const files[] = {"summary.json", "index.html", "junit.xml"};
  char path[4096], junit[4096];
  char *before[3];
  dv_error err = {""};
  for (int k = 0; k < 3; k++) {
    snprintf(path, sizeof path, "%s/%s", out, files[k]);
    before[k] = slurp(path);
  }
  snprintf(junit, sizeof junit, "%s/junit.xml", out);
  CHECK(dv_report_suite_write(out, all_dirs, NALL, junit, &err) == DV_OK, "%s", err.msg);
  for (int k = 0; k < 3; k++) {
    snprintf(path, sizeof path, "%s/%s", out, files[k]);
    char *after = slurp(path);
    CHECK(before[k] && after && !strcmp(before[k], after), "%s differs on a rerun", files[k]);
    free(after);
    free(before[k]);
  }
}

/* the passing scenario alone passes, writes no JUnit; unwritable targets fail cleanly */
static void check_pass_and_errors(const char *fixtures, const char *out) {
  char path[4096], src[4096];
  dv_error err = {""};
  snprintf(src, sizeof src, "%s/rolling_pass", fixtures);
  snprintf(path, sizeof path, "%s/rolling_pass", out);
  CHECK(copy_dir(src, path) == 0, "cannot copy %s", src);
  CHECK(dv_report_suite_write(out, all_dirs, 1, NULL, &err) == DV_OK, "%s", err.msg);
  snprintf(path, sizeof path, "%s/summary.json", out);
  char *text = slurp(path);
  cJSON *sum = text ? cJSON_Parse(text) : NULL;
  CHECK(cJSON_IsTrue(cJSON_GetObjectItem(sum, "pass")), "passing scenario alone fails");
  cJSON_Delete(sum);
  free(text);
  CHECK(remove(path) == 0, "summary.json");
  snprintf(path, sizeof path, "%s/index.html", out);
  CHECK(remove(path) == 0, "index.html");

  /* a JUnit path that cannot be written: an error, and no file written at all */
  snprintf(path, sizeof path, "%s/no/such/dir/junit.xml", out);
  err.msg[0] = '\0';
  CHECK(dv_report_suite_write(out, all_dirs, 1, path, &err) < 0 && err.msg[0], "bad junit path");
  snprintf(path, sizeof path, "%s/summary.json", out);
  CHECK(access(path, F_OK) != 0, "summary.json written although the JUnit file failed");
  snprintf(path, sizeof path, "%s/no/such/dir", out);
  err.msg[0] = '\0';
  CHECK(dv_report_suite_write(path, all_dirs, 1, NULL, &err) < 0 && err.msg[0], "bad out dir");
  CHECK(dv_report_suite_write(NULL, all_dirs, 1, NULL, &err) == DV_EINPUT, "NULL out dir");
}

int main(int argc, char **argv) {
  char tmp[512], full[1024], alone[1024];
  const char *base = getenv("TMPDIR") && *getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
  if (argc < 2) {
    fprintf(stderr, "usage: %s FIXTURES_DIR [KEEP_OUT_DIR]\n", argv[0]);
    return 2;
  }
  snprintf(tmp, sizeof tmp, "%s/dv_suite_report_XXXXXX", base);
  if (!mkdtemp(tmp)) {
    fprintf(stderr, "mkdtemp %s: %s\n", tmp, strerror(errno));
    return 2;
  }
  if (argc > 2)
    snprintf(full, sizeof full, "%s", argv[2]);
  else
    snprintf(full, sizeof full, "%s/full", tmp);
  snprintf(alone, sizeof alone, "%s/alone", tmp);
  CHECK(mkdir(full, 0777) == 0 || errno == EEXIST, "mkdir %s", full);
  CHECK(mkdir(alone, 0777) == 0, "mkdir %s", alone);
  CHECK(prepare(argv[1], full) == 0, "cannot copy the fixtures of %s", argv[1]);

  check_full(argv[1], full);
  check_repeatable(full);
  check_pass_and_errors(argv[1], alone);

  ntemp = 0;
  nftw(full, find_temp, 16, FTW_PHYS);
  nftw(alone, find_temp, 16, FTW_PHYS);
  CHECK(ntemp == 0, "%d temporary files left", ntemp);
  nftw(tmp, remove_one, 16, FTW_DEPTH | FTW_PHYS);
  if (argc > 2) printf("suite report kept in %s\n", full);
  return TEST_RESULT();
}
