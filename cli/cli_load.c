/* cli_load: a scenario loaded for a command, with a line on stderr for every
 * setting the file gave that an engine's check replaced; the files a
 * command's arguments name. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "cli_args.h"
#include "dv_engine.h"

int dv_cli_load_scenario(const char *command, const char *path, const dv_cli_list *sets,
                         dv_scenario *sc, dv_error *err) {
  const int status = dv_engine_load_scenario(path, sets->items, sets->n, sc, err);
  for (size_t i = 0; !status && i < sc->nsections; i++)
    if (sc->replaced[i][0])
      fprintf(stderr, "diskval %s: %s: engines.%s: given %s, replaced (%s)\n", command, path,
              sc->sections[i]->name, sc->replaced[i], sc->derived[i]);
  return status;
}

static int by_name(const void *a, const void *b) {
  return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* the .ini files of dir, sorted, appended to files (the strings are the caller's to free) */
static int list_dir(const char *dir, dv_cli_list *files) {
  DIR *d = opendir(dir);
  if (!d) return -1;
  const size_t first = files->n;
  int status = 0;
  for (struct dirent *e; !status && (e = readdir(d));) {
    const size_t len = strlen(e->d_name);
    if (len < 5 || strcmp(e->d_name + len - 4, ".ini")) continue;
    char *path = malloc(strlen(dir) + len + 2);
    if (!path) status = -1;
    if (path) sprintf(path, "%s/%s", dir, e->d_name);
    if (path && dv_cli_list_push(files, path)) free(path), status = -1;
  }
  closedir(d);
  qsort(files->items + first, files->n - first, sizeof *files->items, by_name);
  return status;
}

int dv_cli_scenario_files(const char *command, const dv_cli_list *args, dv_cli_list *files) {
  for (size_t i = 0; i < args->n; i++) {
    struct stat st;
    if (stat(args->items[i], &st) == 0 && S_ISDIR(st.st_mode)) {
      if (list_dir(args->items[i], files))
        return dv_cli_error(command, "cannot read directory %s", args->items[i]);
    } else {
      char *copy = strdup(args->items[i]);
      if (!copy || dv_cli_list_push(files, copy))
        return free(copy), dv_cli_error(command, "out of memory");
    }
  }
  return files->n ? DV_EXIT_OK : dv_cli_error(command, "no scenario files found");
}

