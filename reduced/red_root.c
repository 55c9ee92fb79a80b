/* red_root: Brent's method to a tolerance (gsl_root_fsolver_brent). */
#include "red_root.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <math.h>

int red_brent(gsl_function *fn, double a, double b, double epsabs, double epsrel, double *root) {
  const double fa = GSL_FN_EVAL(fn, a), fb = GSL_FN_EVAL(fn, b);
  if (!isfinite(fa) || !isfinite(fb)) return GSL_EBADFUNC;
  if ((fa < 0.0 && fb < 0.0) || (fa > 0.0 && fb > 0.0)) return GSL_EINVAL; /* not GSL's abort */
  gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  if (!s) return GSL_ENOMEM;
  int status = gsl_root_fsolver_set(s, fn, a, b);
  for (int i = 0; status == GSL_SUCCESS && i < 200; i++) {
    status = gsl_root_fsolver_iterate(s);
    if (status) break;
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), epsabs,
                               epsrel) == GSL_SUCCESS)
      break;
  }
  *root = gsl_root_fsolver_root(s);
  gsl_root_fsolver_free(s);
  return status;
}
