/* dv_report_escape: entities and valid UTF-8 for HTML and XML; backslashes for Markdown. */
#include "report_escape.h"

#include <stddef.h>
#include <string.h>

/* entities for the ASCII characters that need one (tab and newline in attributes only) */
static const char *const entities[128] = {
    ['&'] = "&amp;",  ['<'] = "&lt;",   ['>'] = "&gt;",   ['"'] = "&quot;",
    ['\''] = "&#39;", ['\r'] = "&#13;", ['\n'] = "&#10;", ['\t'] = "&#9;"};

/* bytes in the valid UTF-8 sequence at s (XML characters only), 0 if invalid */
static size_t utf8_len(const unsigned char *s) {
  static const unsigned long min[] = {0, 0, 0x80, 0x800, 0x10000};
  if (s[0] < 0x80) return 1;
  const size_t n = s[0] >= 0xF8 ? 0 : s[0] >= 0xF0 ? 4 : s[0] >= 0xE0 ? 3 : s[0] >= 0xC0 ? 2 : 0;
  unsigned long cp = s[0] & (0xFFu >> (n + 1));
  for (size_t i = 1; i < n; i++) {
    if ((s[i] & 0xC0) != 0x80) return 0; /* also stops at the terminator */
    cp = cp << 6 | (s[i] & 0x3F);
  }
  if (!n || cp < min[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF) || cp == 0xFFFE ||
      cp == 0xFFFF)
    return 0;
  return n;
}

/* '?' for every byte that does not start a valid sequence */
void dv_report_utf8_scrub(char *text) {
  for (unsigned char *p = (unsigned char *)text; p && *p;) {
    const size_t n = utf8_len(p);
    if (!n) *p = '?';
    p += n ? n : 1;
  }
}

/* an entity, '?', or the character's bytes as they are */
void dv_report_escape(FILE *fp, const char *s, int attr) {
  for (const unsigned char *p = (const unsigned char *)(s ? s : ""); *p;) {
    const int space = *p == '\n' || *p == '\t';
    size_t n = 1;
    if (*p < 0x80 && entities[*p] && (attr || !space)) {
      fputs(entities[*p], fp);
    } else if ((*p < 0x20 && !space) || !(n = utf8_len(p))) {
      fputc('?', fp);
      n = 1;
    } else {
      fwrite(p, 1, n, fp);
    }
    p += n;
  }
}

void dv_report_escape_markdown(FILE *fp, const char *s) {
  const unsigned char *p = (const unsigned char *)(s ? s : "");
  const size_t digits = strspn((const char *)p, "0123456789");
  for (const unsigned char *start = p; *p;) {
    size_t n = 1;
    /* what starts a list or heading at the line's start: "- x", "1. x", "1) x", "=" */
    const int opens_block = (p == start && strchr("-+=", *p)) ||
                            (digits && p == start + digits && (*p == '.' || *p == ')'));
    if (*p == '\t' || *p == '\n' || *p == '\r')
      fputc(' ', fp);
    else if (*p < 0x20 || *p == 0x7f || !(n = utf8_len(p)))
      fputc('?', fp), n = 1;
    else if (opens_block || (*p < 0x80 && strchr("\\`*_{}[]<>#|~&", *p)))
      fputc('\\', fp), fputc(*p, fp);
    else
      fwrite(p, 1, n, fp);
    p += n;
  }
}

/* the text around an escaped value, as the pages write it */
void dv_report_escape_put(FILE *fp, const char *pre, const char *s, int attr, const char *post) {
  fputs(pre, fp);
  dv_report_escape(fp, s, attr);
  fputs(post, fp);
}
