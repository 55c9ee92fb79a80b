/* dv_league_words: short numbers, settings and reasons of a league's cells. */
#include "league_words.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define SHORT_WHY 40 /* bytes of a why a table's cell shows */

void dv_league_short_number(double v, int digits, char *buf, size_t size) {
  const double a = fabs(v);
  if (!isfinite(v) || a == 0 || (a >= 1e-2 && a < 1e4)) { /* every integer digit: 1000, not 1e+03 */
    const int whole = a >= 1 && isfinite(a) ? (int)floor(log10(a)) + 1 : 0;
    snprintf(buf, size, "%.*g", whole > digits ? whole : digits, v);
    return;
  }
  char mant[32];
  int exp = 0;
  snprintf(mant, sizeof mant, "%.*e", digits - 1, v); /* "8.20e-04" */
  char *e = strchr(mant, 'e');
  if (!e) {
    snprintf(buf, size, "%s", mant);
    return;
  }
  sscanf(e + 1, "%d", &exp);
  *e = '\0';
  if (strchr(mant, '.')) { /* "8.20" -> "8.2", "5.00" -> "5" */
    size_t n = strlen(mant);
    while (mant[n - 1] == '0') mant[--n] = '\0';
    if (mant[n - 1] == '.') mant[n - 1] = '\0';
  }
  snprintf(buf, size, "%se%d", mant, exp);
}

void dv_league_settings_words(const dv_league_cell *c, char *buf, size_t size) {
  char step[32];
  const char *dot = strrchr(c->step_key, '.');
  const char *word = dot ? dot + 1 : c->step_key;
  const char *sep = c->choice[0] ? ", " : "";
  dv_league_short_number(c->step, 2, step, sizeof step);
  if (!c->step_key[0] || isnan(c->step))
    snprintf(buf, size, "%s", c->choice);
  else if (!strcmp(word, "timestep"))
    snprintf(buf, size, "%s%s%s s", c->choice, sep, step);
  else
    snprintf(buf, size, "%s%s%s %s", c->choice, sep, word, step);
}

void dv_league_short_why(const dv_league_cell *c, char *buf, size_t size) {
  const char *why = c->why[0] ? c->why : dv_league_outcome_name(c->outcome);
  const char *outcome = dv_league_outcome_name(c->outcome);
  const size_t lead = strlen(outcome);
  if (!strncmp(why, outcome, lead) && !strncmp(why + lead, ": ", 2) && why[lead + 2])
    why += lead + 2; /* "cannot model: no thin disk": the outcome is said beside it */
  size_t n = strcspn(why, ":;(");
  const char *comma = strstr(why, ", ");
  if (comma && (size_t)(comma - why) < n) n = (size_t)(comma - why);
  while (n && why[n - 1] == ' ') n--;
  if (!n) n = strlen(why); /* nothing before its first stop: all of it, cut below */
  const int cut = n > SHORT_WHY;
  if (cut) {
    n = SHORT_WHY;
    while (n && ((unsigned char)why[n] & 0xC0) == 0x80) n--; /* not inside a UTF-8 character */
  }
  snprintf(buf, size, "%.*s%s", (int)n, why, cut ? "..." : "");
}

int dv_league_cell_was_run(const dv_league_cell *c) {
  return c->outcome == DV_LEAGUE_REACHED || c->outcome == DV_LEAGUE_NOT_REACHED;
}

void dv_league_figure_file(const char *object, char *buf, size_t size) {
  const int n = snprintf(buf, size, "work_precision_%s.svg", object);
  const size_t end = n < 0 ? 0 : (size_t)n < size ? (size_t)n - 4 : size - 1;
  for (size_t i = sizeof "work_precision_" - 1; i < end; i++)
    if (!isalnum((unsigned char)buf[i]) && !strchr("_.-", buf[i])) buf[i] = '_';
}
