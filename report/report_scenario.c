/* dv_scenario_report: CSVs, plots, report.json and report.md of one scenario. */
#include "report_scenario.h"

#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_reference.h"
#include "run_decided.h"
#include "run_judge.h"
#include "run_meta.h"
#include "io_file.h"
#include "report_escape.h"
#include "report_page.h"
#include "report_plot.h"
#include "report_portrait.h"
#include "run_trajectory.h"
#include "run_turning.h"

/* v in fmt, or "not measured" for a NaN: a quantity nothing measured is never a number */
static const char *measured(char *buf, size_t size, const char *fmt, double v) {
  if (isnan(v)) return snprintf(buf, size, "not measured"), buf;
  snprintf(buf, size, fmt, v);
  return buf;
}

/* the trajectory tr as dir/name */
static int write_csv(const char *dir, const char *name, const dv_traj *tr, dv_error *err) {
  dv_io_file out;
  int status = dv_io_open_in(&out, dir, name, err);
  if (status) return status;
  fputs(DV_CSV_HEADER "\n", out.fp);
  for (size_t i = 0; i < tr->n; i++) dv_run_csv_row(out.fp, &tr->s[i]);
  return dv_io_commit(&out, err);
}

/* {metric: value} with null for non-finite values */
static cJSON *metrics_json(const double *v) {
  cJSON *o = cJSON_CreateObject();
  for (int m = 0; m < DV_NMETRICS; m++)
    cJSON_AddItemToObject(o, dv_metric_names[m], dv_io_json_number(v[m]));
  return o;
}

/* the share of the discrepancy the stand-in's geometry explains,
 * 1 - err_matched / err_thin, both errors over one window (the shorter of
 * the two comparisons, up to the pointwise end), where r was compared with
 * its own geometry's reference; null where it was not, with why */
static cJSON *geometry_share_json(const dv_comparison *c, const dv_engine_result *r) {
  static const dv_metric_id metrics[] = {DV_THETA_MAX_ERR, DV_PATH_MAX_ERR};
  cJSON *g = cJSON_CreateObject();
  char why[300] = "";
  const int thin_ref = !(r->half_thickness > 0.0); /* not its own geometry's reference */
  if (r->reference_note[0])
    snprintf(why, sizeof why, "n/a: %s", r->reference_note);
  else if (thin_ref && dv_engine_stand_in(r->engine, c->sc))
    snprintf(why, sizeof why,
             "n/a: no reference models this stand-in; compared with the thin disk");
  else if (thin_ref)
    snprintf(why, sizeof why, "n/a: %s simulates the exact thin disk, no stand-in",
             r->engine->name);
  else if (isnan(r->vs_ref.value[DV_THETA_MAX_ERR]) || isnan(r->vs_thin.value[DV_THETA_MAX_ERR]))
    snprintf(why, sizeof why,
             "n/a: the comparison with %s measured nothing (its window ends at t = %g s)",
             isnan(r->vs_ref.value[DV_THETA_MAX_ERR]) ? "its own reference" : "the thin disk",
             isnan(r->vs_ref.value[DV_THETA_MAX_ERR]) ? r->vs_ref.t_window : r->vs_thin.t_window);
  const double window =
      why[0] ? NAN : fmin(fmin(r->vs_ref.t_window, r->vs_thin.t_window), r->pointwise_end);
  dv_metrics own = {{0}, 0, 0.0}, thin = own;
  if (!why[0]) {
    dv_run_compare(&r->traj, &r->matched, window, &own);
    dv_run_compare(&r->traj, &c->thin, window, &thin);
  }
  int negative = 0;
  for (size_t i = 0; i < sizeof metrics / sizeof metrics[0]; i++) {
    const double e = thin.value[metrics[i]];
    double v = !why[0] && e > 0.0 ? 1.0 - own.value[metrics[i]] / e : NAN;
    /* below this the two references differ by their own integration error
     * (measured -3e-13 where the thick disk rolls upright as the thin one) */
    if (fabs(v) < 1e-9) v = 0.0;
    negative |= v < 0.0;
    cJSON_AddItemToObject(g, dv_metric_names[metrics[i]], dv_io_json_number(v));
  }
  cJSON_AddItemToObject(g, "window_end", dv_io_json_number(window));
  if (negative)
    snprintf(why, sizeof why,
             "negative: the engine is further from its own geometry's reference than from the "
             "thin disk; the stand-in's geometry cancels part of the engine's other error");
  cJSON_AddStringToObject(g, "why", why);
  return g;
}

