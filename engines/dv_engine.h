/* dv_engine: one interface for every way of simulating the disk.
 *
 * An engine type is a const method table (GSL style); dv_engines lists them
 * all, and the CLI and the tests iterate it. Every engine speaks the one
 * canonical state of red_disk.h (theta, theta_dot, phi_dot, psi_dot, phi,
 * psi, x, y; SI units, world frame) and converts at its own edge (dv_pose.h).
 *
 * Status: DV_OK; DV_EVENT: the run ended early and normally (the reference
 * reached an event); < 0: the run failed (diverged, lost contact, a library
 * error): stats say which, the process goes on. Engines never call exit.
 */
#ifndef DV_ENGINE_H
#define DV_ENGINE_H

#include "dv_error.h"
#include "scenario.h"
#include "red_disk.h"

/* one output sample */
typedef struct dv_sample {
  double t;             /* s */
  double y[RED_NSTATE]; /* canonical state */
  double contact[2];    /* lowest point of the body on the ground (x, y), m */
  double energy;        /* mechanical energy, J */
  double slip;          /* speed of the body's lowest point, m/s */
  double penetration;   /* depth of the lowest point below the ground, m (>= 0) */
  int contacts;         /* contact points the engine reports */
  double force[3];      /* contact force on the disk (N), NaN where the engine has none */
} dv_sample;

/* outcomes of a run */
typedef enum dv_outcome {
  DV_OUTCOME_COMPLETED = 0, /* ran to the end */
  DV_OUTCOME_EVENT,         /* the reference ended at an event (lying down, validity window) */
  DV_OUTCOME_DIVERGED,      /* NaN, a library's bad-state warning, or a runaway energy */
  DV_OUTCOME_LOST_CONTACT,  /* the disk left the ground */
  DV_OUTCOME_ERROR,         /* a library error callback or a setup failure */
} dv_outcome;

const char *dv_outcome_name(dv_outcome outcome);

/* why a run failed, as the engine saw it */
typedef enum dv_failure {
  DV_FAILURE_NONE = 0,
  DV_FAILURE_NAN,          /* a non-finite state */
  DV_FAILURE_RESET,        /* the library replaced a bad state silently */
  DV_FAILURE_ENERGY,       /* the energy ran away */
  DV_FAILURE_SANK,         /* the disk sank into the ground */
  DV_FAILURE_LOST_CONTACT, /* the disk left the ground */
  DV_FAILURE_LIBRARY,      /* a library error */
  DV_FAILURE_SETUP,        /* a model or initial state the engine cannot take */
  DV_NFAILURES
} dv_failure;

/* "NaN", "silent reset", "energy blow-up", "sinks", "lost contact", "error", ... */
const char *dv_failure_name(dv_failure failure);

/* the outcome a failure ends a run with */
dv_outcome dv_failure_outcome(dv_failure failure);

typedef struct dv_engine_stats {
  long steps;             /* internal steps taken */
  long rhs_evals;         /* right-hand side evaluations (reference), 0 for contact engines */
  double slip_max;        /* largest slip speed seen at a sample, m/s */
  double penetration_max; /* m */
  int contacts_max;       /* most contact points at a sample */
  long warnings;          /* library warnings counted (MuJoCo) */
  dv_outcome outcome;
  dv_failure failure; /* DV_FAILURE_NONE unless the run failed */
  char detail[256];   /* why the run ended, when not completed */
  char method[256];   /* how the run was computed, where a reader needs to know, or "" */
  /* the run ended where the disk lies down (DV_OUTCOME_EVENT): -1 at theta_limit,
   * +1 at pi - theta_limit; 0 otherwise */
  int lay_down;
} dv_engine_stats;

/* what an engine is for */
typedef enum dv_engine_role {
  DV_ENGINE_CONTACT = 0,      /* a contact simulation, compared with the references */
  DV_ENGINE_THIN_REFERENCE,   /* the thin disk: the reference of every comparison */
  DV_ENGINE_MATCHED_REFERENCE /* the disk of a stand-in's thickness, rolling */
} dv_engine_role;

