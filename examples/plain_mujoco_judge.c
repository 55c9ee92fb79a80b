/* plain_mujoco_judge SCENARIO.ini [--run RUN.csv.json] [--pose OUT.csv --dt H]:
 * an engine diskval does not link, checked from its own loop through the C
 * API, without files.
 *
 * A plain MuJoCo loop (no diskval engine): a free body with a cylinder geom
 * of the scenario's disk (its radius, mass and [disk] thickness) on a plane,
 * started in the scenario's initial state, rolling. Every output_dt its
 * qpos and qvel are pushed as a pose (diskval_trajectory_push_pose: the
 * centre, the quaternion, the centre's velocity and the angular velocity in
 * the world frame: MuJoCo's free joint gives the angular velocity in the body
 * frame) and diskval_judge gives the verdict against the reference for that
 * cylinder. Prints the verdict and every metric; exit 0 when it agrees, 1
 * when it does not, 2 on an error.
 *
 * --run RUN.csv.json: instead of its own model, the one `diskval simulate
 * --engine mujoco --out RUN.csv` ran, from the settings that run wrote beside
 * its CSV (timestep, integrator, cone, impratio, solver, tolerance,
 * iterations, noslip_iterations, solref, solimp, friction, geom cylinder and
 * half_thickness; the scenario's gravity and moments A, A, C): the MJCF
 * diskval's MuJoCo engine writes for them, started from the same qpos and
 * qvel (the rolling state's pose, as engines/dv_pose.c computes it, in the
 * same arithmetic) and stepped to the same grid (to each sample time, less
 * half a step). Only geom = cylinder: diskval's thin disk is a collider of
 * its own (engines/mujoco/engine_mujoco_thin.c), not MuJoCo's.
 * --pose OUT.csv --dt H: also write the samples, every H s from 0 (the
 * scenario's output_dt gives the reference's own sample times), in the pose
 * form with velocities: t,x,y,z,qw,qx,qy,qz from qpos, vx,vy,vz,wx,wy,wz from
 * qvel (the angular velocity turned into the world frame). */
#include <diskval/diskval.h>
#include <math.h>
#include <mujoco/mujoco.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* compile the MJCF text xml (len bytes) from memory, as diskval's MuJoCo
 * engine does: no file is written or removed; NULL on an error, said */
static mjModel *load_mjcf(const char *xml, size_t len) {
  mjVFS *vfs = calloc(1, sizeof *vfs); /* about 2 MB: not on the stack */
  mjModel *m = NULL;
  char error[1000] = "";
  if (vfs) mj_defaultVFS(vfs);
  if (vfs && xml && mj_makeEmptyFileVFS(vfs, "disk.xml", (int)len) == 0) {
    memcpy(vfs->filedata[mj_findFileVFS(vfs, "disk.xml")], xml, len);
    m = mj_loadXML("disk.xml", vfs, error, sizeof error);
    mj_deleteVFS(vfs);
  }
  if (!m) fprintf(stderr, "MuJoCo: %s\n", error[0] ? error : "cannot hold the model in memory");
  free(vfs);
  return m;
}

/* the model: the scenario's cylinder on a plane, stiff contact, RK4 at 1e-4 s */
static mjModel *load_model(double r, double h, double mass) {
  char *xml = NULL;
  size_t len = 0;
  FILE *fp = open_memstream(&xml, &len);
  if (!fp) return NULL;
  fprintf(fp,
          "<mujoco><option timestep=\"1e-4\" integrator=\"RK4\"/><worldbody>"
          "<geom type=\"plane\" size=\"0 0 1\" friction=\"2 0 0\" solref=\"0.001 1\"/>"
          "<body><freejoint/><geom type=\"cylinder\" size=\"%.17g %.17g\" mass=\"%.17g\" "
          "friction=\"2 0 0\" solref=\"0.001 1\"/></body></worldbody></mujoco>\n",
          r, h, mass);
  fclose(fp);
  mjModel *m = load_mjcf(xml, len);
  free(xml);
  return m;
}

