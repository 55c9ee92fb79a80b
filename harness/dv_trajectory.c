/* dv_trajectory: the sampling loop over any engine. */
#include "dv_trajectory.h"

#include <string.h>

#include "red_solver.h"

void dv_csv_row(FILE *fp, const red_disk *disk, double t, const double y[RED_NSTATE]) {
  double p[2];
  red_contact_point(disk, y, p);
  fprintf(fp, "%.12g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", t,
          y[RED_TH], y[RED_PH], y[RED_PS], y[RED_X], y[RED_Y], p[0], p[1], y[RED_VTH], y[RED_VPH],
          y[RED_VPS], red_energy(disk, y));
}

int dv_trajectory_run(const dv_engine_type *type, const dv_scenario *sc, FILE *fp,
                      dv_engine_stats *stats, dv_error *err) {
  double y[RED_NSTATE];
  memcpy(y, sc->initial, sizeof y);
  memset(stats, 0, sizeof *stats);
  void *engine = type->alloc(sc, err);
  if (!engine) return DV_ESYSTEM;
  int status = type->reset(engine, y, err);
  if (fp) fputs(DV_CSV_HEADER "\n", fp);
  if (!status && fp) dv_csv_row(fp, &sc->disk, 0.0, y);
  for (long k = 1; status == DV_OK; k++) {
    const double t = red_grid_time(0.0, sc->output_dt, sc->duration, k);
    double t_reached;
    status = type->advance(engine, t, &t_reached, y, err);
    if (status >= 0 && fp) dv_csv_row(fp, &sc->disk, t_reached, y);
    if (t >= sc->duration) break;
  }
  type->stats(engine, stats);
  if (status < 0) snprintf(stats->outcome, sizeof stats->outcome, "failed");
  type->free(engine);
  return status;
}
