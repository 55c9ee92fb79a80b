/* dv_test: a minimal check macro set for the test programs.
 * Each failed check prints file:line and the message; main returns the count. */
#ifndef DV_TEST_H
#define DV_TEST_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int dv_test_failures = 0;

#define CHECK(cond, ...)                                                       \
  do {                                                                         \
    if (!(cond)) {                                                             \
      dv_test_failures++;                                                      \
      fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond); \
      fprintf(stderr, __VA_ARGS__);                                            \
      fputc('\n', stderr);                                                     \
    }                                                                          \
  } while (0)

/* |got - want| <= tol, printing both on failure; with DV_TEST_MEASURE set in
 * the environment every check prints its measured |diff| against its tol, which
 * is how the tolerances of the tests were measured and can be re-measured */
#define CHECK_NEAR(got, want, tol, what)                                                     \
  do {                                                                                       \
    const double got_ = (got), want_ = (want), tol_ = (tol);                                 \
    if (getenv("DV_TEST_MEASURE"))                                                           \
      fprintf(stderr, "%s:%d: measured %s: |diff| %.3g, tol %.3g\n", __FILE__, __LINE__, what, \
              fabs(got_ - want_), tol_);                                                     \
    CHECK(fabs(got_ - want_) <= tol_, "%s: got %.17g want %.17g (|diff| %.3g > %.3g)", what, \
          got_, want_, fabs(got_ - want_), tol_);                                            \
  } while (0)

#define TEST_RESULT() \
  (dv_test_failures ? (fprintf(stderr, "%d check(s) failed\n", dv_test_failures), 1) : 0)

#endif