/* what best, stability and sweeps vary: a discrete choice and a step */
typedef struct dv_engine_search {
  const char *section;    /* engine whose [engines.NAME] holds the keys */
  const char *choice_key; /* e.g. "integrator" */
  const char *step_key;   /* e.g. "timestep", "rtol" */
  double lo, hi;          /* range of the step searched */
  /* a reference: the step range of its own work-precision curves, drawn with a
   * contact engine's sweep ("rtol=1e-6..1e-13:8"); NULL: none */
  const char *work_precision;
} dv_engine_search;

/* a further knob attribution turns: key to value ("gyroscopic" to "on") */
typedef struct dv_engine_extra_knob {
  const char *what; /* "gyroscopic term" */
  const char *key, *value;
} dv_engine_extra_knob;

/* a contact engine's keys of [engines.NAME] that attribution turns */
typedef struct dv_engine_contact {
  const char *geom_key;      /* the body's shape, e.g. "geom" */
  const char *thin_choice;   /* its value for the exact thin disk, e.g. "thin" */
  const char *softness_key;  /* the contact's softness, e.g. "solref_timeconst", "soft_cfm" */
  double stiffer;            /* factor on it for a stiffer contact (0.25, 0.01) */
  double softness_min_steps; /* the library raises the softness to this many steps (0: none) */
  const char *friction_key;  /* e.g. "friction" */
  /* an adapter's: geom_key and thin_choice NULL where the engine has no thin
   * disk (a cylinder always); softness_key NULL where it has no softness */
  const dv_engine_extra_knob *extra;
  size_t nextra;
} dv_engine_contact;

typedef struct dv_engine_type {
  const char *name;        /* as given to --engine */
  const char *description; /* one line */
  dv_engine_role role;
  const dv_settings_section *settings; /* [engines.NAME] */
  const dv_engine_search *search;      /* NULL: nothing to search */
  const dv_engine_contact *contact;    /* a contact engine's knobs; NULL for references */
  /* half-thickness (m) of the body it simulates in sc: 0 for the thin disk or a
   * smooth stand-in compared with it; NULL: 0 */
  double (*half_thickness)(const dv_scenario *sc);
  /* a reference: make sc's reference settings tighter than any compared with
   * (the reference of a sweep over a reference's own settings); NULL otherwise */
  int (*tighten)(dv_scenario *sc, dv_error *err);
  const char *(*version)(void);
  void *(*alloc)(const dv_scenario *sc, dv_error *err);
  int (*reset)(void *engine, const double state[RED_NSTATE], dv_error *err);
  /* advance to time t (s); the sample's t is t, or earlier at an event */
  int (*advance)(void *engine, double t, dv_sample *out, dv_error *err);
  void (*stats)(const void *engine, dv_engine_stats *out);
  void (*free)(void *engine); /* NULL-safe */
  /* an engine made at run time, not in the registry (a recorded trajectory
   * replayed, run/file/run_replay.h): alloc given its own table, whose data it
   * reads; NULL for the registry's engines, which use alloc */
  void *(*alloc_self)(const struct dv_engine_type *self, const dv_scenario *sc, dv_error *err);
  const void *data;
  /* an engine outside the build (an adapter, engines/adapter/): run only
   * where named, never by default; why it cannot run ("" where it can) */
  int outside;
  const char *missing;
  /* its calls go to a module opened when it first runs (engine_module.h) */
  int module;
} dv_engine_type;

/* every engine's table, dv_engine_NAME (engines/NAME/), as dv_engines.def lists them */
#define DV_ENGINE(name) extern const dv_engine_type dv_engine_##name;
#include "dv_engines.def"
#undef DV_ENGINE
#define DV_ENGINE(name) +1
enum { DV_NENGINES = 0
#include "dv_engines.def"
};
#undef DV_ENGINE

