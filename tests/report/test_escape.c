/* test_escape: the one HTML/XML escaper, and the pages that use it.
 *   - dv_report_escape on markup characters, in text and in attributes, and
 *     on invalid UTF-8 (every bad byte a '?', valid multi-byte characters
 *     kept); dv_report_utf8_scrub on the same bytes;
 *   - dv_report_escape_markdown on markup, list starts and control bytes;
 *   - the stability page of a scenario and an engine whose names hold
 *     markup: escaped on the page, no raw '<' or '&' from the names.
 * usage: test_escape (writes into a temporary directory it removes) */
#define _DEFAULT_SOURCE /* mkdtemp, open_memstream */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_test.h"
#include "report_escape.h"
#include "search_stability.h"

/* s escaped as text (attr 0) or as an attribute value; the caller frees */
static char *escaped(const char *s, int attr) {
  char *buf = NULL;
  size_t len = 0;
  FILE *fp = open_memstream(&buf, &len);
  if (!fp) return NULL;
  dv_report_escape(fp, s, attr);
  fclose(fp);
  return buf;
}

/* the whole text file dir/name (caller frees), NULL if unreadable */
static char *slurp(const char *dir, const char *name) {
  char path[1200], *buf = NULL;
  size_t cap = 0;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *fp = fopen(path, "r");
  if (fp && getdelim(&buf, &cap, '\0', fp) < 0) free(buf), buf = NULL; /* up to a NUL: all */
  if (fp) fclose(fp);
  return buf;
}

/* escaping s gives want (as text, or as an attribute value) */
static void check_escape(const char *s, int attr, const char *want) {
  char *got = escaped(s, attr);
  CHECK(got && !strcmp(got, want), "escape(\"%s\", %d): got \"%s\", want \"%s\"", s, attr,
        got ? got : "(null)", want);
  free(got);
}

static void check_escaper(void) {
  check_escape("<&>\"'", 0, "&lt;&amp;&gt;&quot;&#39;");
  check_escape("<&>\"'", 1, "&lt;&amp;&gt;&quot;&#39;");
  check_escape("a\tb\nc\rd", 0, "a\tb\nc&#13;d"); /* text keeps tab and newline */
  check_escape("a\tb\nc\rd", 1, "a&#9;b&#10;c&#13;d");
  check_escape("bell\a esc\x1b", 0, "bell? esc?");
  check_escape(NULL, 0, "");
  /* valid UTF-8 stays: theta, a euro sign, a musical symbol (4 bytes) */
  check_escape("\xce\xb8 \xe2\x82\xac \xf0\x9d\x84\x9e", 0,
               "\xce\xb8 \xe2\x82\xac \xf0\x9d\x84\x9e");
  /* invalid: a lone continuation byte, a truncated sequence, an overlong '/',
   * a surrogate, a byte never used, U+FFFE */
  check_escape("a\x80z", 0, "a?z");
  check_escape("a\xe2\x82z", 0, "a??z");
  check_escape("\xc0\xaf", 0, "??");
  check_escape("\xed\xa0\x80", 0, "???");
  check_escape("\xff<", 0, "?&lt;");
  check_escape("\xef\xbf\xbe", 0, "???");
  char bad[] = "ok \xce\xb8 \x80\xe2\x82 <&>";
  dv_report_utf8_scrub(bad);
  CHECK(!strcmp(bad, "ok \xce\xb8 ??? <&>"), "scrub: got \"%s\"", bad);
  dv_report_utf8_scrub(NULL);
}

/* s as Markdown; the caller frees */
static char *markdown(const char *s) {
  char *buf = NULL;
  size_t len = 0;
  FILE *fp = open_memstream(&buf, &len);
  if (!fp) return NULL;
  dv_report_escape_markdown(fp, s);
  fclose(fp);
  return buf;
}

/* a description reaches report.md as literal text: no HTML, link, emphasis,
 * list or control byte survives; plain words and UTF-8 stay as they are */
static void check_markdown(void) {
  const struct {
    const char *in, *want;
  } cases[] = {
      {"uniform disk, theta 1.0 rad, m r^2 (C = 0)", "uniform disk, theta 1.0 rad, m r^2 (C = 0)"},
      {"<script>alert(1)</script>", "\\<script\\>alert(1)\\</script\\>"},
      {"[x](javascript:y) *b* _i_ `c` &amp; #h |t| ~s~",
       "\\[x\\](javascript:y) \\*b\\* \\_i\\_ \\`c\\` \\&amp; \\#h \\|t\\| \\~s\\~"},
      {"- item", "\\- item"},
      {"12. item", "12\\. item"},
      {"a\x1b[31mred\x7f\tb\r\nc", "a?\\[31mred? b  c"},
      {"\xce\xb8 \xff", "\xce\xb8 ?"},
      {"back\\slash", "back\\\\slash"},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    char *got = markdown(cases[i].in);
    CHECK(got && !strcmp(got, cases[i].want), "markdown(\"%s\"): got \"%s\", want \"%s\"",
          cases[i].in, got ? got : "(null)", cases[i].want);
    free(got);
  }
  char *none = markdown(NULL);
  CHECK(none && !none[0], "markdown(NULL)");
  free(none);
}

/* names with markup reach the stability page only escaped */
static void check_stability_page(void) {
  char dir[] = "/tmp/test_escape.XXXXXX";
  CHECK(mkdtemp(dir) != NULL, "mkdtemp");
  dv_search *s = calloc(1, sizeof *s);
  CHECK(s != NULL, "out of memory");
  if (!s) return;
  s->tolerance = 0.1;
  s->limit = NAN;
  s->best = s->first_failure = -1;
  const dv_stability_row rows[2] = {{"a<b&c", "x\"y'z>", s}, {"plain", "engine", s}};
  dv_error err = {{0}};
  CHECK(dv_search_stability_write(dir, rows, 2, &err) == DV_OK, "write: %s", err.msg);
  char *html = slurp(dir, "stability.html");
  CHECK(html != NULL, "no stability.html");
  if (html) {
    CHECK(strstr(html, "<td>a&lt;b&amp;c</td>") != NULL, "scenario name not escaped:\n%s", html);
    CHECK(strstr(html, "<td>x&quot;y&#39;z&gt;</td>") != NULL, "engine name not escaped:\n%s",
          html);
    CHECK(!strstr(html, "a<b") && !strstr(html, "b&c") && !strstr(html, "z>"),
          "a name's markup is on the page:\n%s", html);
    CHECK(strstr(html, "<td>plain</td><td>engine</td>") != NULL, "plain names changed:\n%s", html);
    CHECK(strstr(html, "not run") != NULL, "a search without probes is not 'not run':\n%s", html);
  }
  free(html);
  const char *const files[] = {"stability.html", "stability.md", "stability.json"};
  for (size_t i = 0; i < 3; i++) {
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", dir, files[i]);
    CHECK(unlink(path) == 0, "%s was not written", files[i]);
  }
  CHECK(rmdir(dir) == 0, "%s: other files left", dir);
  free(s);
}

int main(void) {
  check_escaper();
  check_markdown();
  check_stability_page();
  return TEST_RESULT();
}
