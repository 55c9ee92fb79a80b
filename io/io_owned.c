/* dv_io_owned: the mark of a directory diskval made, and the checks on it. */
#include "io_owned.h"

#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io_file.h"
#include "io_lock.h"
#include "io_temp.h"

int dv_io_owned(const char *path) {
  char mark[4096], head[sizeof DV_IO_MARK_TEXT] = "";
  struct stat st;
  if (lstat(path, &st) || !S_ISDIR(st.st_mode)) return 0;
  if (snprintf(mark, sizeof mark, "%s/" DV_IO_MARK, path) >= (int)sizeof mark) return 0;
  if (lstat(mark, &st) || !S_ISREG(st.st_mode)) return 0;
  FILE *f = fopen(mark, "r");
  if (!f) return 0;
  const size_t n = fread(head, 1, sizeof head - 1, f);
  fclose(f);
  head[n] = '\0';
  return !strncmp(head, "diskval output directory", 24);
}

int dv_io_mark(const char *dir, dv_error *err) {
  return dv_io_write_text(dir, DV_IO_MARK, DV_IO_MARK_TEXT, err);
}

/* the mark of the complete directory dir: the format, then "files:" and the
 * name of every file diskval put in it, one a line, so that anything added
 * later is known for another's */
static int mark_listing(const char *dir, dv_error *err) {
  struct dirent **names;
  const int n = scandir(dir, &names, NULL, alphasort);
  if (n < 0) return dv_fail(err, DV_ESYSTEM, "%s: %s", dir, strerror(errno));
  size_t size = sizeof DV_IO_MARK_TEXT + sizeof DV_IO_MARK_FILES;
  for (int i = 0; i < n; i++) size += strlen(names[i]->d_name) + 1;
  char *text = malloc(size);
  if (text) {
    char *p = text + sprintf(text, "%s", DV_IO_MARK_TEXT DV_IO_MARK_FILES);
    for (int i = 0; i < n; i++) {
      const char *name = names[i]->d_name;
      if (strcmp(name, ".") && strcmp(name, "..") && strcmp(name, DV_IO_MARK) &&
          !strchr(name, '\n'))
        p += sprintf(p, "%s\n", name);
    }
  }
  for (int i = 0; i < n; i++) free(names[i]);
  free(names);
  const int status = text ? dv_io_write_text(dir, DV_IO_MARK, text, err)
                          : dv_fail(err, DV_ESYSTEM, "out of memory");
  free(text);
  return status;
}

/* name may be in a report whose mark lists no files (one diskval made before
 * marks listed them): what a report then held */
static int legacy_name(const char *name) {
  const size_t len = strlen(name);
  return !strcmp(name, "report.json") || !strcmp(name, "report.md") || !strcmp(name, "index.html") ||
         (len > 4 && (!strcmp(name + len - 4, ".csv") || !strcmp(name + len - 4, ".svg")));
}

/* the text of path's mark into *text (caller frees; NULL when unreadable);
 * the names it lists as "\nNAME\n...", or NULL when it lists none */
static const char *mark_list(const char *path, char **text) {
  char mark[4096];
  long len = 0;
  *text = NULL;
  if (snprintf(mark, sizeof mark, "%s/" DV_IO_MARK, path) >= (int)sizeof mark) return NULL;
  FILE *f = fopen(mark, "r");
  if (f && (*text = malloc(1 << 20))) len = (long)fread(*text, 1, (1 << 20) - 1, f);
  if (f) fclose(f);
  if (!*text) return NULL;
  (*text)[len] = '\0';
  const char *list = strstr(*text, "\n" DV_IO_MARK_FILES);
  return list ? list + strlen(DV_IO_MARK_FILES) : NULL; /* "\nNAME\n" for every name */
}

/* list (from mark_list) names name */
static int listed(const char *list, const char *name) {
  char needle[300];
  return list && snprintf(needle, sizeof needle, "\n%s\n", name) < (int)sizeof needle &&
         strstr(list, needle) != NULL;
}

/* path holds the regular file name */
static int holds_file(const char *path, const char *name) {
  char entry[4096];
  struct stat st;
  return snprintf(entry, sizeof entry, "%s/%s", path, name) < (int)sizeof entry &&
         !lstat(entry, &st) && S_ISREG(st.st_mode);
}

/* the first entry of the marked directory path that diskval did not put
 * there (not a regular file it listed in the mark), into name; 1, else 0.
 * A mark that lists no files is a report's from before marks listed them
 * only when a report.json is there: anything else so marked (the --out of
 * a suite, sweep or map from then) holds no file known for diskval's */
