/* dv_report_dir: report directories built aside, renamed into place; error reports. */
#include "report_suite_dir.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io_file.h"
#include "io_temp.h"

int dv_report_dir_begin(char *tmp, size_t size, const char *out_dir, const char *name,
                        dv_error *err) {
  char prefix[1200], stale[200];
  if (dv_io_path(prefix, sizeof prefix, err, "%s/.%s", out_dir, name) ||
      dv_io_temp_template(tmp, size, prefix, err))
    return DV_EINPUT;
  /* what runs killed while writing this report left (a suite also clears the rest) */
  for (int k = 0; k < 2; k++)
    if (!dv_io_path(stale, sizeof stale, NULL, k ? ".%s.old." : ".%s.tmp.", name))
      dv_io_temp_remove_stale(out_dir, stale);
  if (!mkdtemp(tmp)) return dv_fail(err, DV_ESYSTEM, "%s: %s", tmp, strerror(errno));
  const mode_t mask = umask(0);
  umask(mask);
  chmod(tmp, 0777 & ~mask); /* mkdtemp makes it private; a report is for reading */
  return DV_OK;
}

int dv_report_dir_install(const char *tmp, const char *out_dir, const char *name, dv_error *err) {
  char final[1200], old[1200];
  if (dv_io_path(final, sizeof final, err, "%s/%s", out_dir, name) ||
      dv_io_path(old, sizeof old, err, "%s/.%s.old.%ld", out_dir, name, (long)getpid())) {
    dv_io_remove_tree(tmp);
    return DV_EINPUT;
  }
  const int had_old = rename(final, old) == 0;
  if (rename(tmp, final)) {
    dv_fail(err, DV_ESYSTEM, "%s: %s", final, strerror(errno));
    if (had_old) rename(old, final);
    dv_io_remove_tree(tmp);
    return DV_ESYSTEM;
  }
  if (had_old) dv_io_remove_tree(old);
  return DV_OK;
}

/* write text into dir/name */
static int write_file(const char *dir, const char *name, const char *text, dv_error *err) {
  dv_io_file f;
  int status = dv_io_open_in(&f, dir, name, err);
  if (status) return status;
  fputs(text, f.fp);
  status = dv_io_commit(&f, err);
  dv_io_abort(&f);
  return status;
}

/* report.json and report.md of a scenario that failed, into dir */
static int write_error_files(const char *dir, const dv_scenario *sc, const char *cause,
                             dv_error *err) {
  cJSON *root = cJSON_CreateObject();
  cJSON_AddStringToObject(root, "scenario", sc->name);
  cJSON_AddStringToObject(root, "file", sc->path);
  cJSON_AddBoolToObject(root, "pass", 0);
  cJSON_AddStringToObject(root, "error", cause);
  cJSON_AddObjectToObject(root, "engines");
  char *json = cJSON_Print(root);
  cJSON_Delete(root);
  const size_t md_size = strlen(sc->name) + strlen(cause) + 32;
  char *md = malloc(md_size);
  int status = json && md ? DV_OK : dv_fail(err, DV_ESYSTEM, "out of memory");
  if (!status) {
    snprintf(md, md_size, "# %s\n\nerror: %s\n", sc->name, cause);
    status = write_file(dir, "report.json", json, err);
  }
  if (!status) status = write_file(dir, "report.md", md, err);
  free(json);
  free(md);
  return status;
}

int dv_report_dir_write_error(const char *out_dir, const dv_scenario *sc, const char *cause,
                              dv_error *err) {
  char tmp[1300], final[1200];
  int status = dv_report_dir_begin(tmp, sizeof tmp, out_dir, sc->name, err);
  if (!status && (status = write_error_files(tmp, sc, cause, err))) dv_io_remove_tree(tmp);
  if (!status) status = dv_report_dir_install(tmp, out_dir, sc->name, err);
  /* no error report: at least no earlier report that says something else */
  if (status && !dv_io_path(final, sizeof final, NULL, "%s/%s", out_dir, sc->name))
    dv_io_remove_tree(final);
  return status;
}