/* a run's settings: the "settings" object of simulate's RUN.csv.json, read by key
 * (a flat object of numbers and strings) */
typedef struct run_settings {
  double timestep, impratio, tolerance, solref[2], solimp[3], friction, half_thickness;
  int iterations, noslip_iterations;
  char integrator[16], cone[16], solver[16], geom[16];
} run_settings;

/* the text after "KEY": in the settings object, or NULL */
static const char *json_value(const char *json, const char *key) {
  const char *p = strstr(json, "\"settings\"");
  char quoted[64];
  snprintf(quoted, sizeof quoted, "\"%s\"", key);
  p = p ? strstr(p, quoted) : NULL;
  if (!p || !(p = strchr(p + strlen(quoted), ':'))) return NULL;
  for (p++; *p == ' ' || *p == '\t' || *p == '\n'; p++) {
  }
  return p;
}

static int json_number(const char *json, const char *key, double *out) {
  const char *p = json_value(json, key);
  char *end;
  if (!p) return fprintf(stderr, "run settings: no %s\n", key), -1;
  *out = strtod(p, &end);
  return end == p ? (fprintf(stderr, "run settings: %s is not a number\n", key), -1) : 0;
}

static int json_text(const char *json, const char *key, char *out, size_t size) {
  const char *p = json_value(json, key), *end;
  if (!p || *p != '"' || !(end = strchr(p + 1, '"')) || (size_t)(end - p - 1) >= size)
    return fprintf(stderr, "run settings: no text %s\n", key), -1;
  snprintf(out, size, "%.*s", (int)(end - p - 1), p + 1);
  return 0;
}

static int read_run(const char *path, run_settings *s) {
  FILE *fp = fopen(path, "r");
  if (!fp) return fprintf(stderr, "%s: cannot open\n", path), -1;
  static char json[1 << 16];
  const size_t n = fread(json, 1, sizeof json - 1, fp);
  fclose(fp);
  json[n] = 0;
  double iterations, noslip;
  if (json_number(json, "timestep", &s->timestep) || json_number(json, "impratio", &s->impratio) ||
      json_number(json, "tolerance", &s->tolerance) ||
      json_number(json, "iterations", &iterations) ||
      json_number(json, "noslip_iterations", &noslip) ||
      json_number(json, "solref_timeconst", &s->solref[0]) ||
      json_number(json, "solref_dampratio", &s->solref[1]) ||
      json_number(json, "solimp_dmin", &s->solimp[0]) ||
      json_number(json, "solimp_dmax", &s->solimp[1]) ||
      json_number(json, "solimp_width", &s->solimp[2]) ||
      json_number(json, "friction", &s->friction) ||
      json_number(json, "half_thickness", &s->half_thickness) ||
      json_text(json, "integrator", s->integrator, sizeof s->integrator) ||
      json_text(json, "cone", s->cone, sizeof s->cone) ||
      json_text(json, "solver", s->solver, sizeof s->solver) ||
      json_text(json, "geom", s->geom, sizeof s->geom))
    return -1;
  s->iterations = (int)iterations, s->noslip_iterations = (int)noslip;
  if (strcmp(s->geom, "cylinder"))
    return fprintf(stderr, "%s: geom %s: only MuJoCo's own cylinder runs here\n", path, s->geom),
           -1;
  return 0;
}

/* MuJoCo's name of a diskval setting's value */
static const char *mj_name(const char *v) {
  static const char *const map[][2] = {{"euler", "Euler"}, {"rk4", "RK4"}, {"implicit", "implicit"},
                                       {"pgs", "PGS"},     {"cg", "CG"},   {"newton", "Newton"}};
  for (size_t i = 0; i < sizeof map / sizeof map[0]; i++)
    if (!strcmp(v, map[i][0])) return map[i][1];
  return v; /* cone: pyramidal, elliptic */
}

