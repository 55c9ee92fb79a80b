/* red_gsl_words: GSL statuses as what went wrong (red_gsl_words.h). */
#include "red_gsl_words.h"

#include <gsl/gsl_errno.h>

const char *red_gsl_words(int status) {
  switch (status) {
    case GSL_SUCCESS:
      return "no error";
    case GSL_FAILURE: /* evolve: the step size fell below machine precision */
      return "the step size fell below what the tolerance can be met with";
    case GSL_EDOM: /* our right-hand sides and potentials: a non-finite value */
      return "the equations are undefined at the state reached (a non-finite value)";
    case GSL_EINVAL: /* root bracketing, the only GSL_EINVAL our calls can meet */
      return "no sign change between the ends of the interval searched";
    case GSL_EBADFUNC:
      return "the function returned a non-finite value";
    case GSL_EMAXITER:
      return "no convergence within the iteration limit";
    case GSL_ENOMEM:
      return "out of memory";
    case GSL_EZERODIV:
    case GSL_ESING:
      return "a singular matrix";
    case GSL_ENOPROG:
    case GSL_ENOPROGJ:
      return "no progress toward a solution";
    case GSL_ETOL:
    case GSL_ETOLF:
    case GSL_ETOLX:
    case GSL_ETOLG:
    case GSL_EROUND:
    case GSL_ELOSS:
      return "the tolerance asked for cannot be reached in double precision";
    case GSL_EOVRFLW:
    case GSL_EUNDRFLW:
    case GSL_ERANGE:
      return "a value out of the range of double precision";
    default:
      return "a numerical failure";
  }
}
