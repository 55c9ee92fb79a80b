/* run_judge: trajectories from outside judged as a comparison judges a linked
 * engine (run_scenario.h), each served by a replay (run_replay.h).
 *
 * What a file cannot give is not judged, and says why, never faked: the slip
 * of a file with no velocity of its own (the state form's rates assume
 * rolling), a metric whose columns the file lacks (heading and invariants
 * without phi, psi; energy without energy or a pose), and the whole run of a
 * file that ends before the compared window does without lying down. A file
 * whose samples are too sparse to interpolate within a tenth of the theta or
 * path limit is refused (DV_EINPUT): its interpolation, not the engine,
 * would decide the verdict.
 */
#ifndef DV_RUN_JUDGE_H
#define DV_RUN_JUDGE_H

#include "run_replay.h"
#include "run_scenario.h"

/* the share of a limit the interpolation's estimated error may reach */
#define DV_JUDGE_INTERP_SHARE 0.1

/* judge the n replays on sc into c: DV_OK (see c->pass); DV_EINPUT with err
 * the one line of the first file too sparse to judge; < 0 when a reference fails */
int dv_run_judge(const dv_scenario *sc, dv_replay *replays, size_t n, dv_comparison *c,
                 dv_error *err);

#endif
