/* dv_engine: one interface for every way of simulating the disk.
 *
 * An engine type is a const method table (GSL style); dv_engines lists them
 * all, and the CLI and the tests iterate it. Every engine speaks the one
 * canonical state of red_disk.h (theta, theta_dot, phi_dot, psi_dot, phi,
 * psi, x, y; SI units, world frame) and converts at its own edge.
 *
 * Status: DV_OK, DV_EVENT (the run ended early: advance returns the state at
 * the end time it reports), < 0 error (the run failed; the process goes on).
 */
#ifndef DV_ENGINE_H
#define DV_ENGINE_H

#include "dv_error.h"
#include "dv_scenario.h"
#include "red_disk.h"

typedef struct dv_engine_stats {
  long steps;       /* internal steps taken */
  long rhs_evals;   /* right-hand side (or force) evaluations */
  char outcome[32]; /* "completed", "event", "diverged", ... */
  char detail[256]; /* why the run ended, when not completed */
} dv_engine_stats;

typedef struct dv_engine_type {
  const char *name;        /* as given to --engine */
  const char *description; /* one line */
  const char *(*version)(void);
  void *(*alloc)(const dv_scenario *sc, dv_error *err);
  int (*reset)(void *engine, const double state[RED_NSTATE], dv_error *err);
  /* advance to time t (s); *t_reached is t, or earlier at an event */
  int (*advance)(void *engine, double t, double *t_reached, double state[RED_NSTATE],
                 dv_error *err);
  void (*stats)(const void *engine, dv_engine_stats *out);
  void (*free)(void *engine); /* NULL-safe */
} dv_engine_type;

extern const dv_engine_type dv_engine_reduced;

/* NULL-terminated list of every engine */
extern const dv_engine_type *const dv_engines[];

/* the engine called name, or NULL */
const dv_engine_type *dv_engine_find(const char *name);

#endif
