/* dv_cli_map: diskval map: a stability map of upright rolling over the spin
 * and C/(m r^2), per engine and the reference, with the analytic critical
 * curve drawn over its cells and, in each engine's map, the cells whose
 * outcome differs from the reference's crossed. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "cli_args.h"
#include "io_file.h"
#include "io_owned.h"
#include "report_plot_cells.h"
#include "exec_pool.h"
#include "run_progress.h"
#include "run_scenario.h"
#include "report_suite_run.h"
#include "search_sweep.h"
#include "run_trajectory.h"
#include "red_steady.h"

static const char HELP[] =
    "usage: diskval map [SCENARIO] [--c A..B:N] [--spin A..B:N] [--engines LIST]\n"
    "                   [--duration S] [--out DIR] [--jobs N] [--set section.key=value]...\n"
    "\n"
    "Map upright rolling of a disk over C / (m r^2) (default 0.05..0.5:8; at most\n"
    "2A / (m r^2)) and the spin psi_dot (rad/s; default 0.1..4 sqrt(g/r):12, log),\n"
    "nudged by theta_dot = 0.05 rad/s, for DURATION s (default 50 sqrt(r/g): 5 s at\n"
    "r = 0.1 m) in every engine (default: the reference and every contact engine).\n"
    "The disk (radius, mass, A, gravity) is SCENARIO's [disk]; without one, r 0.1 m,\n"
    "m 1 kg, A = m r^2 / 4, g 9.81. The engines' settings follow each cell's scene.\n"
    "A cell 'stays up' while |theta - pi/2| < 0.1 rad; it 'falls' when theta comes\n"
    "within 0.2 rad of the floor (the run ends there) or the disk leaves the ground;\n"
    "else it 'wobbles'. Writes DIR (default: map): map.csv, and map_<engine>.svg: the\n"
    "cells coloured by outcome, the critical spin Omega_c = sqrt(m g r A / (C (C +\n"
    "m r^2))) over them and, in each engine's map, a cross on every cell whose\n"
    "outcome differs from the reference's.\n"
    "--quiet: no progress line on a terminal (cells done, time left).\n";

/* |theta - pi/2| below which a cell stays up (rad) */
#define STAYS_UP_BAND 0.1
/* a disk whose theta comes within this of the floor has fallen (rad): its
 * centre has dropped 80% of the way (sin 0.2 = 0.2); the run ends there */
#define NEAR_FLOOR 0.2
#define NUDGE 0.05 /* theta_dot at the start, rad/s */

enum { STAYS_UP = 0, WOBBLES, FALLS, FAILED, NOUTCOMES };
static const char *const OUTCOMES[NOUTCOMES] = {"stays up", "wobbles", "falls", "error"};
static const int COLOURS[NOUTCOMES] = {3, 2, 4, 8}; /* green, orange, red, grey */

typedef struct cell {
  int outcome;
  double excursion; /* max |theta - pi/2|, rad */
} cell;

typedef struct map {
  const dv_vary *c, *spin;
  const dv_engine_type *engines[DV_MAX_ENGINES + 2]; /* the reference, the engines, NULL */
  size_t nengines;
  double duration;
  red_disk disk;    /* C is set per cell */
  char name[64];    /* the scenario's, or "" */
  const char *path; /* the scenario's file, or NULL */
  int c_log;        /* --c is a log range: a log axis */
} map;

static double value(const dv_vary *v, size_t i) {
  return atof(v->values[i]);
}

/* sqrt(r / g), s (0.1 s without gravity): the disk's time scale */
static double time_scale(const red_disk *d) {
  return d->g > 0.0 ? sqrt(d->r / d->g) : 0.1;
}

/* the disk of cell column ic */
static red_disk cell_disk(const map *mp, size_t ic) {
  red_disk d = mp->disk;
  d.C = value(mp->c, ic) * d.m * d.r * d.r;
  return d;
}

/* the scenario of one cell: upright, spinning, nudged; the run ends near the floor */
static void cell_scenario(const map *mp, size_t ic, size_t is, dv_scenario *sc) {
  memset(sc, 0, sizeof *sc);
  dv_engine_init_scenario(sc);
  snprintf(sc->name, sizeof sc->name, "map");
  sc->duration = mp->duration;
  sc->output_dt = fmin(0.1 * time_scale(&mp->disk), mp->duration);
  sc->disk = cell_disk(mp, ic);
  sc->initial[RED_TH] = M_PI / 2;
  sc->initial[RED_VTH] = NUDGE;
  sc->initial[RED_VPS] = value(mp->spin, is);
  dv_scenario_set_number(sc, dv_engine_of_role(DV_ENGINE_THIN_REFERENCE)->name, "theta_limit",
                         NEAR_FLOOR, NULL);
}

