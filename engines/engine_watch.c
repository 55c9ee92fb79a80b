/* engine_watch: the faults that end a contact engine's run (engine_watch.h). */
#include "engine_watch.h"

#include <math.h>
#include <stdio.h>

int dv_pose_finite(const dv_pose *p) {
  double sum = 0.0;
  for (int i = 0; i < 3; i++) sum += p->pos[i] + p->vel[i] + p->omega[i];
  for (int i = 0; i < 9; i++) sum += p->R[i];
  return isfinite(sum);
}

dv_failure dv_engine_watch_start(dv_engine_watch *w, const red_disk *disk, const dv_pose *pose,
                                 char *msg, size_t size) {
  w->e0 = dv_pose_energy(disk, pose);
  w->e_max = w->e0 + 0.5 * fabs(w->e0) + disk->m * disk->g * disk->r;
  w->airborne = 0.0;
  w->checked = 0;
  if (dv_pose_finite(pose) && isfinite(w->e0)) return DV_FAILURE_NONE;
  snprintf(msg, size, "the initial pose or energy is not finite");
  return DV_FAILURE_SETUP;
}

dv_failure dv_engine_watch_check(dv_engine_watch *w, const red_disk *disk, const dv_geometry *geom,
                                 const dv_pose *p, long k, double dt, char *msg, size_t size) {
  const double t = k * dt;
  if (!dv_pose_finite(p)) {
    snprintf(msg, size, "non-finite state at t = %g s", t);
    return DV_FAILURE_NAN;
  }
  const double energy = dv_pose_energy(disk, p);
  if (!(energy <= w->e_max)) {
    snprintf(msg, size, "runaway energy at t = %g s: %g J > %g J (E0 = %g J)", t, energy,
             w->e_max, w->e0);
    return DV_FAILURE_ENERGY;
  }
  const double height = p->pos[2] + dv_geometry_contact_height(geom, p->R);
  if (height < -DV_WATCH_SUNK * disk->r) {
    snprintf(msg, size, "sank %g m into the ground at t = %g s", -height, t);
    return DV_FAILURE_SANK;
  }
  w->airborne = height > DV_WATCH_AIR * disk->r ? w->airborne + (k - w->checked) * dt : 0.0;
  if (w->airborne > DV_WATCH_AIR_TIME) {
    snprintf(msg, size, "lowest point %g m above the ground for %g s at t = %g s", height,
             w->airborne, t);
    return DV_FAILURE_LOST_CONTACT;
  }
  w->checked = k;
  return DV_FAILURE_NONE;
}
