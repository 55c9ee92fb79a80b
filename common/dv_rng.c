/* dv_rng: splitmix64 and the draws of the generators (dv_rng.h). */
#include "dv_rng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

uint64_t dv_rng_next(dv_rng *g) {
  uint64_t z = (g->s += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double dv_rng_u01(dv_rng *g) {
  return (double)(dv_rng_next(g) >> 11) * 0x1.0p-53;
}

double dv_rng_uniform(dv_rng *g, double a, double b) {
  return a + (b - a) * dv_rng_u01(g);
}

double dv_rng_log_uniform(dv_rng *g, double a, double b) {
  return exp(dv_rng_uniform(g, log(a), log(b)));
}

double dv_round6(double v) {
  char buf[32];
  snprintf(buf, sizeof buf, "%.6g", v);
  return strtod(buf, NULL);
}
