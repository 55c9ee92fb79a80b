/* test_api_judge SCENARIO: an engine's samples judged through the C API,
 * without files (diskval_trajectory_new, _push, _push_pose, diskval_judge).
 * MuJoCo's run of SCENARIO (tests/data/short_circle.ini), pushed sample by
 * sample as states, gets diskval_compare's verdict and metrics within 1e-9
 * relative (measured: 4.2e-14) but slip_max (not judged: a state carries
 * no velocity of its own) and energy_drift (a state's energy is the rolling
 * disk's in that state, not MuJoCo's own: 1.3% apart); pushed as poses without velocities, the same
 * verdict and theta_max_err within 1e-9 (measured 4.2e-12 in the CLI's
 * equivalence test: the quaternion's round trip). Bad samples are refused
 * naming the sample. The reference's own run pushed as states is not judged
 * (never a pass). An error leaves its out safe to read; pushed samples
 * compare as a run; diskval_scenario_new needs a name and names C for C's
 * error when A = 0 (the uniform disk's). Re-measure: the test prints the differences (ctest -V -R
 * api_judge). */
#include <diskval/diskval.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dv_test.h"

/* the quaternion of R = Rz(phi) Ry(theta) Rz(psi - pi/2): qz(phi) qy(theta) qz(psi - pi/2) */
static void quaternion(double theta, double phi, double psi, double q[4]) {
  const double a = 0.5 * phi, b = 0.5 * theta, c = 0.5 * (psi - M_PI / 2);
  /* qz(a) qy(b) = (ca cb, -sa sb, ca sb, sa cb); times qz(c) = (cc, 0, 0, sc) */
  const double p[4] = {cos(a) * cos(b), -sin(a) * sin(b), cos(a) * sin(b), sin(a) * cos(b)};
  q[0] = p[0] * cos(c) - p[3] * sin(c);
  q[1] = p[1] * cos(c) + p[2] * sin(c);
  q[2] = p[2] * cos(c) - p[1] * sin(c);
  q[3] = p[3] * cos(c) + p[0] * sin(c);
}

static double rel(double a, double b) {
  return a == b ? 0.0 : fabs(a - b) / fmax(fabs(a), 1e-300);
}

