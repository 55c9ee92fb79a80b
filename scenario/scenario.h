/* scenario: a scenario file, parsed (inih) and validated against a schema.
 *
 * Sections and keys (radians, SI units), see docs/scenarios.md:
 *   [scenario]   name, description, duration, output_dt, engines, memory_budget
 *   [disk]       radius, mass, thickness, A, C, gravity, friction
 *                (A, C default to a uniform disk of that thickness; thickness to 0, thin)
 *   [initial]    theta and phi, psi, x, y, theta_dot, phi_dot, psi_dot
 *                or theta + steady_circle_radius, or theta + steady_phi_dot
 *   [engines.NAME]   the settings of engine NAME, as its own table declares
 *                    (scenario_schema.h); the engines layer passes the tables
 *   [tolerance], [tolerance.NAME]   limits on the comparison metrics
 * Unknown sections and keys, duplicates, non-numbers and out-of-range values
 * are errors reported as "FILE:LINE: key: what".
 */
#ifndef DV_SCENARIO_H
#define DV_SCENARIO_H

#include <stddef.h>

#include "dv_error.h"
#include "red_disk.h"
#include "scenario_schema.h"

#define DV_MAX_TOLERANCES 32
#define DV_MAX_ENGINE_SECTIONS 20
#define DV_SETTINGS_BYTES 256 /* the largest engine settings struct */
#define DV_DERIVED_BYTES 1024 /* why an engine's derived settings are what they are */
#define DV_REPLACED_BYTES 160 /* the given settings an engine's check changed */

/* what a scenario name may hold: it names the report's directory, so it is
 * one path component of these characters, and not "." or ".." */
#define DV_SCENARIO_NAME_CHARS "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789._-+"

/* the memory a run takes: DV_MEMORY_BASE_MIB MiB plus DV_MEMORY_PER_SAMPLE
 * bytes a sample (duration / output_dt); an upper bound on the peak RSS of
 * compare with four engines (tests/check_memory.sh, docs/reliability.md) */
#define DV_MEMORY_PER_SAMPLE 1024
#define DV_MEMORY_BASE_MIB 64
#define DV_MEMORY_BUDGET_GIB 1.0 /* [scenario] memory_budget's default */

/* [disk] friction's default: every shipped scene rolls within it up to where its
 * motion ends (the largest ratio |F_h| / F_z the reference needs: 1.55 on
 * steady_steep; docs/scenarios.md) */
#define DV_FRICTION_DEFAULT 2.0

/* a scenario file larger than this is refused before more of it is read */
#define DV_SCENARIO_MAX_BYTES (1024 * 1024)

typedef enum dv_init_mode {
  DV_INIT_STATE = 0,     /* the state is given key by key */
  DV_INIT_STEADY_RADIUS, /* theta + steady_circle_radius */
  DV_INIT_STEADY_PHI_DOT /* theta + steady_phi_dot */
} dv_init_mode;

/* the metrics a comparison measures and a tolerance may limit */
typedef enum dv_metric_id {
  DV_THETA_MAX_ERR = 0,
  DV_THETA_RMS_ERR,
  DV_PATH_MAX_ERR,
  DV_PATH_RMS_ERR,
  DV_PATH_HAUSDORFF,
  DV_ENERGY_DRIFT,
  DV_SLIP_MAX,
  DV_THETA_EXTREMA_ERR, /* the lowest and highest theta, each against the reference's */
  DV_INVARIANT_DRIFT,   /* f1, f2 along the engine's own states, of the momentum scale */
  DV_THETA_TURNING_ERR, /* theta at the k-th maximum and minimum, each against the reference's */
  DV_NUTATION_PERIOD_ERR, /* the k-th nutation period against the reference's, s */
  DV_HEADING_PERIOD_ERR,  /* the heading advance over the k-th period against the reference's */
  DV_PHASE_ERR,           /* how far along the reference's contact path the engine's contact is */
  DV_TURNING_LAG, /* the k-th turn's time against the reference's k-th, cumulative, s */
  DV_NMETRICS
} dv_metric_id;

/* names as in scenario files and reports: "theta_max_err", ... */
extern const char *const dv_metric_names[DV_NMETRICS];
/* each metric's unit as reports write it after a value: "rad", "m", "s",
 * "of E(0)", ... */
extern const char *const dv_metric_units[DV_NMETRICS];

/* one tolerance: metric <= limit, for one engine or all ("") */
typedef struct dv_tolerance {
  char engine[32];
  dv_metric_id metric;
  double limit;
} dv_tolerance;

/* an engine's settings: a block only that engine's table knows the layout of */
typedef union dv_settings_block {
  double align;
  void *align_ptr;
  unsigned char bytes[DV_SETTINGS_BYTES];
} dv_settings_block;

typedef struct dv_scenario {
  char path[1024];
  char name[64];
  char description[256];
  char engines[64];     /* engines a comparison runs, e.g. "mujoco, ode" ("": the default) */
  double duration;      /* s */
  double output_dt;     /* s */
  double memory_budget; /* GiB: a run whose samples would need more is refused */
  red_disk disk;
  double thickness; /* m, [disk] thickness, full: 0 the thin disk, else what the engines model */
  double friction;  /* [disk] friction: the coefficient against the ground, every engine's */
  dv_init_mode init_mode;
  double initial[RED_NSTATE];                  /* resolved initial state */
  double steady_circle_radius, steady_phi_dot; /* m, rad/s as given; NAN when not */
  size_t ntolerances;
  dv_tolerance tolerances[DV_MAX_TOLERANCES];
  /* the engine tables it was read with, and their values */
  size_t nsections;
  const dv_settings_section *sections[DV_MAX_ENGINE_SECTIONS];
  dv_settings_block settings[DV_MAX_ENGINE_SECTIONS];
  /* settings a section's check derived (a default of NAN: not given): one
   * line saying why, per section ("" when nothing was derived) */
  char derived[DV_MAX_ENGINE_SECTIONS][DV_DERIVED_BYTES];
  unsigned derived_keys[DV_MAX_ENGINE_SECTIONS]; /* bit i: the section's key i was derived */
  /* given settings the section's check changed: "timestep 0.01 -> 0.005; ..." */
  char replaced[DV_MAX_ENGINE_SECTIONS][DV_REPLACED_BYTES];
  unsigned given_keys[DV_MAX_ENGINE_SECTIONS];   /* bit i: the file, --set or code set key i */
  unsigned core_given[3]; /* the same for [scenario], [disk], [initial] (dv_scenario_with) */
} dv_scenario;

