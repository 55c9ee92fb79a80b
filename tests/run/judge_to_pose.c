/* judge_to_pose RADIUS HALF_THICKNESS [--no-velocity] < STATE.csv > POSE.csv:
 * diskval's state CSV (simulate's) rewritten in judge's pose form: the centre,
 * the body-to-world quaternion and, unless --no-velocity, the velocities of
 * the disk rolling in that state (dv_pose_from_state, the engines' conversion),
 * every number to 17 digits. The equivalence and perturbation tests use it. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_pose.h"
#include "run_trajfile.h"

int main(int argc, char **argv) {
  if (argc < 3) return fprintf(stderr, "usage: judge_to_pose R H [--no-velocity]\n"), 2;
  const dv_geometry geom = {DV_SHAPE_CYLINDER, atof(argv[1]), atof(argv[2])};
  const int vel = !(argc > 3 && !strcmp(argv[3], "--no-velocity"));
  char line[4096];
  if (!fgets(line, sizeof line, stdin)) return 2; /* the state header */
  printf("t,x,y,z,qw,qx,qy,qz%s\n", vel ? ",vx,vy,vz,wx,wy,wz" : "");
  while (fgets(line, sizeof line, stdin)) {
    double v[12]; /* t,theta,phi,psi,x,y,contact_x,contact_y,theta_dot,phi_dot,psi_dot,energy */
    char *p = line;
    for (int i = 0; i < 12; i++) v[i] = strtod(p, &p), p += *p == ',';
    const double y[RED_NSTATE] = {
        [RED_TH] = v[1], [RED_PH] = v[2],  [RED_PS] = v[3],  [RED_X] = v[4],
        [RED_Y] = v[5],  [RED_VTH] = v[8], [RED_VPH] = v[9], [RED_VPS] = v[10]};
    dv_pose pose;
    dv_pose_from_state(&geom, y, &pose);
    double q[4];
    dv_matrix_to_quat(pose.R, q);
    printf("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", v[0], pose.pos[0], pose.pos[1],
           pose.pos[2], q[0], q[1], q[2], q[3]);
    if (vel)
      printf(",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g", pose.vel[0], pose.vel[1], pose.vel[2],
             pose.omega[0], pose.omega[1], pose.omega[2]);
    putchar('\n');
  }
  return 0;
}