/* the name of the reference's integrator in sc */
static const char *integrator_name(const dv_scenario *sc) {
  return red_steppers[dv_reference_settings(sc)->integrator]->name;
}

/* the reference engine r was compared with: the matched disk of its
 * half-thickness, or the thin disk; its own run's wall time (0: the shared thin run) */
static cJSON *engine_reference_json(const dv_comparison *c, const dv_engine_result *r) {
  const int matched = r->half_thickness > 0.0;
  const dv_traj *tr = matched ? &r->matched : &c->thin;
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(
      o, "engine",
      dv_engine_of_role(matched ? DV_ENGINE_MATCHED_REFERENCE : DV_ENGINE_THIN_REFERENCE)->name);
  cJSON_AddNumberToObject(o, "half_thickness", r->half_thickness);
  cJSON_AddStringToObject(o, "integrator", integrator_name(c->sc));
  cJSON_AddNumberToObject(o, "rtol", dv_reference_settings(c->sc)->rtol);
  cJSON_AddStringToObject(o, "outcome",
                          dv_outcome_name((matched ? &r->matched_stats : &c->thin_stats)->outcome));
  cJSON_AddNumberToObject(o, "t_end", tr->n ? tr->s[tr->n - 1].t : 0.0);
  cJSON_AddNumberToObject(o, "wall_s", matched ? r->matched_wall_s : 0.0);
  return o;
}

/* the lying-down judgement: null where neither the engine nor its reference lay down */
static cJSON *event_json(const dv_engine_result *r) {
  const dv_event_verdict *e = &r->event;
  if (!e->judged) return cJSON_CreateNull();
  cJSON *o = cJSON_CreateObject();
  cJSON_AddBoolToObject(o, "agrees", e->agrees);
  cJSON_AddStringToObject(o, "why", e->why);
  cJSON_AddItemToObject(o, "from", dv_io_json_number(e->from));
  cJSON_AddItemToObject(o, "to", dv_io_json_number(e->to));
  cJSON_AddStringToObject(o, "runs", e->note);
  return o;
}

/* the engine's horizon: its early error, the amplification there, why */
static cJSON *horizon_json(const dv_engine_result *r) {
  cJSON *o = cJSON_CreateObject();
  cJSON_AddItemToObject(o, "t", dv_io_json_number(r->horizon));
  cJSON_AddNumberToObject(o, "early_error", r->early_err);
  cJSON *each = cJSON_AddObjectToObject(o, "early_errors");
  for (int j = 0; j < DV_NUDGE_DIRS; j++)
    cJSON_AddNumberToObject(each, dv_nudge_dir_names[j], r->early_of[j]);
  cJSON_AddNumberToObject(o, "early_until", r->early_until);
  cJSON_AddItemToObject(o, "amplification", dv_io_json_number(r->horizon_gain));
  cJSON_AddNumberToObject(o, "nudge", r->nudge);
  cJSON_AddStringToObject(o, "why", r->horizon_why);
  return o;
}

