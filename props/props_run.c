/* props_run: the reference solved again, and a trajectory judged with a known
 * error added (props.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "dv_pose.h"
#include "dv_reference.h"
#include "props.h"
#include "run_judge.h"
#include "run_trajectory.h"

props_error props_none(void) {
  return (props_error){.tail_after = INFINITY, .lambda = 1.0, .tau = 1.0};
}

int props_with(const dv_scenario *sc, const char *const *sets, size_t n, dv_scenario *out,
               dv_error *err) {
  return dv_scenario_with(sc, sets, n, out, err);
}

static int push(void *ctx, const dv_sample *s) {
  return dv_run_traj_push(ctx, s);
}

int props_solve_from(const dv_scenario *sc, const double *nudge, double clock, dv_traj *out,
                     dv_error *err) {
  const dv_engine_type *ref = dv_engine_of_role(sc->thickness > 0.0 ? DV_ENGINE_MATCHED_REFERENCE
                                                                    : DV_ENGINE_THIN_REFERENCE);
  const char *thin = dv_engine_of_role(DV_ENGINE_THIN_REFERENCE)->name;
  char sets[5][80];
  snprintf(sets[0], sizeof sets[0], "engines.%s.rtol=1e-13", thin);
  snprintf(sets[1], sizeof sets[1], "engines.%s.atol=1e-14", thin);
  snprintf(sets[2], sizeof sets[2], "engines.%s.fold=off", thin);
  snprintf(sets[3], sizeof sets[3], "scenario.duration=%.17g", sc->duration * clock);
  snprintf(sets[4], sizeof sets[4], "scenario.output_dt=%.17g", sc->output_dt * clock);
  const char *set[] = {sets[0], sets[1], sets[2], sets[3], sets[4]};
  static dv_scenario fine;
  int status = props_with(sc, set, clock == 1.0 ? 3 : 5, &fine, err);
  /* the start moved after the checks, which would derive a steady start's rates again */
  for (int j = 0; nudge && j <= RED_VPS; j++) fine.initial[j] += nudge[j];
  memset(out, 0, sizeof *out);
  dv_engine_stats st;
  if (!status) status = dv_run_collect(ref, &fine, push, out, &st, err);
  return status < 0 ? status : DV_OK;
}

int props_solve(const dv_scenario *sc, dv_traj *out, dv_error *err) {
  return props_solve_from(sc, NULL, 1.0, out, err);
}

void props_tangent(const dv_traj *tr, size_t i, double u[2]) {
  const size_t a = i ? i - 1 : i, b = i + 1 < tr->n ? i + 1 : i;
  const double dx = tr->s[b].contact[0] - tr->s[a].contact[0];
  const double dy = tr->s[b].contact[1] - tr->s[a].contact[1];
  const double d = hypot(dx, dy);
  u[0] = d > 0.0 ? dx / d : 0.0;
  u[1] = d > 0.0 ? dy / d : 0.0;
}

double props_ramp(const props_error *e, double t) {
  const double span = e->t_full - e->t_from;
  return t <= e->t_from || !(span > 0.0) ? 0.0 : (t - e->t_from) / span;
}

/* the state of sample i with e done to it, at time *t */
static void apply(const dv_scenario *sc, const dv_traj *tr, size_t i, const props_error *e,
                  double *t, double y[RED_NSTATE]) {
  const dv_sample *s = &tr->s[i];
  memcpy(y, s->y, sizeof s->y);
  *t = s->t;
  const double span = e->t_full - e->t_from, ramp = props_ramp(e, s->t);
  y[RED_TH] += e->theta * ramp;
  if (ramp > 0.0) y[RED_VTH] += e->theta / span; /* the rate says so too */
  for (int k = RED_VTH; e->bleed && k <= RED_VPS; k++) y[k] *= 1.0 + e->bleed[i];
  double u[2];
  props_tangent(tr, i, u);
  y[RED_X] += e->phase * ramp * u[0];
  y[RED_Y] += e->phase * ramp * u[1];
  if (s->t > e->tail_after) { /* theta drawn toward upright from the window's end on, smoothly */
    const double over = 20.0 * sc->output_dt, v = (s->t - e->tail_after) / over;
    const double bend = v < 1.0 ? v * v * v : 1.0, rate = v < 1.0 ? 3.0 * v * v / over : 0.0;
    y[RED_VTH] = y[RED_VTH] * (1.0 - 0.3 * bend) - 0.3 * rate * (y[RED_TH] - M_PI_2);
    y[RED_TH] = M_PI_2 + (y[RED_TH] - M_PI_2) * (1.0 - 0.3 * bend);
  }
  const double c = cos(e->shift[2]), sn = sin(e->shift[2]);
  const double px = y[RED_X] - e->origin[0], py = y[RED_Y] - e->origin[1];
  y[RED_X] = e->origin[0] + e->shift[0] + c * px - sn * py;
  y[RED_Y] = e->origin[1] + e->shift[1] + sn * px + c * py;
  y[RED_PH] += e->shift[2];
  y[RED_X] *= e->lambda;
  y[RED_Y] *= e->lambda;
  for (int k = RED_VTH; k <= RED_VPS; k++) y[k] /= e->tau;
  *t *= e->tau;
}

int props_judge(const dv_scenario *sc, const dv_traj *tr, const props_error *e, int pose,
                dv_comparison *c, dv_error *err) {
  dv_trajfile f;
  dv_run_trajfile_begin(&f, "props");
  const dv_geometry geom = {DV_SHAPE_CYLINDER, sc->disk.r, 0.5 * sc->thickness};
  int status = DV_OK;
  for (size_t i = 0; i < tr->n && !status; i++) {
    double t, y[RED_NSTATE];
    apply(sc, tr, i, e, &t, y);
    if (t > sc->duration * (1.0 + 1e-12)) break;
    if (!pose) {
      status = dv_run_trajfile_push_state(&f, sc, t, y, err);
      continue;
    }
    dv_pose p;
    dv_pose_from_state(&geom, y, &p);
    double q[4];
    dv_matrix_to_quat(p.R, q);
    status = dv_run_trajfile_push_pose(&f, sc, t, p.pos, q, p.vel, p.omega, err);
  }
  if (!status) status = dv_run_trajfile_end(&f, sc, err);
  dv_replay *rp = malloc(sizeof *rp);
  memset(c, 0, sizeof *c);
  if (!rp) status = dv_fail(err, DV_ESYSTEM, "out of memory");
  if (!status) {
    dv_run_replay_init(rp, &f, "props");
    status = dv_run_judge(sc, rp, 1, c, err);
  }
  free(rp);
  dv_run_trajfile_free(&f);
  return status;
}
