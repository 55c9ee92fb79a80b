/* dv_cli_map: diskval map: a stability map of upright rolling over the spin
 * and C/(m r^2), per engine and the reference, with the analytic critical
 * curve drawn over it. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "cli_args.h"
#include "io_file.h"
#include "report_plot.h"
#include "exec_pool.h"
#include "run_scenario.h"
#include "report_suite_run.h"
#include "search_sweep.h"
#include "run_trajectory.h"
#include "red_steady.h"

static const char HELP[] =
    "usage: diskval map [--c A..B:N] [--spin A..B:N] [--engines LIST] [--duration S]\n"
    "                   [--out DIR] [--jobs N]\n"
    "\n"
    "Map upright rolling of a disk (r 0.1 m, m 1 kg, A = m r^2 / 4) over C / (m r^2)\n"
    "(default 0.05..0.5:8) and the spin psi_dot (rad/s, default 1..40:12, log), nudged\n"
    "by theta_dot = 0.05 rad/s, for DURATION s (default 5) in every engine (default:\n"
    "the reference and every contact engine). Each cell is 'stays up' (|theta - pi/2| < 0.1 rad),\n"
    "'wobbles', or 'falls' (lies down or leaves the ground). Writes DIR (default: map):\n"
    "map.csv and map_<engine>.svg with the critical spin\n"
    "Omega_c = sqrt(m g r A / (C (C + m r^2))) drawn over the cells.\n";

enum { STAYS_UP = 0, WOBBLES, FALLS, FAILED, NOUTCOMES };
static const char *const OUTCOMES[NOUTCOMES] = {"stays up", "wobbles", "falls", "error"};

typedef struct cell {
  int outcome;
  double excursion; /* max |theta - pi/2|, rad */
} cell;

typedef struct map {
  const dv_vary *c, *spin;
  const dv_engine_type *engines[DV_MAX_ENGINES + 2]; /* the reference, the engines, NULL */
  size_t nengines;
  double duration;
} map;

static double value(const dv_vary *v, size_t i) {
  return atof(v->values[i]);
}

/* the scenario of one cell */
static void cell_scenario(const map *mp, size_t ic, size_t is, dv_scenario *sc) {
  memset(sc, 0, sizeof *sc);
  dv_engine_init_scenario(sc);
  snprintf(sc->name, sizeof sc->name, "map");
  sc->duration = mp->duration;
  sc->output_dt = 0.01;
  sc->disk = red_disk_uniform(0.1, 1.0, 9.81);
  sc->disk.C = value(mp->c, ic) * sc->disk.m * sc->disk.r * sc->disk.r;
  sc->initial[RED_TH] = M_PI / 2;
  sc->initial[RED_VTH] = 0.05;
  sc->initial[RED_VPS] = value(mp->spin, is);
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
  if (status == DV_EVENT || st.outcome == DV_OUTCOME_LOST_CONTACT)
    out->outcome = FALLS;
  else if (status < 0)
    out->outcome = FAILED;
  else
    out->outcome = x.max < 0.1 ? STAYS_UP : WOBBLES;
}

static int write_outputs(const char *dir, const map *mp, const cell *cells, dv_error *err) {
  const size_t nc = mp->c->n, ns = mp->spin->n;
  char path[1200];
  dv_io_file out;
  snprintf(path, sizeof path, "%s/map.csv", dir);
  int status = dv_io_open(&out, path, err);
  if (status) return status;
  fprintf(out.fp, "engine,c_ratio,psi_dot,spin_ratio,outcome,max_excursion\n");
  for (size_t e = 0; e < mp->nengines; e++)
    for (size_t i = 0; i < nc * ns; i++) {
      const cell *cl = &cells[e * nc * ns + i];
      const double c = value(mp->c, i / ns), w = value(mp->spin, i % ns);
      red_disk dk = red_disk_uniform(0.1, 1.0, 9.81);
      dk.C = c * dk.m * dk.r * dk.r;
      fprintf(out.fp, "%s,%g,%g,%.6g,%s,%.6g\n", mp->engines[e]->name, c, w,
              w / red_upright_critical_spin(&dk), OUTCOMES[cl->outcome], cl->excursion);
    }
  status = dv_io_commit(&out, err);
  /* one map per engine: a curve of points per outcome, and the critical spin */
  double *xs = malloc(2 * NOUTCOMES * nc * ns * sizeof *xs), *ys = xs + NOUTCOMES * nc * ns;
  if (!xs) return status ? status : dv_fail(err, DV_ESYSTEM, "out of memory");
  double cx[200], cy[200];
  for (int i = 0; i < 200; i++) {
    red_disk dk = red_disk_uniform(0.1, 1.0, 9.81);
    cx[i] = value(mp->c, 0) + (value(mp->c, nc - 1) - value(mp->c, 0)) * i / 199.0;
    dk.C = cx[i] * dk.m * dk.r * dk.r;
    cy[i] = red_upright_critical_spin(&dk);
  }
  for (size_t e = 0; !status && e < mp->nengines; e++) {
    size_t count[NOUTCOMES] = {0};
    for (size_t i = 0; i < nc * ns; i++) {
      const int o = cells[e * nc * ns + i].outcome;
      xs[o * nc * ns + count[o]] = value(mp->c, i / ns);
      ys[o * nc * ns + count[o]++] = value(mp->spin, i % ns);
    }
    dv_plot_curve curves[NOUTCOMES + 1];
    size_t n = 0;
    for (int o = 0; o < NOUTCOMES; o++)
      if (count[o])
        curves[n++] =
            (dv_plot_curve){OUTCOMES[o],     count[o], xs + o * nc * ns, ys + o * nc * ns, NULL,
                            DV_CURVE_POINTS, o + 1};
    curves[n++] =
        (dv_plot_curve){"critical spin (reduced, linear)", 200, cx, cy, NULL, DV_CURVE_LINE, 0};
    char title[128];
    snprintf(path, sizeof path, "%s/map_%s.svg", dir, mp->engines[e]->name);
    snprintf(title, sizeof title, "upright rolling in %s", mp->engines[e]->name);
    status = dv_report_plot_xy(path, title, "C / (m r^2)", "spin psi_dot (rad/s)", curves, n,
                               DV_PLOT_LOGY, err);
  }
  free(xs);
  return status;
}