/* how the reference amplifies nudges of its initial state (run_horizon.h) */
static cJSON *amplification_json(const dv_amplification *a) {
  cJSON *o = cJSON_CreateObject();
  char words[160];
  dv_run_amplification_words(a, words, sizeof words);
  cJSON_AddNumberToObject(o, "nudge", a->nudge);
  cJSON_AddNumberToObject(o, "rate_nudge", a->size[RED_VPH]);
  cJSON_AddStringToObject(o, "growth", a->growth);
  cJSON_AddItemToObject(o, "exponent", dv_io_json_number(a->exponent));
  cJSON_AddItemToObject(o, "efold_s", dv_io_json_number(a->efold));
  cJSON_AddItemToObject(o, "factor", dv_io_json_number(a->factor));
  cJSON_AddNumberToObject(o, "factor_t", a->factor_t);
  cJSON_AddNumberToObject(o, "measured_to", a->measured_to);
  cJSON_AddStringToObject(o, "words", words);
  return o;
}

static cJSON *engine_json(const dv_comparison *c, const dv_engine_result *r) {
  cJSON *o = metrics_json(r->whole); /* over the whole window; limits: where each is judged */
  const double sim = r->traj.n ? r->traj.s[r->traj.n - 1].t : 0.0;
  cJSON_AddItemToObject(o, "wall_per_sim_s",
                        dv_io_json_number(dv_run_cost_rate(r->wall_s, sim, c->sc->output_dt)));
  cJSON_AddNumberToObject(o, "wall_s", r->wall_s);
  cJSON_AddNumberToObject(o, "steps", (double)r->stats.steps);
  cJSON_AddStringToObject(o, "outcome", dv_run_verdict_name(r->verdict));
  cJSON_AddStringToObject(o, "detail", r->stats.detail);
  cJSON_AddBoolToObject(o, "pass", r->pass);
  cJSON *f = cJSON_AddArrayToObject(o, "failures");
  for (size_t i = 0; i < r->nfailures; i++)
    cJSON_AddItemToArray(f, cJSON_CreateString(r->failures[i]));
  cJSON *tol = cJSON_AddObjectToObject(o, "tolerances");
  cJSON *lim = cJSON_AddObjectToObject(o, "limits");
  for (int m = 0; m < DV_NMETRICS; m++) {
    cJSON_AddItemToObject(tol, dv_metric_names[m], dv_io_json_number(r->tolerance[m]));
    cJSON *l = cJSON_AddObjectToObject(lim, dv_metric_names[m]);
    cJSON_AddItemToObject(l, "value", dv_io_json_number(r->vs_ref.value[m]));
    cJSON_AddItemToObject(l, "limit", dv_io_json_number(r->tolerance[m]));
    cJSON_AddItemToObject(l, "margin", dv_io_json_number(r->vs_ref.value[m] / r->tolerance[m]));
    cJSON_AddStringToObject(l, "from", r->limit_why[m]);
    cJSON_AddNumberToObject(l, "spread", r->excused[m]);
    cJSON_AddStringToObject(l, "unit", dv_metric_units[m]);
  }
  cJSON_AddNumberToObject(o, "window_end", r->vs_ref.t_window);
  cJSON_AddNumberToObject(o, "window_fraction", r->window_fraction);
  cJSON_AddNumberToObject(o, "pointwise_end", r->pointwise_end);
  cJSON_AddStringToObject(o, "decided", r->decided);
  const int deciding = dv_run_deciding_metric(r);
  cJSON_AddItemToObject(o, "decided_metric", deciding < 0
                                                 ? cJSON_CreateNull()
                                                 : cJSON_CreateString(dv_metric_names[deciding]));
  cJSON_AddStringToObject(o, "decided_why", r->decided_why);
  cJSON_AddItemToObject(o, "horizon", horizon_json(r));
  cJSON_AddStringToObject(o, "cause", r->cause);
  cJSON_AddNumberToObject(o, "reference_half_thickness", r->half_thickness);
  char body[48];
  dv_run_body_words(r->half_thickness, body, sizeof body);
  cJSON_AddStringToObject(o, "judged", body);
  cJSON_AddStringToObject(o, "reference_note", r->reference_note);
  cJSON_AddItemToObject(o, "event", event_json(r));
  cJSON_AddItemToObject(o, "reference", engine_reference_json(c, r));
  cJSON_AddItemToObject(o, "vs_thin", metrics_json(r->vs_thin.value));
  cJSON_AddItemToObject(o, "geometry_share", geometry_share_json(c, r));
  cJSON_AddStringToObject(o, "version", r->engine->version());
  cJSON_AddItemToObject(o, "settings", dv_run_meta_settings(r->engine, c->sc));
  cJSON_AddStringToObject(o, "settings_why", dv_scenario_derived(c->sc, r->engine->name));
  char knobs[256];
  dv_engine_knobs_text(r->engine, c->sc, knobs, sizeof knobs);
  cJSON_AddStringToObject(o, "ran_with", knobs);
  const dv_replay *rp = dv_run_replay_of(r->engine);
  if (rp) { /* a recorded trajectory: what interpolating between its rows may add */
    cJSON *in = cJSON_AddObjectToObject(o, "interpolation");
    cJSON_AddItemToObject(in, "theta", dv_io_json_number(rp->interp_theta));
    cJSON_AddItemToObject(in, "path", dv_io_json_number(rp->interp_path));
    cJSON_AddNumberToObject(in, "refused_above", DV_JUDGE_INTERP_SHARE);
  }
  return o;
}