typedef struct excursion {
  double max;
} excursion;

static int track(void *ctx, const dv_sample *s) {
  excursion *x = ctx;
  x->max = fmax(x->max, fabs(s->y[RED_TH] - M_PI / 2));
  return 0;
}

/* dv_pool's task: cell k = (engine, c, spin) */
static void cell_task(size_t k, void *result, void *ctx) {
  const map *mp = ctx;
  const size_t ns = mp->spin->n, nc = mp->c->n;
  const size_t is = k % ns, ic = (k / ns) % nc, ie = k / (ns * nc);
  dv_scenario sc;
  cell_scenario(mp, ic, is, &sc);
  excursion x = {0.0};
  dv_engine_stats st;
  const int status = dv_run_collect(mp->engines[ie], &sc, track, &x, &st, NULL);
  cell *out = result;
  out->excursion = x.max;
  if (status == DV_EVENT || st.outcome == DV_OUTCOME_LOST_CONTACT || x.max >= M_PI / 2 - NEAR_FLOOR)
    out->outcome = FALLS;
  else if (status < 0)
    out->outcome = FAILED;
  else
    out->outcome = x.max < STAYS_UP_BAND ? STAYS_UP : WOBBLES;
}

/* the index of the thin-disk reference among the engines, or -1 */
static int reference_index(const map *mp) {
  for (size_t e = 0; e < mp->nengines; e++)
    if (mp->engines[e]->role == DV_ENGINE_THIN_REFERENCE) return (int)e;
  return -1;
}

/* map.csv: a row per engine and cell; differs: 1 where the outcome is not the reference's */
static int write_csv(const char *dir, const map *mp, const cell *cells, dv_error *err) {
  const size_t nc = mp->c->n, ns = mp->spin->n;
  const int ref = reference_index(mp);
  dv_io_file out;
  const int status = dv_io_open_in(&out, dir, "map.csv", err);
  if (status) return status;
  fprintf(out.fp, "engine,c_ratio,psi_dot,spin_ratio,outcome,max_excursion,differs\n");
  for (size_t e = 0; e < mp->nengines; e++)
    for (size_t i = 0; i < nc * ns; i++) {
      const cell *cl = &cells[e * nc * ns + i];
      const red_disk dk = cell_disk(mp, i / ns);
      const double w = value(mp->spin, i % ns);
      fprintf(out.fp, "%s,%g,%g,%.6g,%s,%.6g,", mp->engines[e]->name, value(mp->c, i / ns), w,
              w / red_upright_critical_spin(&dk), OUTCOMES[cl->outcome], cl->excursion);
      if (ref >= 0 && (int)e != ref)
        fprintf(out.fp, "%d", cl->outcome != cells[(size_t)ref * nc * ns + i].outcome);
      fprintf(out.fp, "\n");
    }
  return dv_io_commit(&out, err);
}

