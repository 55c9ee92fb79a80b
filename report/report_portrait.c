/* report_portrait: the thesis's Figures 4.1-4.6 for a scenario, of the
 * scene's body: the thin disk's effective potential from its integrals f1, f2
 * and its phase plane; a thick disk's (the cylinder) from the matched
 * reference's run. */
#include "report_portrait.h"

#include <math.h>
#include <stdlib.h>

#include "io_file.h"
#include "red_invariants.h"
#include "red_potential.h"
#include "report_plot.h"

#define PORTRAIT_POINTS 400
/* grey: the energy level, apart from the black reference (and the engines: level_colour) */
#define LEVEL_COLOUR 8

/* theta and p_theta = (A + m r^2) theta' of a trajectory, for the phase plane */
static void phase_coordinates(const red_disk *dk, const dv_traj *tr, double *th, double *p) {
  for (size_t i = 0; i < tr->n; i++) {
    th[i] = tr->s[i].y[RED_TH];
    p[i] = (dk->A + dk->m * dk->r * dk->r) * tr->s[i].y[RED_VTH];
  }
}

/* the curves of the portraits: the potential and the level set on a grid of
 * theta, and (theta, p_theta) of the reference and of every engine */
typedef struct portrait {
  double th[PORTRAIT_POINTS], U[PORTRAIT_POINTS], up[PORTRAIT_POINTS], dn[PORTRAIT_POINTS];
  double *traj[1 + DV_MAX_ENGINES]; /* n thetas, then n momenta */
} portrait;

/* the level set's colour on a phase plane beside the n engines' colours: grey,
 * or the first colour none of them has */
static int level_colour(const int *colour, size_t n) {
  int want[1 + DV_MAX_ENGINES], got[1 + DV_MAX_ENGINES];
  for (size_t k = 0; k < n; k++) want[k] = colour[k];
  want[n] = LEVEL_COLOUR;
  dv_report_plot_distinct_colours(want, n + 1, got);
  return got[n];
}

/* draw the portraits of c from pt, whose arrays are allocated, engine k in colour[k] */
static int draw_portraits(const char *dir, const dv_comparison *c, portrait *pt, const int *colour,
                          dv_error *err) {
  const red_disk *dk = &c->sc->disk;
  const double *y0 = c->sc->initial;
  double f1, f2, lo = INFINITY, hi = -INFINITY;
  if (red_invariants(dk, y0, &f1, &f2)) return DV_OK; /* nothing to draw */
  const double E = red_energy(dk, y0), I = dk->A + dk->m * dk->r * dk->r;
  for (size_t i = 0; i < c->thin.n; i++) {
    lo = fmin(lo, c->thin.s[i].y[RED_TH]);
    hi = fmax(hi, c->thin.s[i].y[RED_TH]);
  }
  const double pad = fmax(0.2 * (hi - lo), 0.05);
  lo = fmax(lo - pad, 0.02);
  hi = fmin(hi + pad, M_PI - 0.02);
  for (int i = 0; i < PORTRAIT_POINTS; i++) {
    pt->th[i] = lo + (hi - lo) * i / (PORTRAIT_POINTS - 1);
    if (red_effective_potential(dk, f1, f2, pt->th[i], &pt->U[i])) pt->U[i] = NAN;
    pt->up[i] = pt->U[i] <= E ? sqrt(2.0 * I * (E - pt->U[i])) : NAN;
    pt->dn[i] = -pt->up[i];
  }
  const double ex[2] = {lo, hi}, ey[2] = {E, E};
  const dv_plot_curve pot[2] = {
      {"U(theta)", PORTRAIT_POINTS, pt->th, pt->U, NULL, DV_CURVE_LINE, 0},
      {"energy E", 2, ex, ey, NULL, DV_CURVE_LINE, LEVEL_COLOUR}};
  char path[1200], title[160];
  snprintf(title, sizeof title, "%s: effective potential (f1 %.4g, f2 %.4g)", c->sc->name, f1, f2);
  int status = dv_io_path(path, sizeof path, err, "%s/potential.svg", dir);
  if (!status) status = dv_report_plot_xy(path, title, "tilt theta (rad)", "U (J)", pot, 2, 0, err);
  /* phase plane: the level set, then the reference and every engine */
  dv_plot_curve ph[2 + 1 + DV_MAX_ENGINES];
  _Static_assert(2 + 1 + DV_MAX_ENGINES <= DV_PLOT_MAX_CURVES, "a phase plane holds every engine");
  const int level = level_colour(colour, c->n);
  size_t n = 0;
  ph[n++] =
      (dv_plot_curve){"level set E", PORTRAIT_POINTS, pt->th, pt->up, NULL, DV_CURVE_LINE, level};
  ph[n++] = (dv_plot_curve){"", PORTRAIT_POINTS, pt->th, pt->dn, NULL, DV_CURVE_LINE, level};
  for (size_t k = 0; k <= c->n; k++) {
    const dv_traj *tr = k ? &c->r[k - 1].traj : &c->thin;
    phase_coordinates(dk, tr, pt->traj[k], pt->traj[k] + tr->n);
    ph[n++] = (dv_plot_curve){k ? c->r[k - 1].engine->name : "reference (thin disk)",
                              tr->n,
                              pt->traj[k],
                              pt->traj[k] + tr->n,
                              NULL,
                              DV_CURVE_LINE,
                              k ? colour[k - 1] : 0}; /* the thin reference black */
  }
  snprintf(title, sizeof title, "%s: phase plane", c->sc->name);
  if (!status) status = dv_io_path(path, sizeof path, err, "%s/phase.svg", dir);
  if (!status)
    status =
        dv_report_plot_xy(path, title, "tilt theta (rad)", "p_theta (kg m^2/s)", ph, n, 0, err);
  return status;
}