/* the reference of the scene's body: the thin disk's, or the matched run of
 * the scene's thickness (NULL where no engine needed it) */
static const dv_traj *body_reference(const dv_comparison *c) {
  if (!(c->sc->thickness > 0.0)) return &c->thin;
  for (size_t k = 0; k < c->nmatched; k++)
    if (c->matched[k].status >= 0 &&
        fabs(c->matched[k].half_thickness - 0.5 * c->sc->thickness) <= 1e-12 * c->sc->thickness)
      return &c->matched[k].traj;
  for (size_t i = 0; i < c->n; i++)
    if (c->r[i].matched.n &&
        fabs(c->r[i].half_thickness - 0.5 * c->sc->thickness) <= 1e-12 * c->sc->thickness)
      return &c->r[i].matched;
  return NULL;
}

/* the body's nutation period (s): the mean time from one maximum of theta to
 * the next over its reference's run; NAN where it completes none */
static double body_period(const dv_comparison *c) {
  const dv_traj *tr = body_reference(c);
  if (!tr || tr->n < 3) return NAN;
  double *t = malloc(tr->n * sizeof *t), *th = malloc(tr->n * sizeof *th);
  int *kind = malloc(tr->n * sizeof *kind);
  double first = NAN, last = NAN, count = 0;
  const size_t n = t && th && kind ? dv_run_turning_points(tr, INFINITY, t, th, kind) : 0;
  for (size_t k = 0; k < n; k++)
    if (kind[k] > 0) {
      if (isnan(first)) first = t[k];
      last = t[k], count++;
    }
  free(t), free(th), free(kind);
  return count >= 2 ? (last - first) / (count - 1) : NAN;
}

