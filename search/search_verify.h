/* search_verify: does a contact engine converge to the reference?
 *
 * The engine's time step and contact softness are refined together: h =
 * dt/2^k for k = 0..3 (dt: the scenario's step), the softness scaled by
 * h/dt (and kept at least as many steps as the library ties it to). From the
 * max theta errors against the engine's own reference (the matched one for a
 * cylinder; pointwise to the reference's horizon), the observed order p comes
 * from the last three, and Richardson extrapolation gives the discrepancy at
 * h -> 0:
 *
 *   e(0) = e(h3) - (e(h2) - e(h3)) / (2^p - 1)
 *
 * Its uncertainty is how far the same extrapolation from the first three
 * levels lands from it, when their two orders agree within DV_VERIFY_ORDER_SPREAD
 * (the errors are in their asymptotic range); an e(0) below zero (the
 * errors are magnitudes) is itself within it. "converges to the reference"
 * when |e(0)| <= max(DV_VERIFY_FLOOR, uncertainty) (or the errors already
 * sit below the floor); "converges elsewhere" when e(0) is beyond both, or
 * the errors are flat above the floor (a model discrepancy: its dominant
 * cause from attribution); "does not converge" when the errors grow or wander.
 */
#ifndef DV_SEARCH_VERIFY_H
#define DV_SEARCH_VERIFY_H

#include <stddef.h>

#include "dv_error.h"
#include "search_attribute.h"

#define DV_VERIFY_FLOOR 1e-4 /* rad: a tenth of the engines' default accuracy goal */
#define DV_VERIFY_LEVELS 4
#define DV_VERIFY_FLAT 0.1 /* errors that change less than this share over dt..dt/8 are flat */
#define DV_VERIFY_ORDER_SPREAD 0.5 /* the two observed orders agree within this */

typedef enum dv_convergence {
  DV_CONVERGES = 0,       /* to the reference */
  DV_CONVERGES_ELSEWHERE, /* to something else: a model discrepancy */
  DV_DOES_NOT_CONVERGE,   /* the errors do not fall with the step */
  DV_CONVERGE_NOT_JUDGED, /* levels with the same error exactly, or a pass from no order */
} dv_convergence;

/* "converges to the reference", "converges elsewhere", "does not converge",
 * "not judged" */
const char *dv_search_convergence_name(dv_convergence c);

/* why a fit is DV_CONVERGE_NOT_JUDGED, in words ("" when it is judged): two
 * levels with the same error exactly (one run given twice, or errors of 0
 * that nothing can fall from), or errors that do not fall (order none) yet
 * sit under the floor: neither shows convergence, whatever their size */
void dv_search_convergence_why(const double *step, const double *error, int n,
                               dv_convergence verdict, char *why, size_t size);

typedef struct dv_verification {
  double step[DV_VERIFY_LEVELS];  /* s */
  double error[DV_VERIFY_LEVELS]; /* max theta error against the engine's reference, rad */
  double order;                   /* observed; NAN when the errors do not fall */
  double extrapolated;            /* e(0), rad */
  double uncertainty;             /* of e(0), rad (0: not estimated) */
  dv_convergence verdict;
  char cause[200]; /* converges elsewhere: the knob whose change removes it (attribution) */
} dv_verification;

/* order, extrapolation, uncertainty and verdict (before attribution) from
 * v->step and v->error: dv_search_convergence_judge over verify's 4 levels */
void dv_search_verify_judge(dv_verification *v);

#define DV_CONVERGE_MIN_LEVELS 3
#define DV_CONVERGE_MAX_LEVELS 8
#define DV_CONVERGE_MIN_RATIO 1.1 /* each step at least this much larger than the next */
#define DV_CONVERGE_SAFETY 1.25   /* Roache's grid-convergence-index factor, three levels */

/* The same judging over n errors (DV_CONVERGE_MIN_LEVELS..MAX_LEVELS) at
 * decreasing steps of any ratios (halving is verify's): the order p and e(0)
 * from the last three levels (e(h) = e(0) + K h^p through them: p from the
 * ratio of successive differences, solved by bisection when the two step
 * ratios differ); the uncertainty, with 4 or more levels, from the triple
 * before the last as above; with 3 there is no second triple, and it is
 * Roache's grid convergence index, DV_CONVERGE_SAFETY |e(finest) - e(0)|
 * (the band an order observed from three levels puts on the finest error's
 * extrapolation). The flat test compares the first and the last error.
 * Over verify's 4 halving levels this is dv_search_verify_judge, bit for bit. */
typedef struct dv_convergence_fit {
  double order;        /* NAN when the errors do not fall */
  double extrapolated; /* e(0) */
  double uncertainty;  /* 0: not estimated */
  dv_convergence verdict;
} dv_convergence_fit;
void dv_search_convergence_judge(const double *step, const double *error, int n,
                                 dv_convergence_fit *fit);

/* refine engine on the scenario and judge its convergence */
int dv_search_verify(const struct dv_scenario *sc, const char *engine, dv_verification *out,
                     dv_error *err);

#endif
