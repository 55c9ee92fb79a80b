/* scenario_number: a number, or a multiple of pi, as a scenario value. */
#include "scenario_number.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *skip_blanks(const char *p) {
  return p + strspn(p, " \t");
}

/* a finite number at *p, then blanks; -1 when there is none */
static int number_at(const char **p, double *out) {
  char *end;
  /* an overflow is inf, refused; an underflow (a subnormal, or 0) is a number,
   * as the trajectory reader takes it: ERANGE alone refuses nothing */
  *out = strtod(*p, &end);
  if (end == *p || !isfinite(*out)) return -1;
  *p = skip_blanks(end);
  return 0;
}

/* [NUMBER *] pi [/ NUMBER], or [-+]pi [/ NUMBER] */
static int parse_pi(const char *text, double *out) {
  const char *pi = strstr(text, "pi"), *p = skip_blanks(text);
  double factor = 1.0, divisor = 1.0;
  if (!pi) return -1;
  if ((*p == '-' || *p == '+') && skip_blanks(p + 1) == pi)
    factor = *p == '-' ? -1.0 : 1.0;
  else if (p != pi && (number_at(&p, &factor) || *p != '*' || skip_blanks(p + 1) != pi))
    return -1;
  p = skip_blanks(pi + 2);
  if (*p == '/') {
    p = skip_blanks(p + 1);
    if (number_at(&p, &divisor)) return -1;
  }
  if (*p != '\0') return -1;
  *out = factor * M_PI / divisor;
  return isfinite(*out) ? 0 : -1;
}

int dv_scenario_parse_number(const char *text, double *out) {
  const char *p = text;
  if (number_at(&p, out) == 0 && *p == '\0') return 0;
  return parse_pi(text, out);
}
