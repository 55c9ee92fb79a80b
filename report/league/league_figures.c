/* dv_league_figures: work_precision_OBJECT.svg per object and overview.svg.
 *
 * Per object, one curve per engine run on it: the ok probes of its cells'
 * searches with each cell's chosen choice (every target's cells merged, a
 * probe of the same choice and step once), sorted by cost; the settings of
 * the reached cells starred; each target a black horizontal line across the
 * curves' cost range. The overview: every reached cell one point, its cost
 * against its theta error, one series per engine. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "league.h"
#include "io_file.h"
#include "league_words.h"
#include "report_plot.h"

#define XLABEL "wall s per simulated s (counted)"
#define XLABEL_MEASURED "wall s per simulated s (measured by the cell's compare)"
#define YLABEL "max |#gh error| (rad)"

/* one point of a curve, before it is sorted */
typedef struct point {
  double cost, err, step;
  const char *choice;
  int marked;
} point;

/* a figure's curves and the storage they point into */
typedef struct figure {
  dv_plot_curve c[DV_PLOT_MAX_CURVES];
  size_t n;
  double *x, *y; /* per engine curve its slice, then 2 per target line */
  int *marked;
  size_t used;   /* values of x, y, marked taken */
  double lo, hi; /* the cost range of the drawn points */
} figure;

static int by_cost(const void *a, const void *b) {
  const double x = ((const point *)a)->cost, y = ((const point *)b)->cost;
  return isnan(x) ? !isnan(y) : isnan(y) ? -1 : (x > y) - (x < y);
}

/* text as PLplot text ('#' doubled) */
static void plot_text(const char *text, char *buf, size_t size) {
  size_t k = 0;
  for (const char *p = text; *p && k + 3 < size; p++) {
    if (*p == '#') buf[k++] = '#';
    buf[k++] = *p;
  }
  buf[k] = '\0';
}

static int figure_alloc(figure *f, size_t values) {
  memset(f, 0, sizeof *f);
  f->x = malloc((values + 1) * sizeof *f->x);
  f->y = malloc((values + 1) * sizeof *f->y);
  f->marked = calloc(values + 1, sizeof *f->marked);
  f->lo = INFINITY, f->hi = -INFINITY;
  return f->x && f->y && f->marked ? 0 : -1;
}

static void figure_free(figure *f) {
  free(f->x);
  free(f->y);
  free(f->marked);
}

/* add a curve of the n points pts (sorted here) to f */
static void add_curve(figure *f, const char *label, point *pts, size_t n, int style, int colour) {
  qsort(pts, n, sizeof *pts, by_cost);
  double *x = f->x + f->used, *y = f->y + f->used;
  int *m = f->marked + f->used;
  for (size_t i = 0; i < n; i++) {
    x[i] = pts[i].cost, y[i] = pts[i].err, m[i] = pts[i].marked;
    if (isfinite(x[i]) && x[i] > 0 && isfinite(y[i]) && y[i] > 0) {
      if (x[i] < f->lo) f->lo = x[i];
      if (x[i] > f->hi) f->hi = x[i];
    }
  }
  f->used += n;
  f->c[f->n++] = (dv_plot_curve){label, n, x, y, m, style, colour};
}

/* each target a black line across the drawn points' cost range (none without points) */
static void add_targets(figure *f, const dv_league *lg) {
  const double lo = f->lo < f->hi ? f->lo : f->lo / 2, hi = f->lo < f->hi ? f->hi : f->hi * 2;
  for (size_t t = 0; isfinite(lo) && t < lg->ntargets && f->n < DV_PLOT_MAX_CURVES; t++) {
    double *x = f->x + f->used, *y = f->y + f->used;
    x[0] = lo, x[1] = hi, y[0] = y[1] = lg->targets[t];
    f->used += 2;
    f->c[f->n++] = (dv_plot_curve){t ? "" : "targets", 2, x, y, NULL, DV_CURVE_LINE, 0};
  }
}

/* whether engine was run (reached or not) on object at any target */
static int was_run_on(const dv_league *lg, const char *object, const char *engine) {
  for (size_t i = 0; i < lg->ncells; i++) {
    const dv_league_cell *c = &lg->cells[i];
    if (!strcmp(c->object, object) && !strcmp(c->engine, engine) && dv_league_cell_was_run(c))
      return 1;
  }
  return 0;
}

/* the probes of engine's cells on object into pts (room for ntargets x
 * DV_LEAGUE_MAX_POINTS); their number */
