/* dv_io_json: JSON numbers as the shortest text that reads back exactly.
 *
 * cJSON prints a number with 15 significant digits whenever that lands within
 * a relative DBL_EPSILON of it, so its text does not always read back to the
 * same double (0.1 + 0.2 is printed as 0.3); these numbers are printed by
 * dv_format instead, and NaN and the infinities, which JSON lacks, as null.
 */
#ifndef DV_IO_JSON_H
#define DV_IO_JSON_H

#include <stddef.h>

/* a cJSON item (cJSON *) that prints as v exactly, or null when v is not finite */
void *dv_io_json_double(double v);

/* the JSON value in the regular file path (at most max_bytes), or NULL with
 * why (may be NULL) saying what went wrong; the caller cJSON_Deletes it */
void *dv_io_json_read(const char *path, long max_bytes, char *why, size_t why_size);

#endif
