/* dv_reference: samples and stats of the reference engines. */
#include "dv_reference.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void dv_reference_sample(const red_rolling *rr, const double s[RR_NSTATE], dv_sample *out) {
  double wdot[3];
  red_rolling_to_state(s, out->y);
  red_rolling_contact_point(rr, s, out->contact);
  out->energy = red_rolling_energy(rr, s);
  out->slip = out->penetration = 0.0;
  out->contacts = 1;
  if (red_rolling_dynamics(rr, s, wdot, out->force))
    out->force[0] = out->force[1] = out->force[2] = NAN;
}

void dv_reference_stats(const red_integrator *in, int event, const char *detail,
                        dv_engine_stats *out) {
  red_stats s;
  red_integrator_stats(in, &s);
  memset(out, 0, sizeof *out);
  out->steps = s.steps;
  out->rhs_evals = s.rhs_evals;
  out->contacts_max = 1;
  out->outcome = event >= 0 ? DV_OUTCOME_EVENT : DV_OUTCOME_COMPLETED;
  if (event >= 0) snprintf(out->detail, sizeof out->detail, "%s", detail);
}
