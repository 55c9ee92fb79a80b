/* dv_test_traj: an engine run sampled every output_dt (dv_test_traj.h). */
#include "dv_test_traj.h"

#include <math.h>
#include <string.h>

int dv_test_run(const dv_engine_type *e, const dv_scenario *sc, traj *tr) {
  dv_error err = {{0}};
  void *eng = e->alloc(sc, &err);
  tr->n = 0;
  tr->status = eng ? e->reset(eng, sc->initial, &err) : DV_ESYSTEM;
  for (long k = 0; tr->status == DV_OK && k < DV_TEST_MAXS; k++) {
    const double t = fmin(k * sc->output_dt, sc->duration);
    tr->status = e->advance(eng, t, &tr->s[tr->n], &err);
    if (tr->status >= 0) tr->n++;
    if (t >= sc->duration) break;
  }
  if (eng) {
    e->stats(eng, &tr->stats);
    e->free(eng);
  }
  memcpy(tr->msg, err.msg, sizeof tr->msg);
  return tr->status;
}