static int foreign(const char *path, char *name, size_t size) {
  char *text;
  const char *list = mark_list(path, &text);
  const int legacy = !list && holds_file(path, "report.json");
  DIR *d = opendir(path);
  int found = 0;
  for (struct dirent *e; d && !found && (e = readdir(d));) {
    char entry[4096];
    struct stat st;
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..") || !strcmp(e->d_name, DV_IO_MARK))
      continue;
    found = snprintf(entry, sizeof entry, "%s/%s", path, e->d_name) >= (int)sizeof entry ||
            lstat(entry, &st) || !S_ISREG(st.st_mode) ||
            !(list ? listed(list, e->d_name) : legacy && legacy_name(e->d_name));
    if (found) snprintf(name, size, "%s", entry);
  }
  if (d) closedir(d);
  free(text);
  return found;
}

int dv_io_check_replaceable(const char *path, dv_error *err) {
  struct stat st;
  char other[4200];
  if (lstat(path, &st)) {
    if (errno == ENOENT) return DV_OK;
    return dv_fail(err, DV_EINPUT, "%s: cannot look at it: %s", path, strerror(errno));
  }
  if (dv_io_owned(path) && foreign(path, other, sizeof other))
    return dv_fail(err, DV_EINPUT,
                   "%s: diskval did not make it, and the run would replace the report it is "
                   "in; nothing was written: move it, or choose another --out or scenario name",
                   other);
  if (dv_io_owned(path)) return DV_OK;
  return dv_fail(err, DV_EINPUT,
                 "%s: a %s that diskval did not make is in the way (it has no " DV_IO_MARK
                 "); nothing was written: move it, or choose another --out or scenario name",
                 path, S_ISDIR(st.st_mode) ? "directory" : "file");
}

/* dir holds nothing but diskval's lock (an empty file) and temporaries */
static int empty(const char *dir) {
  DIR *d = opendir(dir);
  if (!d) return 0;
  int any = 0;
  for (struct dirent *e; !any && (e = readdir(d));) {
    char lock[4096];
    struct stat st;
    const int is_lock = !strcmp(e->d_name, DV_IO_LOCK_NAME) &&
                        snprintf(lock, sizeof lock, "%s/%s", dir, e->d_name) < (int)sizeof lock &&
                        !lstat(lock, &st) && S_ISREG(st.st_mode) && st.st_size == 0;
    any = strcmp(e->d_name, ".") && strcmp(e->d_name, "..") && !is_lock &&
          strncmp(e->d_name, DV_IO_TEMP_PREFIX, strlen(DV_IO_TEMP_PREFIX));
  }
  closedir(d);
  return !any;
}

int dv_io_own_dir(const char *dir, const char *const *names, dv_error *err) {
  int status = dv_io_make_dirs(dir, err);
  if (status) return status;
  const int owned = dv_io_owned(dir);
  if (!owned && !empty(dir))
    return dv_fail(err, DV_EINPUT,
                   "%s: holds files diskval did not make (it has no " DV_IO_MARK
                   "); nothing was written: give a new or empty --out, or one diskval wrote",
                   dir);
  char *text = NULL;
  const char *list = owned ? mark_list(dir, &text) : NULL;
  /* a mark from before marks listed files: the command's first output there
   * says the directory is this command's, and its files diskval's */
  const int legacy = owned && !list && names[0] && holds_file(dir, names[0]);
  size_t size = sizeof DV_IO_MARK_TEXT + sizeof DV_IO_MARK_OUT + sizeof DV_IO_MARK_FILES +
                (list ? strlen(list) : 0);
  for (const char *const *f = names; *f && !status; f++) {
    char path[4096];
    struct stat st;
    size += strlen(*f) + 1;
    if (dv_io_path(path, sizeof path, err, "%s/%s", dir, *f))
      status = DV_EINPUT;
    else if (!lstat(path, &st) && !listed(list, *f) && !legacy)
      status = dv_fail(err, DV_EINPUT,
                       "%s: diskval did not make it (the " DV_IO_MARK
                       " of %s does not list "
                       "it), and this run would replace it; nothing was written: move it, or "
                       "choose another --out",
                       path, dir);
  }
  /* the new mark: an --out's, listing what it listed and this run's names */
  char *mark = status ? NULL : malloc(size);
  if (mark) {
    char *p = mark + sprintf(mark, "%s", DV_IO_MARK_TEXT DV_IO_MARK_OUT DV_IO_MARK_FILES);
    if (list) p += sprintf(p, "%s", list + 1);
    for (const char *const *f = names; *f; f++)
      if (!listed(list, *f) && !strchr(*f, '\n')) p += sprintf(p, "%s\n", *f);
    /* written only when it changes: a directory another run holds is not touched */
    if (!text || strcmp(text, mark)) status = dv_io_write_text(dir, DV_IO_MARK, mark, err);
  } else if (!status) {
    status = dv_fail(err, DV_ESYSTEM, "out of memory");
  }
  free(mark);
  free(text);
  return status;
}

