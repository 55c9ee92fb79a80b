/* test_root: red_brent meets the tolerance it is given, epsabs + epsrel |root|,
 * where the events, turning points and period closure rely on it. A triple
 * root makes Brent converge slowly, so a looser stopping test shows:
 * (x - 0.3)^3 on [0, 1] to epsrel 1e-6, 1e-9, 1e-12 is found within
 * 3e-7, 3e-10, 3e-13 (measured 7.1e-8, 1.2e-10, 1.7e-13: a stopping test
 * 1000x looser leaves 1.2e-10 at 1e-12). */
#include <gsl/gsl_errno.h>
#include <math.h>

#include "dv_test.h"
#include "red_root.h"

static double cube(double x, void *p) {
  (void)p;
  return (x - 0.3) * (x - 0.3) * (x - 0.3);
}

static double cos_minus_x(double x, void *p) {
  (void)p;
  return cos(x) - x;
}

int main(void) {
  static const double rel[] = {1e-6, 1e-9, 1e-12};
  for (int i = 0; i < 3; i++) {
    gsl_function f = {cube, NULL};
    double root = NAN;
    CHECK(red_brent(&f, 0.0, 1.0, 0.0, rel[i], &root) == GSL_SUCCESS, "cube %g", rel[i]);
    printf("(x - 0.3)^3, epsrel %g: error %.3g\n", rel[i], fabs(root - 0.3));
    CHECK(fabs(root - 0.3) <= rel[i] * 0.3, "cube: error %g over %g", fabs(root - 0.3),
          rel[i] * 0.3);
    gsl_function g = {cos_minus_x, NULL};
    CHECK(red_brent(&g, 0.0, 1.0, 0.0, rel[i], &root) == GSL_SUCCESS, "cos %g", rel[i]);
    CHECK(fabs(root - 0.73908513321516064) <= rel[i] * 0.74, "cos(x) = x: error %g",
          fabs(root - 0.73908513321516064));
  }
  /* an absolute tolerance alone, around a root at 0 */
  gsl_function f = {cube, NULL};
  double root = NAN;
  CHECK(red_brent(&f, 0.0, 1.0, 1e-10, 0.0, &root) == GSL_SUCCESS && fabs(root - 0.3) <= 1e-10,
        "epsabs 1e-10: error %g", fabs(root - 0.3));
  /* no sign change: refused, never GSL's abort */
  gsl_function g = {cos_minus_x, NULL};
  CHECK(red_brent(&g, 0.8, 1.0, 0.0, 1e-12, &root) == GSL_EINVAL, "no sign change");
  return TEST_RESULT();
}
