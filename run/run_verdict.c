/* run_verdict: the one name table of verdicts. */
#include "run_verdict.h"

#include <math.h>
#include <stdio.h>

const char *dv_run_verdict_name(dv_verdict verdict) {
  static const char *const names[DV_NVERDICTS] = {
      [DV_VERDICT_AGREES] = "agrees",         [DV_VERDICT_EXCEEDS] = "exceeds tolerance",
      [DV_VERDICT_DIVERGED] = "diverged",     [DV_VERDICT_LOST_CONTACT] = "lost contact",
      [DV_VERDICT_ERROR] = "error",           [DV_VERDICT_ENDED_BY_EVENT] = "ended by event",
      [DV_VERDICT_INVALID] = "invalid",       [DV_VERDICT_MISSING] = "missing",
      [DV_VERDICT_NOT_JUDGED] = "not judged", [DV_VERDICT_OUTSIDE_VALIDITY] = "outside validity"};
  return (unsigned)verdict < DV_NVERDICTS ? names[verdict] : "unknown";
}

dv_verdict dv_run_verdict_of_outcome(dv_outcome outcome) {
  switch (outcome) {
    case DV_OUTCOME_DIVERGED:
      return DV_VERDICT_DIVERGED;
    case DV_OUTCOME_LOST_CONTACT:
      return DV_VERDICT_LOST_CONTACT;
    case DV_OUTCOME_EVENT:
      return DV_VERDICT_ENDED_BY_EVENT;
    case DV_OUTCOME_COMPLETED:
      return DV_VERDICT_AGREES;
    default:
      return DV_VERDICT_ERROR;
  }
}

int dv_run_verdict_failed(dv_verdict verdict) {
  return verdict == DV_VERDICT_DIVERGED || verdict == DV_VERDICT_LOST_CONTACT ||
         verdict == DV_VERDICT_ERROR || verdict == DV_VERDICT_INVALID ||
         verdict == DV_VERDICT_MISSING;
}

dv_limit_check dv_run_limit_check(double value, double limit) {
  if (isnan(limit)) return DV_LIMIT_NONE;
  return value <= limit ? DV_LIMIT_WITHIN : DV_LIMIT_OVER;
}

void dv_run_body_words(double half_thickness, char *out, size_t size) {
  if (half_thickness > 0.0)
    snprintf(out, size, "vs cylinder h %.4g mm", 1e3 * half_thickness);
  else
    snprintf(out, size, "vs thin disk");
}