/* path resolved as far as it exists (symbolic links, ".", ".."), the rest
 * of it appended as given: 0, or -1 */
static int resolve(const char *path, char *out, size_t size) {
  char head[PATH_MAX], tail[PATH_MAX] = "", real[PATH_MAX], rest[PATH_MAX];
  if (snprintf(head, sizeof head, "%s", path) >= (int)sizeof head) return -1;
  for (int depth = 0; depth < 256; depth++) {
    if (realpath(head[0] ? head : ".", real)) {
      const int len = snprintf(out, size, "%s%s", strcmp(real, "/") ? real : "", tail);
      return len >= 0 && (size_t)len < size ? 0 : -1;
    }
    char *slash = strrchr(head, '/');
    const char *last = slash ? slash + 1 : head;
    const int skip = !*last || !strcmp(last, "."); /* "o/./x" is "o/x", o or not */
    if (snprintf(rest, sizeof rest, "%s%s%s", skip ? "" : "/", skip ? "" : last, tail) >=
        (int)sizeof rest)
      return -1;
    memcpy(tail, rest, sizeof tail);
    if (!slash)
      head[0] = '\0';
    else if (slash == head)
      head[1] = '\0'; /* "/x": the root */
    else
      *slash = '\0';
  }
  return -1;
}

/* p (resolved) is d or lies under it */
static int under(const char *p, const char *d) {
  const size_t n = strlen(d);
  return !strncmp(p, d, n) && (p[n] == '/' || p[n] == '\0' || !strcmp(d, "/"));
}

int dv_io_within(const char *path, const char *dir) {
  char p[PATH_MAX + 256], d[PATH_MAX + 256];
  if (resolve(dir, d, sizeof d)) return 0;
  /* where the name is, and where it leads when it is a symbolic link */
  if (!dv_io_canonical(path, p, sizeof p) && under(p, d)) return 1;
  return !resolve(path, p, sizeof p) && under(p, d);
}

int dv_io_check_inputs(const char *dir, const char *const *names, const char *const *inputs,
                       size_t n, dv_error *err) {
  for (const char *const *f = names; *f; f++) {
    char path[4096];
    if (dv_io_path(path, sizeof path, err, "%s/%s", dir, *f)) return DV_EINPUT;
    for (size_t i = 0; i < n; i++)
      if (inputs[i] && dv_io_same_file(inputs[i], path))
        return dv_fail(err, DV_EINPUT,
                       "%s: an input of this run is its output %s; nothing was written: move "
                       "it, or choose another --out",
                       inputs[i], path);
  }
  return DV_OK;
}

int dv_io_dir_begin(char *tmp, size_t size, const char *parent, dv_error *err) {
  if (dv_io_temp_template(tmp, size, parent, err)) return DV_EINPUT;
  dv_io_temp_remove_stale(parent); /* what runs killed while writing here left */
  if (dv_io_temp_make(tmp, 1)) return dv_fail(err, DV_ESYSTEM, "%s: %s", tmp, strerror(errno));
  const mode_t mask = umask(0);
  umask(mask);
  chmod(tmp, 0777 & ~mask); /* mkdtemp makes it private; a report is for reading */
  if (dv_io_mark(tmp, err)) return dv_io_dir_discard(tmp), DV_ESYSTEM;
  return DV_OK;
}

void dv_io_dir_discard(const char *tmp) {
  dv_io_remove_tree(tmp);
  dv_io_temp_forget(tmp);
}

/* move the marked directory final aside, into a new temporary directory of
 * parent whose path goes into old; 0, or -1 when there is none */
static int set_aside(const char *final, const char *parent, char *old, size_t size) {
  if (!dv_io_owned(final) || dv_io_temp_template(old, size, parent, NULL) || !mkdtemp(old))
    return -1;
  if (rename(final, old) == 0) return 0; /* a directory replaces an empty one */
  rmdir(old);
  return -1;
}

int dv_io_dir_install(const char *tmp, const char *final, const char *parent, dv_error *err) {
  char old[PATH_MAX];
  if (dv_io_check_replaceable(final, err)) {
    dv_io_dir_discard(tmp);
    return DV_EINPUT;
  }
  if (mark_listing(tmp, err)) {
    dv_io_dir_discard(tmp);
    return DV_ESYSTEM;
  }
  const int had_old = set_aside(final, parent, old, sizeof old) == 0;
  if (rename(tmp, final)) {
    dv_fail(err, DV_ESYSTEM, "%s: %s", final, strerror(errno));
    if (had_old) rename(old, final);
    dv_io_dir_discard(tmp);
    return DV_ESYSTEM;
  }
  dv_io_temp_forget(tmp);
  if (had_old) dv_io_remove_tree(old);
  return DV_OK;
}