/* engines: NULL-terminated, at most DV_MAX_ENGINE_SECTIONS, each named after
 * its engine. Every setting at its default; the rest zero (for scenarios
 * built in code). */
void dv_scenario_init(dv_scenario *sc, const dv_settings_section *const *engines);

/* a scenario built in code: [scenario], [disk] and [initial] at their
 * defaults (as a file that gives no optional key) */
void dv_scenario_core_defaults(dv_scenario *sc);

/* set [SECTION] KEY of the core sections to v, checked as in a file */
int dv_scenario_set_core(dv_scenario *sc, const char *section, const char *key, double v,
                         dv_error *err);

/* the core sections' checks and what they derive (the moments, a steady
 * start), in a load's order; DV_OK or DV_EINPUT ("disk.C: ...") */
int dv_scenario_check_core(dv_scenario *sc, dv_error *err);

/* parse and validate path against the core sections and engines; overrides
 * are "section.key=value" strings applied after the file (as from --set).
 * Returns DV_OK or DV_EINPUT with err set. */
int dv_scenario_load(const dv_settings_section *const *engines, const char *path,
                     const char *const *overrides, size_t noverrides, dv_scenario *sc,
                     dv_error *err);

/* on 1: from now on each file a load reads is kept whole in memory, and a
 * later load of the same path in this process (or a child forked after it)
 * reads it from there, never again from the file: a command that loads
 * twice (once to check, then with its settings probed in a process of its
 * own: a time limit) reads a FIFO or an edited file once; 0: loads read
 * their files again (the default), what is kept stays for a later on */
void dv_scenario_keep_texts(int on);

/* base with overrides ("section.key=value", as --set) applied and every
 * section's check run again: what a load of base's file with those overrides
 * gives, without reading the file again (the values base's checks derived,
 * such as A, C, a steady start's rates and an engine's step, are derived
 * anew). Returns DV_OK or DV_EINPUT ("section.key: what"). */
int dv_scenario_with(const dv_scenario *base, const char *const *overrides, size_t noverrides,
                     dv_scenario *out, dv_error *err);

/* the settings block of engine (its struct, as its table describes), or NULL */
const void *dv_scenario_settings(const dv_scenario *sc, const char *engine);

/* the value of [engines.ENGINE] key as a number (a choice's index); NAN when unknown */
double dv_scenario_get(const dv_scenario *sc, const char *engine, const char *key);

/* set [engines.ENGINE] key from text (as in a file), or to a number, checked as at load */
int dv_scenario_set(dv_scenario *sc, const char *engine, const char *key, const char *text,
                    dv_error *err);
int dv_scenario_set_number(dv_scenario *sc, const char *engine, const char *key, double v,
                           dv_error *err);

/* why engine's derived settings are what they are ("timestep 5e-05 s: wobble
 * period 0.04 s / 800, ..."), as its section's check wrote it; "" when the
 * scenario gave them or the engine derives none. Setting one of those keys
 * afterwards (dv_scenario_set*) clears it: the line no longer describes them. */
const char *dv_scenario_derived(const dv_scenario *sc, const char *engine);

/* 1 when [engines.ENGINE] key was derived (and not set since), else 0 */
int dv_scenario_is_derived(const dv_scenario *sc, const char *engine, const char *key);

/* 1 when [engines.ENGINE] key was given (file, --set, dv_scenario_set*), else 0:
 * a section's check derives only what was not */
int dv_scenario_is_given(const dv_scenario *sc, const char *engine, const char *key);

/* run engine section i's check (0, or -1 with issue filled in), recording
 * every given setting it changed (dv_scenario_replaced) */
int dv_scenario_check_engine(dv_scenario *sc, size_t i, dv_setting_issue *issue);

/* the given settings of engine its check changed ("timestep 0.01 -> 0.005"),
 * the reason being in dv_scenario_derived; "" when none */
const char *dv_scenario_replaced(const dv_scenario *sc, const char *engine);

/* for a section's check: record why, naming the keys derived (NULL-terminated); a why
 * longer than DV_DERIVED_BYTES - 1 is cut and ends with an ellipsis */
void dv_scenario_set_derived(dv_scenario *sc, const char *engine, const char *const *keys,
                             const char *why);

/* the limit on metric for engine: [tolerance.ENGINE], else [tolerance], else INFINITY;
 * *own (NULL: not asked) is 1, 0 or -1 for those three */
double dv_scenario_tolerance(const dv_scenario *sc, const char *engine, dv_metric_id metric,
                             int *own);

/* 0 when name may name a scenario (DV_SCENARIO_NAME_CHARS), else -1 with what set */
int dv_scenario_check_name(const char *name, char *what, size_t size);

/* the memory a run of sc takes, GiB (DV_MEMORY_BASE_MIB plus DV_MEMORY_PER_SAMPLE
 * a sample); a load refuses more than sc->memory_budget. *samples: the count */
double dv_scenario_memory_gib(const dv_scenario *sc, double *samples);

#endif
