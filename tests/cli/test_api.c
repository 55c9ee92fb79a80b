/* test_api SCENARIOS_DIR: the public C API (include/diskval/diskval.h)
 * through libdiskval: a scenario from a file and one built in code, runs,
 * trajectories compared, a comparison's verdict, and the error convention. */
#include <diskval/diskval.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dv_test.h"

/* a rolling disk built in code: the reference and MuJoCo agree on theta */
static void check_in_code(void) {
  diskval_error err = {{0}};
  const diskval_disk disk = {.radius = 0.1, .mass = 1.0, .gravity = 9.81};
  const diskval_state y0 = {.theta = 1.2, .psi_dot = 30.0, .phi_dot = 2.0};
  diskval_scenario *sc = NULL;
  int s = diskval_scenario_new("in_code", &disk, &y0, 0.5, 0.01, &sc, &err);
  CHECK(s == 0, "diskval_scenario_new: %s", err.msg);
  if (s) return;
  CHECK(strcmp(diskval_scenario_name(sc), "in_code") == 0, "name");
  CHECK_NEAR(diskval_scenario_duration(sc), 0.5, 0, "duration");
  diskval_trajectory *ref = NULL, *mj = NULL;
  s = diskval_run(sc, "reduced", &ref, &err);
  CHECK(s >= 0, "reduced: %s", err.msg);
  s = diskval_run(sc, "mujoco", &mj, &err);
  CHECK(s >= 0, "mujoco: %s", err.msg);
  if (ref && mj) {
    CHECK(diskval_trajectory_size(ref) == 51, "reference samples: %zu",
          diskval_trajectory_size(ref));
    diskval_sample first;
    CHECK(diskval_trajectory_sample(ref, 0, &first) == 0, "sample 0");
    CHECK_NEAR(first.state.theta, 1.2, 0, "theta(0)");
    CHECK(diskval_trajectory_sample(ref, 51, &first) == -1, "sample out of range");
    diskval_metrics m;
    CHECK(diskval_compare_trajectories(mj, ref, &m, &err) == 0, "compare: %s", err.msg);
    const double e = diskval_metric(&m, "theta_max_err");
    CHECK(e >= 0 && e < 1e-2, "theta_max_err %g", e);
    CHECK(isnan(diskval_metric(&m, "no_such_metric")), "unknown metric");
    CHECK(m.n_window > 40, "window of %zu samples", m.n_window);
  }
  diskval_trajectory_free(ref);
  diskval_trajectory_free(mj);
  CHECK(diskval_scenario_set(sc, "mujoco", "timestep", "1e-4", &err) == 0, "set: %s", err.msg);
  CHECK(diskval_scenario_set(sc, "mujoco", "no_such_key", "1", &err) < 0 && err.msg[0],
        "an unknown key is refused");
  /* [disk] friction: set from code as in a file, refused as there */
  CHECK(diskval_scenario_set(sc, "disk", "friction", "0.8", &err) == 0, "friction: %s", err.msg);
  CHECK(diskval_scenario_set(sc, "disk", "friction", "nan", &err) < 0 &&
            strstr(err.msg, "friction"),
        "a NaN friction: %s", err.msg);
  CHECK(diskval_scenario_set(sc, "disk", "friction", "-1", &err) < 0 &&
            strstr(err.msg, "friction"),
        "a negative friction: %s", err.msg);
  CHECK(diskval_scenario_set(sc, "disk", "radius", "1", &err) < 0, "disk.radius is not set here");
  diskval_scenario_free(sc);
  const diskval_state flat = {.theta = 0.0};
  sc = NULL;
  CHECK(diskval_scenario_new("flat", &disk, &flat, 1, 0.1, &sc, &err) == DISKVAL_EINPUT && !sc,
        "theta = 0 refused");
  CHECK(diskval_scenario_new("x", &disk, &y0, 1, 2, &sc, &err) == DISKVAL_EINPUT, "output_dt");
  /* 1e7 samples need 9.6 GiB (scenario.h): refused before anything runs */
  CHECK(diskval_scenario_new("x", &disk, &y0, 10, 1e-6, &sc, &err) == DISKVAL_EINPUT &&
            strstr(err.msg, "GiB of memory"),
        "1e7 samples: %s", err.msg);
}

