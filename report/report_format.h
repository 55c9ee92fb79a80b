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
 *                   "version": TEXT, "horizon": s | null (predictable to the end)},
 *     "pass": bool,                       every engine passed
 *     "engines": {
 *       ENGINE: {
 *         "theta_max_err", "theta_rms_err", "path_max_err", "path_rms_err",
 *         "path_hausdorff", "energy_drift", "slip_max":  numbers, against the
 *                                  geometry-matched reference (the thin disk
 *                                  for a thin or ellipsoid stand-in),
 *         "wall_per_sim_s": s per simulated s (the only timing field),
 *         "steps": n,
 *         "outcome": "agrees"|"exceeds tolerance"|"diverged"|"lost contact"
 *                    |"ended by event"|"error"|"not judged",
 *         "detail": TEXT,
 *         "pass": bool,
 *         "failures": [TEXT, ...]   "SCENARIO: ENGINE: METRIC = V > LIMIT",
 *         "tolerances": {METRIC: limit, ...},   every metric has one
 *         "limits": {METRIC: {"value", "limit", "margin": value / limit,
 *                             "from": "[tolerance.ENGINE]" | "default: ..."}},
 *         "window_end": s,          end of the compared window
 *         "window_fraction": x,     of the reference's run it covers
 *         "pointwise_end": s,       the pointwise metrics (theta_max_err,
 *                                   theta_rms_err, path_max_err, path_rms_err)
 *                                   cover the window to here: the reference's
 *                                   predictability horizon (run_horizon.h)
 *         "decided": TEXT,          which part decided the verdict
 *         "cause": TEXT,            an excess's dominant cause from attribution
 *                                   (geometry, time step, contact softness and
 *                                   slip, the rest, with its share), or ""
 *         "reference_half_thickness": m,   of its matched reference
 *         "vs_thin": {METRIC: value, ...}, the same metrics against the thin disk
 *         "geometry_share": {"theta_max_err": x, "path_max_err": y},
 *                                   1 - vs_matched / vs_thin: the share of the
 *                                   discrepancy the stand-in's geometry explains
 *         "version": TEXT, "settings": {KEY: value, ...}
 *       }, ...
 *     },
 *     "plots": ["theta.svg", ...]
 *   }
 * Suite, in OUT/: index.html, summary.json ({"pass": bool, "scenarios":
 * [{"scenario", "dir", "pass", "engines": {ENGINE: {"pass", "outcome",
 * "theta_max_err", "path_max_err", "wall_per_sim_s", "failures"}}}]}), and
 * the JUnit XML (one test case per scenario x engine).
 */
#ifndef DV_REPORT_H
#define DV_REPORT_H

#endif
