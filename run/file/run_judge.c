/* run_judge: a comparison of recorded trajectories (run_judge.h). */
#include "run_judge.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

typedef struct judge_ctx {
  int sparse;   /* a file too sparse to judge */
  dv_error why; /* the first such file, in one line */
} judge_ctx;

/* metric m not judged, and why */
static void not_judged(dv_engine_result *r, int m, const char *why) {
  r->tolerance[m] = NAN;
  snprintf(r->limit_why[m], sizeof r->limit_why[m], "not judged: %.99s", why);
}

/* the end of the compared window: the reference's end or its validity limit */
static double window_end(const dv_comparison *c, const dv_engine_result *r) {
  const dv_traj *ref = r->half_thickness > 0.0 ? &r->matched : &c->thin;
  const double end = ref->n ? ref->s[ref->n - 1].t : 0.0;
  return r->half_thickness > 0.0 ? end : fmin(end, c->thin_valid_end);
}

/* the interpolation's error against the limits: a file too sparse into ctx */
static void check_sparse(judge_ctx *ctx, const dv_replay *rp, const dv_engine_result *r) {
  const double lth = DV_JUDGE_INTERP_SHARE * r->tolerance[DV_THETA_MAX_ERR];
  const double lp = DV_JUDGE_INTERP_SHARE * r->tolerance[DV_PATH_MAX_ERR];
  /* rows between the sample times no sample serves: each must agree with
   * the interpolation through the rows at them, or it would go unjudged */
  const double bl = DV_JUDGE_BETWEEN_SHARE / DV_JUDGE_INTERP_SHARE;
  const int bth = rp->between_theta > bl * lth, bp = rp->between_path > bl * lp;
  if (!ctx->sparse && (bth || bp)) {
    ctx->sparse = 1;
    dv_fail(&ctx->why, DV_EINPUT,
            "%.400s:%ld: a row between the scenario's sample times disagrees with the rows at "
            "them: its %s is %.3g %s from their interpolation (Akima) beyond twice its "
            "uncertainty (against Steffen), %.3g times %g of its limit %.3g %s; every row must "
            "count, so rows no sample serves must agree with those that do",
            rp->file->path, bth ? rp->between_theta_line : rp->between_path_line,
            bth ? "theta" : "contact point", bth ? rp->between_theta : rp->between_path,
            bth ? "rad" : "m", bth ? rp->between_theta / (bl * lth) : rp->between_path / (bl * lp),
            DV_JUDGE_BETWEEN_SHARE,
            bth ? r->tolerance[DV_THETA_MAX_ERR] : r->tolerance[DV_PATH_MAX_ERR],
            bth ? "rad" : "m");
    return;
  }
  const int th = rp->interp_theta > lth, p = rp->interp_path > lp;
  if (ctx->sparse || !(th || p)) return;
  ctx->sparse = 1;
  dv_fail(&ctx->why, DV_EINPUT,
          "%.400s:%ld: samples too sparse to judge: interpolating between them (Akima against "
          "Steffen) is uncertain by %.3g %s in %s after this line, %.3g times %g of its limit %.3g "
          "%s; give samples more often",
          rp->file->path, th ? rp->theta_line : rp->path_line,
          th ? rp->interp_theta : rp->interp_path, th ? "rad" : "m",
          th ? "theta" : "the contact point", (th ? rp->interp_theta / lth : rp->interp_path / lp),
          DV_JUDGE_INTERP_SHARE,
          th ? r->tolerance[DV_THETA_MAX_ERR] : r->tolerance[DV_PATH_MAX_ERR], th ? "rad" : "m");
}

/* value column k (DV_CSV_HEADER's k+1: theta .. energy) of s */
static double value_of(const dv_sample *s, int k) {
  static const int state[DV_TRAJ_NVALUES] = {RED_TH, RED_PH,  RED_PS,  RED_X,   RED_Y, -1,
                                             -1,     RED_VTH, RED_VPH, RED_VPS, -1};
  return state[k] >= 0 ? s->y[state[k]]
         : k == 5      ? s->contact[0]
         : k == 6      ? s->contact[1]
                       : s->energy;
}

/* v, written with its last digit at 10^digit, is r to that digit: r rounded
 * there reads back as v (either way at a tie). Not a measured tolerance but
 * the rounding's bound: the text is within half its last place of r, and v,
 * the double nearest the text, within half an ulp of the text; the factor
 * 1 + 4 eps covers pow's and the subtraction's rounding. At full precision
 * (simulate's shortest round trip) half a place is under half an ulp, so two
 * different doubles never match. Checked (tests/check_judge_hostile.sh): the
 * reference's output written with %.10g is its own, theta 1e-9 rad off on one
 * row is not. An exact value (DV_TRAJ_EXACT) is r, bit for bit. */
static int same_printed(double v, double r, signed char digit) {
  if (v == r) return 1;
  if (digit == DV_TRAJ_EXACT || !isfinite(r)) return 0;
  const double half_ulp = 0.5 * (nextafter(fabs(v), INFINITY) - fabs(v));
  return fabs(v - r) <= 0.5 * pow(10.0, digit) * (1.0 + 4.0 * DBL_EPSILON) + half_ulp;
}

/* the file is the reference's own output: a row at every sample time of ref
 * (the replay's run eng has as many samples) whose every value column the
 * file gives is ref's there, to the digits it is written with (what the file
 * does not give is derived, and does not count). Rows between the sample
 * times serve no sample: check_sparse holds them to those at them. The pose
 * form is a conversion of the state, never the reference's own digits. */
