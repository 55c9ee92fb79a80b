/* make_wide_suite: a suite's reports as wide and wordy as they come, and its pages.
 *
 * usage: make_wide_suite OUT_DIR [SCENARIOS [ENGINES]]
 * Writes OUT_DIR/<scenario>/report.json (report_format.h) for SCENARIOS
 * scenarios (default 20) of ENGINES engines each (default 10: the five linked
 * and five adapters with long names), every verdict class among them, with
 * the long "decided" paragraphs, notes and failures real reports carry, plus
 * four 900x600 SVG plots each; one scenario is a harness error. Then the
 * suite's files (dv_report_suite_write), which write each scenario's page.
 * For check_html_layout.sh: the pages at their widest and wordiest.
 */
#include <cjson/cJSON.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "report_suite.h"

#define MAX_SCENARIOS 64
#define MAX_ENGINES 16

static const char *const engine_names[MAX_ENGINES] = {
    "ode", "mujoco", "bullet", "dart", "simbody", "adapter-rapier3d-compat-0.12",
    "adapter-cannon-es-0.20-with-sleep", "adapter-ammo.js-wasm", "adapter-oimo-physics",
    "adapter-physx-js-webidl", "e11", "e12", "e13", "e14", "e15", "e16"};

static const char *const outcomes[] = {"agrees", "exceeds tolerance", "diverged", "lost contact",
                                       "not judged", "outside validity", "ended by event"};

/* the paragraph a "decided" of today's reports can be (about 400 characters) */
static const char decided[] =
    "a nudged reference run ended at t = 1.335 s, before the reference: past it nothing "
    "measures the amplification; amplification exponential (e-fold 0.21 s, factor 3.1e4 at "
    "t = 1.2 s); theta_turning_err 0.043 > 0.01 (2nd minimum 40 ms early) over the compared "
    "window to t = 1.23 s (61% of the reference's run): rolling needs more friction than mu "
    "there; the pointwise errors to the horizon t = 0.266 s";

/* text into dir/name; 0 on success */
static int spit(const char *dir, const char *name, const char *text) {
  char path[8192];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *fp = fopen(path, "wb");
  if (!fp) return -1;
  const int bad = fputs(text, fp) < 0;
  return fclose(fp) || bad ? -1 : 0;
}

/* engine e of scenario s: a verdict class by (s + e), limits, long texts */
static cJSON *engine(int s, int e) {
  const char *outcome = outcomes[(s + e) % (int)(sizeof outcomes / sizeof *outcomes)];
  const int pass = !strcmp(outcome, "agrees") || !strcmp(outcome, "ended by event");
  const double margin = pass ? 0.42 : 4.3;
  cJSON *o = cJSON_CreateObject();
  cJSON_AddNumberToObject(o, "theta_max_err", 0.01 * margin);
  cJSON_AddNumberToObject(o, "path_max_err", 0.002);
  cJSON_AddNumberToObject(o, "wall_per_sim_s", 0.123);
  cJSON_AddStringToObject(o, "outcome", outcome);
  cJSON_AddStringToObject(o, "detail", decided);
  cJSON_AddBoolToObject(o, "pass", pass);
  cJSON *limits = cJSON_AddObjectToObject(o, "limits");
  static const char *const metrics[] = {"theta_max_err", "path_max_err", "heading_period_err",
                                        "theta_turning_err"};
  for (int m = 0; m < 4; m++) {
    cJSON *l = cJSON_AddObjectToObject(limits, metrics[m]);
    const double mm = m == 3 ? margin : margin / (m + 2.0);
    cJSON_AddNumberToObject(l, "value", 0.01 * mm);
    cJSON_AddNumberToObject(l, "limit", 0.01);
    cJSON_AddNumberToObject(l, "margin", mm);
    cJSON_AddStringToObject(l, "from", "[tolerance.engine] a limit of the scene's own file");
  }
  cJSON_AddNumberToObject(o, "window_end", 1.23);
  cJSON_AddNumberToObject(o, "window_fraction", 0.61);
  cJSON_AddNumberToObject(o, "pointwise_end", 0.266);
  cJSON_AddStringToObject(o, "decided", decided);
  cJSON_AddStringToObject(o, "decided_metric", "theta_turning_err"); /* the largest margin */
  if (e % 2) cJSON_AddStringToObject(o, "decided_why", decided);
  cJSON *h = cJSON_AddObjectToObject(o, "horizon");
  cJSON_AddStringToObject(h, "why", decided);
  cJSON_AddStringToObject(o, "judged", e % 3 ? "vs thin disk" : "vs cylinder h 1.165 mm");
  cJSON_AddStringToObject(o, "reference_note", e % 4 ? "" : decided);
  cJSON_AddStringToObject(o, "cause", pass ? "" : decided);
  cJSON_AddStringToObject(o, "settings_why", decided);
  cJSON *failures = cJSON_AddArrayToObject(o, "failures");
  if (!pass) cJSON_AddItemToArray(failures, cJSON_CreateString(decided));
  return o;
}

