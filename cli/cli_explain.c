/* cli_explain: the cause of an engine's excess, by attribution (search layer). */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "cli_args.h"
#include "report_suite_run.h"
#include "run_scenario.h"
#include "search_attribute.h"

/* dv_report_explain's cause: the knob whose change removes the engine's
 * excess, searched from the comparison's own run (ctx: the dv_cause_mode) */
static int attribute(void *ctx, const dv_scenario *sc, const dv_comparison *c,
                     const dv_engine_result *r, char *out, size_t size) {
  static dv_attribution a; /* large: not on the stack */
  dv_error err = {{0}};
  if (dv_search_cause(sc, c, r, *(const dv_cause_mode *)ctx, &a, &err)) {
    snprintf(out, size, "unknown (%s)", err.msg);
    return 0;
  }
  dv_search_attribute_cause(&a, out, size);
  return 0;
}

/* --cause none: no attribution run; the failure says so */
static int not_searched(void *ctx, const dv_scenario *sc, const dv_comparison *c,
                        const dv_engine_result *r, char *out, size_t size) {
  (void)ctx, (void)sc, (void)c, (void)r;
  snprintf(out, size, "not searched (--cause none)");
  return 0;
}

int dv_cli_explainer(const char *command, const char *mode, const dv_cli_list *sets,
                     dv_report_explain *out) {
  static const dv_cause_mode quick = DV_CAUSE_QUICK, full = DV_CAUSE_FULL;
  (void)sets;
  out->cause = attribute;
  out->ctx = (void *)&quick;
  if (!mode || strcmp(mode, "quick") == 0) return DV_OK;
  out->ctx = (void *)&full;
  if (strcmp(mode, "full") == 0) return DV_OK;
  out->cause = not_searched;
  out->ctx = NULL;
  if (strcmp(mode, "none") == 0) return DV_OK;
  return dv_cli_usage_error(command, "--cause %s: quick, full or none", mode);
}