/* the run's model: the MJCF diskval's MuJoCo engine writes (engine_mujoco.c) */
static mjModel *load_run_model(const run_settings *s, const diskval_disk *k) {
  char *xml = NULL;
  size_t len = 0;
  FILE *fp = open_memstream(&xml, &len);
  if (!fp) return NULL;
  fprintf(fp,
          "<mujoco model=\"diskval\">\n"
          "  <option timestep=\"%.17g\" gravity=\"0 0 %.17g\" integrator=\"%s\" cone=\"%s\"\n"
          "          impratio=\"%.17g\" solver=\"%s\" tolerance=\"%.17g\" iterations=\"%d\"\n"
          "          noslip_iterations=\"%d\"/>\n"
          "  <default>\n"
          "    <geom condim=\"3\" friction=\"%.17g 0 0\" solref=\"%.17g %.17g\"\n"
          "          solimp=\"%.17g %.17g %.17g 0.5 2\"/>\n"
          "  </default>\n"
          "  <worldbody>\n"
          "    <geom type=\"plane\" size=\"0 0 1\" contype=\"0\" conaffinity=\"1\"/>\n"
          "    <body>\n"
          "      <freejoint/>\n"
          "      <inertial pos=\"0 0 0\" mass=\"%.17g\" diaginertia=\"%.17g %.17g %.17g\"/>\n"
          "      <geom type=\"cylinder\" size=\"%.17g %.17g\" contype=\"1\" conaffinity=\"0\"/>\n"
          "    </body>\n"
          "  </worldbody>\n"
          "</mujoco>\n",
          s->timestep, -k->gravity, mj_name(s->integrator), s->cone, s->impratio,
          mj_name(s->solver), s->tolerance, s->iterations, s->noslip_iterations, s->friction,
          s->solref[0], s->solref[1], s->solimp[0], s->solimp[1], s->solimp[2], k->mass, k->A, k->A,
          k->C, k->radius, s->half_thickness);
  fclose(fp);
  mjModel *m = load_mjcf(xml, len);
  free(xml);
  return m;
}

/* qpos and qvel of the cylinder rolling in state y, in engines/dv_pose.c's
 * arithmetic (dv_pose_from_state, dv_geometry_contact_vector), the quaternion
 * from the rotation matrix by MuJoCo as diskval's engine sets it */
static void run_initial_qpos(const diskval_state *y, double r, double h, double *qpos,
                             double *qvel) {
  const double th = y->theta, ph = y->phi, ps = y->psi;
  const double s = sin(th), c = cos(th), sp = sin(ph), cp = cos(ph);
  const double a[3] = {cp, sp, 0.0}, t[3] = {sp, -cp, 0.0};
  const double d[3] = {c * a[0], c * a[1], -s}, n[3] = {s * a[0], s * a[1], c};
  const double cs = cos(ps), ss = sin(ps);
  double R[9], w[3], rho[3];
  for (int i = 0; i < 3; i++) {
    R[3 * i + 0] = cs * t[i] + ss * d[i];
    R[3 * i + 1] = -ss * t[i] + cs * d[i];
    R[3 * i + 2] = n[i];
  }
  for (int i = 0; i < 3; i++)
    w[i] = y->phi_dot * (i == 2) - y->theta_dot * t[i] + y->psi_dot * n[i];
  const double nz = R[8], sn = sqrt(fmax(0.0, 1.0 - nz * nz)), sg = (nz > 0.0) - (nz < 0.0);
  for (int i = 0; i < 3; i++) {
    const double di = (sn > 0.0) ? (nz * R[3 * i + 2] - (i == 2)) / sn : 0.0;
    rho[i] = r * di - h * sg * R[3 * i + 2];
  }
  qpos[0] = y->x, qpos[1] = y->y, qpos[2] = -rho[2];
  mju_mat2Quat(qpos + 3, R);
  const double wr[3] = {w[1] * rho[2] - w[2] * rho[1], w[2] * rho[0] - w[0] * rho[2],
                        w[0] * rho[1] - w[1] * rho[0]};
  for (int i = 0; i < 3; i++) qvel[i] = -wr[i];
  mju_mulMatTVec(qvel + 3, R, w, 3, 3); /* body = R^T world */
}

