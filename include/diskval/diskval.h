/* diskval: the rolling-disk reference, the scenario loader and the engine
 * comparison, as a library (libdiskval, CMake package diskval::diskval,
 * pkg-config module diskval).
 *
 * Units: SI throughout (s, m, kg, rad, rad/s, J).
 * Status returns (every int function): 0 ok, > 0 informational (1: the run
 * ended early at an event, e.g. the disk lay down), < 0 error (-1 bad input,
 * -2 numerical failure, -3 I/O or memory); on error err->msg says why (err
 * may be NULL). Objects are owned by the caller and freed with their _free
 * function (NULL-safe); out-parameters are written only on success.
 * One thread at a time: the engines' and GSL's error handlers are process-wide
 * (the computing calls switch GSL's aborting handler off while they run and
 * put the caller's back); run in parallel in processes, as diskval suite does.
 */
#ifndef DISKVAL_H
#define DISKVAL_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define DISKVAL_API __attribute__((visibility("default")))
#else
#define DISKVAL_API
#endif

#define DISKVAL_OK 0
#define DISKVAL_EVENT 1     /* informational: a run ended at an event */
#define DISKVAL_EINPUT -1   /* bad input: scenario, engine name, argument */
#define DISKVAL_ENUMERIC -2 /* a numerical method failed */
#define DISKVAL_ESYSTEM -3  /* I/O or memory */

#define DISKVAL_MAX_METRICS 32

/* a caller-owned error message buffer, filled on failure */
typedef struct diskval_error {
  char msg[512];
} diskval_error;

/* a scenario: disk, initial state, times, engine settings, tolerances (opaque) */
typedef struct diskval_scenario diskval_scenario;

/* an engine's samples over a scenario (opaque) */
typedef struct diskval_trajectory diskval_trajectory;

/* the disk: radius (m), mass (kg), moments A about a diameter and C about the
 * axis (kg m^2; both 0: a uniform disk of that thickness; A alone 0: its A),
 * gravity (m/s^2),
 * full thickness (m, less than the diameter; 0: the thin disk). Checked as
 * a scenario file's [disk] (e.g. C <= 2A) */
typedef struct diskval_disk {
  double radius, mass, A, C, gravity;
  double thickness;
} diskval_disk;

/* the state: tilt theta (rad, pi/2 upright), its rate, the heading and spin
 * rates, heading phi, spin psi (rad) and the centre's ground projection (m) */
typedef struct diskval_state {
  double theta, theta_dot, phi_dot, psi_dot, phi, psi, x, y;
} diskval_state;

/* one output sample: time (s), state, contact point on the ground (m), energy (J) */
typedef struct diskval_sample {
  double t;
  diskval_state state;
  double contact_x, contact_y;
  double energy;
} diskval_sample;

/* metrics of an engine against a reference; NAN where not measured */
typedef struct diskval_metrics {
  size_t n;                              /* metrics in use */
  const char *name[DISKVAL_MAX_METRICS]; /* "theta_max_err", "path_max_err", ... (static) */
  double value[DISKVAL_MAX_METRICS];     /* rad, m, or relative, as the name says */
  size_t n_window;                       /* samples compared */
  double t_window;                       /* end of the compared window, s */
} diskval_metrics;

/* an engine compared with the reference for the body it simulates */
typedef struct diskval_comparison {
  int pass;                          /* 1: judged, every metric within its limit, lying down
                                      * (if it does) where the reference allows */
  char verdict[32];                  /* "agrees", "exceeds tolerance", "diverged", ... */
  char decided[160];                 /* what decided the verdict, one line: "passes: METRIC
                                      * V <= L (...)", "fails: ...", "not judged: ..." */
  diskval_metrics metrics;           /* against its own reference */
  double limit[DISKVAL_MAX_METRICS]; /* each metric's limit, same order */
  double wall_s;                     /* wall-clock time of the engine's run, s */
  const char *decided_metric;        /* the metric whose limit decided, a name of metrics
                                      * (static), or NULL when none did (a run that failed,
                                      * one not judged, an event) */
  char decided_why[1600];            /* why, in sentences: the reference, where the compared
                                      * window ends and why, the horizon, the limit's source */
} diskval_comparison;

/* the library's version, "MAJOR.MINOR.PATCH" (static) */
DISKVAL_API const char *diskval_version(void);

/* load and validate a scenario file; overrides are n "section.key=value" strings (as --set) */
DISKVAL_API int diskval_scenario_load(const char *path, const char *const *overrides, size_t n,
                                      diskval_scenario **out, diskval_error *err);

/* a scenario from code, every value checked and engine settings derived as a load
 * would (errors name the file's key: "disk.C: ..."); name as a file's (not NULL);
 * 0 < output_dt <= duration (s); disk A = 0: the uniform disk's A */
DISKVAL_API int diskval_scenario_new(const char *name, const diskval_disk *disk,
                                     const diskval_state *initial, double duration,
                                     double output_dt, diskval_scenario **out, diskval_error *err);