/* a 900x600 plot that names itself */
static int plot(const char *dir, const char *name) {
  char svg[512];
  snprintf(svg, sizeof svg,
           "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"900\" height=\"600\">"
           "<rect width=\"900\" height=\"600\" fill=\"#fff\" stroke=\"#000\"/>"
           "<text x=\"40\" y=\"60\" font-size=\"40\">%s</text></svg>\n",
           name);
  return spit(dir, name, svg);
}

/* scenario s with ne engines into out/name */
static int scenario(const char *out, const char *name, int s, int ne) {
  static const char *const plots[] = {"theta.svg", "theta_error.svg", "path.svg", "energy.svg"};
  char dir[4096];
  snprintf(dir, sizeof dir, "%s/%s", out, name);
  if (mkdir(dir, 0777) && errno != EEXIST) return -1;
  cJSON *r = cJSON_CreateObject();
  cJSON_AddStringToObject(r, "scenario", name);
  cJSON_AddStringToObject(r, "description", decided);
  cJSON_AddStringToObject(r, "file", "objects/a_scenario_file_with_a_rather_long_name.ini");
  cJSON_AddNumberToObject(r, "duration", 2);
  cJSON_AddNumberToObject(r, "output_dt", 0.01);
  cJSON *ref = cJSON_AddObjectToObject(r, "reference");
  cJSON_AddStringToObject(ref, "engine", "reduced");
  cJSON_AddStringToObject(ref, "outcome", "completed");
  cJSON_AddStringToObject(ref, "detail", decided);
  cJSON_AddBoolToObject(r, "pass", 0);
  cJSON *engines = cJSON_AddObjectToObject(r, "engines");
  for (int e = 0; e < ne; e++) cJSON_AddItemToObject(engines, engine_names[e], engine(s, e));
  cJSON *list = cJSON_AddArrayToObject(r, "plots");
  int status = 0;
  for (int k = 0; k < 4; k++) {
    cJSON_AddItemToArray(list, cJSON_CreateString(plots[k]));
    status |= plot(dir, plots[k]);
  }
  char *text = cJSON_Print(r);
  status |= !text || spit(dir, "report.json", text);
  free(text);
  cJSON_Delete(r);
  return status;
}

int main(int argc, char **argv) {
  const int ns = argc > 2 ? atoi(argv[2]) : 20, ne = argc > 3 ? atoi(argv[3]) : 10;
  if (argc < 2 || argc > 4 || ns < 2 || ns > MAX_SCENARIOS || ne < 1 || ne > MAX_ENGINES) {
    fprintf(stderr, "usage: %s OUT_DIR [SCENARIOS (2..64) [ENGINES (1..16)]]\n", argv[0]);
    return 2;
  }
  char names[MAX_SCENARIOS][64];
  const char *dirs[MAX_SCENARIOS];
  for (int s = 0; s < ns; s++) {
    snprintf(names[s], sizeof names[s], "s%02d_a_steel_euler_disk_on_glass_spinning_down", s);
    dirs[s] = names[s];
    if (s > 0 && scenario(argv[1], names[s], s, ne)) {
      fprintf(stderr, "make_wide_suite: cannot write %s/%s: %s\n", argv[1], names[s],
              strerror(errno));
      return 1;
    }
  }
  /* scenario 0: a harness error with a long cause */
  char dir[4096];
  snprintf(dir, sizeof dir, "%s/%s", argv[1], names[0]);
  if ((mkdir(dir, 0777) && errno != EEXIST) ||
      spit(dir, "report.json", "{\"scenario\": \"s00\", \"pass\": false, \"engines\": {}, "
                               "\"error\": \"timed out after 600 s: the comparison of every "
                               "engine with its reference did not end within the suite's time "
                               "limit, a scenario's own runs one at a time\"}")) {
    fprintf(stderr, "make_wide_suite: cannot write %s: %s\n", dir, strerror(errno));
    return 1;
  }
  dv_error err = {""};
  if (dv_report_suite_write(argv[1], dirs, (size_t)ns, NULL, &err)) {
    fprintf(stderr, "make_wide_suite: %s\n", err.msg);
    return 1;
  }
  return 0;
}
