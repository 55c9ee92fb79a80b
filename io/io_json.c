/* dv_io_json: exact numbers for cJSON, as raw items. */
#include "io_json.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "dv_format.h"
#include "dv_input.h"

/* the text of dv_format_json as a raw item: cJSON prints it as it is */
void *dv_io_json_double(double v) {
  char text[DV_FORMAT_SIZE];
  dv_format_json(v, text, sizeof text);
  return cJSON_CreateRaw(text);
}

void *dv_io_json_read(const char *path, long max_bytes, char *why, size_t why_size) {
  char ignored[8];
  if (!why) why = ignored, why_size = sizeof ignored;
  FILE *fp = dv_input_open(path);
  struct stat st;
  char *buf = NULL;
  cJSON *json = NULL;
  if (!fp)
    snprintf(why, why_size, "cannot open: %s", strerror(errno));
  else if (fstat(fileno(fp), &st) || !S_ISREG(st.st_mode) || st.st_size > max_bytes)
    snprintf(why, why_size, "not a regular file of at most %ld bytes", max_bytes);
  else if (!(buf = malloc((size_t)st.st_size + 1)) ||
           fread(buf, 1, (size_t)st.st_size, fp) != (size_t)st.st_size)
    snprintf(why, why_size, "cannot read: %s", buf ? strerror(errno) : "out of memory");
  else if (buf[st.st_size] = '\0', !(json = cJSON_Parse(buf)))
    snprintf(why, why_size, "not valid JSON");
  if (fp) fclose(fp);
  free(buf);
  return json;
}
