/* dv_output: files that appear whole or not at all.
 *
 * Output goes to a temporary file beside the target and is renamed over it
 * on commit; abort (or a failed write) removes it. "-" means stdout; an
 * existing device or pipe (/dev/null) is written in place, never replaced.
 */
#ifndef DV_OUTPUT_H
#define DV_OUTPUT_H

#include <stdio.h>

#include "dv_error.h"

typedef struct dv_output {
  FILE *fp;
  char path[1024];     /* final name, "" for stdout */
  char tmp_path[1040]; /* temporary name while writing */
  int direct;          /* a device or pipe: written in place */
} dv_output;

int dv_output_open(dv_output *out, const char *path, dv_error *err);
int dv_output_commit(dv_output *out, dv_error *err); /* flush, close, rename */
void dv_output_abort(dv_output *out);                /* NULL-safe, idempotent */

#endif