/* set [engines.ENGINE] key from text, checked as in a file and by --set (e.g.
 * "mujoco", "timestep", "1e-4"): its range, then every engine section's
 * checks across keys (a theta_limit past the initial theta is refused); sc
 * is unchanged when it is refused. ENGINE "disk" and key "friction" set
 * [disk] friction, the coefficient every engine takes (default 2) */
DISKVAL_API int diskval_scenario_set(diskval_scenario *sc, const char *engine, const char *key,
                                     const char *value, diskval_error *err);

/* the scenario's name, duration (s) and initial state; NULL-safe on the outputs */
DISKVAL_API const char *diskval_scenario_name(const diskval_scenario *sc);
DISKVAL_API double diskval_scenario_duration(const diskval_scenario *sc);
DISKVAL_API void diskval_scenario_initial(const diskval_scenario *sc, diskval_state *out);

/* the scenario's disk, its moments derived where not given */
DISKVAL_API void diskval_scenario_disk(const diskval_scenario *sc, diskval_disk *out);

/* free a scenario (NULL-safe) */
DISKVAL_API void diskval_scenario_free(diskval_scenario *sc);

/* the name of engine i (0, 1, ...: "reduced", "matched", "mujoco", "ode", ...), NULL past the last
 */
DISKVAL_API const char *diskval_engine_name(size_t i);

/* run engine over sc, a sample every output_dt: 0, 1 (ended at an event) or < 0 */
DISKVAL_API int diskval_run(const diskval_scenario *sc, const char *engine,
                            diskval_trajectory **out, diskval_error *err);

/* the number of samples in tr */
DISKVAL_API size_t diskval_trajectory_size(const diskval_trajectory *tr);

/* sample i of tr (i < size) into out; returns 0, or -1 when i is out of range */
DISKVAL_API int diskval_trajectory_sample(const diskval_trajectory *tr, size_t i,
                                          diskval_sample *out);

/* free a trajectory (NULL-safe) */
DISKVAL_API void diskval_trajectory_free(diskval_trajectory *tr);

/* metrics of engine against reference at equal times, over the window both cover
 * (runs, or samples pushed: ended as diskval_judge ends them); on error out
 * holds no metric (n 0: diskval_metric gives NAN) */
DISKVAL_API int diskval_compare_trajectories(const diskval_trajectory *engine,
                                             const diskval_trajectory *reference,
                                             diskval_metrics *out, diskval_error *err);

/* run engine on sc and judge it against its reference, as `diskval compare` does: 0 (see out->pass)
 * or < 0 (out then "not judged", pass 0, no metric; so for diskval_judge) */
DISKVAL_API int diskval_compare(const diskval_scenario *sc, const char *engine,
                                diskval_comparison *out, diskval_error *err);

/* a rigid body's pose, world frame: the disk's centre (m), the body-to-world
 * unit quaternion (w, x, y, z) with the body's z axis along the disk's axis
 * (that of R = Rz(phi) Ry(theta) Rz(psi - pi/2)), the centre's velocity (m/s)
 * and the angular velocity (rad/s) */
typedef struct diskval_pose {
  double pos[3], quat[4], vel[3], omega[3];
} diskval_pose;

/* an empty trajectory of sc (kept by the caller while the trajectory lives)
 * for the caller's own samples: an engine diskval does not link, judged
 * without files. name: the one its errors and verdict carry (NULL: "trajectory") */
DISKVAL_API int diskval_trajectory_new(const diskval_scenario *sc, const char *name,
                                       diskval_trajectory **out, diskval_error *err);

/* append the sample at time t (s, from 0, increasing): a state, or a pose
 * (with_velocity 0: vel and omega are not given; the rates come from the
 * samples). All of a trajectory's samples are states, or all poses. Checked
 * as `diskval judge` checks a file's rows ("NAME:N:COLUMN: ...", N the
 * sample from 1): finite, times increasing, a unit quaternion within 1e-6 */
DISKVAL_API int diskval_trajectory_push(diskval_trajectory *tr, double t,
                                        const diskval_state *state, diskval_error *err);
DISKVAL_API int diskval_trajectory_push_pose(diskval_trajectory *tr, double t,
                                             const diskval_pose *pose, int with_velocity,
                                             diskval_error *err);

/* judge tr (from diskval_trajectory_new, at least 5 samples, starting at
 * sc's initial state) against sc's reference as `diskval judge` does: 0 (see
 * out->pass) or < 0 (-1 with err naming the sample; e.g. samples too sparse
 * to interpolate within a tenth of the limits). tr may be pushed on after */
DISKVAL_API int diskval_judge(const diskval_scenario *sc, const diskval_trajectory *tr,
                              diskval_comparison *out, diskval_error *err);

/* the value of metric name in m, or NAN when m has none of that name */
DISKVAL_API double diskval_metric(const diskval_metrics *m, const char *name);

#ifdef __cplusplus
}
#endif

#endif