/* the engines linked in, NULL-terminated (dv_engines.def) */
extern const dv_engine_type *const dv_engines_linked[];

#define DV_MAX_ADAPTERS 12 /* engines outside the build a process takes (adapter.h) */
#define DV_MAX_REGISTERED (DV_NENGINES + DV_MAX_ADAPTERS)

/* every engine, NULL-terminated: the linked ones, then the adapters found
 * (engines/adapter/adapter.h), read once per process */
const dv_engine_type *const *dv_engine_list(void);

/* the engine called name, or NULL */
const dv_engine_type *dv_engine_find(const char *name);

/* why engine cannot run: its module is missing or broken, or the adapter's
 * program is (opens the module); NULL where it can run */
const char *dv_engine_unavailable(const dv_engine_type *engine);

/* the first engine of role (every role has one) */
const dv_engine_type *dv_engine_of_role(dv_engine_role role);

/* the half-thickness of engine's body in sc (0: thin) */
double dv_engine_half_thickness(const dv_engine_type *engine, const dv_scenario *sc);

/* every engine's detail for the run ending at the lying-down limit: "theta
 * reached the lower limit 0.01 rad" (lower: theta < theta_limit, else
 * theta > pi - theta_limit), then " at t = T s" when t is finite */
void dv_engine_limit_detail(int lower, double theta_limit, double t, char *buf, size_t size);

/* a run ends lying down at time t (lower: at theta_limit, else at pi -
 * theta_limit): stats' outcome (an event), side and detail, in the words of
 * dv_engine_limit_detail */
void dv_engine_lay_down(dv_engine_stats *stats, int lower, double theta_limit, double t);

/* does engine simulate a stand-in shape in sc, not the exact thin disk (0 for references) */
int dv_engine_stand_in(const dv_engine_type *engine, const dv_scenario *sc);

/* does engine simulate the scene's own body in sc: the thin disk where [disk]
 * thickness is 0, else the cylinder of that thickness (1 for references) */
int dv_engine_own_body(const dv_engine_type *engine, const dv_scenario *sc);

/* the knobs of engine that decide its answer, as they ran in sc: "integrator
 * implicit, timestep 8e-06 s, solref_timeconst 1.6e-05 s, geom thin" ("" for
 * an engine with none) */
void dv_engine_knobs_text(const dv_engine_type *engine, const dv_scenario *sc, char *buf,
                          size_t size);

/* sc, loaded against every engine's settings table (scenario.h) */
int dv_engine_load_scenario(const char *path, const char *const *overrides, size_t noverrides,
                            dv_scenario *sc, dv_error *err);

/* a scenario with every engine's settings at their defaults (for code); those
 * derived from the scene (NAN) stay NAN and each engine derives them from
 * the scenario it is given, unless dv_engine_derive_settings fills them */
void dv_engine_init_scenario(dv_scenario *sc);

/* run every engine's section check on sc, as a load does: the settings it
 * leaves to the scene (NAN) derived, with their reasons (dv_scenario_derived);
 * for scenarios built in code, once their disk, state and times are set */
int dv_engine_derive_settings(dv_scenario *sc, dv_error *err);

/* parse "mujoco,ode" into engines (NULL-terminated, at most max - 1) */
int dv_engine_parse_list(const char *list, const dv_engine_type **engines, size_t max,
                         dv_error *err);

/* fill the sample's derived fields (contact, energy, slip, penetration) from a
 * pose and geometry; used by the contact engines */
struct dv_pose;
struct dv_geometry;
void dv_sample_from_pose(const red_disk *disk, const struct dv_geometry *geom,
                         const struct dv_pose *pose, double t, const double *prev_y,
                         dv_sample *out);

/* fold a sample into the per-run maxima: slip, penetration, contacts */
void dv_stats_add_sample(dv_engine_stats *stats, const dv_sample *s);

#endif
