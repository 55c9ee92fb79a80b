/* dv_run: one scenario through the references and the engines, compared.
 *
 * Every engine is judged against the reference of the scene's body: the
 * thin disk, or the geometry-matched disk (engine "matched") of the scene's
 * thickness; an engine that would simulate another body is not judged
 * (dv_run_cannot_model); every engine is also compared with the thin disk.
 * The compared window ends where the reference ends (its event or validity
 * limit). Every metric has a limit (run_limits.h). The pointwise metrics
 * (theta_max_err, theta_rms_err, path_max_err, path_rms_err, phase_err) and
 * turning_lag are judged over the window against their limit plus the
 * shadow of the engine's early error (run_shadow.h, run_horizon.h), the
 * pointwise ones up to where that shadow reaches the motion's size; the
 * timing-insensitive ones (path_hausdorff, theta_extrema_err, energy_drift,
 * invariant_drift, slip_max, the turning values and periods) over the whole
 * window, unless the reference nudged by the engine's early error moves them
 * by half their limit. An engine's lying down is judged against the
 * reference's and those nudged runs' (run_event.h).
 *
 * Not judged, never a pass: an engine that is the reference it would be
 * compared with (the same engine on the same scenario: it measures nothing),
 * and a window of fewer than DV_MIN_WINDOW_SAMPLES samples, or shorter than
 * the scene's shortest time scale (engine_scene.h: spin, turning, wobble,
 * growth, fall), or than DV_MIN_WINDOW_FRACTION of the reference's run.
 */
#ifndef DV_RUN_H
#define DV_RUN_H

#include "run_compare.h"
#include "run_event.h"
#include "run_horizon.h"
#include "run_verdict.h"
#include "dv_engine.h"
#include "scenario.h"

#define DV_MAX_ENGINES 16 /* engines compared in one run */
#define DV_MAX_FAILURES (DV_NMETRICS + 1)
/* a compared window shorter than this share of the reference's run is not judged */
#define DV_MIN_WINDOW_FRACTION 0.1
/* nor one of fewer samples than this (the first is the shared start) */
#define DV_MIN_WINDOW_SAMPLES 10
/* the motion's size that ends pointwise judging where the shadow reaches
 * it is at least this many of the default limit: a steady motion does not
 * swing, and past ten limits a pointwise comparison says nothing of them */
#define DV_SHADOW_SIZE_FLOOR 10.0
/* characters of an engine's one-line "decided" (run_decided.h) */
#define DV_DECIDED_MAX 120

typedef struct dv_engine_result {
  const dv_engine_type *engine;
  int status; /* of the engine's run */
  dv_engine_stats stats;
  dv_traj traj;          /* the engine's samples (up to a failure) */
  double wall_s;         /* wall-clock time of the engine's run, s */
  double half_thickness; /* of its reference: 0 for the thin disk */
  dv_traj matched;       /* that reference's samples when half_thickness > 0 */
  dv_engine_stats matched_stats;
  double matched_wall_s;            /* wall-clock time of that reference's run, s */
  dv_metrics vs_ref, vs_thin;       /* against its own reference, and the thin disk */
  double tolerance[DV_NMETRICS];    /* limits (run_limits.h): never none */
  char limit_why[DV_NMETRICS][112]; /* where each limit came from */
  double window_fraction;           /* of the reference's run the window covers */
  double pointwise_end;             /* s: the pointwise metrics cover the window up to here */
  double early_err;               /* rad: its largest theta error to early_until (run_horizon.h) */
  double early_of[DV_NUDGE_DIRS]; /* its largest errors there, by dv_nudge_dir_names */
  double early_until;             /* s: the scene's shortest time scale, at least output_dt */
  double horizon;      /* s: where its shadow reaches the motion's size (INFINITY: never) */
  double horizon_gain; /* the reference's amplification of a nudge there (or at the end) */
  double nudge;                   /* rad: its event's theta nudge, max(early_err, the nudge) */
  double spread[DV_NMETRICS];     /* what its early errors as nudges move each metric by */
  dv_run_end nudged[2];           /* how those nudged reference runs ended */
  char horizon_why[560];          /* its shadow in words: the early error, the spread, its end */
  char decided[DV_DECIDED_MAX + 1]; /* what decided the verdict, one line (run_decided.h) */
  char decided_why[1600];           /* why: the window's end, the horizon, the limit's source */
  char cause[200];                /* an excess's cause, from attribution ("": unknown) */
  char reference_note[200];       /* why its reference is not its own geometry's ("": it is) */
  dv_event_verdict event;         /* its lying down against the reference's (run_event.h) */
  char not_judged[240];           /* why the run is not judged, set by a hook ("": it is) */
  int other_body; /* it simulated another body than the scene's (not judged: cannot model) */
  double excused[DV_NMETRICS]; /* of each value, what the shadow excused (run_shadow.h): its
                                  tolerance is its limit plus this */
  double whole[DV_NMETRICS];   /* each metric over the whole compared window (vs_ref: where it
                                  is judged, to pointwise_end for a pointwise one) */
  double shadow_at_end[2];     /* rad, m: the shadow in theta and the contact point where
                                  pointwise judging ends */
  double motion_size[2];       /* rad, m: the motion's size the shadow is held against */
  int unpredictable_by; /* which of those the shadow reached (0 theta, 1 path, 2 a nudged run
                           ended: lay down sooner) */
  int pass;
  dv_verdict verdict;
  size_t nfailures;
  char failures[DV_MAX_FAILURES][384];
} dv_engine_result;

