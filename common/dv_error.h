/* dv_error: a caller-owned message buffer that every fallible function fills.
 *
 * Status convention (all modules): 0 success, > 0 informational, < 0 error.
 */
#ifndef DV_ERROR_H
#define DV_ERROR_H

#include <stddef.h>

enum {
  DV_OK = 0,
  DV_EVENT = 1,     /* informational: the run ended at an event */
  DV_EINPUT = -1,   /* bad input: scenario, option or argument */
  DV_ENUMERIC = -2, /* a numerical method failed */
  DV_ESYSTEM = -3,  /* I/O or memory */
};

typedef struct dv_error {
  char msg[512];
} dv_error;

/* format a message into err (NULL-safe); returns status for tail calls */
int dv_fail(dv_error *err, int status, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#endif
