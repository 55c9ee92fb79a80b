/* test_scenario_values: how a scenario value may be written (scenario_number.h)
 * and how a refused one is described (scenario_schema.h). */
#include <math.h>
#include <string.h>

#include "dv_test.h"
#include "scenario_schema.h"

typedef struct block {
  double v;
} block;

static const dv_setting_spec THETA = {
    "theta", DV_SETTING_REAL, 0, 0, DV_SETTING_OPEN_LO | DV_SETTING_OPEN_HI, 0, 0.0, M_PI, NULL,
    NULL,    "rad",           ""};

/* text reads as want, exactly */
static void check_value(const char *text, double want) {
  block b = {NAN};
  char what[300] = "";
  CHECK(dv_setting_parse(&THETA, text, &b, what, sizeof what) == 0, "'%s': %s", text, what);
  CHECK(b.v == want, "'%s' is %.17g, want %.17g", text, b.v, want);
}

/* text is refused with a message holding expect */
static void check_refused(const char *text, const char *expect) {
  block b = {NAN};
  char what[300] = "";
  CHECK(dv_setting_parse(&THETA, text, &b, what, sizeof what) == -1, "'%s' accepted", text);
  CHECK(strstr(what, expect), "'%s': '%s' does not say '%s'", text, what, expect);
}

int main(void) {
  check_value("1.25", 1.25);
  check_value(" 0.5 ", 0.5);
  check_value("pi/2", M_PI / 2);
  check_value("pi / 3", M_PI / 3);
  check_value("3*pi/4", 3 * M_PI / 4);
  check_value("0.5 * pi", 0.5 * M_PI);
  check_value("+pi/2", M_PI / 2);
  check_value(" pi/6 ", M_PI / 6);
  /* a subnormal is a number (the trajectory reader's strtod takes it too); an
   * underflow to 0 is 0, judged by the range */
  check_value("4.9e-324", 4.9e-324);
  check_value("1e-310", 1e-310);
  check_refused("1e-400", "0 is outside (0, 3.141592653589793)");
  const char *bad[] = {"2pi", "pi2", "pi*2",  "pi/2/2", "(pi)/2", "pi/2x", "sin(pi)", "pie",
                       "pi/", "*pi", "2**pi", "pi pi",  "PI/2",   "e",     "x",       ""};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) check_refused(bad[i], "not a number");
  /* not finite: NaN and inf, written or made */
  const char *infinite[] = {"nan",    "inf",  "-inf",   "1e400",     "nan*pi",
                            "inf*pi", "pi/0", "pi/nan", "pi/1e-320", "1e308*pi"};
  for (size_t i = 0; i < sizeof infinite / sizeof infinite[0]; i++)
    check_refused(infinite[i], "not a number");
  /* the range with every digit that tells the value from its bound:
   * pi itself is outside the open (0, pi) */
  check_refused("pi", "3.141592653589793 is outside (0, 3.141592653589793)");
  check_refused("-pi/2", "-1.5707963267948966 is outside");
  check_refused("3.1415926535897936", "is outside (0, 3.141592653589793)");
  return TEST_RESULT();
}