static int write_json(const char *dir, const dv_comparison *c, int plotted, dv_error *err) {
  const dv_scenario *sc = c->sc;
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "scenario", sc->name);
  cJSON_AddStringToObject(o, "description", sc->description);
  cJSON_AddStringToObject(o, "file", sc->path);
  cJSON_AddNumberToObject(o, "duration", sc->duration);
  cJSON_AddNumberToObject(o, "output_dt", sc->output_dt);
  cJSON *ref = cJSON_AddObjectToObject(o, "reference");
  const dv_engine_type *thin = dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
  cJSON_AddStringToObject(ref, "engine", thin->name);
  cJSON_AddStringToObject(ref, "integrator", integrator_name(sc));
  cJSON_AddNumberToObject(ref, "rtol", dv_reference_settings(sc)->rtol);
  cJSON_AddStringToObject(ref, "outcome", dv_outcome_name(c->thin_stats.outcome));
  cJSON_AddStringToObject(ref, "detail", c->thin_stats.detail);
  cJSON_AddStringToObject(ref, "method", c->thin_stats.method);
  cJSON_AddItemToObject(ref, "horizon", dv_io_json_number(c->horizon));
  cJSON_AddItemToObject(ref, "amplification", amplification_json(&c->amp));
  cJSON_AddNumberToObject(ref, "body_half_thickness", 0.5 * sc->thickness);
  cJSON_AddItemToObject(ref, "body_nutation_period", dv_io_json_number(body_period(c)));
  cJSON_AddNumberToObject(ref, "t_end", c->thin.n ? c->thin.s[c->thin.n - 1].t : 0.0);
  cJSON_AddStringToObject(ref, "version", thin->version());
  cJSON_AddNumberToObject(ref, "wall_s", c->thin_wall_s);
  cJSON_AddNumberToObject(ref, "horizon_wall_s", c->horizon_wall_s);
  cJSON_AddBoolToObject(o, "pass", c->pass);
  cJSON *engines = cJSON_AddObjectToObject(o, "engines");
  for (size_t i = 0; i < c->n; i++)
    cJSON_AddItemToObject(engines, c->r[i].engine->name, engine_json(c, &c->r[i]));
  cJSON *plots = cJSON_AddArrayToObject(o, "plots");
  for (size_t i = 0; plotted && dv_report_plot_files[i]; i++)
    cJSON_AddItemToArray(plots, cJSON_CreateString(dv_report_plot_files[i]));
  for (size_t i = 0; plotted && i < 2; i++) {
    char p[1300];
    const char *name = i ? "phase.svg" : "potential.svg";
    if (!dv_io_path(p, sizeof p, NULL, "%s/%s", dir, name) && !access(p, F_OK))
      cJSON_AddItemToArray(plots, cJSON_CreateString(name));
  }
  return dv_io_json_write(dir, "report.json", o, err);
}

