/* test_plot: dv_plot writes four complete SVG files from synthetic
 * trajectories (offset, NaN-holed, empty, constant), leaves no temporary file
 * behind, works twice in one process, and fails cleanly on a missing dir. */
#include <dirent.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "dv_plot.h"
#include "dv_test.h"

#define N 200

/* a sample at time t on a small circle, tilt 1 + 0.1 sin t + offset */
static dv_sample sample(double t, double offset) {
  dv_sample s;
  memset(&s, 0, sizeof s);
  s.t = t;
  s.y[RED_TH] = 1.0 + 0.1 * sin(t) + offset;
  s.contact[0] = 0.5 * cos(0.3 * t) + offset;
  s.contact[1] = 0.5 * sin(0.3 * t);
  s.energy = 2.0 + 1e-9 * t + offset;
  return s;
}

/* n samples over [0, 10] s with the given offset */
static int make_traj(dv_traj *tr, size_t n, double offset) {
  for (size_t i = 0; i < n; i++) {
    const dv_sample s = sample(10.0 * (double)i / (double)(N - 1), offset);
    if (dv_traj_push(tr, &s) != 0) return -1;
  }
  return 0;
}

/* the whole file at path, or NULL */
static char *slurp(const char *path, long *size) {
  FILE *fp = fopen(path, "rb");
  if (!fp) return NULL;
  char *buf = NULL;
  if (fseek(fp, 0, SEEK_END) == 0 && (*size = ftell(fp)) >= 0 && fseek(fp, 0, SEEK_SET) == 0 &&
      (buf = malloc((size_t)*size + 1)) != NULL) {
    buf[fread(buf, 1, (size_t)*size, fp)] = '\0';
  }
  fclose(fp);
  return buf;
}

/* the four files are complete SVG documents with drawn lines, and nothing else is in dir */
static void check_dir(const char *dir) {
  size_t nfiles = 0;
  for (const char *const *name = dv_plot_files; *name; name++, nfiles++) {
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, *name);
    long size = 0;
    char *text = slurp(path, &size);
    CHECK(text != NULL, "%s: missing", path);
    if (!text) continue;
    CHECK(size > 0, "%s: empty", path);
    CHECK(strncmp(text, "<?xml", 5) == 0 || strncmp(text, "<svg", 4) == 0, "%s: no SVG header",
          path);
    CHECK(strstr(text, "<polyline") || strstr(text, "<path"), "%s: no line drawn", path);
    CHECK(strstr(text, "</svg>") != NULL, "%s: not closed", path);
    free(text);
  }
  CHECK(nfiles == 4, "dv_plot_files lists %zu files", nfiles);
  DIR *d = opendir(dir);
  CHECK(d != NULL, "%s: cannot list", dir);
  if (!d) return;
  size_t seen = 0;
  for (struct dirent *e; (e = readdir(d)) != NULL;) {
    if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
    int known = 0;
    for (const char *const *name = dv_plot_files; *name; name++) known |= !strcmp(*name, e->d_name);
    CHECK(known, "%s: stray file %s", dir, e->d_name);
    seen++;
  }
  closedir(d);
  CHECK(seen == nfiles, "%s: %zu files, want %zu", dir, seen, nfiles);
}

/* remove the plots and dir */
static void remove_dir(const char *dir) {
  for (const char *const *name = dv_plot_files; *name; name++) {
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, *name);
    unlink(path);
  }
  rmdir(dir);
}

int main(int argc, char **argv) {
  dv_traj ref = {0}, close_by = {0}, holed = {0}, empty = {0}, flat = {0};
  CHECK(make_traj(&ref, N, 0.0) == 0 && make_traj(&close_by, N, 1e-6) == 0 &&
            make_traj(&holed, N, 1e-3) == 0,
        "out of memory");
  for (size_t i = 0; i < 5; i++) { /* a constant tilt: a collapsed range of its own */
    dv_sample s = sample((double)i, 0.0);
    s.y[RED_TH] = 1.0;
    s.energy = 0.0;
    CHECK(dv_traj_push(&flat, &s) == 0, "out of memory");
  }
  holed.s[50].y[RED_TH] = NAN; /* a hole in every plot */
  holed.s[50].contact[0] = INFINITY;
  holed.s[50].energy = NAN;
  holed.s[51].y[RED_TH] = NAN;

  dv_plot_input in = {.title = "synthetic #1", .thin = &ref, .nseries = 4};
  in.series[0] = (dv_plot_series){"close (1e-6)", &close_by, &ref};
  in.series[1] = (dv_plot_series){"holed", &holed, &ref};
  in.series[2] = (dv_plot_series){"empty", &empty, &ref};
  in.series[3] = (dv_plot_series){"flat", &flat, &flat};

  /* a kept dir (argv[1]) lets one look at the plots */
  char dir[] = "/tmp/test_plot.XXXXXX";
  CHECK(mkdtemp(dir) != NULL, "mkdtemp failed");
  dv_error err = {{0}};
  for (int round = 0; round < 2; round++) { /* twice: PLplot's global state is reset */
    const int status = dv_plot_scenario(dir, &in, &err);
    CHECK(status == DV_OK, "round %d: status %d: %s", round, status, err.msg);
    check_dir(dir);
  }

  /* nothing to draw at all: still four valid plots */
  dv_plot_input none = {.title = "nothing", .thin = &empty, .nseries = 1};
  none.series[0] = (dv_plot_series){"empty", &empty, &empty};
  char dir2[] = "/tmp/test_plot.XXXXXX";
  CHECK(mkdtemp(dir2) != NULL, "mkdtemp failed");
  CHECK(dv_plot_scenario(dir2, &none, &err) == DV_OK, "empty input: %s", err.msg);
  check_dir(dir2);
  if (argc > 1)
    printf("empty plots kept in %s\n", dir2);
  else
    remove_dir(dir2);

  /* a missing directory: an error, no crash */
  char missing[PATH_MAX];
  snprintf(missing, sizeof missing, "%s/no/such/dir", dir);
  err.msg[0] = '\0';
  CHECK(dv_plot_scenario(missing, &in, &err) == DV_ESYSTEM, "missing dir accepted");
  CHECK(err.msg[0] != '\0', "missing dir: no message");

  if (argc > 1)
    printf("plots kept in %s\n", dir);
  else
    remove_dir(dir);
  dv_traj_free(&ref);
  dv_traj_free(&close_by);
  dv_traj_free(&holed);
  dv_traj_free(&empty);
  dv_traj_free(&flat);
  return TEST_RESULT();
}
