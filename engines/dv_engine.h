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

typedef struct dv_engine_stats {
  long steps;             /* internal steps taken */
  long rhs_evals;         /* right-hand side evaluations (reference), 0 for contact engines */
  double slip_max;        /* largest slip speed seen at a sample, m/s */
  double penetration_max; /* m */
  int contacts_max;       /* most contact points at a sample */
  long warnings;          /* library warnings counted (MuJoCo) */
  dv_outcome outcome;
  char detail[256]; /* why the run ended, when not completed */
} dv_engine_stats;

typedef struct dv_engine_type {
  const char *name;        /* as given to --engine */
  const char *description; /* one line */
  const char *(*version)(void);
  void *(*alloc)(const dv_scenario *sc, dv_error *err);
  int (*reset)(void *engine, const double state[RED_NSTATE], dv_error *err);
  /* advance to time t (s); the sample's t is t, or earlier at an event */
  int (*advance)(void *engine, double t, dv_sample *out, dv_error *err);
  void (*stats)(const void *engine, dv_engine_stats *out);
  void (*free)(void *engine); /* NULL-safe */
} dv_engine_type;

extern const dv_engine_type dv_engine_reduced; /* thin disk, reduced equations */
extern const dv_engine_type dv_engine_matched; /* thick disk, Newton-Euler rolling */
extern const dv_engine_type dv_engine_ode;     /* ODE 0.16 contact simulation */
extern const dv_engine_type dv_engine_mujoco;  /* MuJoCo 2.2 contact simulation */

/* NULL-terminated list of every engine */
extern const dv_engine_type *const dv_engines[];

/* the engine called name, or NULL */
const dv_engine_type *dv_engine_find(const char *name);

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
