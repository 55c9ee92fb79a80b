/* dv_league: every engine on the same real objects, error against cost.
 *
 * A cell is one object (a scenario file), one engine and one accuracy target
 * T (rad of theta, with the matching path target: the scene's path limit
 * scaled as its theta limit is scaled to T). Its settings are best's search
 * (search_best.h) with both targets, stopped where a run would cost more
 * than the cost cap or where the error stops falling with the step; the
 * cell's numbers come from a compare at those settings with the targets as
 * its limits (the report that backs the cell), so re-running that compare
 * reproduces the claim. A cell is a function of the object file's bytes,
 * the engine's version, the target, the cost cap and the --set overrides:
 * its key; a league reuses every cell of its output directory whose key
 * matches and whose claims are its backing report's, so an interrupted
 * league resumes where it stopped.
 *
 * Here (report/league/): the table, a cell as JSON, the summary and the
 * writers. The cells' search, the compare backing each, the cache and the
 * pool that runs them: search/league/ (league_run.h); the command, its
 * arguments alone: cli/league/cmd_league.c.
 */
#ifndef DV_LEAGUE_H
#define DV_LEAGUE_H

#include <stddef.h>

#include "dv_error.h"

#define DV_LEAGUE_MAX_TARGETS 6
#define DV_LEAGUE_MAX_OBJECTS 64
#define DV_LEAGUE_MAX_ENGINES 16
#define DV_LEAGUE_MAX_POINTS 48 /* probes of one cell's search kept for its curve */
#define DV_LEAGUE_COST_CAP 20.0 /* s of wall a simulated s: a costlier probe is not run */
#define DV_LEAGUE_FORMAT "diskval-league/1"

/* how a cell ended */
typedef enum dv_league_outcome {
  DV_LEAGUE_REACHED = 0,   /* settings found that meet both targets */
  DV_LEAGUE_NOT_REACHED,   /* none: why and cause say what stops it */
  DV_LEAGUE_CANNOT_MODEL,  /* the engine has no shape for the object's body */
  DV_LEAGUE_NOT_RUN,       /* the league stopped before it (interrupted, or its process died) */
} dv_league_outcome;

/* "reached", "not reached", "cannot model", "not run" */
const char *dv_league_outcome_name(dv_league_outcome o);

/* one probe of a cell's search: a point of its work-precision curve */
typedef struct dv_league_point {
  char choice[32];  /* the integrator (or stepper, ...) */
  double step;      /* s (the reference: rtol) */
  double theta_err; /* rad, NAN when the run failed */
  double path_err;  /* m, NAN when the run failed */
  double cost;      /* s of wall a simulated s, counted (steps x the choice's s a step) */
  int ok;           /* ran through its compared window */
} dv_league_point;

typedef struct dv_league_cell {
  char object[64];          /* the scenario's name */
  char scenario_file[512];  /* as given */
  char engine[32];
  char engine_version[96];
  double target;            /* rad: theta_max_err's limit */
  double path_target;       /* m: path_max_err's limit */
  dv_league_outcome outcome;
  /* the settings that reached it (or, not reached, the closest probe's) */
  char choice_key[96], choice[32]; /* e.g. engines.mujoco.integrator, rk4 */
  char step_key[96];               /* e.g. engines.mujoco.timestep */
  double step;
  /* the backing compare at those settings */
  double theta_max_err, path_max_err; /* rad, m; NAN when nothing was compared */
  double wall_per_sim_s;              /* s of wall a simulated s of the engine's run */
  long steps;                         /* the engine's steps over the run */
  double sim_s;                       /* simulated s of the run */
  double order;             /* observed over the chosen integrator's probes (NAN: none) */
  char verdict[24];         /* the backing compare's: pass, fail, not judged, error */
  char why[240];            /* not reached / cannot model: what stops it, measured */
  char cause[320];          /* the knob whose change removes the error (attribution), or "" */
  char report[256];         /* the backing report's folder, relative to the league's */
  char key[17];             /* 16 hex digits */
  double wall_s;            /* s the cell took (its search and its compare) */
  size_t npoints;
  dv_league_point points[DV_LEAGUE_MAX_POINTS];
} dv_league_cell;

typedef struct dv_league_object {
  char name[64];
  char file[512];
  char description[160];
  double radius, thickness, duration; /* m, m, s */
} dv_league_object;

typedef struct dv_league_engine {
  char name[32];
  char version[96];
  int available;
  char why[240]; /* not available: the reason */
} dv_league_engine;

typedef struct dv_league {
  char date[32];     /* ISO 8601, UTC */
  char machine[256]; /* uname, CPU model, cores */
  char diskval_version[32];
  double cost_cap;   /* s a simulated s */
  size_t ntargets;
  double targets[DV_LEAGUE_MAX_TARGETS];
  size_t nobjects;
  dv_league_object objects[DV_LEAGUE_MAX_OBJECTS];
  size_t nengines;
  dv_league_engine engines[DV_LEAGUE_MAX_ENGINES];
  size_t ncells; /* nobjects x (available engines) x ntargets, object-major, then engine, target */
  dv_league_cell *cells;
  int interrupted;
  const char *const *overrides; /* the --set overrides every cell ran with (the caller's) */
  size_t noverrides;
} dv_league;

/* an engine's standing at one target, over the objects it was run on */
typedef struct dv_league_summary {
  const char *engine;
  double target;
  size_t reached, not_reached, cannot_model, not_run;
  double geomean_wall_per_sim_s; /* over the reached cells; NAN when none */
  double geomean_steps_per_sim_s;
} dv_league_summary;

/* the summary of engine at target */
void dv_league_summarize(const dv_league *lg, const char *engine, double target,
                         dv_league_summary *out);

/* the cell of object, engine, target, or NULL */
const dv_league_cell *dv_league_cell_of(const dv_league *lg, const char *object,
                                        const char *engine, double target);

/* the writers: each writes one file (or the figures) into the existing dir */
int dv_league_write_json(const char *dir, const dv_league *lg, dv_error *err); /* league.json */
int dv_league_write_csv(const char *dir, const dv_league *lg, dv_error *err);  /* league.csv */
int dv_league_write_md(const char *dir, const dv_league *lg, dv_error *err);   /* league.md */
int dv_league_write_html(const char *dir, const dv_league *lg, dv_error *err); /* league.html */
/* work_precision_OBJECT.svg per object and overview.svg */
int dv_league_write_figures(const char *dir, const dv_league *lg, dv_error *err);

/* all of the above, league.json first; the first error ends it */
int dv_league_write_all(const char *dir, const dv_league *lg, dv_error *err);

/* the names of the files and folders a league writes into its folder (for
 * dv_io_own_dir), the main one first, NULL-ended: out holds 8 + lg->nobjects
 * pointers, names lg->nobjects strings (the figures') */
void dv_league_output_names(const dv_league *lg, char (*names)[96], const char **out);

/* one cell as a JSON object (cJSON *), and back: the cache's form and league.json's cells */
struct cJSON;
struct cJSON *dv_league_cell_to_json(const dv_league_cell *c);
int dv_league_cell_from_json(const struct cJSON *j, dv_league_cell *c, dv_error *err);

#endif
