/* dv_clock: CLOCK_MONOTONIC in seconds. */
#include "dv_clock.h"

#include <time.h>

double dv_clock_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}
