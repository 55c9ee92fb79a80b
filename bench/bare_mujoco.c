/* bare_mujoco: the baseline of bench_harness.sh for `diskval simulate
 * --engine mujoco`: the same model (the MJCF the engine builds, and its
 * thin-disk collider), the same initial state and steps, and the same CSV,
 * from a plain mj_step loop without the harness's checks.
 *
 *   bare_mujoco SCENARIO OUT.csv [section.key=value]...
 */
#include <math.h>
#include <mujoco/mujoco.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_pose.h"
#include "engine_mujoco_model.h"
#include "engine_mujoco_thin.h"
#include "red_solver.h"
#include "run_trajectory.h"

enum { GEOM_THIN = 0, GEOM_ELLIPSOID = 2 }; /* [engines.mujoco] geom */

static mjModel *load(const char *xml, int len, char *msg, int size) {
  mjVFS *vfs = calloc(1, sizeof *vfs);
  mjModel *m = NULL;
  mj_defaultVFS(vfs);
  if (len >= 0 && !mj_makeEmptyFileVFS(vfs, "disk.xml", len)) {
    memcpy(vfs->filedata[mj_findFileVFS(vfs, "disk.xml")], xml, (size_t)len);
    m = mj_loadXML("disk.xml", vfs, msg, size);
  }
  mj_deleteVFS(vfs);
  free(vfs);
  return m;
}

int main(int argc, char **argv) {
  dv_scenario sc;
  dv_error err;
  char xml[2048], msg[300] = "the model does not fit";
  if (argc < 3) {
    fprintf(stderr, "usage: bare_mujoco SCENARIO OUT.csv [section.key=value]...\n");
    return 2;
  }
  if (dv_engine_load_scenario(argv[1], (const char *const *)argv + 3, (size_t)argc - 3, &sc,
                              &err)) {
    fprintf(stderr, "%s\n", err.msg);
    return 2;
  }
  mjModel *m = load(xml, dv_mujoco_model_xml(&sc, xml, sizeof xml), msg, (int)sizeof msg);
  FILE *fp = fopen(argv[2], "w");
  if (!m || !fp) {
    fprintf(stderr, "bare_mujoco: %s\n", m ? argv[2] : msg);
    return 2;
  }
  const int geom = (int)dv_scenario_get(&sc, "mujoco", "geom");
  const dv_geometry shape = {
      geom == GEOM_ELLIPSOID ? DV_SHAPE_ELLIPSOID : DV_SHAPE_CYLINDER, sc.disk.r,
      geom == GEOM_THIN ? 0.0 : dv_scenario_get(&sc, "mujoco", "half_thickness")};
  if (geom == GEOM_THIN) dv_mujoco_thin_install();
  mjData *d = mj_makeData(m);
  dv_pose pose;
  dv_pose_from_state(&shape, sc.initial, &pose);
  mju_copy3(d->qpos, pose.pos);
  mju_mat2Quat(d->qpos + 3, pose.R);
  mju_copy3(d->qvel, pose.vel);
  mju_mulMatTVec(d->qvel + 3, pose.R, pose.omega, 3, 3);
  mj_forward(m, d);
  double prev[RED_NSTATE];
  memcpy(prev, sc.initial, sizeof prev);
  fputs(DV_CSV_HEADER "\n", fp);
  const double half = 0.5 * m->opt.timestep;
  for (long k = 0;; k++) {
    const double t = red_grid_time(0.0, sc.output_dt, sc.duration, k);
    while (d->time < t - half) mj_step(m, d);
    dv_sample s;
    dv_mujoco_read_pose(d, &pose);
    dv_sample_from_pose(&sc.disk, &shape, &pose, t, prev, &s);
    memcpy(prev, s.y, sizeof prev);
    dv_run_csv_row(fp, &s);
    if (t >= sc.duration) break;
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return fclose(fp) ? 2 : 0;
}
