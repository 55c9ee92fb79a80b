/* dv_report: the per-scenario report of a comparison, and the suite's.
 *
 * Per scenario, in OUT/<scenario>/:
 *   reduced.csv, <engine>.csv, matched-<engine>.csv   trajectories (DESIGN 5)
 *   theta.svg, theta_error.svg, path.svg, energy.svg  plots (dv_plot.h)
 *   report.md                                          the table for people
 *   report.json:
 *   {
 *     "scenario": NAME, "description": TEXT, "file": PATH,
 *     "duration": s, "output_dt": s,
 *     "reference": {"engine": "reduced", "integrator": NAME, "rtol": x,
 *                   "outcome": "completed"|"event", "detail": TEXT, "t_end": s,
 *                   "version": TEXT, "horizon": s | null: where nudges of 1e-6
 *                   (rad in theta, of the rate scale in each rate) have grown
 *                   by 0.01 rad, the latest any engine's horizon is (null:
 *                   never, to the end),
 *                   "amplification": {"nudge": rad, "rate_nudge": rad/s,
 *                                     "growth": "linear"|"power"|
 *                                     "exponential"|"bounded"|"too short",
 *                                     "exponent", "efold_s", "factor": G,
 *                                     "factor_t": s, "measured_to": s,
 *                                     "words": TEXT} (run_horizon.h),
 *                   "wall_s": s, its run's wall-clock time,
 *                   "horizon_wall_s": s, the nudged runs' that find the horizon},
 *     "pass": bool,                       every engine passed
 *     "engines": {
 *       ENGINE: {
 *         "theta_max_err", "theta_rms_err", "path_max_err", "path_rms_err",
 *         "path_hausdorff", "energy_drift", "slip_max", "theta_extrema_err",
 *         "invariant_drift", "theta_turning_err", "nutation_period_err",
 *         "heading_period_err", "phase_err", "turning_lag" (dv_metric_names):
 *                                  numbers (null: not measurable, or
 *                                  infinite) over the whole compared window,
 *                                  against the reference of the scene's body
 *                                  (an engine of another body: not judged);
 *                                  limits.METRIC.value is the same where it
 *                                  is judged (a pointwise one to pointwise_end),
 *         "wall_per_sim_s": s per simulated s; null for a run shorter than
 *                           one output_dt,
 *         "wall_s": s, the run's wall-clock time (the timing fields: wall_*),
 *         "steps": n,
 *         "outcome": "agrees"|"exceeds tolerance"|"diverged"|"lost contact"
 *                    |"ended by event"|"error"|"not judged"|"outside validity",
 *         "detail": TEXT,
 *         "pass": bool,
 *         "failures": [TEXT, ...]   "SCENARIO: ENGINE: METRIC = V UNIT > LIMIT UNIT",
 *         "tolerances": {METRIC: limit, ...},   every metric has one
 *         "limits": {METRIC: {"value", "limit", "margin": value / limit,
 *                             "from": "[tolerance.ENGINE]" | "default: ...",
 *                             "spread": what the shadow of the engine's early
 *                               error excused of value (limit is the scene's
 *                               limit plus it: run_shadow.h),
 *                             "unit": "rad" | "m" | "s" | ...}},
 *         "window_end": s,          end of the compared window
 *         "window_fraction": x,     of the reference's run it covers
 *         "pointwise_end": s,       the pointwise metrics (theta_max_err,
 *                                   theta_rms_err, path_max_err, path_rms_err,
 *                                   phase_err) are judged to here: where the
 *                                   shadow of its early error reaches the
 *                                   motion's size, else the window's end
 *         "decided": TEXT,          what decided the verdict, one line of at
 *                                   most DV_DECIDED_MAX characters starting
 *                                   "passes", "fails" or "not judged"
 *                                   (run_decided.h)
 *         "decided_why": TEXT,      why, in sentences: where the compared
 *                                   window ends and why, the horizon (the
 *                                   engine's early error, the reference's
 *                                   amplification), the deciding limit's source
 *         "horizon": {"t": s | null, "early_error": rad, "early_until": s,
 *                     "early_errors": {"theta": rad, "theta_dot", "phi_dot",
 *                                      "psi_dot": rad/s},
 *                     "amplification": G there (null: a nudged run ended),
 *                     "nudge": rad (its lying down's), "why": TEXT}
 *         "cause": TEXT,            an excess's dominant cause from attribution
 *                                   (geometry, time step, contact softness and
 *                                   slip, the rest, with its share), or ""
 *         "reference_half_thickness": m,   of its matched reference
 *         "judged": TEXT,           the body whose reference judged it, as
 *                                   every line says it: "vs cylinder h 1.165
 *                                   mm" or "vs thin disk"
 *         "reference_note": TEXT,   why that reference is not the one for its
 *                                   geometry (a thick one that crossed upright
 *                                   falls back to the thin disk), or ""
 *         "event": null | {"agrees": bool, "why": TEXT ("" when it agrees),
 *                          "from": s | null, "to": s | null (no latest),
 *                          "runs": TEXT}: the engine's lying down against
 *                                   the reference's and the nudged runs'
 *                                   (run_event.h); null where neither the
 *                                   engine nor its reference lay down inside
 *                                   the window
 *         "reference": {"engine": "matched" | "reduced", "half_thickness": m,
 *                       "integrator": NAME, "rtol": x, "outcome": TEXT, "t_end": s,
 *                       "wall_s": s (its own run; 0: the thin one above)}:
 *                                   the reference this engine was judged against
 *         "vs_thin": {METRIC: value, ...}, the same metrics against the thin disk
 *         "geometry_share": {"theta_max_err": x, "path_max_err": y, "why": TEXT},
 *                                   1 - vs_matched / vs_thin: the share of the
 *                                   discrepancy the stand-in's geometry explains;
 *                                   null with why "n/a: ..." where the engine was
 *                                   not compared with its own geometry's
 *                                   reference; why says it where a share is
 *                                   negative (the geometry cancels other error)
 *         "version": TEXT, "settings": {KEY: value, ...}
 *         "settings_why": TEXT,     the settings chosen for the scene and why ("": none)
 *       }, ...
 *     },
 *     "plots": ["theta.svg", ...]
 *   }
 * A scenario whose run failed (an error, a time limit, a crash) has an error
 * report instead, report.md and report.json {"scenario", "file", "pass":
 * false, "error": CAUSE, "engines": {}} (report_suite_dir.h).
 * Suite, in OUT/: index.html, summary.json ({"pass": bool, "scenarios":
 * [{"scenario", "dir", "pass", "engines": {ENGINE: {"pass", "outcome",
 * "theta_max_err", "path_max_err", "wall_per_sim_s", "failures", "limits",
 * "reference"}}}]}), and the JUnit XML (a test suite per scenario, a test
 * case per engine with its numbers as properties: report_suite.h).
 * Both, and the run JSON and verify.json, as JSON Schemas: tests/fixtures/schemas/
 * (a field changed here is changed there: the json_schemas test holds them equal).
 */
#ifndef DV_REPORT_H
#define DV_REPORT_H

#endif
