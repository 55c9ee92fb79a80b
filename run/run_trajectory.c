/* dv_trajectory: the sampling loop over any engine. */
#include "run_trajectory.h"

#include <math.h>
#include <string.h>

#include "dv_format.h"
#include "red_solver.h"
#include "run_progress.h"

/* a row of n numbers into line: t to 12 significant digits (the grid time), the rest exact */
static size_t format_row(char *line, double t, const double *v, int n) {
  char *p = line;
  p += dv_format_precision(t, 12, p, DV_FORMAT_SIZE);
  for (int i = 0; i < n; i++) {
    *p++ = ',';
    p += dv_format_double(v[i], p, DV_FORMAT_SIZE);
  }
  *p++ = '\n';
  return (size_t)(p - line);
}

/* a trajectory row, the columns of DV_CSV_HEADER, in one write */
void dv_run_csv_row(FILE *fp, const dv_sample *s) {
  const double *y = s->y;
  const double v[] = {y[RED_TH],     y[RED_PH],  y[RED_PS],  y[RED_X],   y[RED_Y], s->contact[0],
                      s->contact[1], y[RED_VTH], y[RED_VPH], y[RED_VPS], s->energy};
  char line[(1 + sizeof v / sizeof *v) * (DV_FORMAT_SIZE + 1)];
  fwrite(line, 1, format_row(line, s->t, v, (int)(sizeof v / sizeof *v)), fp);
}

static int sample_finite(const dv_sample *s) {
  double sum = s->t + s->contact[0] + s->contact[1] + s->energy;
  for (int i = 0; i < RED_NSTATE; i++) sum += s->y[i];
  return isfinite(sum);
}

/* a row of the forces file: the contact force and the friction it needs */
static void force_row(FILE *fp, const dv_sample *s) {
  const double *F = s->force;
  const double v[] = {F[0], F[1], F[2], hypot(F[0], F[1]) / F[2]};
  char line[(1 + sizeof v / sizeof *v) * (DV_FORMAT_SIZE + 1)];
  fwrite(line, 1, format_row(line, s->t, v, (int)(sizeof v / sizeof *v)), fp);
}

/* a sink that refuses a sample could not keep it (the CSV writer never refuses) */
static int out_of_memory(const dv_engine_type *type, long k, const dv_sample *s, dv_error *err) {
  return dv_fail(err, DV_ESYSTEM,
                 "out of memory: the %s run's trajectory could not grow to keep sample %ld "
                 "(t = %g s; %zu bytes a sample)",
                 type->name, k + 1, s->t, sizeof *s);
}

int dv_run_collect(const dv_engine_type *type, const dv_scenario *sc, dv_sample_sink sink,
                   void *ctx, dv_engine_stats *stats, dv_error *err) {
  dv_sample s;
  memset(stats, 0, sizeof *stats);
  void *engine = type->alloc_self ? type->alloc_self(type, sc, err) : type->alloc(sc, err);
  if (!engine) {
    stats->outcome = DV_OUTCOME_ERROR;
    snprintf(stats->detail, sizeof stats->detail, "%.255s", err ? err->msg : "setup failed");
    return DV_ESYSTEM;
  }
  int status = type->reset(engine, sc->initial, err);
  /* the first sample is read back from the engine: its own view of the start */
  if (!status) status = type->advance(engine, 0.0, &s, err);
  if (!status && sink(ctx, &s)) status = out_of_memory(type, 0, &s, err);
  dv_run_progress_run_begin(sc->name, type->name, type->role != DV_ENGINE_CONTACT, sc->duration);
  for (long k = 1; status == DV_OK; k++) {
    const double t = red_grid_time(0.0, sc->output_dt, sc->duration, k);
    status = type->advance(engine, t, &s, err);
    /* a replay's NaN marks a column its record does not give (its rows were
     * checked finite when read, run_trajfile.h): not a divergence */
    if (status >= 0 && !type->alloc_self && !sample_finite(&s)) {
      status = dv_fail(err, DV_ENUMERIC, "non-finite state at t = %g s", t);
      break;
    }
    if (status >= 0 && sink(ctx, &s)) status = out_of_memory(type, k, &s, err);
    if (status >= 0) dv_run_progress_run_at(s.t);
    if (t >= sc->duration) break;
  }
  dv_run_progress_run_end();
  type->stats(engine, stats);
  if (status == DV_ENUMERIC && stats->outcome < DV_OUTCOME_DIVERGED) {
    /* the engine did not see it: the harness's own check caught it */
    stats->outcome = DV_OUTCOME_DIVERGED;
    snprintf(stats->detail, sizeof stats->detail, "%.255s", err ? err->msg : "diverged");
  }
  type->free(engine);
  return status;
}

typedef struct csv_files {
  FILE *fp, *forces;
} csv_files;

static int write_rows(void *ctx, const dv_sample *s) {
  const csv_files *f = ctx;
  if (f->fp) dv_run_csv_row(f->fp, s);
  if (f->forces) force_row(f->forces, s);
  return 0;
}

int dv_run_write_csv(const dv_engine_type *type, const dv_scenario *sc, FILE *fp, FILE *forces,
                     dv_engine_stats *stats, dv_error *err) {
  csv_files f = {fp, forces};
  if (fp) fputs(DV_CSV_HEADER "\n", fp);
  if (forces) fputs(DV_FORCES_HEADER "\n", forces);
  return dv_run_collect(type, sc, write_rows, &f, stats, err);
}