static size_t object_points(const dv_league *lg, const char *object, const char *engine,
                            point *pts) {
  size_t n = 0;
  for (size_t t = 0; t < lg->ntargets; t++) {
    const dv_league_cell *c = dv_league_cell_of(lg, object, engine, lg->targets[t]);
    if (!c || !dv_league_cell_was_run(c)) continue;
    for (size_t k = 0; k < c->npoints && k < DV_LEAGUE_MAX_POINTS; k++) {
      const dv_league_point *p = &c->points[k];
      size_t j = 0;
      if (!p->ok || strcmp(p->choice, c->choice)) continue;
      while (j < n && !(pts[j].step == p->step && !strcmp(pts[j].choice, p->choice))) j++;
      if (j == n) pts[n++] = (point){p->cost, p->theta_err, p->step, p->choice, 0};
    }
  }
  for (size_t t = 0; t < lg->ntargets; t++) { /* star the settings that reached a target */
    const dv_league_cell *c = dv_league_cell_of(lg, object, engine, lg->targets[t]);
    for (size_t j = 0; c && c->outcome == DV_LEAGUE_REACHED && j < n; j++)
      if (pts[j].step == c->step && !strcmp(pts[j].choice, c->choice)) pts[j].marked = 1;
  }
  return n;
}

static int write_object(const char *dir, const dv_league *lg, const dv_league_object *ob,
                        dv_error *err) {
  const size_t per_engine = lg->ntargets * DV_LEAGUE_MAX_POINTS;
  char file[160], path[1400], name[160], title[400], shown[80] = "";
  size_t run = 0, drawn = 0;
  figure f;
  const int no_room = figure_alloc(&f, lg->nengines * per_engine + 2 * lg->ntargets);
  point *pts = malloc((per_engine + 1) * sizeof *pts);
  int status = DV_OK;
  if (!pts || no_room) {
    free(pts);
    figure_free(&f);
    return dv_fail(err, DV_ESYSTEM, "league: out of memory for %s's figure", ob->name);
  }
  for (size_t e = 0; e < lg->nengines; e++) {
    const dv_league_engine *en = &lg->engines[e];
    if (!en->available || !was_run_on(lg, ob->name, en->name)) continue;
    run++;
    if (drawn + lg->ntargets >= DV_PLOT_MAX_CURVES) continue; /* the targets' lines need room */
    const size_t n = object_points(lg, ob->name, en->name, pts);
    add_curve(&f, en->name, pts, n, DV_CURVE_LINE_POINTS, dv_report_plot_engine_colour(en->name));
    drawn++;
  }
  add_targets(&f, lg);
  if (drawn < run) snprintf(shown, sizeof shown, " (the first %zu of %zu engines)", drawn, run);
  plot_text(ob->name, name, sizeof name);
  snprintf(title, sizeof title, "%s: #gh error against cost, starred where reached%s", name, shown);
  dv_league_figure_file(ob->name, file, sizeof file);
  status = dv_io_path(path, sizeof path, err, "%s/%s", dir, file);
  if (!status)
    status =
        dv_report_plot_xy(path, title, XLABEL, YLABEL, f.c, f.n, DV_PLOT_LOGX | DV_PLOT_LOGY, err);
  free(pts);
  figure_free(&f);
  return status;
}

/* overview.svg: each reached cell a point, one series per engine run anywhere */
static int write_overview(const char *dir, const dv_league *lg, dv_error *err) {
  char path[1200], title[200], shown[80] = "";
  size_t run = 0, drawn = 0;
  figure f;
  const int no_room = figure_alloc(&f, lg->ncells + 2 * lg->ntargets);
  point *pts = malloc((lg->ncells + 1) * sizeof *pts);
  int status = DV_OK;
  if (!pts || no_room) {
    free(pts);
    figure_free(&f);
    return dv_fail(err, DV_ESYSTEM, "league: out of memory for the overview");
  }
  for (size_t e = 0; e < lg->nengines; e++) {
    const dv_league_engine *en = &lg->engines[e];
    size_t n = 0, any = 0;
    for (size_t i = 0; en->available && i < lg->ncells; i++) {
      const dv_league_cell *c = &lg->cells[i];
      if (strcmp(c->engine, en->name)) continue;
      any |= dv_league_cell_was_run(c);
      if (c->outcome == DV_LEAGUE_REACHED)
        pts[n++] = (point){c->wall_per_sim_s, c->theta_max_err, c->step, c->choice, 0};
    }
    if (!any) continue;
    run++;
    if (drawn + lg->ntargets >= DV_PLOT_MAX_CURVES) continue;
    add_curve(&f, en->name, pts, n, DV_CURVE_POINTS, dv_report_plot_engine_colour(en->name));
    drawn++;
  }
  add_targets(&f, lg);
  if (drawn < run) snprintf(shown, sizeof shown, " (the first %zu of %zu engines)", drawn, run);
  snprintf(title, sizeof title, "every object: #gh error against cost of the reached cells%s",
           shown);
  status = dv_io_path(path, sizeof path, err, "%s/overview.svg", dir);
  if (!status)
    status =
        dv_report_plot_xy(path, title, XLABEL_MEASURED, YLABEL, f.c, f.n, DV_PLOT_LOGX | DV_PLOT_LOGY, err);
  free(pts);
  figure_free(&f);
  return status;
}

int dv_league_write_figures(const char *dir, const dv_league *lg, dv_error *err) {
  int status = DV_OK;
  for (size_t o = 0; !status && o < lg->nobjects; o++)
    status = write_object(dir, lg, &lg->objects[o], err);
  return status ? status : write_overview(dir, lg, err);
}