/* the matched reference for one half-thickness, run once for every engine of that body */
typedef struct dv_matched_run {
  double half_thickness; /* m */
  int status;            /* of its run; < 0: err says why */
  dv_error err;
  dv_traj traj;
  dv_engine_stats stats;
  double wall_s;
} dv_matched_run;

typedef struct dv_comparison {
  const dv_scenario *sc;
  dv_traj thin; /* the thin-disk reference */
  dv_engine_stats thin_stats;
  double thin_wall_s;    /* wall-clock time of the thin reference's run, s */
  double horizon_wall_s; /* of the nudged reference runs (amplification, spreads), s */
  double thin_valid_end; /* where rolling stops describing the physics, s */
  dv_amplification amp;  /* how the reference amplifies a DV_HORIZON_NUDGE (run_horizon.h) */
  double horizon;        /* s: amp.horizon, where a nudge of the start grows by the limit */
  double spread[DV_NMETRICS]; /* what amp's nudge of the reference moves each metric by */
  double min_window;          /* s: the scene's shortest time scale (no shorter window judged) */
  size_t n;
  dv_engine_result r[DV_MAX_ENGINES];
  int pass; /* every engine passed */
  size_t nmatched;
  dv_matched_run matched[DV_MAX_ENGINES]; /* each half-thickness's matched reference, once */
  int borrowed; /* thin and amp are another comparison's (dv_run_engine_against): not freed */
} dv_comparison;

/* run the engines on sc and compare; the references run on ref_sc (NULL:
 * sc; a tighter reference for sweeps of the reference's own settings).
 * DV_OK (see out->pass), or < 0 when a reference fails */
int dv_run_scenario(const dv_scenario *sc, const dv_scenario *ref_sc,
                    const dv_engine_type *const *engines, size_t n, dv_comparison *out,
                    dv_error *err);

/* what a caller adds to the judging of an engine it made (run_judge.h):
 * called once each engine's metrics and limits are set, before its verdict;
 * it may mark a metric not judged (tolerance NAN, limit_why saying why) or
 * the whole run (not_judged) */
typedef struct dv_run_hook {
  void (*before_verdict)(void *ctx, const dv_comparison *c, dv_engine_result *r);
  void *ctx;
} dv_run_hook;

/* dv_run_scenario with hook (NULL: none) */
int dv_run_scenario_hooked(const dv_scenario *sc, const dv_scenario *ref_sc,
                           const dv_engine_type *const *engines, size_t n, const dv_run_hook *hook,
                           dv_comparison *out, dv_error *err);

/* one engine on sc judged against the references refs already ran (on
 * ref_sc, NULL: sc, with the same physics: sc differs from refs->sc only in
 * the engine's settings): the thin disk and its amplification are refs',
 * the matched reference for the engine's half-thickness too where refs has
 * it (else run here). out is a comparison of that one engine that borrows
 * refs' references (refs must outlive it); free it with
 * dv_run_comparison_free. DV_OK (see out->pass), or < 0 when a reference
 * run here fails */
int dv_run_engine_against(const dv_comparison *refs, const dv_scenario *sc,
                          const dv_scenario *ref_sc, const dv_engine_type *engine,
                          dv_comparison *out, dv_error *err);

/* the parts of dv_run_scenario_hooked, for a caller that runs them apart
 * (run_parallel.h): c begun for sc; the thin reference and its
 * amplification on ref_sc into c (< 0: err names the run); an engine's own
 * run into r (its failure in r->status); a matched reference into m (its
 * failure in m->status, m->err); and the judging of r against c's
 * references (the matched one from c->matched[], run and kept there when
 * missing), added to c's pass. Every comparison begun must be freed
 * (dv_run_comparison_free) */
void dv_run_comparison_begin(const dv_scenario *sc, dv_comparison *c);
int dv_run_thin_reference(const dv_scenario *ref_sc, dv_comparison *c, dv_error *err);
void dv_run_engine_only(const dv_engine_type *engine, const dv_scenario *sc, dv_engine_result *r);
/* 1 when engine, as sc sets it up, simulates another body than sc's (a
 * stand-in: a cylinder for a thin disk, a thinner one for a coin), with
 * why ("cannot model: ..."); 0 when it simulates the scene's body. The one
 * rule of compare, suite, judge and league */
int dv_run_cannot_model(const dv_engine_type *engine, const dv_scenario *sc, char *why,
                        size_t size);
/* what r's engine simulates on sc, without running it: its half-thickness, another body */
void dv_run_engine_body(const dv_engine_type *engine, const dv_scenario *sc, dv_engine_result *r);
void dv_run_matched_reference(const dv_scenario *ref_sc, double half_thickness, dv_matched_run *m);
int dv_run_engine_judge(dv_comparison *c, const dv_scenario *ref_sc, const dv_run_hook *hook,
                        dv_engine_result *r, dv_error *err);

void dv_run_comparison_free(dv_comparison *c);

/* 1 for a metric that compares samples at equal times */
int dv_run_metric_pointwise(dv_metric_id metric);
/* 1 for a metric judged against its limit plus the shadow of the engine's
 * early error: the pointwise ones and turning_lag */
int dv_run_metric_shadowed(dv_metric_id metric);

/* wall-clock seconds per simulated second; NaN when the run simulated
 * less than one output interval: a rate over next to nothing says nothing */
double dv_run_cost_rate(double wall_s, double sim_s, double output_dt);

#endif