/* report.md: the verdict, the reference, a table row per engine, the failures */
static int write_markdown(const char *dir, const dv_comparison *c, dv_error *err) {
  dv_io_file out;
  int status = dv_io_open_in(&out, dir, "report.md", err);
  if (status) return status;
  FILE *fp = out.fp;
  const dv_scenario *sc = c->sc;
  /* the scene's and engines' names too: an adapter's or a user's words, never markup */
  fputs("# ", fp);
  dv_report_escape_markdown(fp, sc->name);
  fprintf(fp, ": %s\n\n", c->pass ? "pass" : "FAIL");
  dv_report_escape_markdown(fp, sc->description); /* the user's text: no markup, no control bytes */
  fputs("\n\n", fp);
  /* every word an engine gives (a detail, a method, a setting's value, a
   * failure with an adapter's error line and stderr) is text, never markup */
  fprintf(fp, "Reference: reduced equations, %s at rtol %g; %s%s", integrator_name(sc),
          dv_reference_settings(sc)->rtol, dv_outcome_name(c->thin_stats.outcome),
          c->thin_stats.detail[0] ? ": " : "");
  dv_report_escape_markdown(fp, c->thin_stats.detail);
  fprintf(fp, " (t = %g s).\n\n", c->thin.n ? c->thin.s[c->thin.n - 1].t : 0.0);
  if (c->thin_stats.method[0]) {
    fprintf(fp, "Reference method%s: ", sc->thickness > 0.0 ? " (the thin disk's)" : "");
    dv_report_escape_markdown(fp, c->thin_stats.method);
    fputs(".\n\n", fp);
  }
  char words[160], body[64] = "the thin disk";
  if (sc->thickness > 0.0)
    snprintf(body, sizeof body, "the matched cylinder, %.3g mm thick", 1e3 * sc->thickness);
  const double period = body_period(c);
  if (isfinite(period))
    fprintf(fp, "The scene's body (%s) nutates every %.4g s (its reference's maxima of theta).\n\n",
            body, period);
  dv_run_amplification_words(&c->amp, words, sizeof words);
  fprintf(fp,
          "Amplification: the reference of the scene's body (%s) nudged by %g rad in theta and "
          "by %g rad/s in each rate leaves it %s (per %g of a nudge).\n\n",
          body, c->amp.nudge, c->amp.size[RED_VPH], words, DV_HORIZON_NUDGE);
  fprintf(fp,
          "| engine | outcome | reference | theta max (rad) | theta rms | path max (m) | "
          "path rms | Hausdorff (m) | energy drift | slip max (m/s) | theta max vs thin | "
          "wall s / sim s |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (size_t i = 0; i < c->n; i++) {
    const dv_engine_result *r = &c->r[i];
    const double *v = r->vs_ref.value;
    const double sim = r->traj.n ? r->traj.s[r->traj.n - 1].t : 0.0;
    char ref[48];
    if (r->half_thickness > 0.0)
      snprintf(ref, sizeof ref, "%s, h = %g m",
               dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE)->name, r->half_thickness);
    else
      snprintf(ref, sizeof ref, "thin disk");
    char rate[32] = "n/a"; /* the run simulated less than one output interval */
    const double per_sim_s = dv_run_cost_rate(r->wall_s, sim, sc->output_dt);
    if (!isnan(per_sim_s)) snprintf(rate, sizeof rate, "%.3g", per_sim_s);
    static const dv_metric_id cols[] = {DV_THETA_MAX_ERR, DV_THETA_RMS_ERR,  DV_PATH_MAX_ERR,
                                        DV_PATH_RMS_ERR,  DV_PATH_HAUSDORFF, DV_ENERGY_DRIFT,
                                        DV_SLIP_MAX};
    fputs("| ", fp);
    dv_report_escape_markdown(fp, r->engine->name);
    fprintf(fp, " | %s | %s |", dv_run_verdict_name(r->verdict), ref);
    char cell[32];
    for (size_t k = 0; k < sizeof cols / sizeof *cols; k++)
      fprintf(fp, " %s |", measured(cell, sizeof cell, "%.3g", v[cols[k]]));
    fprintf(fp, " %s | %s |\n",
            measured(cell, sizeof cell, "%.3g", r->vs_thin.value[DV_THETA_MAX_ERR]), rate);
  }
  for (size_t i = 0; i < c->n; i++) { /* what decided: each metric against its limit */
    const dv_engine_result *r = &c->r[i];
    fputc('\n', fp);
    dv_report_escape_markdown(fp, r->engine->name);
    fprintf(fp, ": %s: ", dv_run_verdict_name(r->verdict));
    dv_report_escape_markdown(fp, r->decided);
    fputs("\n\n", fp);
    dv_report_escape_markdown(fp, r->decided_why);
    fputs("\n\n", fp);
    const dv_replay *rp = dv_run_replay_of(r->engine);
    if (rp) { /* a recorded trajectory: where from (the user's path: escaped), what its
               * interpolation may add */
      dv_report_escape_markdown(fp, r->engine->name);
      fputs(": ", fp);
      dv_report_escape_markdown(fp, r->stats.method);
      fprintf(fp,
              "; the interpolation's estimated error %.3g rad in theta, %.3g m in the contact "
              "point (refused above %g of the limits).\n\n",
              rp->interp_theta, rp->interp_path, DV_JUDGE_INTERP_SHARE);
    }
    char knobs[256];
    dv_engine_knobs_text(r->engine, c->sc, knobs, sizeof knobs);
    if (knobs[0]) {
      dv_report_escape_markdown(fp, r->engine->name);
      fputs(" ran with ", fp);
      dv_report_escape_markdown(fp, knobs);
      fputs(".\n\n", fp);
    }
    if (dv_scenario_derived(c->sc, r->engine->name)[0]) {
      dv_report_escape_markdown(fp, r->engine->name);
      fputs(" settings chosen: ", fp);
      dv_report_escape_markdown(fp, dv_scenario_derived(c->sc, r->engine->name));
      fputs(".\n\n", fp);
    }
    if (r->event.judged)
      fprintf(fp, "Lying down: %s%s%s.\n\n", r->event.agrees ? "agrees" : r->event.why,
              r->event.agrees ? " with the reference: " : ": ", r->event.note);
    fprintf(fp,
            "| metric | value | limit | margin (value / limit) | limit from |\n"
            "|---|---|---|---|---|\n");
    for (int m = 0; m < DV_NMETRICS; m++) {
      char val[32], lim[32], margin[32];
      measured(val, sizeof val, "%.3g", r->vs_ref.value[m]);
      measured(lim, sizeof lim, "%.3g", r->tolerance[m]);
      measured(margin, sizeof margin, "%.3g", r->vs_ref.value[m] / r->tolerance[m]);
      fprintf(fp, "| %s | %s | %s | %s | %s |\n", dv_metric_names[m], val,
              isnan(r->tolerance[m]) ? "none" : lim,
              isnan(r->vs_ref.value[m] / r->tolerance[m]) ? "-" : margin, r->limit_why[m]);
    }
  }
  for (size_t i = 0; i < c->n; i++)
    for (size_t k = 0; k < c->r[i].nfailures; k++) {
      fputs("\n- ", fp);
      dv_report_escape_markdown(fp, c->r[i].failures[k]);
    }
  fprintf(fp, "\n");
  return dv_io_commit(&out, err);
}

