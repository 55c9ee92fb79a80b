/* engine_ode_body: ODE body state <-> dv_pose. */
#include "engine_ode_body.h"

void dv_ode_read_pose(dBodyID body, dv_pose *p) {
  const dReal *pos = dBodyGetPosition(body), *R = dBodyGetRotation(body);
  const dReal *v = dBodyGetLinearVel(body), *w = dBodyGetAngularVel(body);
  for (int i = 0; i < 3; i++) {
    p->pos[i] = pos[i];
    p->vel[i] = v[i];
    p->omega[i] = w[i];
    for (int j = 0; j < 3; j++) p->R[3 * i + j] = R[4 * i + j]; /* ODE rows have 4 entries */
  }
}

void dv_ode_write_pose(dBodyID body, const dv_pose *p) {
  dMatrix3 R = {0};
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) R[4 * i + j] = p->R[3 * i + j];
  dBodySetPosition(body, p->pos[0], p->pos[1], p->pos[2]);
  dBodySetRotation(body, R);
  dBodySetLinearVel(body, p->vel[0], p->vel[1], p->vel[2]);
  dBodySetAngularVel(body, p->omega[0], p->omega[1], p->omega[2]);
}
