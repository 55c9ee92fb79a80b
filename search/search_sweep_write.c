/* dv_search_sweep_write: a sweep as sweep.csv, sweep.json, the work-precision plot
 * and, where a timestep is varied, the error-against-timestep plot with the
 * fitted order of each curve. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_format.h"
#include "io_file.h"
#include "io_json.h"
#include "run_meta.h"
#include "report_plot.h"
#include "search_sweep.h"

size_t dv_search_sweep_curve_key(const dv_sweep *s) {
  for (size_t v = 0; v < s->nvary; v++) {
    const char *dot = strrchr(s->vary[v].key, '.');
    if (dot && (!strcmp(dot, ".timestep") || !strcmp(dot, ".rtol"))) return v;
  }
  return s->nvary ? s->nvary - 1 : 0;
}

int dv_search_sweep_fits_order(const dv_sweep *s) {
  const dv_engine_type *e = dv_engine_find(s->engine);
  const dv_engine_search *k = e ? e->search : NULL;
  char step[96];
  if (!k || !s->nvary) return 0;
  snprintf(step, sizeof step, "engines.%s.%s", k->section, k->step_key);
  return !strcmp(s->vary[dv_search_sweep_curve_key(s)].key, step);
}

void dv_search_sweep_curve_label(const dv_sweep *s, size_t k, char *out, size_t size) {
  const size_t key = dv_search_sweep_curve_key(s);
  int len = snprintf(out, size, "%s", s->engine);
  for (size_t v = 0; v < s->nvary; v++)
    if (v != key && len >= 0 && (size_t)len < size)
      len += snprintf(out + len, size - (size_t)len, " %s", s->p[k].values[v]);
}

/* the ok points of one curve, in sweep order */
typedef struct curve {
  char label[96];
  char order_label[128]; /* the label with the fitted order */
  size_t n;
  double *x, *y, *h; /* cost, theta error, the curve key's value */
  int *marked;       /* Pareto points */
} curve;

/* a sweep's curves and the storage of their points */
typedef struct curves {
  size_t n;
  curve *c;
  double *values; /* 3 per ok point */
  int *marks;     /* 1 per ok point */
} curves;

/* whether points a and b lie on one curve: the same values but for the curve key */
static int same_curve(const dv_sweep *s, size_t key, const dv_sweep_point *a,
                      const dv_sweep_point *b) {
  for (size_t v = 0; v < s->nvary; v++)
    if (v != key && strcmp(a->values[v], b->values[v])) return 0;
  return 1;
}

/* free what make_curves allocated; cs is left empty */
static void curves_free(curves *cs) {
  free(cs->c);
  free(cs->values);
  free(cs->marks);
  memset(cs, 0, sizeof *cs);
}

/* group the ok points into curves along the curve key, labelled by the
 * other keys' values (a curve without ok points stays, empty); -1 without memory */
static int make_curves(const dv_sweep *s, curves *cs) {
  const size_t key = dv_search_sweep_curve_key(s);
  size_t *of = calloc(s->n + 1, sizeof *of), *first = calloc(s->n + 1, sizeof *first), nok = 0;
  memset(cs, 0, sizeof *cs);
  cs->c = calloc(s->n + 1, sizeof *cs->c);
  for (size_t i = 0; of && first && cs->c && i < s->n; i++) {
    const dv_sweep_point *p = &s->p[i];
    size_t c = 0;
    while (c < cs->n && !same_curve(s, key, &s->p[first[c]], p)) c++;
    if (c == cs->n) {
      first[cs->n++] = i;
      dv_search_sweep_curve_label(s, i, cs->c[c].label, sizeof cs->c[c].label);
    }
    of[i] = c;
    nok += p->ok;
    cs->c[c].n += p->ok; /* counted here, filled below */
  }
  cs->values = malloc(3 * (nok + 1) * sizeof *cs->values);
  cs->marks = malloc((nok + 1) * sizeof *cs->marks);
  const int ok = of && first && cs->c && cs->values && cs->marks;
  double *v = cs->values;
  int *m = cs->marks;
  for (size_t c = 0; ok && c < cs->n; c++) { /* each curve's share of the storage */
    curve *cv = &cs->c[c];
    const size_t len = cv->n;
    cv->x = v, cv->y = v + len, cv->h = v + 2 * len, cv->marked = m, cv->n = 0;
    v += 3 * len, m += len;
  }
  for (size_t i = 0; ok && i < s->n; i++) {
    const dv_sweep_point *p = &s->p[i];
    curve *c = &cs->c[of[i]];
    if (!p->ok) continue;
    c->x[c->n] = p->wall_per_sim_s;
    c->y[c->n] = p->metric[DV_THETA_MAX_ERR];
    c->h[c->n] = s->nvary ? atof(p->values[key]) : NAN;
    c->marked[c->n++] = p->pareto;
  }
  free(of);
  free(first);
  if (!ok) curves_free(cs);
  return ok ? 0 : -1;
}