/* a disk from code is checked as a file's [disk] and [initial]: bad values
 * are refused with the key that holds them; moments derive from the thickness */
static void check_disk_input(void) {
  const diskval_state y0 = {.theta = 1.2, .psi_dot = 30.0};
  const struct {
    diskval_disk disk;
    const char *key;
  } bad[] = {
      {{.radius = 0.1, .mass = 1, .A = 0.001, .C = 0.003, .gravity = 9.81}, "disk.C"},
      {{.radius = 0.1, .mass = 1, .A = NAN, .C = 0.001, .gravity = 9.81}, "disk.A"},
      {{.radius = 0.1, .mass = -1, .gravity = 9.81}, "disk.mass"},
      {{.radius = 0.1, .mass = 1, .gravity = 9.81, .thickness = 0.2}, "disk.thickness"},
      {{.radius = INFINITY, .mass = 1, .gravity = 9.81}, "disk.radius"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    diskval_error err = {{0}};
    diskval_scenario *sc = NULL;
    const int s = diskval_scenario_new("bad", &bad[i].disk, &y0, 1, 0.1, &sc, &err);
    CHECK(s == DISKVAL_EINPUT && !sc && strncmp(err.msg, bad[i].key, strlen(bad[i].key)) == 0,
          "%s: status %d, '%s'", bad[i].key, s, err.msg);
    diskval_scenario_free(sc);
  }
  diskval_error err = {{0}};
  diskval_scenario *sc = NULL;
  const diskval_state nan_rate = {.theta = 1.2, .theta_dot = NAN};
  const diskval_disk thick = {.radius = 0.1, .mass = 2.0, .gravity = 9.81, .thickness = 0.03};
  CHECK(diskval_scenario_new("x", &thick, &nan_rate, 1, 0.1, &sc, &err) == DISKVAL_EINPUT &&
            strstr(err.msg, "initial.theta_dot"),
        "NaN rate: %s", err.msg);
  CHECK(diskval_scenario_new("thick", &thick, &y0, 1, 0.1, &sc, &err) == 0, "thick: %s", err.msg);
  diskval_disk got = {0};
  diskval_scenario_disk(sc, &got);
  /* a solid cylinder: A = m (r^2 / 4 + t^2 / 12), C = m r^2 / 2 */
  CHECK_NEAR(got.A, 2.0 * (0.01 / 4 + 0.0009 / 12), 1e-17, "A of the thick disk");
  CHECK_NEAR(got.C, 2.0 * 0.01 / 2, 1e-17, "C of the thick disk"); /* a few ulps */
  CHECK_NEAR(got.thickness, 0.03, 0, "thickness");
  diskval_scenario_free(sc);
}

/* a shipped scenario: MuJoCo's verdict, and errors by the convention */
static void check_file(const char *dir) {
  char path[1024];
  snprintf(path, sizeof path, "%s/steady_circle.ini", dir);
  diskval_error err = {{0}};
  diskval_scenario *sc = NULL;
  const char *set[] = {"scenario.duration=1"};
  int s = diskval_scenario_load(path, set, 1, &sc, &err);
  CHECK(s == 0, "load %s: %s", path, err.msg);
  if (s) return;
  CHECK_NEAR(diskval_scenario_duration(sc), 1.0, 0, "override");
  diskval_comparison c;
  s = diskval_compare(sc, "mujoco", &c, &err);
  CHECK(s == 0, "diskval_compare: %s", err.msg);
  if (s == 0) {
    CHECK(c.pass == 1 && strcmp(c.verdict, "agrees") == 0, "verdict %s (%s)", c.verdict, c.decided);
    CHECK(strncmp(c.decided, "passes: ", 8) == 0 && !strchr(c.decided, '\n'),
          "decided is no one line naming the pass: '%s'", c.decided);
    CHECK(c.metrics.n >= 9 && strcmp(c.metrics.name[0], "theta_max_err") == 0, "metric names");
    /* the deciding metric is the one decided names, and its share of its limit the largest */
    char named[64] = "";
    sscanf(c.decided, "passes: %63s", named);
    CHECK(c.decided_metric && !strcmp(c.decided_metric, named), "decided_metric %s, decided '%s'",
          c.decided_metric ? c.decided_metric : "NULL", c.decided);
    for (size_t m = 0; c.decided_metric && m < c.metrics.n; m++)
      if (!strcmp(c.metrics.name[m], c.decided_metric))
        for (size_t k = 0; k < c.metrics.n; k++)
          CHECK(!(c.metrics.value[k] / c.limit[k] > c.metrics.value[m] / c.limit[m]),
                "%s is nearer its limit than %s", c.metrics.name[k], c.decided_metric);
    char limit_of[96];
    snprintf(limit_of, sizeof limit_of, "The limit of %s", c.decided_metric ? c.decided_metric : "?");
    CHECK(!strncmp(c.decided_why, "Judged vs thin disk. The compared window runs to", 48) &&
              strstr(c.decided_why, limit_of),
          "decided_why does not say the reference, the window and the deciding limit: '%s'",
          c.decided_why);
    CHECK(c.metrics.value[0] <= c.limit[0], "theta_max_err %g > %g", c.metrics.value[0],
          c.limit[0]);
  }
  diskval_trajectory *tr = NULL;
  CHECK(diskval_run(sc, "warp", &tr, &err) == DISKVAL_EINPUT && !tr && strstr(err.msg, "warp"),
        "unknown engine: %s", err.msg);
  CHECK(diskval_compare(sc, "warp", &c, NULL) == DISKVAL_EINPUT, "NULL err is allowed");
  diskval_scenario_free(sc);
  sc = NULL;
  CHECK(diskval_scenario_load("/nonexistent.ini", NULL, 0, &sc, &err) < 0 && !sc && err.msg[0],
        "a missing file is an error");
}

/* a setting from code meets the checks a file and --set apply: a theta_limit
 * that puts the initial theta (1 rad) outside is refused, naming both keys,
 * and leaves the scenario as it was (the reference still runs to the end) */
static void check_set_checked(const char *dir) {
  char path[1024];
  snprintf(path, sizeof path, "%s/steady_circle.ini", dir);
  diskval_error err = {{0}};
  diskval_scenario *sc = NULL;
  const char *set[] = {"scenario.duration=0.5"};
  if (diskval_scenario_load(path, set, 1, &sc, &err)) {
    CHECK(0, "load %s: %s", path, err.msg);
    return;
  }
  int s = diskval_scenario_set(sc, "reduced", "theta_limit", "1.5", &err);
  CHECK(s == DISKVAL_EINPUT && strstr(err.msg, "engines.reduced.theta_limit") &&
            strstr(err.msg, "initial.theta") && strstr(err.msg, "lying-down"),
        "theta_limit 1.5 past theta 1: status %d, '%s'", s, err.msg);
  s = diskval_scenario_set(sc, "reduced", "theta_limit", "0.9", &err);
  CHECK(s == 0, "theta_limit 0.9 inside: %s", err.msg);
  diskval_trajectory *tr = NULL;
  s = diskval_run(sc, "reduced", &tr, &err);
  CHECK(s == 0 && diskval_trajectory_size(tr) == 51, "after a refused set: status %d, %zu samples",
        s, diskval_trajectory_size(tr));
  diskval_trajectory_free(tr);
  diskval_scenario_free(sc);
}

/* run every check */
int main(int argc, char **argv) {
  CHECK(argc == 2, "usage: test_api SCENARIOS_DIR");
  if (argc != 2) return TEST_RESULT();
  CHECK(strcmp(diskval_version(), DV_PROJECT_VERSION) == 0, "version %s", diskval_version());
  for (size_t i = 0;; i++) {
    const char *name = diskval_engine_name(i);
    if (!name) {
      CHECK(i >= 4, "%zu engines", i);
      break;
    }
  }
  check_in_code();
  check_disk_input();
  check_file(argv[1]);
  check_set_checked(argv[1]);
  return TEST_RESULT();
}
