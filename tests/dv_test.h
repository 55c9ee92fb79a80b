/* dv_test: a minimal check macro set for the test programs.
 * Each failed check prints file:line and the message; main returns the count. */
#ifndef DV_TEST_H
#define DV_TEST_H

#include <math.h>
#include <stdio.h>

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

/* |got - want| <= tol, printing both on failure */
#define CHECK_NEAR(got, want, tol, what)                                                      \
  CHECK(fabs((got) - (want)) <= (tol), "%s: got %.17g want %.17g (|diff| %.3g > %.3g)", what, \
        (double)(got), (double)(want), fabs((got) - (want)), (double)(tol))

#define TEST_RESULT() \
  (dv_test_failures ? (fprintf(stderr, "%d check(s) failed\n", dv_test_failures), 1) : 0)

#endif