/* sweep.csv: a row per point, the metrics exact */
static int write_csv(const char *dir, const dv_sweep *s, dv_error *err) {
  dv_io_file out;
  int status = dv_io_open_in(&out, dir, "sweep.csv", err);
  if (status) return status;
  fprintf(out.fp, "engine");
  for (size_t v = 0; v < s->nvary; v++) fprintf(out.fp, ",%s", s->vary[v].key);
  for (int m = 0; m < DV_NMETRICS; m++) fprintf(out.fp, ",%s", dv_metric_names[m]);
  fprintf(out.fp, ",wall_per_sim_s,steps,outcome,pareto\n");
  for (size_t i = 0; i < s->n; i++) {
    const dv_sweep_point *p = &s->p[i];
    fprintf(out.fp, "%s", s->engine);
    for (size_t v = 0; v < s->nvary; v++) fprintf(out.fp, ",%s", p->values[v]);
    char num[DV_FORMAT_SIZE];
    for (int m = 0; m < DV_NMETRICS; m++) {
      dv_format_double(p->metric[m], num, sizeof num);
      fprintf(out.fp, ",%s", num);
    }
    dv_format_precision(p->wall_per_sim_s, 6, num, sizeof num); /* timing: 6 digits say enough */
    fprintf(out.fp, ",%s,", num);
    fprintf(out.fp, p->steps < 0 ? "nan" : "%ld", p->steps); /* < 0: not run */
    fprintf(out.fp, ",%s,%d\n", dv_run_verdict_name(p->verdict), p->pareto);
  }
  return dv_io_commit(&out, err);
}

/* sweep.json: the points, and the fitted order of every curve, numbers exact */
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
      cJSON_AddItemToObject(q, dv_metric_names[m], dv_io_json_double(p->metric[m]));
    cJSON_AddItemToObject(q, "wall_per_sim_s", dv_io_json_double(p->wall_per_sim_s));
    cJSON_AddItemToObject(q, "steps", dv_io_json_double(p->steps < 0 ? NAN : (double)p->steps));
    cJSON_AddStringToObject(q, "outcome", dv_run_verdict_name(p->verdict));
    cJSON_AddStringToObject(q, "detail", p->detail);
    cJSON_AddBoolToObject(q, "ok", p->ok);
    cJSON_AddBoolToObject(q, "pareto", p->pareto);
    cJSON_AddItemToArray(pts, q);
  }
  cJSON *orders = cJSON_AddArrayToObject(o, "orders");
  for (size_t c = 0; dv_search_sweep_fits_order(s) && c < nc; c++) {
    cJSON *q = cJSON_CreateObject();
    dv_step_fit fit;
    dv_search_fit_convergence(cv[c].h, cv[c].y, cv[c].n, &fit);
    const char *cause = dv_search_sweep_floor_cause(s, cv[c].label);
    cJSON_AddStringToObject(q, "curve", cv[c].label);
    cJSON_AddItemToObject(q, "order", dv_io_json_double(fit.order));
    cJSON_AddItemToObject(q, "floor", dv_io_json_double(fit.floor));
    cJSON_AddItemToObject(q, "floor_step", dv_io_json_double(fit.floor_step));
    cJSON_AddItemToObject(q, "floor_cause", cause ? cJSON_CreateString(cause) : cJSON_CreateNull());
    cJSON_AddItemToArray(orders, q);
  }
  return dv_io_json_write(dir, "sweep.json", o, err);
}

