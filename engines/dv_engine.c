/* dv_engine: the registry of engines and what they share. */
#include "dv_engine.h"

#include <math.h>
#include <string.h>

#include "dv_pose.h"

const dv_engine_type *const dv_engines[] = {&dv_engine_reduced, &dv_engine_matched,
                                            &dv_engine_mujoco, &dv_engine_ode, NULL};

const dv_engine_type *dv_engine_find(const char *name) {
  for (const dv_engine_type *const *e = dv_engines; *e; e++)
    if (strcmp((*e)->name, name) == 0) return *e;
  return NULL;
}

const char *dv_outcome_name(dv_outcome outcome) {
  static const char *const names[] = {"completed", "event", "diverged", "lost_contact", "error"};
  return (unsigned)outcome < sizeof names / sizeof names[0] ? names[outcome] : "unknown";
}

void dv_sample_from_pose(const red_disk *disk, const dv_geometry *geom, const dv_pose *pose,
                         double t, const double *prev_y, dv_sample *out) {
  double p[3];
  out->t = t;
  dv_state_from_pose(pose, prev_y, out->y);
  dv_pose_lowest_point(geom, pose, p, &out->slip);
  out->contact[0] = p[0];
  out->contact[1] = p[1];
  out->penetration = fmax(0.0, -p[2]);
  out->energy = dv_pose_energy(disk, pose);
  out->force[0] = out->force[1] = out->force[2] = NAN;
}

void dv_stats_add_sample(dv_engine_stats *st, const dv_sample *s) {
  st->slip_max = fmax(st->slip_max, s->slip);
  st->penetration_max = fmax(st->penetration_max, s->penetration);
  if (s->contacts > st->contacts_max) st->contacts_max = s->contacts;
}
