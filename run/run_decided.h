/* run_decided: what decided an engine's verdict, in one line and in sentences.
 *
 * decided (at most DV_DECIDED_MAX characters, one line) starts with
 * "passes", "fails" or "not judged" and names what decided:
 *   fails: turning_lag 0.14 s > 0.0042 s (5th minimum 143 ms early)
 *   passes: theta_max_err 3.3e-05 rad <= 0.0002 rad (0.17 of its limit), vs cylinder h 1 mm
 *   not judged: compared window 0 s (rolling needs more friction than mu = 0.3 from t = 1.23 s)
 *   fails: the run diverged at t = 0.42 s
 * a fail's metric is the one furthest over its limit (value / limit; a
 * value not measured is the furthest), a pass's the one nearest its limit;
 * the reference is named where it is not the thin disk. decided_why says,
 * in sentences, where the compared window ends and why, how far the
 * pointwise metrics reach (the shadow of the early error) and where the
 * deciding limit comes from, with what the shadow added to it.
 */
#ifndef DV_RUN_DECIDED_H
#define DV_RUN_DECIDED_H

#include "run_scenario.h"

/* r->decided and r->decided_why, once r is judged against ref (its
 * reference's run: ref_st; ref_end: where that reference stops describing
 * the physics) in c */
void dv_run_say_decided(const dv_comparison *c, const dv_traj *ref, const dv_engine_stats *ref_st,
                        double ref_end, dv_engine_result *r);

/* the metric that decided r's verdict as above, or -1 where no metric did
 * (a run that failed, was not judged, or lay down where it should not) */
int dv_run_deciding_metric(const dv_engine_result *r);

/* what the shadow added to metric m's limit, in words, into buf: ", plus
 * 0.00019 rad the spread of its early error excuses" ("" where nothing) */
void dv_run_excused_words(const dv_engine_result *r, int m, char *buf, size_t size);

#endif
