/* dv_search_sweep_write: a sweep as sweep.csv, sweep.json, the work-precision plot
 * and, where a timestep is varied, the error-against-timestep plot with the
 * fitted order of each curve. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_meta.h"
#include "io_file.h"
#include "report_plot.h"
#include "search_sweep.h"

#define MAX_CURVES 16

/* the varied key that orders a curve: a timestep or a tolerance, else the last */
static size_t curve_key(const dv_sweep *s) {
  for (size_t v = 0; v < s->nvary; v++) {
    const char *dot = strrchr(s->vary[v].key, '.');
    if (dot && (!strcmp(dot, ".timestep") || !strcmp(dot, ".rtol"))) return v;
  }
  return s->nvary ? s->nvary - 1 : 0;
}

typedef struct curve {
  char label[96];
  size_t n;
  double x[DV_SWEEP_MAX_VALUES], y[DV_SWEEP_MAX_VALUES], h[DV_SWEEP_MAX_VALUES];
  int marked[DV_SWEEP_MAX_VALUES];
} curve;

/* group the ok points into curves along the curve key, labelled by the rest */
static size_t make_curves(const dv_sweep *s, curve *cv, size_t max) {
  const size_t key = curve_key(s);
  size_t nc = 0;
  for (size_t i = 0; i < s->n; i++) {
    const dv_sweep_point *p = &s->p[i];
    char label[96];
    int len = snprintf(label, sizeof label, "%s", s->engine);
    for (size_t v = 0; v < s->nvary; v++)
      if (v != key && len < (int)sizeof label)
        len += snprintf(label + len, sizeof label - (size_t)len, " %s", p->values[v]);
    size_t c = 0;
    while (c < nc && strcmp(cv[c].label, label)) c++;
    if (c == nc) {
      if (nc == max) continue;
      memset(&cv[nc], 0, sizeof cv[nc]);
      snprintf(cv[nc++].label, sizeof cv[0].label, "%s", label);
    }
    if (!p->ok || cv[c].n == DV_SWEEP_MAX_VALUES) continue;
    cv[c].x[cv[c].n] = p->wall_per_sim_s;
    cv[c].y[cv[c].n] = p->metric[DV_THETA_MAX_ERR];
    cv[c].h[cv[c].n] = s->nvary ? atof(p->values[key]) : NAN;
    cv[c].marked[cv[c].n++] = p->pareto;
  }
  return nc;
}

static int write_csv(const char *dir, const dv_sweep *s, dv_error *err) {
  char path[1200];
  dv_io_file out;
  snprintf(path, sizeof path, "%s/sweep.csv", dir);
  int status = dv_io_open(&out, path, err);
  if (status) return status;
  fprintf(out.fp, "engine");
  for (size_t v = 0; v < s->nvary; v++) fprintf(out.fp, ",%s", s->vary[v].key);
  for (int m = 0; m < DV_NMETRICS; m++) fprintf(out.fp, ",%s", dv_metric_names[m]);
  fprintf(out.fp, ",wall_per_sim_s,steps,outcome,pareto\n");
  for (size_t i = 0; i < s->n; i++) {
    const dv_sweep_point *p = &s->p[i];
    fprintf(out.fp, "%s", s->engine);
    for (size_t v = 0; v < s->nvary; v++) fprintf(out.fp, ",%s", p->values[v]);
    for (int m = 0; m < DV_NMETRICS; m++) fprintf(out.fp, ",%.9g", p->metric[m]);
    fprintf(out.fp, ",%.6g,%ld,%s,%d\n", p->wall_per_sim_s, p->steps, dv_run_verdict_name(p->verdict), p->pareto);
  }
  return dv_io_commit(&out, err);
}