static int own_output(const dv_trajfile *f, const dv_traj *eng, const dv_traj *ref) {
  if (f->form != DV_TRAJ_STATE || eng->n != ref->n || ref->n < 2) return 0;
  size_t j = 0;
  for (size_t i = 0; i < ref->n; i++) {
    const dv_sample *b = &ref->s[i];
    /* a recorded time to 1e-9 s relative, the replay's (run_replay.h) */
    const double near = 1e-9 * fmax(1.0, fabs(b->t));
    while (j < f->n && f->s[j].t < b->t - near) j++;
    if (j == f->n || fabs(f->s[j].t - b->t) > near) return 0;
    const dv_sample *a = &f->s[j];
    for (int k = 0; k < DV_TRAJ_NVALUES; k++)
      if ((f->given >> k & 1u) &&
          !same_printed(value_of(a, k), value_of(b, k), f->digit ? f->digit[j][k] : DV_TRAJ_EXACT))
        return 0;
  }
  return 1;
}

static void before_verdict(void *p, const dv_comparison *c, dv_engine_result *r) {
  judge_ctx *ctx = p;
  const dv_replay *rp = dv_run_replay_of(r->engine);
  if (!rp) return;
  const dv_trajfile *f = rp->file;
  if (!f->has_slip) {
    r->vs_ref.value[DV_SLIP_MAX] = r->vs_thin.value[DV_SLIP_MAX] = NAN; /* unmeasured, not 0 */
    not_judged(r, DV_SLIP_MAX,
               f->form == DV_TRAJ_POSE
                   ? "no velocities (vx..wz) in the file: no slip to measure"
                   : "the state form's rates assume rolling: no slip to measure");
  }
  /* what needs the columns a file lacks: NaN samples there may fold into a
   * maximum as nothing, so these are not judged whatever they came to */
  if (!f->has_angles) {
    r->vs_ref.value[DV_HEADING_PERIOD_ERR] = r->vs_thin.value[DV_HEADING_PERIOD_ERR] = NAN;
    not_judged(r, DV_HEADING_PERIOD_ERR, "no phi in the file: no heading to compare");
  }
  if (!f->has_angles && !f->has_rates) {
    r->vs_ref.value[DV_INVARIANT_DRIFT] = r->vs_thin.value[DV_INVARIANT_DRIFT] = NAN;
    not_judged(r, DV_INVARIANT_DRIFT, "no rates in the file, nor phi, psi to derive them from");
  }
  if (!f->has_energy) {
    r->vs_ref.value[DV_ENERGY_DRIFT] = r->vs_thin.value[DV_ENERGY_DRIFT] = NAN;
    not_judged(r, DV_ENERGY_DRIFT, "no energy in the file, nor a pose to compute it from");
  }
  for (int m = 0; m < DV_NMETRICS; m++)
    if (isnan(r->vs_ref.value[m]) && !isnan(r->tolerance[m]))
      not_judged(r, m,
                 r->traj.n < 2          ? "the run ended at its first sample: nothing measured"
                 : m == DV_ENERGY_DRIFT ? "no energy in the file, nor a pose to compute it from"
                                        : "no phi, psi, x, y in the file to compute it from");
  const double end = window_end(c, r);
  if (own_output(f, &r->traj, r->half_thickness > 0.0 ? &r->matched : &c->thin))
    snprintf(r->not_judged, sizeof r->not_judged,
             "its every sample is the reference's, to the digits the file gives (the "
             "reference's own output): its errors are zero and measure nothing");
  else if (rp->ends_early && rp->t_end < end - 0.5 * c->sc->output_dt)
    snprintf(r->not_judged, sizeof r->not_judged,
             "the file ends at t = %g s, before the compared window does (t = %g s), without "
             "lying down: what it does not cover cannot be judged",
             rp->t_end, end);
  /* a given energy the state does not bear out would make the energy drift
   * the column's, not the run's */
  size_t row;
  const double gap = dv_run_trajfile_energy_gap(f, c->sc, end, &row);
  const double share = f->has_rates ? DV_JUDGE_ENERGY_SHARE : DV_JUDGE_ENERGY_SHARE_DERIVED;
  const double le = share * r->tolerance[DV_ENERGY_DRIFT];
  if (!ctx->sparse && gap > le) {
    ctx->sparse = 1;
    dv_fail(&ctx->why, DV_EINPUT,
            "%.400s:%ld: the energy is not the energy of the state the row gives: off by %.3g of "
            "the starting energy, %.3g times %g of the energy drift's limit %.3g (the drift would "
            "measure the column, not the run): the columns disagree",
            f->path, f->line[row], gap, gap / le, share, r->tolerance[DV_ENERGY_DRIFT]);
  }
  check_sparse(ctx, rp, r);
}

int dv_run_judge(const dv_scenario *sc, dv_replay *replays, size_t n, dv_comparison *c,
                 dv_error *err) {
  const dv_engine_type *types[DV_MAX_ENGINES];
  if (n > DV_MAX_ENGINES)
    return dv_fail(err, DV_EINPUT, "at most %d trajectories at a time", DV_MAX_ENGINES);
  size_t rows = 0;
  for (size_t i = 0; i < n; i++) types[i] = &replays[i].type, rows += replays[i].file->n;
  if (rows > dv_run_trajfile_max_rows(sc))
    return dv_fail(err, DV_EINPUT,
                   "%zu rows in %zu trajectories: judged with the comparison they need more than "
                   "memory_budget = %g GiB (%d bytes a row; raise it with --set "
                   "scenario.memory_budget=GIB)",
                   rows, n, sc->memory_budget, DV_TRAJ_ROW_BYTES);
  judge_ctx ctx = {0, {{0}}};
  const dv_run_hook hook = {before_verdict, &ctx};
  const int status = dv_run_scenario_hooked(sc, NULL, types, n, &hook, c, err);
  if (status < 0) return status;
  if (ctx.sparse) return *err = ctx.why, DV_EINPUT;
  return DV_OK;
}
