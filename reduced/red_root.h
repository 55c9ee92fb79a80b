/* red_root: a sign change of a function, by Brent's method (GSL). */
#ifndef RED_ROOT_H
#define RED_ROOT_H

#include <gsl/gsl_math.h>

/* the root of fn in [a, b], where fn's values have opposite signs, to within
 * epsabs + epsrel |root| (at most 200 iterations); returns a GSL status:
 * GSL_EBADFUNC where fn is not finite (a callback's way to stop), GSL_EINVAL
 * where fn(a) and fn(b) have the same sign (returned, never GSL's handler) */
int red_brent(gsl_function *fn, double a, double b, double epsabs, double epsrel, double *root);

#endif
