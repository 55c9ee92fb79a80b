/* test_limit_check: the one check of a metric against its limit, and the
 * verdict classes. At the limit is within; a hair above it, an infinite or a
 * NaN value is over (what could not be measured never passes); a NaN limit is
 * no rule (not judged). A verdict that says the run failed is exactly one of
 * diverged, lost contact, error, invalid, missing. The validity window ends
 * where the contact force's tangential magnitude leaves the friction cone. The
 * rate scale (the slip limit's speed) is the fastest of the rates that set it. */
#include <math.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_reference.h"
#include "dv_test.h"
#include "run_limits.h"
#include "run_verdict.h"

/* the validity window ends where the contact force's tangential magnitude
 * leaves the cone mu Fz, though each component alone stays inside it */
static void check_friction_cone(void) {
  dv_scenario sc;
  dv_engine_init_scenario(&sc);
  const double mu = dv_matched_friction(&sc);
  dv_sample s[3];
  memset(s, 0, sizeof s);
  const double each[3] = {0.5, 0.7, 0.72}; /* of mu Fz: magnitudes 0.71, 0.99, 1.018 */
  for (int i = 0; i < 3; i++) {
    s[i].t = 0.1 * (i + 1);
    s[i].force[0] = s[i].force[1] = each[i] * mu;
    s[i].force[2] = 1.0;
  }
  CHECK_NEAR(dv_reference_valid_until(&sc, s, 3), 0.2, 1e-15, "the cone's magnitude");
  s[2].force[0] = s[2].force[1] = 0.0, s[2].force[2] = -1e-9; /* the ground pulls */
  CHECK_NEAR(dv_reference_valid_until(&sc, s, 3), 0.2, 1e-15, "a pulling ground");
  s[2].force[2] = 1.0;
  CHECK(isinf(dv_reference_valid_until(&sc, s, 3)), "inside the cone throughout");
}

/* the rate scale is the fastest of the spin, the heading rate and sqrt(g / r) */
static void check_rate_scale(void) {
  dv_scenario sc;
  dv_engine_init_scenario(&sc);
  sc.disk.r = 0.1, sc.disk.g = 9.81; /* sqrt(g / r) = 9.9 rad/s */
  const double rates[][2] = {{50, 1}, {-1, 50}, {1, -50}, {2, 3}}; /* phi_dot, psi_dot */
  const double want[] = {50, 50, 50, sqrt(98.1)};
  for (int i = 0; i < 4; i++) {
    sc.initial[RED_VPH] = rates[i][0], sc.initial[RED_VPS] = rates[i][1];
    CHECK_NEAR(dv_run_rate_scale(&sc), want[i], 1e-12, "the rate scale");
  }
}

int main(void) {
  check_rate_scale();
  static const struct {
    double value, limit;
    dv_limit_check want;
  } cases[] = {
      {0.5, 1.0, DV_LIMIT_WITHIN},
      {1.0, 1.0, DV_LIMIT_WITHIN}, /* at the limit */
      {0.0, 0.0, DV_LIMIT_WITHIN},
      {-INFINITY, 1.0, DV_LIMIT_WITHIN},
      {NAN, 1.0, DV_LIMIT_OVER},
      {INFINITY, 1.0, DV_LIMIT_OVER},
      {1e-300, 0.0, DV_LIMIT_OVER},
      {NAN, INFINITY, DV_LIMIT_OVER},
      {0.5, NAN, DV_LIMIT_NONE},
      {NAN, NAN, DV_LIMIT_NONE},
      {INFINITY, NAN, DV_LIMIT_NONE},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
    CHECK(dv_run_limit_check(cases[i].value, cases[i].limit) == cases[i].want,
          "value %g, limit %g: %d, want %d", cases[i].value, cases[i].limit,
          dv_run_limit_check(cases[i].value, cases[i].limit), cases[i].want);
  const double limits[] = {1e-12, 0.01, 1.0, 1e6};
  for (size_t i = 0; i < sizeof limits / sizeof limits[0]; i++) {
    const double l = limits[i];
    CHECK(dv_run_limit_check(l, l) == DV_LIMIT_WITHIN, "at the limit %g", l);
    CHECK(dv_run_limit_check(nextafter(l, INFINITY), l) == DV_LIMIT_OVER, "just above %g", l);
    CHECK(dv_run_limit_check(nextafter(l, 0.0), l) == DV_LIMIT_WITHIN, "just below %g", l);
  }

  /* the failed class, member by member; every verdict has its own name */
  static const int failed[DV_NVERDICTS] = {
      [DV_VERDICT_DIVERGED] = 1, [DV_VERDICT_LOST_CONTACT] = 1, [DV_VERDICT_ERROR] = 1,
      [DV_VERDICT_INVALID] = 1,  [DV_VERDICT_MISSING] = 1};
  for (int v = 0; v < DV_NVERDICTS; v++) {
    CHECK(dv_run_verdict_failed((dv_verdict)v) == failed[v], "%s: failed %d, want %d",
          dv_run_verdict_name((dv_verdict)v), dv_run_verdict_failed((dv_verdict)v), failed[v]);
    CHECK(strcmp(dv_run_verdict_name((dv_verdict)v), "unknown"), "verdict %d has no name", v);
    for (int w = 0; w < v; w++)
      CHECK(strcmp(dv_run_verdict_name((dv_verdict)v), dv_run_verdict_name((dv_verdict)w)),
            "verdicts %d and %d share the name %s", v, w, dv_run_verdict_name((dv_verdict)v));
  }
  /* each way a run ends maps to its verdict */
  static const struct {
    dv_outcome outcome;
    dv_verdict verdict;
  } ends[] = {{DV_OUTCOME_COMPLETED, DV_VERDICT_AGREES},
              {DV_OUTCOME_EVENT, DV_VERDICT_ENDED_BY_EVENT},
              {DV_OUTCOME_DIVERGED, DV_VERDICT_DIVERGED},
              {DV_OUTCOME_LOST_CONTACT, DV_VERDICT_LOST_CONTACT},
              {DV_OUTCOME_ERROR, DV_VERDICT_ERROR}};
  for (size_t i = 0; i < sizeof ends / sizeof ends[0]; i++)
    CHECK(dv_run_verdict_of_outcome(ends[i].outcome) == ends[i].verdict, "outcome %d -> %s",
          ends[i].outcome, dv_run_verdict_name(dv_run_verdict_of_outcome(ends[i].outcome)));
  check_friction_cone();
  return TEST_RESULT();
}
