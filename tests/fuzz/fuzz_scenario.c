/* fuzz_scenario: libFuzzer target for the scenario parser and validator.
 * Each input is a scenario file; the first line of an input that starts
 * with "#set " is also applied as a --set override. Any input must end in
 * DV_OK or DV_EINPUT with a message, never a crash, a leak or a hang. */
#include <gsl/gsl_errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_engine.h"
#include "engine_choose.h"
#include "scenario.h"

/* a property every input must keep; a violation aborts, which libFuzzer reports */
#define CHECK_OR_ABORT(cond) \
  do {                       \
    if (!(cond)) abort();    \
  } while (0)

static char path[64];

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static dv_scenario sc;
  if (!path[0]) {
    gsl_set_error_handler_off();
    /* a valid scene's settings are probed in one engine (and in those it
     * names): the probe's code is every engine's, and five engines' probes
     * took 8 s an input under the sanitizers, leaving the parser few inputs */
    static const dv_engine_type *probed[2];
    probed[0] = dv_engine_find("ode");
    dv_engine_choose_only(probed);
    snprintf(path, sizeof path, "/tmp/fuzz_scenario.%ld.ini", (long)getpid());
  }
  FILE *fp = fopen(path, "wb");
  if (!fp) return 0;
  fwrite(data, 1, size, fp);
  fclose(fp);
  char set[256] = "";
  const char *sets[1] = {set};
  if (size > 5 && !memcmp(data, "#set ", 5)) {
    size_t n = 0;
    while (5 + n < size && n + 1 < sizeof set && data[5 + n] != '\n') n++;
    memcpy(set, data + 5, n);
    set[n] = '\0';
  }
  dv_error err = {{0}};
  const int status = dv_engine_load_scenario(path, sets, set[0] ? 1 : 0, &sc, &err);
  CHECK_OR_ABORT(status == DV_OK || status == DV_EINPUT);
  CHECK_OR_ABORT(status == DV_OK || err.msg[0]); /* every refusal explains itself */
  return 0;
}
