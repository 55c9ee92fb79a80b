/* dv_rng: the generators' reproducible stream (splitmix64): the same scene
 * for the same seed on every machine, whatever its libc. */
#ifndef DV_RNG_H
#define DV_RNG_H

#include <stdint.h>

typedef struct dv_rng {
  uint64_t s;
} dv_rng;

uint64_t dv_rng_next(dv_rng *g);
double dv_rng_u01(dv_rng *g);                              /* uniform in [0, 1), 53 bits */
double dv_rng_uniform(dv_rng *g, double a, double b);      /* uniform in [a, b) */
double dv_rng_log_uniform(dv_rng *g, double a, double b);  /* log-uniform in [a, b) */
/* v rounded to 6 significant digits: a scene's .ini reads back as drawn */
double dv_round6(double v);

#endif