static int write_json(const char *dir, const dv_sweep *s, const curve *cv, size_t nc,
                      dv_error *err) {
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "scenario", s->scenario);
  cJSON_AddStringToObject(o, "engine", s->engine);
  cJSON *vary = cJSON_AddArrayToObject(o, "vary");
  for (size_t v = 0; v < s->nvary; v++)
    cJSON_AddItemToArray(vary, cJSON_CreateString(s->vary[v].key));
  cJSON *pts = cJSON_AddArrayToObject(o, "points");
  for (size_t i = 0; i < s->n; i++) {
    const dv_sweep_point *p = &s->p[i];
    cJSON *q = cJSON_CreateObject();
    cJSON *set = cJSON_AddObjectToObject(q, "settings");
    for (size_t v = 0; v < s->nvary; v++)
      cJSON_AddStringToObject(set, s->vary[v].key, p->values[v]);
    for (int m = 0; m < DV_NMETRICS; m++)
      cJSON_AddItemToObject(q, dv_metric_names[m], dv_io_json_number(p->metric[m]));
    cJSON_AddItemToObject(q, "wall_per_sim_s", dv_io_json_number(p->wall_per_sim_s));
    cJSON_AddNumberToObject(q, "steps", (double)p->steps);
    cJSON_AddStringToObject(q, "outcome", dv_run_verdict_name(p->verdict));
    cJSON_AddStringToObject(q, "detail", p->detail);
    cJSON_AddBoolToObject(q, "ok", p->ok);
    cJSON_AddBoolToObject(q, "pareto", p->pareto);
    cJSON_AddItemToArray(pts, q);
  }
  cJSON *orders = cJSON_AddArrayToObject(o, "orders");
  for (size_t c = 0; c < nc; c++) {
    cJSON *q = cJSON_CreateObject();
    cJSON_AddStringToObject(q, "curve", cv[c].label);
    cJSON_AddItemToObject(q, "order", dv_io_json_number(dv_search_fit_order(cv[c].h, cv[c].y, cv[c].n)));
    cJSON_AddItemToArray(orders, q);
  }
  return dv_io_json_write(dir, "sweep.json", o, err);
}

int dv_search_sweep_write_tables(const char *dir, const dv_sweep *s, dv_error *err) {
  static curve cv[MAX_CURVES];
  const size_t nc = make_curves(s, cv, MAX_CURVES);
  int status = write_csv(dir, s, err);
  return status ? status : write_json(dir, s, cv, nc, err);
}

int dv_search_sweep_write(const char *dir, const dv_sweep *s, const dv_sweep *ref, dv_error *err) {
  static curve cv[MAX_CURVES], rc[MAX_CURVES];
  const size_t nc = make_curves(s, cv, MAX_CURVES);
  const size_t nr = ref ? make_curves(ref, rc, MAX_CURVES - nc) : 0;
  int status = write_csv(dir, s, err);
  if (!status) status = write_json(dir, s, cv, nc, err);
  dv_plot_curve pc[MAX_CURVES];
  char path[1200], title[160];
  for (size_t c = 0; c < nc; c++)
    pc[c] = (dv_plot_curve){cv[c].label,          cv[c].n,   cv[c].x, cv[c].y, cv[c].marked,
                            DV_CURVE_LINE_POINTS, (int)c + 1};
  for (size_t c = 0; c < nr; c++)
    pc[nc + c] =
        (dv_plot_curve){rc[c].label,          rc[c].n,          rc[c].x, rc[c].y, rc[c].marked,
                        DV_CURVE_LINE_POINTS, (int)(nc + c) + 1};
  snprintf(path, sizeof path, "%s/work_precision.svg", dir);
  snprintf(title, sizeof title, "%s: theta error against cost", s->scenario);
  if (!status)
    status = dv_report_plot_xy(path, title, "wall seconds per simulated second", "max |theta error| (rad)",
                        pc, nc + nr, DV_PLOT_LOGX | DV_PLOT_LOGY, err);
  const char *dot = s->nvary ? strrchr(s->vary[curve_key(s)].key, '.') : NULL;
  if (status || !dot || strcmp(dot, ".timestep")) return status;
  static char labels[MAX_CURVES][128];
  for (size_t c = 0; c < nc; c++) {
    snprintf(labels[c], sizeof labels[c], "%.90s (order %.2f)", cv[c].label,
             dv_search_fit_order(cv[c].h, cv[c].y, cv[c].n));
    pc[c] = (dv_plot_curve){labels[c], cv[c].n, cv[c].h, cv[c].y, NULL, DV_CURVE_LINE_POINTS,
                            (int)c + 1};
  }
  snprintf(path, sizeof path, "%s/error_vs_timestep.svg", dir);
  snprintf(title, sizeof title, "%s: theta error against the timestep", s->scenario);
  return dv_report_plot_xy(path, title, "timestep (s)", "max |theta error| (rad)", pc, nc,
                    DV_PLOT_LOGX | DV_PLOT_LOGY, err);
}
