/* dv_error: formatting of error messages. */
#include "dv_error.h"

#include <stdarg.h>
#include <stdio.h>

int dv_fail(dv_error *err, int status, const char *fmt, ...) {
  if (err) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
  }
  return status;
}