int main(int argc, char **argv) {
  if (argc < 2) return fprintf(stderr, "usage: test_api_judge SCENARIO\n"), 2;
  diskval_error err = {{0}};
  diskval_scenario *sc = NULL;
  int s = diskval_scenario_load(argv[1], NULL, 0, &sc, &err);
  CHECK(s == 0, "load: %s", err.msg);
  if (s) return TEST_RESULT();
  diskval_trajectory *run = NULL, *states = NULL, *poses = NULL;
  CHECK(diskval_run(sc, "mujoco", &run, &err) >= 0, "run: %s", err.msg);
  CHECK(diskval_trajectory_new(sc, "states", &states, &err) == 0, "new: %s", err.msg);
  CHECK(diskval_trajectory_new(sc, "poses", &poses, &err) == 0, "new: %s", err.msg);
  diskval_disk disk;
  diskval_scenario_disk(sc, &disk);
  for (size_t i = 0; i < diskval_trajectory_size(run); i++) {
    diskval_sample x;
    diskval_trajectory_sample(run, i, &x);
    CHECK(diskval_trajectory_push(states, x.t, &x.state, &err) == 0, "push %zu: %s", i, err.msg);
    diskval_pose p = {{x.state.x, x.state.y, disk.radius * sin(x.state.theta)}, {0}, {0}, {0}};
    quaternion(x.state.theta, x.state.phi, x.state.psi, p.quat);
    CHECK(diskval_trajectory_push_pose(poses, x.t, &p, 0, &err) == 0, "pose %zu: %s", i, err.msg);
  }
  diskval_comparison want, got, pose;
  CHECK(diskval_compare(sc, "mujoco", &want, &err) == 0, "compare: %s", err.msg);
  CHECK(diskval_judge(sc, states, &got, &err) == 0, "judge: %s", err.msg);
  CHECK(diskval_judge(sc, poses, &pose, &err) == 0, "judge poses: %s", err.msg);
  CHECK(strcmp(want.verdict, got.verdict) == 0 && want.pass == got.pass, "verdict %s, compare's %s",
        got.verdict, want.verdict);
  CHECK(strcmp(want.verdict, pose.verdict) == 0, "poses: verdict %s, compare's %s", pose.verdict,
        want.verdict);
  double worst = 0.0;
  for (size_t m = 0; m < want.metrics.n; m++) {
    if (!strcmp(want.metrics.name[m], "slip_max")) {
      CHECK(isnan(got.limit[m]), "slip_max judged: limit %g", got.limit[m]);
      continue;
    }
    if (!strcmp(want.metrics.name[m], "energy_drift")) continue;
    const double r = rel(want.metrics.value[m], got.metrics.value[m]);
    if (!(isnan(want.metrics.value[m]) && isnan(got.metrics.value[m]))) worst = fmax(worst, r);
    CHECK(r <= 1e-9 || (isnan(want.metrics.value[m]) && isnan(got.metrics.value[m])),
          "%s: %.17g, compare's %.17g", want.metrics.name[m], got.metrics.value[m],
          want.metrics.value[m]);
  }
  const double th = rel(diskval_metric(&want.metrics, "theta_max_err"),
                        diskval_metric(&pose.metrics, "theta_max_err"));
  CHECK(th <= 1e-9, "poses: theta_max_err %.3g apart", th);
  printf("states: every metric within %.3g of compare's; poses: theta_max_err within %.3g\n", worst,
         th);
  /* the reference's own run pushed as states is the reference: not judged, never a pass */
  diskval_trajectory *ref = NULL, *mine = NULL, *near = NULL;
  diskval_comparison self;
  CHECK(diskval_run(sc, "reduced", &ref, &err) >= 0, "run reduced: %s", err.msg);
  CHECK(diskval_trajectory_new(sc, "mine", &mine, &err) == 0, "new: %s", err.msg);
  CHECK(diskval_trajectory_new(sc, "near", &near, &err) == 0, "new: %s", err.msg);
  for (size_t i = 0; ref && i < diskval_trajectory_size(ref); i++) {
    diskval_sample x;
    diskval_trajectory_sample(ref, i, &x);
    diskval_trajectory_push(mine, x.t, &x.state, &err);
    if (i == 10) x.state.theta += 1e-9; /* another run, by one sample */
    diskval_trajectory_push(near, x.t, &x.state, &err);
  }
  CHECK(diskval_judge(sc, mine, &self, &err) == 0, "judge the reference: %s", err.msg);
  CHECK(!self.pass && !strcmp(self.verdict, "not judged"), "the reference's own run: %s, pass %d",
        self.verdict, self.pass);
  /* theta 1e-9 rad off at one sample: judged (the pushed values count exactly) */
  CHECK(diskval_judge(sc, near, &self, &err) == 0, "judge the near copy: %s", err.msg);
  CHECK(strcmp(self.verdict, "not judged") != 0, "the reference's near copy: %s", self.verdict);
  diskval_trajectory_free(ref);
  diskval_trajectory_free(mine);
  diskval_trajectory_free(near);
  /* the errors of a bad sample name it */
  diskval_state bad = {.theta = NAN};
  CHECK(diskval_trajectory_push(states, 10.0, &bad, &err) == -1 && strstr(err.msg, "states:"),
        "NaN: %s", err.msg);
  diskval_pose q = {{0, 0, 0.1}, {2, 0, 0, 0}, {0}, {0}};
  CHECK(diskval_trajectory_push_pose(poses, 10.0, &q, 0, &err) == -1 &&
            strstr(err.msg, "not 1 within"),
        "norm: %s", err.msg);
  CHECK(diskval_trajectory_push_pose(states, 10.0, &q, 0, &err) == -1 &&
            strstr(err.msg, "one kind of sample"),
        "mixed: %s", err.msg);
  diskval_trajectory *few = NULL;
  diskval_trajectory_new(sc, "few", &few, &err);
  diskval_sample x0;
  diskval_trajectory_sample(run, 0, &x0);
  diskval_trajectory_push(few, 0.0, &x0.state, &err);
  CHECK(diskval_judge(sc, few, &got, &err) == -1 && strstr(err.msg, "at least 5"), "few: %s",
        err.msg);
  /* an error leaves out safe to read: no metric, NAN by name */
  CHECK(got.metrics.n == 0 && isnan(diskval_metric(&got.metrics, "theta_max_err")) && !got.pass,
        "judge's out after an error: n %zu, pass %d", got.metrics.n, got.pass);
  diskval_metrics m;
  m.n = 7; /* as uninitialised memory might hold */
  CHECK(diskval_compare_trajectories(few, NULL, &m, &err) == -1 && m.n == 0 &&
            isnan(diskval_metric(&m, "theta_max_err")),
        "compare_trajectories' out after an error: n %zu", m.n);
  /* pushed samples are a trajectory of their own: compared, not "empty" */
  CHECK(diskval_compare_trajectories(states, run, &m, &err) == 0 &&
            diskval_metric(&m, "theta_max_err") == 0.0,
        "pushed states against their run: %s, theta_max_err %g", err.msg,
        diskval_metric(&m, "theta_max_err"));
  diskval_trajectory_free(few);
  /* a scenario needs a name; with A = 0 (the uniform disk's) an error in C names C */
  diskval_scenario *made = NULL;
  diskval_state s0;
  diskval_scenario_initial(sc, &s0);
  CHECK(diskval_scenario_new(NULL, &disk, &s0, 0.3, 0.01, &made, &err) == -1 &&
            strstr(err.msg, "NULL name"),
        "NULL name: %s", err.msg);
  diskval_disk bad_c = disk;
  bad_c.A = 0.0, bad_c.C = -1.0;
  CHECK(diskval_scenario_new("c", &bad_c, &s0, 0.3, 0.01, &made, &err) == -1 &&
            strstr(err.msg, "disk.C"),
        "A = 0, C = -1: %s", err.msg);
  bad_c.C = 3.0 * disk.A; /* over 2A */
  CHECK(diskval_scenario_new("c", &bad_c, &s0, 0.3, 0.01, &made, &err) == -1 &&
            strstr(err.msg, "disk.C"),
        "A = 0, C = 3A: %s", err.msg);
  diskval_trajectory_free(run);
  diskval_trajectory_free(states);
  diskval_trajectory_free(poses);
  diskval_scenario_free(sc);
  return TEST_RESULT();
}