/* the pose of d (qpos as stored; the velocities in the world frame) */
static void read_pose(const mjData *d, diskval_pose *p) {
  double R[9], q[4] = {d->qpos[3], d->qpos[4], d->qpos[5], d->qpos[6]};
  for (int i = 0; i < 3; i++) p->pos[i] = d->qpos[i], p->vel[i] = d->qvel[i];
  for (int i = 0; i < 4; i++) p->quat[i] = q[i];
  mju_normalize4(q);
  mju_quat2Mat(R, q); /* world = R body */
  mju_mulMatVec(p->omega, R, d->qvel + 3, 3, 3);
}

int main(int argc, char **argv) {
  const char *run_path = NULL, *pose_path = NULL;
  double dt_out = 0.01;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!strcmp(argv[i], "--run"))
      run_path = argv[i + 1];
    else if (!strcmp(argv[i], "--pose"))
      pose_path = argv[i + 1];
    else if (!strcmp(argv[i], "--dt"))
      dt_out = atof(argv[i + 1]);
    else
      argc = 0;
  }
  if (argc < 2 || argc % 2 || !(dt_out > 0.0))
    return fprintf(stderr, "usage: %s SCENARIO.ini [--run RUN.csv.json] [--pose OUT.csv --dt H]\n",
                   argv[0]),
           2;
  diskval_error err;
  diskval_scenario *sc;
  if (diskval_scenario_load(argv[1], NULL, 0, &sc, &err) < 0)
    return fprintf(stderr, "%s\n", err.msg), 2;
  diskval_disk disk;
  diskval_state y0;
  diskval_scenario_disk(sc, &disk);
  diskval_scenario_initial(sc, &y0);
  double h = 0.5 * disk.thickness;
  const double duration = diskval_scenario_duration(sc);
  run_settings rs;
  mjModel *m = NULL;
  if (!run_path) {
    m = load_model(disk.radius, h > 0 ? h : 1e-4, disk.mass);
  } else if (!read_run(run_path, &rs)) {
    h = rs.half_thickness;
    m = load_run_model(&rs, &disk);
  }
  mjData *d = m ? mj_makeData(m) : NULL;
  FILE *pose = pose_path && d ? fopen(pose_path, "w") : NULL;
  diskval_trajectory *tr = NULL;
  int status =
      m && d && (pose || !pose_path) ? diskval_trajectory_new(sc, "plain_mujoco", &tr, &err) : -3;
  if (!status && run_path) {
    run_initial_qpos(&y0, disk.radius, h, d->qpos, d->qvel);
    mj_forward(m, d); /* as diskval's engine does after setting the state */
  } else if (!status) {
    initial_qpos(&y0, disk.radius, h, d->qpos, d->qvel);
  }
  if (pose) fprintf(pose, "t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n");
  for (long k = 0; !status; k++) {
    /* the sample times of diskval's runs: k dt, the last one the duration */
    double t = k * dt_out;
    if (fabs(t - duration) <= 1e-9 * dt_out || t > duration) t = duration;
    while (d->time < t - 0.5 * m->opt.timestep) mj_step(m, d);
    diskval_pose p;
    read_pose(d, &p);
    status = diskval_trajectory_push_pose(tr, t, &p, 1, &err);
    if (pose) {
      fprintf(pose, "%.17g", t);
      for (int i = 0; i < 3; i++) fprintf(pose, ",%.17g", p.pos[i]);
      for (int i = 0; i < 4; i++) fprintf(pose, ",%.17g", p.quat[i]);
      for (int i = 0; i < 3; i++) fprintf(pose, ",%.17g", p.vel[i]);
      for (int i = 0; i < 3; i++) fprintf(pose, ",%.17g", p.omega[i]);
      fprintf(pose, "\n");
    }
    if (t >= duration) break;
  }
  if (pose && fclose(pose) && !status) status = -3;
  diskval_comparison c;
  if (!status) status = diskval_judge(sc, tr, &c, &err);
  if (status < 0) {
    fprintf(stderr, "%s\n", status == -3 && !tr ? "MuJoCo: no model, or cannot write" : err.msg);
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
