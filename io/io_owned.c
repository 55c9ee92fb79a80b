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
  struct stat st;
  size_t len = 0;
  *text = NULL;
  if (snprintf(mark, sizeof mark, "%s/" DV_IO_MARK, path) >= (int)sizeof mark) return NULL;
  FILE *f = fopen(mark, "r");
  /* whole: generate's 100000 scenes list 5 MB (64 MiB at most) */
  const size_t size = f && !fstat(fileno(f), &st) && st.st_size < (64L << 20)
                          ? (size_t)st.st_size + 1
                          : (size_t)(64L << 20);
  if (f && (*text = malloc(size))) len = fread(*text, 1, size - 1, f);
  if (f) fclose(f);
  if (!*text) return NULL;
  (*text)[len] = '\0';
  const char *list = strstr(*text, "\n" DV_IO_MARK_FILES);
  return list ? list + strlen(DV_IO_MARK_FILES) : NULL; /* "\nNAME\n" for every name */
}

/* the digests of a mark's text: "sums:\n" and its lines, up to "\nfiles:", their
 * length into *len; NULL when it has none */
static const char *mark_sums(const char *text, size_t *len) {
  const char *s = text ? strstr(text, "\n" DV_IO_MARK_SUMS) : NULL;
  const char *f = s ? strstr(s, "\n" DV_IO_MARK_FILES) : NULL;
  *len = f ? (size_t)(f - s) : 0;
  return f ? s + 1 : NULL;
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
  size_t sums_len;
  const char *sums = mark_sums(text, &sums_len); /* generate's digests stay */
  size_t size = sizeof DV_IO_MARK_TEXT + sizeof DV_IO_MARK_OUT + sizeof DV_IO_MARK_FILES +
                (list ? strlen(list) : 0) + sums_len;
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
    char *p = mark + sprintf(mark, "%s", DV_IO_MARK_TEXT DV_IO_MARK_OUT);
    if (sums) p += sprintf(p, "%.*s", (int)sums_len, sums);
    p += sprintf(p, "%s", DV_IO_MARK_FILES);
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

uint64_t dv_io_digest(const void *bytes, size_t len) {
  const unsigned char *b = bytes;
  uint64_t h = 14695981039346656037ULL; /* FNV-1a, 64 bits */
  for (size_t i = 0; i < len; i++) h = (h ^ b[i]) * 1099511628211ULL;
  return h;
}

/* one line of a mark's digests: a name (not ended by '\0') and its digest */
typedef struct sum_line {
  const char *name;
  size_t len;
  uint64_t digest;
} sum_line;

static int sum_line_cmp(const void *pa, const void *pb) {
  const sum_line *a = pa, *b = pb;
  const size_t n = a->len < b->len ? a->len : b->len;
  const int c = memcmp(a->name, b->name, n);
  if (c || a->len != b->len) return c ? c : (a->len < b->len ? -1 : 1);
  return (a->digest > b->digest) - (a->digest < b->digest);
}

/* the lines "DIGEST NAME" of sums (len bytes from mark_sums) into *lines
 * (caller frees), sorted; how many, or -1 when out of memory */
static long sum_lines(const char *sums, size_t len, sum_line **lines) {
  long n = 0;
  *lines = NULL;
  if (!sums) return 0;
  const char *end = sums + len;
  for (const char *p = sums; p < end; p++) n += *p == '\n';
  if (!(*lines = malloc((size_t)(n ? n : 1) * sizeof **lines))) return -1;
  n = 0;
  for (const char *p = memchr(sums, '\n', len); p && p + 1 < end;) {
    const char *line = p + 1, *eol = memchr(line, '\n', (size_t)(end - line));
    char *after;
    if (!eol) break;
    const uint64_t digest = strtoull(line, &after, 16);
    if (after == line + 16 && *after == ' ' && after + 1 < eol)
      (*lines)[n++] = (sum_line){after + 1, (size_t)(eol - after - 1), digest};
    p = eol;
  }
  qsort(*lines, (size_t)n, sizeof **lines, sum_line_cmp);
  return n;
}

/* the bytes of the regular file path (at most limit) into *bytes (caller
 * frees), their count into *len: 0, or -1 when it cannot be read whole */
static int read_whole(const char *path, size_t limit, char **bytes, size_t *len) {
  FILE *f = fopen(path, "rb");
  *bytes = f ? malloc(limit + 1) : NULL;
  *len = *bytes ? fread(*bytes, 1, limit + 1, f) : 0;
  const int ok = *bytes && !ferror(f) && *len <= limit;
  if (f) fclose(f);
  return ok ? 0 : -1;
}

int dv_io_check_unedited(const char *dir, const char *const *names, dv_io_same_fn same, void *arg,
                         dv_error *err) {
  if (!dv_io_owned(dir)) return DV_OK;
  char *text = NULL, *bytes = NULL;
  sum_line *lines = NULL;
  const char *list = mark_list(dir, &text);
  size_t sums_len;
  const char *sums = mark_sums(text, &sums_len);
  const long n = sum_lines(sums, sums_len, &lines);
  int status = n < 0 ? dv_fail(err, DV_ESYSTEM, "out of memory") : DV_OK;
  for (size_t i = 0; !status && names[i]; i++) {
    char path[4096];
    struct stat st;
    size_t len;
    if (dv_io_path(path, sizeof path, err, "%s/%s", dir, names[i])) {
      status = DV_EINPUT;
      break;
    }
    /* new, not diskval's (dv_io_own_dir names it), or left to dv_io_open */
    if ((list && !listed(list, names[i])) || stat(path, &st) || !S_ISREG(st.st_mode)) continue;
    free(bytes);
    int ours = !read_whole(path, 1 << 20, &bytes, &len);
    if (ours) {
      const sum_line key = {names[i], strlen(names[i]), dv_io_digest(bytes, len)};
      ours = (n > 0 && bsearch(&key, lines, (size_t)n, sizeof *lines, sum_line_cmp)) ||
             same(i, bytes, len, arg);
    }
    if (!ours)
      status = dv_fail(err, DV_EINPUT,
                       "%s: not what diskval wrote there (the " DV_IO_MARK
                       " of %s records other bytes: edited since), and this run would replace "
                       "it; nothing was written: move it, or choose another --out",
                       path, dir);
  }
  free(bytes);
  free(lines);
  free(text);
  return status;
}

static int name_cmp(const void *a, const void *b) {
  return strcmp(*(const char *const *)a, *(const char *const *)b);
}

int dv_io_mark_sums(const char *dir, const char *const *names, const uint64_t *digests, size_t n,
                    int also, dv_error *err) {
  char *text = NULL, *mark = NULL;
  const char **sorted = malloc((n ? n : 1) * sizeof *sorted);
  sum_line *lines = NULL;
  const char *list = mark_list(dir, &text);
  size_t sums_len;
  const char *sums = mark_sums(text, &sums_len);
  const long old = sum_lines(sums, sums_len, &lines);
  size_t size = sizeof DV_IO_MARK_TEXT + sizeof DV_IO_MARK_OUT + sizeof DV_IO_MARK_SUMS +
                sizeof DV_IO_MARK_FILES + (list ? strlen(list) : 0) + sums_len;
  for (size_t i = 0; i < n; i++) size += 18 + strlen(names[i]);
  int status = DV_OK;
  if (!text || !list)
    status = dv_fail(err, DV_ESYSTEM, "%s: its " DV_IO_MARK " cannot be read", dir);
  else if (!sorted || old < 0 || !(mark = malloc(size)))
    status = dv_fail(err, DV_ESYSTEM, "out of memory");
  if (!status) {
    memcpy(sorted, names, n * sizeof *sorted);
    qsort(sorted, n, sizeof *sorted, name_cmp);
    char *p = mark + sprintf(mark, "%s", DV_IO_MARK_TEXT DV_IO_MARK_OUT DV_IO_MARK_SUMS);
    for (size_t i = 0; i < n; i++)
      if (!strchr(names[i], '\n'))
        p += sprintf(p, "%016llx %s\n", (unsigned long long)digests[i], names[i]);
    for (long k = 0; k < old; k++) { /* the digests that stay */
      char name[300];
      const char *key = name;
      if (lines[k].len >= sizeof name) continue;
      memcpy(name, lines[k].name, lines[k].len);
      name[lines[k].len] = '\0';
      if (also || !n || !bsearch(&key, sorted, n, sizeof *sorted, name_cmp))
        p += sprintf(p, "%016llx %s\n", (unsigned long long)lines[k].digest, name);
    }
    sprintf(p, "%s%s", DV_IO_MARK_FILES, list + 1);
    status = dv_io_write_text(dir, DV_IO_MARK, mark, err);
  }
  free(mark);
  free(lines);
  free(sorted);
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
