/* run_verdict: how an engine's run compares with its reference, as one
 * word CI and people read; the same names in every output. */
#ifndef DV_RUN_VERDICT_H
#define DV_RUN_VERDICT_H

#include <stddef.h>

#include "dv_engine.h"

typedef enum dv_verdict {
  DV_VERDICT_AGREES = 0,       /* every metric within its limit */
  DV_VERDICT_EXCEEDS,          /* "exceeds tolerance": a metric above its limit */
  DV_VERDICT_DIVERGED,         /* the run failed: NaN, a blow-up, a reset state */
  DV_VERDICT_LOST_CONTACT,     /* the disk left the ground */
  DV_VERDICT_ERROR,            /* a library or set-up error */
  DV_VERDICT_ENDED_BY_EVENT,   /* the engine lay down before the reference's end (run_event.h) */
  DV_VERDICT_INVALID,          /* settings refused before the run (sweeps) */
  DV_VERDICT_MISSING,          /* never reported (a lost MPI rank) */
  DV_VERDICT_NOT_JUDGED,       /* nothing measured: a window too short, the reference itself */
  DV_VERDICT_OUTSIDE_VALIDITY, /* not judged: rolling stops describing the physics at once */
  DV_NVERDICTS
} dv_verdict;

/* "agrees", "exceeds tolerance", "diverged", "lost contact", "error",
 * "ended by event", "invalid", "missing", "not judged", "outside validity" */
const char *dv_run_verdict_name(dv_verdict verdict);

/* the verdict of a run that failed with outcome */
dv_verdict dv_run_verdict_of_outcome(dv_outcome outcome);

/* a verdict that says the run itself failed (diverged, lost contact, error, invalid, missing) */
int dv_run_verdict_failed(dv_verdict verdict);

/* a metric against its limit: within (value <= limit), over (above it, or a
 * value that is NaN: what could not be measured never passes), or none (the
 * limit is NaN: a metric without a rule is not judged) */
typedef enum dv_limit_check { DV_LIMIT_WITHIN = 0, DV_LIMIT_OVER, DV_LIMIT_NONE } dv_limit_check;
dv_limit_check dv_run_limit_check(double value, double limit);

/* which body's reference judged a run, for every output line: "vs cylinder
 * h 1.165 mm" (the matched reference of that half-thickness) or "vs thin disk" */
void dv_run_body_words(double half_thickness, char *out, size_t size);

#endif