int dv_search_sweep_write_tables(const char *dir, const dv_sweep *s, dv_error *err) {
  curves cs;
  if (make_curves(s, &cs)) return dv_fail(err, DV_ESYSTEM, "sweep: out of memory");
  int status = write_csv(dir, s, err);
  if (!status) status = write_json(dir, s, cs.c, cs.n, err);
  curves_free(&cs);
  return status;
}

/* the plots of the curves cs of s, with the reference's curves rc (if any)
 * on the work-precision plot where there is room */
static int write_plots(const char *dir, const dv_sweep *s, curves *cs, const curves *rc,
                       dv_error *err) {
  dv_plot_curve pc[DV_PLOT_MAX_CURVES];
  char path[1200], title[200], shown[64] = "";
  char ref_label[DV_PLOT_MAX_CURVES][128]; /* the reference's errors are against itself, tighter */
  const size_t nc = cs->n < DV_PLOT_MAX_CURVES ? cs->n : DV_PLOT_MAX_CURVES;
  const size_t nr = rc->n < DV_PLOT_MAX_CURVES - nc ? rc->n : DV_PLOT_MAX_CURVES - nc;
  if (nc < cs->n) /* a plot holds so many curves; the tables have them all */
    snprintf(shown, sizeof shown, " (the first %zu of %zu curves)", nc, cs->n);
  for (size_t c = 0; c < nc + nr; c++) {
    const curve *cv = c < nc ? &cs->c[c] : &rc->c[c - nc];
    const char *label = cv->label;
    if (c >= nc) {
      snprintf(ref_label[c], sizeof ref_label[c], "%.90s (vs its own tighter run)", cv->label);
      label = ref_label[c];
    }
    pc[c] = (dv_plot_curve){label, cv->n, cv->x, cv->y, cv->marked, DV_CURVE_LINE_POINTS,
                            (int)c + 1};
  }
  snprintf(title, sizeof title, "%s: theta error against cost%s", s->scenario, shown);
  int status = dv_io_path(path, sizeof path, err, "%s/work_precision.svg", dir);
  if (!status)
    status =
        dv_report_plot_xy(path, title, "wall seconds per simulated second",
                          "max |theta error| (rad)", pc, nc + nr, DV_PLOT_LOGX | DV_PLOT_LOGY, err);
  const char *dot = s->nvary ? strrchr(s->vary[dv_search_sweep_curve_key(s)].key, '.') : NULL;
  if (status || !dot || strcmp(dot, ".timestep") || !dv_search_sweep_fits_order(s)) return status;
  for (size_t c = 0; c < nc; c++) {
    curve *cv = &cs->c[c];
    dv_step_fit fit;
    dv_search_fit_convergence(cv->h, cv->y, cv->n, &fit);
    if (isnan(fit.floor))
      snprintf(cv->order_label, sizeof cv->order_label, "%.90s (order %.2f)", cv->label, fit.order);
    else if (isnan(fit.order))
      snprintf(cv->order_label, sizeof cv->order_label, "%.80s (flat: floor %.2g rad)", cv->label,
               fit.floor);
    else
      snprintf(cv->order_label, sizeof cv->order_label, "%.70s (order %.2f, floor %.2g rad)",
               cv->label, fit.order, fit.floor);
    pc[c] = (dv_plot_curve){cv->order_label,      cv->n,     cv->h, cv->y, NULL,
                            DV_CURVE_LINE_POINTS, (int)c + 1};
  }
  snprintf(title, sizeof title, "%s: theta error against the timestep%s", s->scenario, shown);
  status = dv_io_path(path, sizeof path, err, "%s/error_vs_timestep.svg", dir);
  if (!status)
    status = dv_report_plot_xy(path, title, "timestep (s)", "max |theta error| (rad)", pc, nc,
                               DV_PLOT_LOGX | DV_PLOT_LOGY, err);
  return status;
}

int dv_search_sweep_write(const char *dir, const dv_sweep *s, const dv_sweep *ref, dv_error *err) {
  curves cs, rc = {0};
  if (make_curves(s, &cs) || (ref && make_curves(ref, &rc))) {
    curves_free(&cs);
    return dv_fail(err, DV_ESYSTEM, "sweep: out of memory");
  }
  int status = write_csv(dir, s, err);
  if (!status) status = write_json(dir, s, cs.c, cs.n, err);
  if (!status) status = write_plots(dir, s, &cs, &rc, err);
  curves_free(&cs);
  curves_free(&rc);
  return status;
}
