/* test_upright_reference: the geometry-matched reference of a thick disk at
 * exact upright, through the comparison.
 *
 * A cylinder stand-in exactly upright and not tilting (tests/data/
 * upright_thick.ini) is compared with its own reference, which finishes (it
 * used to stall) and keeps theta = pi/2; a forced step budget ends the
 * reference with an error that says so; where the thick disk crosses upright
 * (scenarios/upright_stable.ini, theta' = 0.01 rad/s) the compared window ends
 * there, said, and nothing is judged against another body (it once fell back
 * to the thin disk), its geometry share is n/a (not 0), and
 * a run that ends within one output interval has no cost per simulated
 * second (it read 7e9 s / s).
 */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "dv_test.h"
#include "report_scenario.h"
#include "run_scenario.h"

static const char *out_dir; /* argv[3]: where the reports go */

/* report.json of c, written into out_dir/name; NULL on failure */
static cJSON *report_json(const dv_comparison *c, const char *name) {
  char dir[512], path[600];
  dv_error err = {{0}};
  snprintf(dir, sizeof dir, "%s/%s", out_dir, name);
  mkdir(out_dir, 0755);
  mkdir(dir, 0755);
  const int status = dv_report_scenario_write(dir, c, &err);
  CHECK(status == DV_OK, "report: %s", err.msg);
  snprintf(path, sizeof path, "%s/report.json", dir);
  FILE *fp = fopen(path, "r");
  static char text[1 << 20];
  const size_t n = fp ? fread(text, 1, sizeof text - 1, fp) : 0;
  if (fp) fclose(fp);
  text[n] = '\0';
  return cJSON_Parse(text);
}

/* engines.NAME.key of report.json */
static const cJSON *engine_item(const cJSON *report, const char *engine, const char *key) {
  return cJSON_GetObjectItem(cJSON_GetObjectItem(cJSON_GetObjectItem(report, "engines"), engine),
                             key);
}

static void load(const char *path, const char *const *sets, size_t n, dv_scenario *sc) {
  dv_error err = {{0}};
  const int status = dv_engine_load_scenario(path, sets, n, sc, &err);
  CHECK(status == DV_OK, "%s: %s", path, err.msg);
}

/* path with sets compared in engine alone, into c; the status */
static int compare_one(const char *path, const char *const *sets, size_t nsets,
                       const dv_engine_type *engine, dv_scenario *sc, dv_comparison *c,
                       dv_error *err) {
  const dv_engine_type *engines[] = {engine};
  load(path, sets, nsets, sc);
  return dv_run_scenario(sc, NULL, engines, 1, c, err);
}

/* the cylinder upright: its own reference, completed, upright throughout
 * (measured, printed below: |theta - pi/2| = 0; 1e-14 allows the dense output's rounding) */
static void check_upright_cylinder(const char *path) {
  static dv_comparison c;
  const char *const sets[] = {"engines.mujoco.geom=cylinder"};
  dv_scenario sc;
  dv_error err = {{0}};
  const int status = compare_one(path, sets, 1, &dv_engine_mujoco, &sc, &c, &err);
  CHECK(status == DV_OK, "upright cylinder: %s", err.msg);
  if (status) return;
  const dv_engine_result *r = &c.r[0];
  double tilt = 0.0;
  for (size_t i = 0; i < r->matched.n; i++)
    tilt = fmax(tilt, fabs(r->matched.s[i].y[RED_TH] - M_PI / 2));
  const double t_end = r->matched.n ? r->matched.s[r->matched.n - 1].t : 0.0;
  printf(
      "upright cylinder: reference h = %g m, %s at t = %g s, |theta - pi/2| <= %.2e, note "
      "'%s'\n",
      r->half_thickness, dv_outcome_name(r->matched_stats.outcome), t_end, tilt, r->reference_note);
  CHECK(r->half_thickness > 0.0 && !r->reference_note[0],
        "the cylinder is not compared with its own reference: %s", r->reference_note);
  CHECK(r->matched_stats.outcome == DV_OUTCOME_COMPLETED && t_end == sc.duration,
        "matched reference: %s at t = %g s: %s", dv_outcome_name(r->matched_stats.outcome), t_end,
        r->matched_stats.detail);
  CHECK(tilt <= 1e-14, "the upright reference tilts by %.3g rad", tilt);
  cJSON *report = report_json(&c, "cylinder");
  const cJSON *share = engine_item(report, "mujoco", "geometry_share");
  CHECK(cJSON_IsNumber(cJSON_GetObjectItem(share, "theta_max_err")),
        "compared with its own geometry, the cylinder has a geometry share");
  cJSON_Delete(report);
  dv_run_comparison_free(&c);
}

