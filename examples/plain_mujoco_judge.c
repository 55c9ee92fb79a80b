/* plain_mujoco_judge SCENARIO.ini: an engine diskval does not link, checked
 * from its own loop through the C API, without files.
 *
 * A plain MuJoCo loop (no diskval engine): a free body with a cylinder geom
 * of the scenario's disk (its radius, mass and [disk] thickness) on a plane,
 * started in the scenario's initial state, rolling. Every output_dt its
 * qpos and qvel are pushed as a pose (diskval_trajectory_push_pose: the
 * centre, the quaternion, the centre's velocity and the angular velocity in
 * the world frame: MuJoCo's free joint gives the angular velocity in the body
 * frame) and diskval_judge gives the verdict against the reference for that
 * cylinder. Prints the verdict and every metric; exit 0 when it agrees, 1
 * when it does not, 2 on an error. */
#include <diskval/diskval.h>
#include <math.h>
#include <mujoco/mujoco.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

/* the quaternion (w, x, y, z) of R = Rz(phi) Ry(theta) Rz(psi - pi/2) */
static void quaternion(double theta, double phi, double psi, double q[4]) {
  const double a = 0.5 * phi, b = 0.5 * theta, c = 0.5 * (psi - M_PI / 2);
  const double p[4] = {cos(a) * cos(b), -sin(a) * sin(b), cos(a) * sin(b), sin(a) * cos(b)};
  q[0] = p[0] * cos(c) - p[3] * sin(c);
  q[1] = p[1] * cos(c) + p[2] * sin(c);
  q[2] = p[2] * cos(c) - p[1] * sin(c);
  q[3] = p[3] * cos(c) + p[0] * sin(c);
}

/* qpos and qvel of the cylinder (radius r, half-thickness h) rolling in state y:
 * omega = phi' ez - theta' t + psi' n, the centre's velocity -omega x rho for the
 * contact vector rho = r d - h sign(n.z) n (README "Judge your own engine") */
static void initial_qpos(const diskval_state *y, double r, double h, double *qpos, double *qvel) {
  const double st = sin(y->theta), ct = cos(y->theta), sp = sin(y->phi), cp = cos(y->phi);
  const double a[3] = {cp, sp, 0}, t[3] = {sp, -cp, 0};
  const double d[3] = {ct * a[0], ct * a[1], -st}, n[3] = {st * a[0], st * a[1], ct};
  double w[3], rho[3];
  for (int i = 0; i < 3; i++) {
    w[i] = (i == 2 ? y->phi_dot : 0.0) - y->theta_dot * t[i] + y->psi_dot * n[i];
    rho[i] = r * d[i] - h * (ct >= 0 ? 1.0 : -1.0) * n[i];
  }
  qpos[0] = y->x, qpos[1] = y->y, qpos[2] = -rho[2];
  quaternion(y->theta, y->phi, y->psi, qpos + 3);
  qvel[0] = -(w[1] * rho[2] - w[2] * rho[1]);
  qvel[1] = -(w[2] * rho[0] - w[0] * rho[2]);
  qvel[2] = -(w[0] * rho[1] - w[1] * rho[0]);
  double R[9];
  mju_quat2Mat(R, qpos + 3);
  for (int i = 0; i < 3; i++) /* body frame: R^T omega */
    qvel[3 + i] = R[i] * w[0] + R[3 + i] * w[1] + R[6 + i] * w[2];
}

/* the model: the scenario's cylinder on a plane, stiff contact, RK4 at 1e-4 s */
static mjModel *load_model(double r, double h, double mass) {
  char path[] = "/tmp/plain_mujoco_judge.XXXXXX";
  const int fd = mkstemp(path);
  if (fd < 0) return NULL;
  FILE *fp = fdopen(fd, "w");
  fprintf(fp,
          "<mujoco><option timestep=\"1e-4\" integrator=\"RK4\"/><worldbody>"
          "<geom type=\"plane\" size=\"0 0 1\" friction=\"2 0 0\" solref=\"0.001 1\"/>"
          "<body><freejoint/><geom type=\"cylinder\" size=\"%.17g %.17g\" mass=\"%.17g\" "
          "friction=\"2 0 0\" solref=\"0.001 1\"/></body></worldbody></mujoco>\n",
          r, h, mass);
  fclose(fp);
  char error[1000] = "";
  mjModel *m = mj_loadXML(path, NULL, error, sizeof error);
  unlink(path);
  if (!m) fprintf(stderr, "MuJoCo: %s\n", error);
  return m;
}

int main(int argc, char **argv) {
  if (argc < 2) return fprintf(stderr, "usage: %s SCENARIO.ini\n", argv[0]), 2;
  diskval_error err;
  diskval_scenario *sc;
  if (diskval_scenario_load(argv[1], NULL, 0, &sc, &err) < 0)
    return fprintf(stderr, "%s\n", err.msg), 2;
  diskval_disk disk;
  diskval_state y0;
  diskval_scenario_disk(sc, &disk);
  diskval_scenario_initial(sc, &y0);
  const double h = 0.5 * disk.thickness, dt_out = 0.01, duration = diskval_scenario_duration(sc);
  mjModel *m = load_model(disk.radius, h > 0 ? h : 1e-4, disk.mass);
  mjData *d = m ? mj_makeData(m) : NULL;
  diskval_trajectory *tr = NULL;
  int status = m && d ? diskval_trajectory_new(sc, "plain_mujoco", &tr, &err) : -3;
  if (!status) initial_qpos(&y0, disk.radius, h, d->qpos, d->qvel);
  for (long k = 0; !status && k * dt_out <= duration + 1e-9; k++) {
    while (d->time < k * dt_out - 1e-9) mj_step(m, d);
    diskval_pose p;
    double R[9];
    for (int i = 0; i < 3; i++) p.pos[i] = d->qpos[i], p.vel[i] = d->qvel[i];
    for (int i = 0; i < 4; i++) p.quat[i] = d->qpos[3 + i];
    mju_quat2Mat(R, p.quat); /* world = R body */
    for (int i = 0; i < 3; i++)
      p.omega[i] = R[3 * i] * d->qvel[3] + R[3 * i + 1] * d->qvel[4] + R[3 * i + 2] * d->qvel[5];
    status = diskval_trajectory_push_pose(tr, d->time, &p, 1, &err);
  }
  diskval_comparison c;
  if (!status) status = diskval_judge(sc, tr, &c, &err);
  if (status < 0) {
    fprintf(stderr, "%s\n", status == -3 && !tr ? "MuJoCo: no model" : err.msg);
  } else {
    printf("%s: plain MuJoCo loop: %s (%s)\n", diskval_scenario_name(sc), c.verdict, c.decided);
    for (size_t i = 0; i < c.metrics.n; i++)
      printf("  %-20s %.3g (limit %.3g)\n", c.metrics.name[i], c.metrics.value[i], c.limit[i]);
  }
  diskval_trajectory_free(tr);
  mj_deleteData(d);
  mj_deleteModel(m);
  diskval_scenario_free(sc);
  return status < 0 ? 2 : c.pass ? 0 : 1;
}
