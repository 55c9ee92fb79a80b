/* dv_clock: wall-clock time for measuring cost. */
#ifndef DV_CLOCK_H
#define DV_CLOCK_H

/* seconds on a monotonic clock (differences only) */
double dv_clock_now(void);

#endif
