/* test_faults: a fault inside one run is that run's outcome, not the
 * process's: a fake engine that emits NaN at step k ends as diverged with a
 * message, and runs after it complete normally. */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "dv_engine.h"
#include "dv_test.h"
#include "run_trajectory.h"

/* the reference engine, with theta replaced by NaN from the k-th advance on */
typedef struct fake {
  void *inner;
  long calls, nan_at;
} fake;

static void *fake_alloc(const dv_scenario *sc, dv_error *err) {
  fake *f = calloc(1, sizeof *f);
  if (!f) return NULL;
  f->inner = dv_engine_reduced.alloc(sc, err);
  f->nan_at = 7;
  if (!f->inner) return free(f), NULL;
  return f;
}
static int fake_reset(void *p, const double s[RED_NSTATE], dv_error *err) {
  return dv_engine_reduced.reset(((fake *)p)->inner, s, err);
}
static int fake_advance(void *p, double t, dv_sample *out, dv_error *err) {
  fake *f = p;
  const int status = dv_engine_reduced.advance(f->inner, t, out, err);
  if (++f->calls >= f->nan_at) out->y[RED_TH] = NAN;
  return status;
}
static void fake_stats(const void *p, dv_engine_stats *out) {
  dv_engine_reduced.stats(((const fake *)p)->inner, out);
}
static void fake_free(void *p) {
  fake *f = p;
  if (!f) return;
  dv_engine_reduced.free(f->inner);
  free(f);
}
static const char *fake_version(void) {
  return "test";
}
static const dv_engine_type fake_engine = {.name = "fake",
                                           .description = "emits NaN at step 7",
                                           .role = DV_ENGINE_CONTACT,
                                           .version = fake_version,
                                           .alloc = fake_alloc,
                                           .reset = fake_reset,
                                           .advance = fake_advance,
                                           .stats = fake_stats,
                                           .free = fake_free};

int main(int argc, char **argv) {
  gsl_set_error_handler_off();
  if (argc < 2) return fprintf(stderr, "usage: test_faults SCENARIO\n"), 2;
  static dv_scenario sc;
  dv_error err = {{0}};
  CHECK(dv_engine_load_scenario(argv[1], NULL, 0, &sc, &err) == DV_OK, "%s", err.msg);
  dv_engine_stats st;
  FILE *sink = fopen("/dev/null", "w");
  int status = dv_run_write_csv(&fake_engine, &sc, sink, NULL, &st, &err);
  printf("fake: status %d, outcome %s: %s\n", status, dv_outcome_name(st.outcome), st.detail);
  CHECK(status < 0 && st.outcome == DV_OUTCOME_DIVERGED, "fake engine: status %d outcome %s",
        status, dv_outcome_name(st.outcome));
  CHECK(st.detail[0] != '\0', "no message for the diverged run");
  /* the next run in the same process is unaffected */
  status = dv_run_write_csv(&dv_engine_reduced, &sc, sink, NULL, &st, &err);
  CHECK(status == DV_OK && st.outcome == DV_OUTCOME_COMPLETED, "reference after the fault: %d %s",
        status, err.msg);
  fclose(sink);
  return TEST_RESULT();
}
