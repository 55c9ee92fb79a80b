/* run_progress: signs of life during long runs, on stderr.
 *
 * Off until a command turns it on (dv_run_progress_start), so code that links
 * the library sees nothing. Two things, both on stderr:
 *
 *  - the progress line, only when stderr is a terminal: one line rewritten
 *    with \r, at most DV_PROGRESS_HZ times a second, from DV_PROGRESS_DELAY_S
 *    of wall time into a run, cleared when the run ends:
 *      "steady_circle mujoco  t 12.3/5000 s  3m12s left"
 *    (the time left of that run, from its rate so far); or, while tasks run in
 *    the exec pool's processes, counted by the parent as each ends:
 *      "scenario 12/30  1m05s left  (steady_circle: pass)"
 *    The tasks' own processes show nothing.
 *  - the warning, one line, terminal or not (a log that stays silent for
 *    minutes should say why), when the work ahead will take longer than
 *    DV_PROGRESS_WARN_S. Before a comparison, once for all its runs, and
 *    before a simulate's run: each engine is probed for DV_PROGRESS_PROBE_S
 *    of wall time, sampling a few times a shortest time scale of the scene
 *    (not output_dt: its first interval alone may take minutes), and its rate
 *    (wall seconds per simulated second, measured: no cost model covers the
 *    adaptive reference) times the duration summed; the runs then say
 *    nothing more. Otherwise once for each run, when DV_PROGRESS_CALIBRATE_S
 *    of it have shown its rate; and once for the tasks of a pool, from the
 *    rate of those ended.
 */
#ifndef DV_RUN_PROGRESS_H
#define DV_RUN_PROGRESS_H

#include <stddef.h>

#include "dv_engine.h"

#define DV_PROGRESS_HZ 10           /* line updates a second at most */
#define DV_PROGRESS_DELAY_S 0.25    /* s of wall time before a run's line appears */
#define DV_PROGRESS_CALIBRATE_S 0.5 /* s of wall time that set a run's estimate */
#define DV_PROGRESS_WARN_S 60.0     /* s: runs longer than this are announced */
#define DV_PROGRESS_PROBE_S 0.1     /* s of wall time a comparison's probe of an engine takes */
/* ... or less, from this much on, once its engine's whole run projects to
 * below DV_PROGRESS_WARN_S / DV_PROGRESS_PROBE_SHARE: short runs are not run twice in full */
#define DV_PROGRESS_PROBE_MIN_S 0.01
#define DV_PROGRESS_PROBE_SHARE 16.0
/* a probe samples this many times a shortest time scale of the scene (engine_scene.h) */
#define DV_PROGRESS_PROBE_PER_SCALE 4.0

/* turn progress on for command ("compare"); quiet: neither line nor warning;
 * stdout_busy: the command writes to stdout while it runs (no line when
 * stdout is a terminal too: its rows would break the line) */
void dv_run_progress_start(const char *command, int quiet, int stdout_busy);

/* before dv_run_scenario's runs: the thin reference on ref_sc three times (the
 * run and the two of the horizon), each engine on sc and, for a thick body,
 * its matched reference; probed and announced as above (nothing when the
 * warning is off, in a pool's task, or once it has been given) */
void dv_run_progress_plan(const dv_scenario *sc, const dv_scenario *ref_sc,
                          const dv_engine_type *const *engines, size_t n);

/* before verify's levels (each level k a comparison of each engine at a
 * step 2^k times finer, its references run again): probed and announced as above */
void dv_run_progress_plan_levels(const dv_scenario *sc, const dv_engine_type *const *engines,
                                  size_t n, int levels);

/* a single run of engine over sc (simulate): probed and announced as above */
void dv_run_progress_plan_run(const dv_scenario *sc, const dv_engine_type *engine);

/* the wall seconds that dv_run_progress_plan's comparison, or a run of engine
 * over sc, will take, probed whether or not the warning is on (NAN when no
 * memory); kept for the next plan, which then probes no more */
double dv_run_progress_estimate(const dv_scenario *sc, const dv_scenario *ref_sc,
                                const dv_engine_type *const *engines, size_t n);
double dv_run_progress_estimate_run(const dv_scenario *sc, const dv_engine_type *engine);

/* keep seconds (a comparison's or a run's, probed by another process: a
 * timed task) as the estimate the next dv_run_progress_estimate* or plan
 * returns without probing; NAN: none kept */
void dv_run_progress_keep_estimate(double seconds);

/* what the runs that follow are ("nudged references"); NULL: each says by its
 * engine, "reference" or "engine run" */
void dv_run_progress_role(const char *role);

/* a run of engine (a reference or not) over scenario for duration simulated
 * seconds begins, is at simulated time t, has ended (dv_run_collect calls these) */
void dv_run_progress_run_begin(const char *scenario, const char *engine, int reference,
                               double duration);
void dv_run_progress_run_at(double t);
void dv_run_progress_run_end(void);

/* n tasks of the exec pool begin ("scenario", "point"); one has ended, with a
 * note for the line (may be NULL); they have all ended. Runs in between are
 * silent (they are the tasks' own processes, or MPI ranks'); a pool inside a
 * task is silent too. */
void dv_run_progress_tasks_begin(const char *noun, size_t n);
void dv_run_progress_task_ended(const char *note);
void dv_run_progress_tasks_end(void);

/* work of a known forecast begins (best's search): announced as above when
 * longer than DV_PROGRESS_WARN_S */
void dv_run_progress_plan_total(const char *what, double seconds, const char *basis);

/* more work after what was planned (attribution after a failed comparison):
 * announced when longer than DV_PROGRESS_WARN_S, whatever was announced before */
void dv_run_progress_announce(const char *what, double seconds, const char *basis);

/* one line on stderr, "diskval COMMAND: text", where the warning is on and
 * not in a pool's task (best's probes as each ends) */
void dv_run_progress_say(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* dv_run_progress_task_ended(NULL) as the exec pool's on_result */
void dv_run_progress_on_result(size_t k, int ran, void *ctx);

#endif