/* max_steps = 1: the reference ends at once with the guard's reason */
static void check_step_budget(const char *path) {
  static dv_comparison c;
  const char *const sets[] = {"engines.mujoco.geom=cylinder", "engines.reduced.max_steps=1"};
  dv_scenario sc;
  dv_error err = {{0}};
  const int status = compare_one(path, sets, 2, &dv_engine_mujoco, &sc, &c, &err);
  printf("step budget 1: status %d: %s\n", status, err.msg);
  CHECK(status == DV_ENUMERIC && strstr(err.msg, "step budget spent"),
        "a spent step budget is not an error that says so: %d '%s'", status, err.msg);
  dv_run_comparison_free(&c);
}

/* crossing upright: the window ends there, said, not judged; no rate for a 1e-14 s run */
static void check_fallback(const char *path) {
  static dv_comparison c;
  const char *const sets[] = {"engines.matched.half_thickness=0.002"};
  dv_scenario sc;
  dv_error err = {{0}};
  const int status = compare_one(path, sets, 1, &dv_engine_matched, &sc, &c, &err);
  CHECK(status == DV_OK, "upright_stable: %s", err.msg);
  if (status) return;
  const dv_engine_result *r = &c.r[0];
  const double sim = r->traj.n ? r->traj.s[r->traj.n - 1].t : 0.0;
  const double rate = dv_run_cost_rate(r->wall_s, sim, sc.output_dt);
  printf("upright_stable, matched at h = 2 mm: ran to t = %g s in %g s, rate %g; note '%s'\n", sim,
         r->wall_s, rate, r->reference_note);
  CHECK(r->half_thickness == 0.002 && strstr(r->reference_note, "upright") &&
            r->verdict == DV_VERDICT_NOT_JUDGED && !r->pass,
        "the window's end at upright is not said, or the run is judged (%s, h %g): '%s'",
        dv_run_verdict_name(r->verdict), r->half_thickness, r->reference_note);
  CHECK(sim < sc.output_dt && isnan(rate), "a %g s run has a rate %g s / s", sim, rate);
  CHECK(dv_run_cost_rate(2.0, 4.0, 0.01) == 0.5, "the rate of a full run");
  /* report.json: no rate and no geometry share, each null, the share saying why */
  cJSON *report = report_json(&c, "fallback");
  const cJSON *share = engine_item(report, "matched", "geometry_share");
  const char *why = cJSON_GetStringValue(cJSON_GetObjectItem(share, "why"));
  printf("report.json: wall_per_sim_s %s, geometry share why '%s'\n",
         cJSON_IsNull(engine_item(report, "matched", "wall_per_sim_s")) ? "null" : "a number",
         why ? why : "(none)");
  CHECK(cJSON_IsNull(engine_item(report, "matched", "wall_per_sim_s")),
        "report.json: a rate for a 1e-14 s run");
  CHECK(cJSON_IsNull(cJSON_GetObjectItem(share, "theta_max_err")) && why &&
            strncmp(why, "n/a: ", 5) == 0 && strstr(why, "upright"),
        "report.json: the fallback's geometry share is not n/a with why: '%s'", why ? why : "");
  cJSON_Delete(report);
  dv_run_comparison_free(&c);
}

int main(int argc, char **argv) {
  if (argc != 4)
    return fprintf(stderr, "usage: %s UPRIGHT_THICK UPRIGHT_STABLE OUT_DIR\n", argv[0]), 2;
  out_dir = argv[3];
  check_upright_cylinder(argv[1]);
  check_step_budget(argv[1]);
  check_fallback(argv[2]);
  return TEST_RESULT();
}
