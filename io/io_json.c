/* dv_io_json: exact numbers for cJSON, as raw items. */
#include "io_json.h"

#include <cjson/cJSON.h>

#include "dv_format.h"

/* the text of dv_format_json as a raw item: cJSON prints it as it is */
void *dv_io_json_double(double v) {
  char text[DV_FORMAT_SIZE];
  dv_format_json(v, text, sizeof text);
  return cJSON_CreateRaw(text);
}
