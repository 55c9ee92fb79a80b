/* test_gsl_words: no GSL status reaches a user in GSL's own words
 * ("invalid argument supplied by user" speaks to GSL's caller). Every status
 * GSL defines gets words of ours, none of them gsl_strerror's; the sources
 * passing gsl_strerror on are checked apart (tests/CMakeLists.txt). */
#include <gsl/gsl_errno.h>
#include <string.h>

#include "dv_test.h"
#include "red_gsl_words.h"

int main(void) {
  gsl_set_error_handler_off();
  for (int status = GSL_CONTINUE; status <= GSL_EOF; status++) {
    const char *ours = red_gsl_words(status), *theirs = gsl_strerror(status);
    CHECK(ours && ours[0], "status %d: no words", status);
    CHECK(strcmp(ours, theirs) != 0, "status %d: GSL's own words '%s'", status, theirs);
    CHECK(!strstr(ours, "user") && !strstr(ours, "GSL"), "status %d: '%s'", status, ours);
  }
  CHECK(strstr(red_gsl_words(GSL_EINVAL), "sign change"), "a root not bracketed: '%s'",
        red_gsl_words(GSL_EINVAL));
  return TEST_RESULT();
}
