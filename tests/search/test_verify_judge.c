/* test_verify_judge: verify's verdict from its four errors (search_verify.h),
 * on sequences of known limit e(h) = L + c h^p, so the Richardson value and
 * its uncertainty can be checked against the truth:
 *   - order 1 to L = 0: converges, e(0) within 1e-12 of 0;
 *   - order 1 to L = 0.01 (above the floor): converges elsewhere, e(0) = L
 *     to 1e-12, no uncertainty (the two orders agree exactly);
 *   - order 2 to L = 0.003: e(0) = L to 1e-12, order 2;
 *   - the clean sequence 0.248, 0.127, 0.064, 0.032 (printed: order
 *     0.977, e(0) -1.03e-3, uncertainty 3.4e-3 from the earlier levels):
 *     converges, the uncertainty covering e(0);
 *   - errors that grow: does not converge; flat above the floor: elsewhere;
 *     errors of 0, or flat under the floor: not judged;
 *   - three levels (judge --step over 3 files) at ratios 2, 3 and unequal
 *     (1e-3, 4e-4, 1e-4), orders 1..4: e(0) = L and the order p to 1e-9, the
 *     uncertainty 1.25 |e(finest) - L| (exact data: measured worst 8.9e-16 in
 *     the order, 5.2e-18 in e(0), rounding and the bisection's 1e-15; re-measure
 *     with DV_TEST_MEASURE=1 build/tests/test_verify_judge). */
#include <math.h>
#include <string.h>

#include "dv_test.h"
#include "search_verify.h"

/* the verdict on e(h) = L + c (h / dt)^p at h = dt / 2^k */
static dv_verification judge(double L, double c, double p) {
  dv_verification v;
  memset(&v, 0, sizeof v);
  for (int k = 0; k < DV_VERIFY_LEVELS; k++) {
    v.step[k] = 1e-3 / (1 << k);
    v.error[k] = L + c * pow(0.5, p * k);
  }
  dv_search_verify_judge(&v);
  return v;
}

static dv_verification judge_errors(const double e[DV_VERIFY_LEVELS]) {
  dv_verification v;
  memset(&v, 0, sizeof v);
  for (int k = 0; k < DV_VERIFY_LEVELS; k++) v.step[k] = 1e-3 / (1 << k), v.error[k] = e[k];
  dv_search_verify_judge(&v);
  return v;
}

int main(void) {
  dv_verification v = judge(0.0, 0.2, 1.0);
  CHECK(v.verdict == DV_CONVERGES, "order 1 to 0: %s", dv_search_convergence_name(v.verdict));
  CHECK_NEAR(v.extrapolated, 0.0, 1e-12, "order 1 to 0: e(0)");
  CHECK_NEAR(v.order, 1.0, 1e-9, "order 1 to 0: order");

  v = judge(0.01, 0.2, 1.0);
  CHECK(v.verdict == DV_CONVERGES_ELSEWHERE, "order 1 to 0.01: %s",
        dv_search_convergence_name(v.verdict));
  CHECK_NEAR(v.extrapolated, 0.01, 1e-12, "order 1 to 0.01: e(0)");
  CHECK(v.uncertainty <= 1e-12, "order 1 to 0.01: uncertainty %g", v.uncertainty);

  v = judge(0.003, 0.05, 2.0);
  CHECK_NEAR(v.extrapolated, 0.003, 1e-12, "order 2 to 0.003: e(0)");
  CHECK_NEAR(v.order, 2.0, 1e-9, "order 2 to 0.003: order");
  CHECK(v.verdict == DV_CONVERGES_ELSEWHERE, "order 2 to 0.003: %s",
        dv_search_convergence_name(v.verdict));

  const double clean[] = {0.248, 0.127, 0.064, 0.032};
  v = judge_errors(clean);
  printf("0.248 .. 0.032: order %.3f, e(0) %.3g, uncertainty %.3g: %s\n", v.order, v.extrapolated,
         v.uncertainty, dv_search_convergence_name(v.verdict));
  CHECK(v.verdict == DV_CONVERGES, "a clean order-1 sequence: %s",
        dv_search_convergence_name(v.verdict));
  CHECK(v.uncertainty >= fabs(v.extrapolated) && v.uncertainty < 0.01,
        "uncertainty %g against e(0) %g", v.uncertainty, v.extrapolated);

  const double grow[] = {0.01, 0.02, 0.04, 0.08}, flat[] = {0.05, 0.0499, 0.0501, 0.05};
  v = judge_errors(grow);
  CHECK(v.verdict == DV_DOES_NOT_CONVERGE, "growing errors: %s",
        dv_search_convergence_name(v.verdict));
  v = judge_errors(flat);
  CHECK(v.verdict == DV_CONVERGES_ELSEWHERE, "flat errors: %s",
        dv_search_convergence_name(v.verdict));
  /* errors of 0, or errors flat under the floor, show no convergence */
  const double zero[] = {0.0, 0.0, 0.0, 0.0}, low[] = {2e-6, 2.01e-6, 1.99e-6, 2e-6};
  v = judge_errors(zero);
  CHECK(v.verdict == DV_CONVERGE_NOT_JUDGED, "errors of 0: %s",
        dv_search_convergence_name(v.verdict));
  v = judge_errors(low);
  CHECK(v.verdict == DV_CONVERGE_NOT_JUDGED, "flat errors under the floor: %s",
        dv_search_convergence_name(v.verdict));
  const double ratios[][3] = {{1e-3, 5e-4, 2.5e-4}, {9e-3, 3e-3, 1e-3}, {1e-3, 4e-4, 1e-4}};
  for (int k = 0; k < 3; k++) {
    for (double p = 1.0; p <= 4.0; p += 1.0) {
      const double L = 0.002, *h = ratios[k], c = 0.1 / pow(h[0], p); /* e(h0) - L = 0.1 */
      const double e[3] = {L + c * pow(h[0], p), L + c * pow(h[1], p), L + c * pow(h[2], p)};
      dv_convergence_fit f;
      dv_search_convergence_judge(h, e, 3, &f);
      CHECK_NEAR(f.order, p, 1e-9, "3 levels: order");
      CHECK_NEAR(f.extrapolated, L, 1e-9 * L, "3 levels: e(0)");
      CHECK_NEAR(f.uncertainty, 1.25 * c * pow(h[2], p), 1e-6 * c * pow(h[2], p),
                 "3 levels: the grid convergence index");
    }
  }
  return TEST_RESULT();
}