/* the CSV file name of trajectory k of c's report (0: the thin reference,
 * 1..n: engine k-1, n+1..2n: the matched reference of engine k-n-1, "" when
 * it has none) into name */
static void csv_name(const dv_comparison *c, size_t k, char *name, size_t size) {
  if (k == 0)
    snprintf(name, size, "%s.csv", dv_engine_of_role(DV_ENGINE_THIN_REFERENCE)->name);
  else if (k <= c->n)
    snprintf(name, size, "%s.csv", c->r[k - 1].engine->name);
  else if (c->r[k - c->n - 1].half_thickness > 0.0)
    snprintf(name, size, "%s-%s.csv", dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE)->name,
             c->r[k - c->n - 1].engine->name);
  else
    name[0] = '\0';
}

/* trajectories k > j of c's report are one run: the thin reference compared
 * as an engine with itself ("not judged"), written once under its name */
static int same_run(const dv_comparison *c, size_t k, size_t j) {
  return j == 0 && k >= 1 && k <= c->n &&
         c->r[k - 1].engine == dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
}

/* s appended to the plots' series of in; an error when they are full */
static int add_series(dv_plot_input *in, dv_plot_series s, const char *scenario, dv_error *err) {
  if (in->nseries >= DV_PLOT_MAX_SERIES)
    return dv_fail(err, DV_EINPUT, "%s: %s: more than %d series to plot", scenario, s.label,
                   DV_PLOT_MAX_SERIES);
  in->series[in->nseries++] = s;
  return DV_OK;
}

/* the end of r's compared window, -INFINITY when it compared nothing past the start */
static double compared_until(const dv_engine_result *r) {
  return r->vs_ref.n_window >= 2 ? r->vs_ref.t_window : -INFINITY;
}

