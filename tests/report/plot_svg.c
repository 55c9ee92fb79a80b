/* plot_svg: the plot tests' synthetic trajectories and SVG readers (plot_svg.h) */
#include "plot_svg.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

dv_sample pt_sample(double t, double offset) {
  dv_sample s;
  memset(&s, 0, sizeof s);
  s.t = t;
  s.y[RED_TH] = 1.0 + 0.1 * sin(t) + offset;
  s.y[RED_VTH] = 0.1 * cos(t); /* turns at t = pi/2 + k pi */
  s.contact[0] = 0.5 * cos(0.3 * t) + offset;
  s.contact[1] = 0.5 * sin(0.3 * t);
  s.energy = 2.0 + 1e-9 * t + offset;
  return s;
}

/* n samples over [0, 10] s with the given offset */
static int make_traj(dv_traj *tr, size_t n, double offset) {
  for (size_t i = 0; i < n; i++) {
    const dv_sample s = pt_sample(10.0 * (double)i / (double)(PT_N - 1), offset);
    if (dv_run_traj_push(tr, &s) != 0) return -1;
  }
  return 0;
}

int pt_make_runs(dv_traj *ref, dv_traj *close_by, dv_traj *holed) {
  if (make_traj(ref, PT_N, 0.0) != 0 || make_traj(close_by, PT_N, 1e-6) != 0 ||
      make_traj(holed, PT_N, 1e-3) != 0)
    return -1;
  holed->s[50].y[RED_TH] = NAN; /* a hole in every plot */
  holed->s[50].contact[0] = INFINITY;
  holed->s[50].energy = NAN;
  holed->s[51].y[RED_TH] = NAN;
  return 0;
}

dv_plot_series pt_whole_run(const char *label, const dv_traj *traj, const dv_traj *ref) {
  return (dv_plot_series){label, traj, ref, INFINITY, INFINITY, NAN, 0};
}

char *pt_slurp(const char *path, long *size) {
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

char *pt_plot_text(const char *dir, const char *name) {
  char path[PATH_MAX];
  long size = 0;
  snprintf(path, sizeof path, "%s/%s", dir, name);
  return pt_slurp(path, &size);
}

void pt_remove_dir(const char *dir) {
  for (const char *const *name = dv_report_plot_files; *name; name++) {
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/%s", dir, *name);
    unlink(path);
  }
  rmdir(dir);
}

int pt_attr_of(const char *el, const char *name, char *out, size_t size) {
  const char *end = strchr(el, '>'), *a = strstr(el, name);
  if (!a || (end && a > end)) return 0;
  a += strlen(name);
  const char *q = strchr(a, '"');
  if (!q) return 0;
  snprintf(out, size, "%.*s", (int)(q - a), a);
  return 1;
}

void pt_decode_text(const char *el, char *out, size_t size) {
  const char *end = strstr(el, "</text>");
  size_t k = 0;
  for (const char *p = el; p && p < end && k + 1 < size; p++) {
    unsigned c;
    if (!strncmp(p, "&#x", 3) && sscanf(p + 3, "%x", &c) == 1) {
      out[k++] = c < 128 ? (char)c : '?';
      p = strchr(p, ';');
    }
  }
  out[k] = '\0';
}

char *pt_svg_text(const char *svg) {
  size_t len = 1;
  char *all = calloc(strlen(svg) + 1, 1), line[512];
  for (const char *p = svg; all && (p = strstr(p, "<text")); p++) {
    pt_decode_text(p, line, sizeof line);
    len += (size_t)sprintf(all + len - 1, "%s\n", line);
  }
  return all;
}

int pt_svg_lines(const char *svg, const char *colour, size_t min_pts, double op_lo, double op_hi,
                 double box[4]) {
  int n = 0, any = 0;
  for (const char *p = svg; (p = strstr(p, "<polyline")); p++) {
    char c[16], op[32];
    const char *end = strstr(p, "/>"), *pts = strstr(p, "points=\"");
    if (!end || !pts || pts > end || !pt_attr_of(p, "stroke=\"", c, sizeof c) ||
        !pt_attr_of(p, "stroke-opacity=\"", op, sizeof op))
      continue;
    const int other = strcmp(c, "#000000") && strcmp(c, "#FFFFFF") && strcmp(c, "#E1E1E1");
    if ((colour[0] ? strcmp(c, colour) != 0 : !other) || atof(op) < op_lo || atof(op) > op_hi)
      continue;
    double lbox[4] = {0};
    size_t m = 0;
    double x, y;
    for (const char *q = pts + 8; q < end && sscanf(q, "%lf,%lf", &x, &y) == 2; m++) {
      if (!m || x < lbox[0]) lbox[0] = x;
      if (!m || x > lbox[1]) lbox[1] = x;
      if (!m || y < lbox[2]) lbox[2] = y;
      if (!m || y > lbox[3]) lbox[3] = y;
      q += strcspn(q, " \n\"");
      q += strspn(q, " \n");
    }
    if (m <= min_pts) continue;
    for (int k = 0; k < 4; k++)
      box[k] = !any ? lbox[k] : k % 2 ? fmax(box[k], lbox[k]) : fmin(box[k], lbox[k]);
    any = 1;
    n++;
  }
  return n;
}

int pt_svg_legend_box(const char *svg, double box[4]) {
  for (const char *p = svg; (p = strstr(p, "<polyline")); p++) {
    char c[16], pts[512];
    if (!pt_attr_of(p, "stroke=\"", c, sizeof c) || strcmp(c, "#000000") ||
        !pt_attr_of(p, "points=\"", pts, sizeof pts))
      continue;
    double x[6], y[6];
    int m = 0;
    for (const char *q = pts; m < 6 && q && sscanf(q, "%lf,%lf", &x[m], &y[m]) == 2; m++)
      q = strpbrk(q + 1, " \n") ? q + strcspn(q, " \n") + 1 : NULL;
    if (m != 5 || x[0] != x[4] || y[0] != y[4]) continue;
    box[0] = fmin(fmin(x[0], x[1]), x[2]), box[1] = fmax(fmax(x[0], x[1]), x[2]);
    box[2] = fmin(fmin(y[0], y[1]), y[2]), box[3] = fmax(fmax(y[0], y[1]), y[2]);
    return 1;
  }
  return 0;
}

int pt_count_of(const char *hay, const char *needle) {
  int n = 0;
  for (const char *p = hay; (p = strstr(p, needle)); p++) n++;
  return n;
}