/* the body of a thick scene: the matched reference of an engine that simulated it, with
 * *h its half-thickness; NULL for a thin scene or where no engine ran the cylinder */
static const dv_traj *thick_body(const dv_comparison *c, double *h) {
  const double want = 0.5 * c->sc->thickness;
  for (size_t i = 0; want > 0.0 && i < c->n; i++)
    if (c->r[i].half_thickness == want && c->r[i].matched.n > 1) {
      *h = want;
      return &c->r[i].matched;
    }
  return NULL;
}

/* The cylinder's portraits. Its theta' is orthogonal to its other rates in the
 * energy (the contact vector and the heading and spin rates lie in the disk's
 * meridian plane, theta' turns about the tangent), so E = I theta'^2 / 2 + U(theta)
 * with I = A + m (r^2 + h^2), and U along the matched reference's own run is
 * E - I theta'^2 / 2: its potential over the range it sweeps, its level set its
 * own curve in the phase plane. */
static int draw_thick(const char *dir, const dv_comparison *c, const dv_traj *body, double h,
                      double **traj, const int *colour, dv_error *err) {
  const red_disk *dk = &c->sc->disk;
  const double I = dk->A + dk->m * (dk->r * dk->r + h * h), E = body->s[0].energy;
  double lo = INFINITY, hi = -INFINITY;
  double *th = traj[0], *U = traj[0] + body->n;
  for (size_t i = 0; i < body->n; i++) {
    const double v = body->s[i].y[RED_VTH];
    th[i] = body->s[i].y[RED_TH];
    U[i] = E - 0.5 * I * v * v;
    lo = fmin(lo, th[i]);
    hi = fmax(hi, th[i]);
  }
  const double pad = fmax(0.2 * (hi - lo), 0.05), ex[2] = {lo - pad, hi + pad}, ey[2] = {E, E};
  const dv_plot_curve pot[2] = {
      {"U(theta) along the matched run", body->n, th, U, NULL, DV_CURVE_LINE, 0},
      {"energy E", 2, ex, ey, NULL, DV_CURVE_LINE, LEVEL_COLOUR}};
  char path[1200], title[200];
  snprintf(title, sizeof title, "%s: effective potential of the cylinder (h %.3g mm)", c->sc->name,
           1e3 * h);
  int status = dv_io_path(path, sizeof path, err, "%s/potential.svg", dir);
  if (!status) status = dv_report_plot_xy(path, title, "tilt theta (rad)", "U (J)", pot, 2, 0, err);
  dv_plot_curve ph[1 + DV_MAX_ENGINES];
  _Static_assert(1 + DV_MAX_ENGINES <= DV_PLOT_MAX_CURVES, "a phase plane holds every engine");
  size_t n = 0;
  for (size_t k = 0; k <= c->n; k++) {
    const dv_traj *tr = k ? &c->r[k - 1].traj : body;
    double *t = traj[k + 1], *p = traj[k + 1] + tr->n;
    for (size_t i = 0; i < tr->n; i++) {
      t[i] = tr->s[i].y[RED_TH];
      p[i] = I * tr->s[i].y[RED_VTH];
    }
    ph[n++] = (dv_plot_curve){k ? c->r[k - 1].engine->name : "reference (matched, the level set E)",
                              tr->n,
                              t,
                              p,
                              NULL,
                              DV_CURVE_LINE,
                              k ? colour[k - 1] : colour[c->n]};
  }
  snprintf(title, sizeof title, "%s: phase plane of the cylinder (h %.3g mm)", c->sc->name,
           1e3 * h);
  if (!status) status = dv_io_path(path, sizeof path, err, "%s/phase.svg", dir);
  if (!status)
    status =
        dv_report_plot_xy(path, title, "tilt theta (rad)", "p_theta (kg m^2/s)", ph, n, 0, err);
  return status;
}

/* the thesis's Figures 4.1-4.6 for this scenario: the effective potential of
 * theta for its f1, f2 with the energy level, and the phase plane with the
 * level set and every engine's trajectory over it */
int dv_report_portraits(const char *dir, const dv_comparison *c, const int *colour, dv_error *err) {
  double h = 0.0;
  const dv_traj *body = thick_body(c, &h);
  if (body) { /* arrays: the body's, then its and every engine's theta and p_theta */
    double *traj[2 + DV_MAX_ENGINES] = {NULL};
    int status = DV_OK;
    for (size_t k = 0; !status && k <= c->n + 1; k++) {
      const size_t n = k < 2 ? body->n : c->r[k - 2].traj.n;
      if (!(traj[k] = malloc(2 * (n + 1) * sizeof(double)))) status = DV_ESYSTEM;
    }
    if (status)
      dv_fail(err, status, "%s: portraits: out of memory", c->sc->name);
    else
      status = draw_thick(dir, c, body, h, traj, colour, err);
    for (size_t k = 0; k <= c->n + 1; k++) free(traj[k]);
    return status;
  }
  portrait *pt = calloc(1, sizeof *pt);
  int status = pt ? DV_OK : DV_ESYSTEM;
  for (size_t k = 0; !status && k <= c->n; k++) {
    const dv_traj *tr = k ? &c->r[k - 1].traj : &c->thin;
    if (!(pt->traj[k] = malloc(2 * (tr->n + 1) * sizeof(double)))) status = DV_ESYSTEM;
  }
  if (status)
    dv_fail(err, status, "%s: portraits: out of memory", c->sc->name);
  else
    status = draw_portraits(dir, c, pt, colour, err);
  for (size_t k = 0; pt && k <= c->n; k++) free(pt->traj[k]);
  free(pt);
  return status;
}
