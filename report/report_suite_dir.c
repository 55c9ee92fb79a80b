/* dv_report_dir: report directories built aside, renamed into place; error reports. */
#include "report_suite_dir.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io_file.h"
#include "io_lock.h"
#include "io_owned.h"
#include "io_temp.h"
#include "report_escape.h"
#include "report_page.h"

int dv_report_dir_begin(char *tmp, size_t size, const char *out_dir, const char *name,
                        dv_error *err) {
  char final[1200];
  if (dv_io_path(final, sizeof final, err, "%s/%s", out_dir, name) ||
      dv_io_check_replaceable(final, err))
    return DV_EINPUT;
  return dv_io_dir_begin(tmp, size, out_dir, err);
}

void dv_report_dir_discard(const char *tmp) {
  dv_io_dir_discard(tmp);
}

int dv_report_dir_install(const char *tmp, const char *out_dir, const char *name, dv_error *err) {
  char final[1200];
  if (dv_io_path(final, sizeof final, err, "%s/%s", out_dir, name)) {
    dv_io_dir_discard(tmp);
    return DV_EINPUT;
  }
  return dv_io_dir_install(tmp, final, out_dir, err);
}

/* path (an input of the run) lies inside dir, which the run replaces */
static int inside(const char *path, const char *dir, dv_error *err) {
  if (!dv_io_within(path, dir)) return DV_OK;
  return dv_fail(err, DV_EINPUT,
                 "%s: an input of this run lies inside %s, which the run would replace; "
                 "nothing was written: move it, or choose another --out",
                 path, dir);
}

int dv_report_dir_check(const char *out_dir, const dv_scenario *scs, size_t n,
                        const char *const *inputs, size_t ninputs, dv_error *err) {
  struct stat st;
  if (stat(out_dir, &st) == 0 && !S_ISDIR(st.st_mode))
    return dv_fail(err, DV_EINPUT, "%s: not a directory", out_dir);
  for (size_t i = 0; i < n; i++) {
    char final[1200];
    int status = dv_io_path(final, sizeof final, err, "%s/%s", out_dir, scs[i].name);
    /* a report of diskval's: an input in it is named as one, before as a file diskval did
     * not make */
    if (!status && !dv_io_owned(final)) status = dv_io_check_replaceable(final, err);
    for (size_t k = 0; !status && k < n; k++) status = inside(scs[k].path, final, err);
    for (size_t k = 0; !status && k < ninputs; k++) status = inside(inputs[k], final, err);
    if (!status) status = dv_io_check_replaceable(final, err);
    if (status) return status;
  }
  return DV_OK;
}

int dv_report_dir_check_junit(const char *junit, const char *out_dir, const dv_scenario *scs,
                              size_t n, const char *const *inputs, size_t ninputs, dv_error *err) {
  if (!junit || !strcmp(junit, "-")) return DV_OK;
  if (dv_io_check_output(junit, err)) return DV_EINPUT;
  char real[PATH_MAX];
  for (int k = 0; k < 2; k++) { /* the name given, and the file a link leads to */
    const char *path = k ? realpath(junit, real) : junit;
    const char *base = path && strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    if (base && (!strcmp(base, DV_IO_MARK) || !strcmp(base, DV_IO_LOCK_NAME) ||
                 !strncmp(base, DV_IO_TEMP_PREFIX, strlen(DV_IO_TEMP_PREFIX))))
      return dv_fail(err, DV_EINPUT, "--junit '%s': %s is the name of diskval's own files", junit,
                     base);
  }
  for (size_t i = 0; i < n + ninputs; i++) {
    const char *in = i < n ? scs[i].path : inputs[i - n];
    if (dv_io_same_file(junit, in))
      return dv_fail(err, DV_EINPUT, "--junit '%s' is an input of this run (%s)", junit, in);
  }
  for (size_t i = 0; i < n; i++) {
    char dir[1200];
    if (dv_io_path(dir, sizeof dir, err, "%s/%s", out_dir, scs[i].name)) return DV_EINPUT;
    if (dv_io_within(junit, dir))
      return dv_fail(err, DV_EINPUT, "--junit '%s' lies inside %s, which this run replaces", junit,
                     dir);
  }
  return DV_OK;
}

/* report.json and report.md of a scenario that failed, into dir: the cause
 * (an engine's or adapter's words among them) as text, never markup */
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
  int status = json ? DV_OK : dv_fail(err, DV_ESYSTEM, "out of memory");
  if (!status) status = dv_io_write_text(dir, "report.json", json, err);
  dv_io_file md;
  if (!status && !(status = dv_io_open_in(&md, dir, "report.md", err))) {
    fputs("# ", md.fp);
    dv_report_escape_markdown(md.fp, sc->name);
    fputs("\n\nerror: ", md.fp);
    dv_report_escape_markdown(md.fp, cause);
    fputc('\n', md.fp);
    status = dv_io_commit(&md, err);
    dv_io_abort(&md);
  }
  if (!status) status = dv_report_page_write(dir, err);
  free(json);
  return status;
}

int dv_report_dir_write_error(const char *out_dir, const dv_scenario *sc, const char *cause,
                              dv_error *err) {
  char tmp[1300], final[1200];
  int status = dv_report_dir_begin(tmp, sizeof tmp, out_dir, sc->name, err);
  if (!status && (status = write_error_files(tmp, sc, cause, err))) dv_report_dir_discard(tmp);
  if (!status) status = dv_report_dir_install(tmp, out_dir, sc->name, err);
  /* no error report: at least no earlier report (of diskval's) that says something else */
  if (status && !dv_io_path(final, sizeof final, NULL, "%s/%s", out_dir, sc->name) &&
      dv_io_owned(final) && !dv_io_check_replaceable(final, NULL))
    dv_io_remove_tree(final);
  return status;
}