/* the default engines: the thin-disk reference and every contact engine */
static void default_engines(map *mp) {
  mp->engines[0] = dv_engine_of_role(DV_ENGINE_THIN_REFERENCE);
  dv_cli_engine_list(NULL, mp->engines + 1, NULL);
}

/* the command once its options are read */
static int run_map(map *mp, const char *cspec, const char *sspec, const char *engines,
                   const char *out, int jobs) {
  char cbuf[128], sbuf[128];
  dv_error err = {{0}};
  snprintf(cbuf, sizeof cbuf, "c=%s", cspec);
  snprintf(sbuf, sizeof sbuf, "spin=%s", sspec);
  if (dv_search_vary_parse(cbuf, "map", (dv_vary *)mp->c, &err) ||
      dv_search_vary_parse(sbuf, "map", (dv_vary *)mp->spin, &err))
    return dv_cli_usage_error("map", "%s", err.msg);
  if (engines && dv_engine_parse_list(engines, mp->engines, DV_MAX_ENGINES + 1, &err))
    return dv_cli_usage_error("map", "%s", err.msg);
  if (!engines) default_engines(mp);
  while (mp->engines[mp->nengines]) mp->nengines++;
  for (size_t i = 0; i < mp->c->n; i++)
    if (!(value(mp->c, i) > 0.0 && value(mp->c, i) <= 0.5))
      return dv_cli_usage_error("map", "--c: C / (m r^2) must lie in (0, 0.5] (C <= 2A)");
  if (dv_exec_mpi_rank() == 0 && dv_io_make_dirs(out, &err)) /* a bad --out fails at once */
    return dv_cli_error("map", "%s", err.msg);
  const size_t n = mp->nengines * mp->c->n * mp->spin->n;
  cell *cells = calloc(n, sizeof *cells);
  if (!cells) return dv_cli_error("map", "out of memory");
  for (size_t k = 0; k < n; k++) cells[k].outcome = FAILED;
  const int pool = dv_exec_pool_run(n, sizeof *cells, cell_task, mp, cells, jobs, NULL);
  int code = DV_EXIT_OK;
  if (pool == 1) { /* a worker rank */
    free(cells);
    return DV_EXIT_OK;
  }
  if (pool != 0 || write_outputs(out, mp, cells, &err))
    code = dv_cli_error("map", "%s", err.msg[0] ? err.msg : "stopped early");
  else
    printf("map: %zu cells x %zu engines: %s/map.csv, %s/map_<engine>.svg\n",
           mp->c->n * mp->spin->n, mp->nengines, out, out);
  free(cells);
  return code;
}

int dv_cli_map(int argc, char **argv) {
  const char *cspec = "0.05..0.5:8", *sspec = "1..40:12", *engines = NULL, *out = "map";
  double duration = 5.0;
  int jobs = dv_cli_default_jobs();
  const dv_cli_option options[] = {
      {"c", DV_CLI_TEXT, &cspec, 0, 0},         {"spin", DV_CLI_TEXT, &sspec, 0, 0},
      {"engines", DV_CLI_TEXT, &engines, 0, 0}, {"duration", DV_CLI_REAL, &duration, 1e-6, 3600.0},
      {"out", DV_CLI_TEXT, &out, 0, 0},         {"jobs", DV_CLI_INT, &jobs, 1, 1024},
  };
  const dv_cli_command cmd = {"map", HELP, options, 6, 0, 0};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_vary c, spin;
  map mp = {&c, &spin, {NULL}, 0, duration};
  const int code = run_map(&mp, cspec, sspec, engines, out, jobs);
  dv_cli_args_free(&cmd, &a);
  return code;
}
