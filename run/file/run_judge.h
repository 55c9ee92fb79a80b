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

/* A row between the scenario's sample times, which no sample serves, is
 * refused (DV_EINPUT) when it lies farther from the Akima interpolant through
 * the rows at the sample times than twice that interpolant's Akima-Steffen
 * difference there plus this share of the theta or path limit (run_replay.h).
 * Measured on honest files written every 1 ms and judged at output_dt 0.01 s
 * (simulate --set scenario.output_dt=0.001): MuJoCo and ODE on a 1 s steady
 * circle (tests/data/short_circle.ini) at most 1.6e-6 rad and 2.3e-7 m past
 * the uncertainty; MuJoCo's fall (scenarios/falling.ini), theta dropping fast
 * before it lies down, 5.3e-4 rad and 3.0e-5 m: 0.053 and 0.03 of the limits
 * 0.01 rad and 0.001 m, so 0.5 leaves a margin of 9 over the worst. A hostile
 * file with theta 1 rad off on the rows between is 1 rad past it. Re-measure:
 * judge such a file with --set tolerance.theta_max_err=1e-12 (or
 * path_max_err): the refusal prints the distance. */
#define DV_JUDGE_BETWEEN_SHARE 0.5

/* A state-form file's energy column is refused (DV_EINPUT) where, within the
 * compared window, it lies farther from the energy of the state its row gives
 * (dv_pose_energy; rates given, or derived from the angles) than this share
 * of the energy drift's limit, as a share of the starting energy: the drift
 * would measure the column, not the run. Measured on honest files (simulate
 * of every engine, 1 s steady circle tests/data/short_circle.ini and
 * scenarios/falling.ini, with their rates, and cut to t,theta,phi,psi,x,y,
 * energy): with rates at most 1.4e-4 (MuJoCo's fall: its contact is not pure
 * rolling) against the limit 0.01, so 0.1 leaves a margin of 7; with rates
 * derived at most 4.7e-3 (Simbody's fall near its window's end: the derived
 * rates' error), so 0.8 leaves 1.7. A file whose energy stays constant while
 * its state slows by 0.94% over 1 s is off by 0.0117: 1.46 times it.
 * Re-measure: judge such a file with --set tolerance.energy_drift=1e-12; the
 * refusal prints the gap. */
#define DV_JUDGE_ENERGY_SHARE 0.1
#define DV_JUDGE_ENERGY_SHARE_DERIVED 0.8

/* judge the n replays on sc into c: DV_OK (see c->pass); DV_EINPUT with err
 * the one line of the first file too sparse to judge; < 0 when a reference fails */
int dv_run_judge(const dv_scenario *sc, dv_replay *replays, size_t n, dv_comparison *c,
                 dv_error *err);

#endif