/* map_<engine>.svg: the cells, the critical spin, the cells that differ from the reference */
static int write_maps(const char *dir, const map *mp, const cell *cells, dv_error *err) {
  const size_t nc = mp->c->n, ns = mp->spin->n;
  const int ref = reference_index(mp);
  enum { NCURVE = 200 };
  double *cx = malloc((2 * NCURVE + nc + ns) * sizeof *cx), *cy = cx + NCURVE, *xs = cy + NCURVE,
         *ys = xs + nc;
  int *cls = malloc(2 * nc * ns * sizeof *cls), *marked = cls + nc * ns;
  int status = cx && cls ? DV_OK : dv_fail(err, DV_ESYSTEM, "out of memory");
  for (size_t i = 0; !status && i < NCURVE; i++) {
    cx[i] = value(mp->c, 0) + (value(mp->c, nc - 1) - value(mp->c, 0)) * (double)i / (NCURVE - 1);
    red_disk dk = mp->disk;
    dk.C = cx[i] * dk.m * dk.r * dk.r;
    cy[i] = red_upright_critical_spin(&dk);
  }
  for (size_t i = 0; !status && i < nc; i++) xs[i] = value(mp->c, i);
  for (size_t j = 0; !status && j < ns; j++) ys[j] = value(mp->spin, j);
  for (size_t e = 0; !status && e < mp->nengines; e++) {
    size_t differ = 0;
    for (size_t i = 0; i < nc * ns; i++) {
      cls[i] = cells[e * nc * ns + i].outcome;
      marked[i] = ref >= 0 && (int)e != ref && cls[i] != cells[(size_t)ref * nc * ns + i].outcome;
      differ += (size_t)marked[i];
    }
    char path[1200], title[200], mark[96];
    snprintf(title, sizeof title, "%s%supright rolling in %s", mp->name, mp->name[0] ? ": " : "",
             mp->engines[e]->name);
    if (ref >= 0 && (int)e != ref)
      snprintf(title + strlen(title), sizeof title - strlen(title), " (%zu of %zu cells differ)",
               differ, nc * ns);
    snprintf(mark, sizeof mark, "not as %s", ref >= 0 ? mp->engines[ref]->name : "");
    const dv_cell_map m = {title,
                           "C / (m r#u2#d)",
                           "spin d#gq/dt (rad/s)",
                           nc,
                           ns,
                           xs,
                           ys,
                           mp->c_log,
                           1,
                           cls,
                           NOUTCOMES,
                           OUTCOMES,
                           COLOURS,
                           marked,
                           mark,
                           NCURVE,
                           cx,
                           cy,
                           "critical spin (linear)"};
    status = dv_io_path(path, sizeof path, err, "%s/map_%s.svg", dir, mp->engines[e]->name);
    if (!status) status = dv_report_plot_cells(path, &m, err);
  }
  free(cx);
  free(cls);
  return status;
}

static int write_outputs(const char *dir, const map *mp, const cell *cells, dv_error *err) {
  const int status = write_csv(dir, mp, cells, err);
  return status ? status : write_maps(dir, mp, cells, err);
}

/* the default engines: the thin-disk reference and every contact engine */
static void default_engines(map *mp) {
  mp->engines[0] = dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
  dv_cli_engine_list(NULL, mp->engines + 1, NULL);
}

/* the values of --option (a list or a log range) into out, every one a number
 * in (lo, hi], increasing (an axis of the plots); errors name the option as typed */
static int parse_axis(const char *option, const char *spec, double lo, double hi,
                      const char *range_what, dv_vary *out) {
  char as_typed[160];
  dv_error err = {{0}};
  if (!spec[0])
    return dv_cli_usage_error("map", "--%s '': expected a list v1,v2,... or a log range a..b:n",
                              option);
  snprintf(as_typed, sizeof as_typed, "--%s %s", option, spec);
  memset(out, 0, sizeof *out);
  if (dv_search_values_parse(spec, as_typed, out, &err))
    return dv_cli_usage_error("map", "%s", err.msg);
  for (size_t i = 0; i < out->n; i++) {
    char *end;
    const double v = strtod(out->values[i], &end);
    if (*end || !(v > lo && v <= hi))
      return dv_cli_usage_error("map", "--%s %s: '%s': %s must lie in (%.6g, %.6g]", option, spec,
                                out->values[i], range_what, lo, hi);
    /* checked here, not by the plot after every cell has run */
    if (i > 0 && !(v > value(out, i - 1)))
      return dv_cli_usage_error("map", "--%s %s: the values must increase ('%s' after '%s')",
                                option, spec, out->values[i], out->values[i - 1]);
  }
  return DV_EXIT_OK;
}

/* the disk of the scenario at path with sets, or the default disk; its name */
static int read_disk(const dv_cli_args *a, map *mp) {
  mp->disk = red_disk_uniform(0.1, 1.0, 9.81);
  if (!a->args.n) {
    if (a->sets.n) return dv_cli_usage_error("map", "--set needs a SCENARIO");
    return DV_EXIT_OK;
  }
  dv_scenario *sc = malloc(sizeof *sc);
  dv_error err = {{0}};
  if (!sc) return dv_cli_error("map", "out of memory");
  const int status = dv_cli_load_scenario("map", a->args.items[0], &a->sets, sc, &err);
  if (!status) {
    mp->disk = sc->disk;
    mp->path = a->args.items[0];
    snprintf(mp->name, sizeof mp->name, "%s", sc->name);
  }
  free(sc);
  return status ? dv_cli_error("map", "%s", err.msg) : DV_EXIT_OK;
}

