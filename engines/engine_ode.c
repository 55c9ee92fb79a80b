/* engine_ode: placeholder, replaced by the ode contact engine. */
#include "dv_engine.h"

static const char *version(void) { return "?"; }
static void *alloc(const dv_scenario *sc, dv_error *err) {
  (void)sc;
  return dv_fail(err, DV_ESYSTEM, "the ode engine is not built yet"), (void *)0;
}
static int reset(void *e, const double s[RED_NSTATE], dv_error *err) { return DV_ESYSTEM; }
static int advance(void *e, double t, dv_sample *out, dv_error *err) { return DV_ESYSTEM; }
static void stats(const void *e, dv_engine_stats *out) {}
static void release(void *e) {}

const dv_engine_type dv_engine_ode = {"ode", "placeholder", version, alloc, reset, advance, stats, release};
