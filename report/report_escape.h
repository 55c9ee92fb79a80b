/* dv_report_escape: text made safe for HTML and XML pages, and for Markdown.
 *
 * Every name and message a page shows goes through this escaper:
 * '&', '<', '>', '"', '\'' and carriage return become entities or character
 * references; so do tab and newline in a double-quoted attribute value (in
 * text they stay); any other control character and every byte that is not
 * part of valid UTF-8 (or encodes a character XML does not allow) becomes '?'.
 */
#ifndef DV_REPORT_ESCAPE_H
#define DV_REPORT_ESCAPE_H

#include <stdio.h>

/* s escaped for HTML/XML text, or for a double-quoted attribute value when
 * attr; NULL is written as nothing */
void dv_report_escape(FILE *fp, const char *s, int attr);

/* pre, s escaped (as an attribute value when attr), post */
void dv_report_escape_put(FILE *fp, const char *pre, const char *s, int attr, const char *post);

/* s as literal Markdown text (CommonMark) on one line: \ ` * _ { } [ ] < > #
 * | ~ & backslash-escaped (so '<' opens no HTML tag, '&' no entity, '[' no
 * link), and so is what would open a list or heading at the start ("- ",
 * "1. ", "="); tab, newline and carriage return a space; any other control
 * character and invalid UTF-8 '?'; NULL: nothing */
void dv_report_escape_markdown(FILE *fp, const char *s);

/* the bytes of invalid UTF-8 in text replaced by '?', in place (NULL-safe) */
void dv_report_utf8_scrub(char *text);

#endif