/* the command once its options are read */
static int run_map(map *mp, const char *cspec, const char *sspec, const char *engines,
                   const char *out, int jobs) {
  char spin_default[64];
  dv_error err = {{0}};
  const red_disk *d = &mp->disk;
  if (!sspec) { /* 0.1..4 sqrt(g/r): 1..40 rad/s at r = 0.1 m */
    snprintf(spin_default, sizeof spin_default, "%.4g..%.4g:12", 0.1 / time_scale(d),
             4.0 / time_scale(d));
    sspec = spin_default;
  }
  if (isnan(mp->duration)) mp->duration = 50.0 * time_scale(d);
  int code = parse_axis("c", cspec, 0.0, 2.0 * d->A / (d->m * d->r * d->r), "C / (m r^2) (C <= 2A)",
                        (dv_vary *)mp->c);
  mp->c_log = strstr(cspec, "..") != NULL;
  if (!code) code = parse_axis("spin", sspec, 0.0, 1e6, "the spin (rad/s)", (dv_vary *)mp->spin);
  if (code) return code;
  if (engines && dv_engine_parse_list(engines, mp->engines, DV_MAX_ENGINES + 1, &err))
    return dv_cli_error("map", "%s", err.msg);
  if (!engines) default_engines(mp);
  while (mp->engines[mp->nengines]) mp->nengines++;
  /* a bad --out fails at once; the scenario (map reads it first) is none of the outputs */
  const char *outputs[DV_MAX_ENGINES + 3] = {"map.csv"};
  char svg[DV_MAX_ENGINES + 1][96];
  for (size_t e = 0; e < mp->nengines; e++) {
    snprintf(svg[e], sizeof svg[e], "map_%s.svg", mp->engines[e]->name);
    outputs[e + 1] = svg[e];
  }
  if (dv_io_check_inputs(out, outputs, (const char *const *)&mp->path, mp->path ? 1 : 0, &err) ||
      (dv_exec_mpi_rank() == 0 && dv_io_own_dir(out, outputs, &err)))
    return dv_cli_error("map", "%s", err.msg);
  const size_t n = mp->nengines * mp->c->n * mp->spin->n;
  cell *cells = calloc(n, sizeof *cells);
  if (!cells) return dv_cli_error("map", "out of memory");
  for (size_t k = 0; k < n; k++) cells[k].outcome = FAILED;
  dv_run_progress_tasks_begin("cell", n);
  const int pool =
      dv_exec_pool_run(n, sizeof *cells, cell_task, mp, cells, jobs, dv_run_progress_on_result);
  dv_run_progress_tasks_end();
  if (pool == 1) { /* a worker rank */
    free(cells);
    return DV_EXIT_OK;
  }
  if (pool != 0 || write_outputs(out, mp, cells, &err))
    code = dv_cli_error("map", "%s", err.msg[0] ? err.msg : "stopped early");
  else
    printf("map: %zu cells x %zu engines, %g s each: %s/map.csv, %s/map_<engine>.svg\n",
           mp->c->n * mp->spin->n, mp->nengines, mp->duration, out, out);
  free(cells);
  return code;
}

int dv_cli_map(int argc, char **argv) {
  const char *cspec = "0.05..0.5:8", *sspec = NULL, *engines = NULL, *out = "map";
  double duration = NAN;
  int jobs = dv_cli_default_jobs();
  const dv_cli_option options[] = {
      {"c", DV_CLI_TEXT, &cspec, 0, 0},         {"spin", DV_CLI_TEXT, &sspec, 0, 0},
      {"engines", DV_CLI_TEXT, &engines, 0, 0}, {"duration", DV_CLI_REAL, &duration, 1e-6, 3600.0},
      {"out", DV_CLI_TEXT, &out, 0, 0},         {"jobs", DV_CLI_INT, &jobs, 1, 1024},
  };
  const dv_cli_command cmd = {"map", HELP, options, 6, 0, 1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_vary c, spin;
  map mp = {.c = &c, .spin = &spin, .duration = duration};
  dv_run_progress_start("map", a.quiet, 0);
  int code = read_disk(&a, &mp);
  if (!code) code = run_map(&mp, cspec, sspec, engines, out, jobs);
  dv_cli_args_free(&cmd, &a);
  return code;
}
