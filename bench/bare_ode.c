/* bare_ode: the baseline of bench_harness.sh for `diskval simulate --engine
 * ode`: the same world, body, geom (the thin-disk user geom, or a cylinder)
 * and contacts as engine_ode.c, from the scenario's [engines.ode] settings as
 * the engine resolves them, stepped in a plain loop without the harness's
 * checks, writing the same CSV.
 *
 *   bare_ode SCENARIO OUT.csv [section.key=value]...
 */
#include <math.h>
#include <ode/ode.h>
#include <stdio.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_pose.h"
#include "engine_ode_body.h"
#include "engine_ode_thin.h"
#include "red_solver.h"
#include "run_trajectory.h"

static double setting(const dv_scenario *sc, const char *key) {
  return dv_scenario_get(sc, "ode", key);
}

int main(int argc, char **argv) {
  dv_scenario sc;
  dv_error err;
  if (argc < 3) {
    fprintf(stderr, "usage: bare_ode SCENARIO OUT.csv [section.key=value]...\n");
    return 2;
  }
  if (dv_engine_load_scenario(argv[1], (const char *const *)argv + 3, (size_t)argc - 3, &sc,
                              &err)) {
    fprintf(stderr, "%s\n", err.msg);
    return 2;
  }
  FILE *fp = fopen(argv[2], "w");
  if (!fp) return perror(argv[2]), 2;
  const double dt = setting(&sc, "timestep"), h = setting(&sc, "half_thickness");
  const int quick = setting(&sc, "stepper") == 1, cylinder = setting(&sc, "geom") == 1;
  const dv_geometry shape = {DV_SHAPE_CYLINDER, sc.disk.r, cylinder ? h : 0.0};
  dInitODE2(0);
  dWorldID world = dWorldCreate();
  dWorldSetGravity(world, 0.0, 0.0, -sc.disk.g);
  dWorldSetERP(world, setting(&sc, "erp"));
  dWorldSetCFM(world, setting(&sc, "cfm"));
  dWorldSetQuickStepNumIterations(world, (int)setting(&sc, "iterations"));
  dBodyID body = dBodyCreate(world);
  dMass mass;
  dMassSetParameters(&mass, sc.disk.m, 0, 0, 0, sc.disk.A, sc.disk.A, sc.disk.C, 0, 0, 0);
  dBodySetMass(body, &mass);
  dGeomID disk =
      cylinder ? dCreateCylinder(NULL, sc.disk.r, 2.0 * h) : dv_ode_thin_create(sc.disk.r);
  dGeomSetBody(disk, body);
  dGeomID plane = dCreatePlane(NULL, 0.0, 0.0, 1.0, 0.0);
  dJointGroupID group = dJointGroupCreate(0);
  dContact contact;
  memset(&contact, 0, sizeof contact);
  contact.surface.mode = dContactSoftERP | dContactSoftCFM;
  if (setting(&sc, "friction_model") == 0) contact.surface.mode |= dContactApprox1;
  contact.surface.mu = setting(&sc, "friction");
  contact.surface.soft_erp = setting(&sc, "soft_erp");
  contact.surface.soft_cfm = setting(&sc, "soft_cfm");

  dv_pose pose;
  dv_pose_from_state(&shape, sc.initial, &pose);
  dv_ode_write_pose(body, &pose);
  double prev[RED_NSTATE];
  memcpy(prev, sc.initial, sizeof prev);
  fputs(DV_CSV_HEADER "\n", fp);
  long steps = 0;
  for (long k = 0;; k++) {
    const double t = red_grid_time(0.0, sc.output_dt, sc.duration, k);
    for (; steps * dt < t - 0.5 * dt; steps++) {
      dContactGeom cg[4];
      const int n = dCollide(disk, plane, 4, cg, sizeof cg[0]);
      for (int i = 0; i < n; i++) {
        contact.geom = cg[i];
        dJointAttach(dJointCreateContact(world, group, &contact), body, NULL);
      }
      quick ? dWorldQuickStep(world, dt) : dWorldStep(world, dt);
      dJointGroupEmpty(group);
    }
    dv_sample s;
    dv_ode_read_pose(body, &pose);
    dv_sample_from_pose(&sc.disk, &shape, &pose, t, prev, &s);
    memcpy(prev, s.y, sizeof prev);
    dv_run_csv_row(fp, &s);
    if (t >= sc.duration) break;
  }
  dJointGroupDestroy(group);
  dGeomDestroy(plane);
  dGeomDestroy(disk);
  dWorldDestroy(world);
  dCloseODE();
  return fclose(fp) ? 2 : 0;
}
