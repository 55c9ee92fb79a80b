/* dv_league_summary: an engine's standing at one target, and a cell's look-up. */
#include <math.h>
#include <string.h>

#include "league.h"

/* exp of the mean log of the positive finite values seen; NAN when none */
typedef struct geomean {
  double log_sum;
  size_t n;
} geomean;

static void geomean_add(geomean *g, double v) {
  if (isfinite(v) && v > 0) g->log_sum += log(v), g->n++;
}

static double geomean_of(const geomean *g) {
  return g->n ? exp(g->log_sum / (double)g->n) : NAN;
}

void dv_league_summarize(const dv_league *lg, const char *engine, double target,
                         dv_league_summary *out) {
  geomean wall = {0, 0}, steps = {0, 0};
  memset(out, 0, sizeof *out);
  out->engine = engine;
  out->target = target;
  for (size_t i = 0; i < lg->ncells; i++) {
    const dv_league_cell *c = &lg->cells[i];
    if (c->target != target || strcmp(c->engine, engine)) continue;
    switch (c->outcome) {
      case DV_LEAGUE_REACHED:
        out->reached++;
        geomean_add(&wall, c->wall_per_sim_s);
        geomean_add(&steps, c->sim_s > 0 && c->steps > 0 ? (double)c->steps / c->sim_s : NAN);
        break;
      case DV_LEAGUE_NOT_REACHED:
        out->not_reached++;
        break;
      case DV_LEAGUE_CANNOT_MODEL:
        out->cannot_model++;
        break;
      default:
        out->not_run++;
        break;
    }
  }
  out->geomean_wall_per_sim_s = geomean_of(&wall);
  out->geomean_steps_per_sim_s = geomean_of(&steps);
}

const dv_league_cell *dv_league_cell_of(const dv_league *lg, const char *object, const char *engine,
                                        double target) {
  for (size_t i = 0; i < lg->ncells; i++) {
    const dv_league_cell *c = &lg->cells[i];
    if (c->target == target && !strcmp(c->object, object) && !strcmp(c->engine, engine)) return c;
  }
  return NULL;
}