int dv_report_scenario_write(const char *dir, const dv_comparison *c, dv_error *err) {
  _Static_assert(DV_MAX_ENGINES + 1 <= DV_PLOT_MAX_SERIES,
                 "the plots hold every engine and the matched reference");
  char name[96];
  for (size_t k = 0; k <= 2 * c->n; k++) /* one file is never two of the report's outputs */
    for (size_t j = 0; j < k; j++) {
      char other[96];
      csv_name(c, k, name, sizeof name);
      csv_name(c, j, other, sizeof other);
      if (name[0] && !strcmp(name, other) && !same_run(c, k, j))
        return dv_fail(err, DV_EINPUT,
                       "%s: two trajectories of the report of %s would be this one file; "
                       "nothing was written",
                       name, c->sc->name);
    }
  snprintf(name, sizeof name, "%s.csv", dv_engine_of_role(DV_ENGINE_THIN_REFERENCE)->name);
  int status = write_csv(dir, name, &c->thin, err);
  dv_plot_input plot = {.title = c->sc->name, .thin = &c->thin, .window_end = -INFINITY};
  for (size_t i = 0; i < c->n; i++) /* the latest window end */
    plot.window_end = fmax(plot.window_end, compared_until(&c->r[i]));
  if (c->n == 0) plot.window_end = INFINITY; /* the references alone: nothing was compared */
  for (size_t i = 0; !status && i < c->n; i++) {
    const dv_engine_result *r = &c->r[i];
    snprintf(name, sizeof name, "%s.csv", r->engine->name);
    status = write_csv(dir, name, &r->traj, err);
    if (!status && r->half_thickness > 0.0) {
      snprintf(name, sizeof name, "%s-%s.csv", dv_engine_of_role(DV_ENGINE_MATCHED_REFERENCE)->name,
               r->engine->name);
      status = write_csv(dir, name, &r->matched, err);
    }
    if (!status)
      status = add_series(
          &plot,
          (dv_plot_series){r->engine->name, &r->traj,
                           r->half_thickness > 0.0 ? &r->matched : &c->thin, compared_until(r),
                           r->pointwise_end, r->tolerance[DV_THETA_MAX_ERR],
                           isnan(r->tolerance[DV_THETA_TURNING_ERR]) || r->not_judged[0] != '\0'},
          c->sc->name, err);
  }
  /* the reference a thick engine's verdict uses, drawn beside the thin one */
  char matched_label[96] = "";
  for (size_t i = 0; !status && i < c->n && !matched_label[0]; i++)
    if (c->r[i].half_thickness > 0.0) {
      snprintf(matched_label, sizeof matched_label, "reference (matched, thickness %.3g mm)",
               2e3 * c->r[i].half_thickness);
      status = add_series(&plot,
                          (dv_plot_series){matched_label, &c->r[i].matched, NULL, plot.window_end,
                                           INFINITY, NAN, 0},
                          c->sc->name, err);
    }
  int colour[DV_PLOT_MAX_SERIES] = {0}; /* the engines', then the matched reference's */
  dv_report_plot_series_colours(&plot, colour);
  if (!status) status = dv_report_plot_scenario(dir, &plot, err);
  if (!status) status = dv_report_portraits(dir, c, colour, err);
  if (!status) status = write_markdown(dir, c, err);
  if (!status) status = write_json(dir, c, 1, err);
  if (!status) status = dv_report_page_write(dir, err); /* read back from report.json */
  return status;
}

void dv_report_scenario_print(FILE *fp, const dv_comparison *c) {
  for (size_t i = 0; i < c->n; i++) {
    const dv_engine_result *r = &c->r[i];
    char th[32], path[32], body[48];
    dv_run_body_words(r->half_thickness, body, sizeof body);
    fprintf(fp, "%-24s %-8s %-18s theta %s  path %s  %s  %s\n", c->sc->name, r->engine->name,
            dv_run_verdict_name(r->verdict),
            measured(th, sizeof th, "%.2e rad", r->whole[DV_THETA_MAX_ERR]),
            measured(path, sizeof path, "%.2e m", r->whole[DV_PATH_MAX_ERR]), body,
            r->pass ? "pass" : "FAIL");
    fprintf(fp, "    %s\n", r->decided);
    if (r->reference_note[0]) fprintf(fp, "    %s\n", r->reference_note);
    if (r->event.judged && r->event.agrees) fprintf(fp, "    lies down: %s\n", r->event.note);
    for (size_t k = 0; k < r->nfailures; k++) fprintf(fp, "    %s\n", r->failures[k]);
  }
}
