/* run_trajfile: the strict reader of outside trajectories (run_trajfile.h). */
#include "run_trajfile.h"

#include <errno.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_input.h"
#include "dv_pose.h"
#include "dv_reference.h"
#include "run_trajcheck.h"

/* the columns either form may name, in DV_CSV_HEADER's order, then the pose form's */
enum {
  C_T,
  C_TH,
  C_PH,
  C_PS,
  C_X,
  C_Y,
  C_CX,
  C_CY,
  C_VTH,
  C_VPH,
  C_VPS,
  C_E, /* state */
  C_Z,
  C_QW,
  C_QX,
  C_QY,
  C_QZ,
  C_VX,
  C_VY,
  C_VZ,
  C_WX,
  C_WY,
  C_WZ, /* pose */
  NCOLS
};
_Static_assert(C_E - C_TH + 1 == DV_TRAJ_NVALUES, "the value columns are theta .. energy");
static const char *const names[NCOLS] = {
    "t",         "theta",   "phi",     "psi",    "x",  "y",  "contact_x", "contact_y",
    "theta_dot", "phi_dot", "psi_dot", "energy", "z",  "qw", "qx",        "qy",
    "qz",        "vx",      "vy",      "vz",     "wx", "wy", "wz"};
/* the columns of only one form */
static int state_only(int c) {
  return c == C_TH || c == C_PH || c == C_PS || (c >= C_CX && c <= C_E);
}
static int pose_only(int c) {
  return c >= C_Z;
}

#define MAX_FIELDS 64
#define MAX_LINE 4096

typedef struct reader {
  const char *path;
  dv_error *err;
  int col[NCOLS]; /* each column's index in the header, -1 when absent */
  int ncols;
} reader;

static int fail_at(const reader *rd, long line, int column, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

/* "PATH:LINE:COLUMN: what" (column 0: the whole line, "PATH:LINE: what") */
static int fail_at(const reader *rd, long line, int column, const char *fmt, ...) {
  char what[400];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(what, sizeof what, fmt, ap);
  va_end(ap);
  if (column > 0)
    return dv_fail(rd->err, DV_EINPUT, "%.400s:%ld:%d: %s", rd->path, line, column, what);
  return dv_fail(rd->err, DV_EINPUT, "%.400s:%ld: %s", rd->path, line, what);
}

/* split line (modified) at commas, fields trimmed of blanks; the count, or -1 when too many */
static int split(char *line, char **fields) {
  int n = 0;
  for (char *p = line;; p++) {
    if (n == MAX_FIELDS) return -1;
    while (*p == ' ' || *p == '\t') p++;
    fields[n++] = p;
    char *end = strchr(p, ',');
    char *stop = end ? end : p + strlen(p);
    char *q = stop;
    while (q > p && (q[-1] == ' ' || q[-1] == '\t')) q--;
    *q = '\0';
    if (!end) return n;
    p = end;
  }
}

/* the header: every column known, none twice, one form, what each form needs */
static int read_header(reader *rd, char *line, long lineno, dv_traj_form *form) {
  char *f[MAX_FIELDS];
  const int n = split(line, f);
  if (n < 0) return fail_at(rd, lineno, 0, "more than %d columns", MAX_FIELDS);
  for (int c = 0; c < NCOLS; c++) rd->col[c] = -1;
  rd->ncols = n;
  int state = 0, pose = 0;
  for (int i = 0; i < n; i++) {
    int c = 0;
    while (c < NCOLS && strcmp(f[i], names[c])) c++;
    if (c == NCOLS)
      return fail_at(rd, lineno, i + 1,
                     "unknown column '%.60s' (the state form: "
                     "t,theta,phi,psi,x,y,contact_x,"
                     "contact_y,theta_dot,phi_dot,psi_dot,energy; the pose form: "
                     "t,x,y,z,qw,qx,qy,qz[,vx,vy,vz,wx,wy,wz])",
                     f[i]);
    if (rd->col[c] >= 0)
      return fail_at(rd, lineno, i + 1, "column '%s' given twice (also column %d)", names[c],
                     rd->col[c] + 1);
    rd->col[c] = i;
    if (state_only(c) && !state) state = i + 1;
    if (pose_only(c) && !pose) pose = i + 1;
  }
  if (state && pose) {
    const int later = state > pose ? state : pose, earlier = state > pose ? pose : state;
    return fail_at(rd, lineno, later,
                   "column '%s' of the %s form with '%s' of the %s form: one form a file",
                   f[later - 1], later == state ? "state" : "pose", f[earlier - 1],
                   later == state ? "pose" : "state");
  }
  *form = pose ? DV_TRAJ_POSE : DV_TRAJ_STATE;
  static const int pose_need[] = {C_T, C_X, C_Y, C_Z, C_QW, C_QX, C_QY, C_QZ};
  if (*form == DV_TRAJ_POSE) {
    for (size_t k = 0; k < sizeof pose_need / sizeof *pose_need; k++)
      if (rd->col[pose_need[k]] < 0)
        return fail_at(rd, lineno, 0,
                       "missing column '%s': the pose form needs t,x,y,z,qw,qx,qy,qz",
                       names[pose_need[k]]);
    int nv = 0;
    for (int c = C_VX; c <= C_WZ; c++) nv += rd->col[c] >= 0;
    if (nv && nv < 6)
      return fail_at(rd, lineno, 0, "%d of the velocity columns vx,vy,vz,wx,wy,wz: all six or none",
                     nv);
    return DV_OK;
  }
  if (rd->col[C_T] < 0) return fail_at(rd, lineno, 0, "missing column 't'");
  if (rd->col[C_TH] < 0) return fail_at(rd, lineno, 0, "missing column 'theta'");
  if ((rd->col[C_CX] < 0) != (rd->col[C_CY] < 0))
    return fail_at(rd, lineno, 0, "missing column '%s': contact_x and contact_y come together",
                   rd->col[C_CX] < 0 ? "contact_x" : "contact_y");
  const int npose =
      (rd->col[C_PH] >= 0) + (rd->col[C_PS] >= 0) + (rd->col[C_X] >= 0) + (rd->col[C_Y] >= 0);
  if (npose && npose < 4)
    return fail_at(rd, lineno, 0, "%d of the columns phi,psi,x,y: all four or none", npose);
  if (rd->col[C_CX] < 0 && !npose)
    return fail_at(rd, lineno, 0,
                   "missing columns: the contact point (contact_x,contact_y) or the pose it is "
                   "computed from (phi,psi,x,y)");
  const int nr = (rd->col[C_VTH] >= 0) + (rd->col[C_VPH] >= 0) + (rd->col[C_VPS] >= 0);
  if (nr && nr < 3)
    return fail_at(rd, lineno, 0,
                   "%d of the rate columns theta_dot,phi_dot,psi_dot: all three or none", nr);
  return DV_OK;
}

/* the decimal exponent of the place of text's last digit ("0.25": -2, "3e-7":
 * -7, "120": 0), within [-127, 127]; DV_TRAJ_EXACT for text that is not
 * plain decimal (strtod's hexadecimal) */
static signed char last_digit(const char *p) {
  if (*p == '+' || *p == '-') p++;
  long decimals = 0, digits = 0;
  int dot = 0;
  for (; *p; p++) {
    if (*p >= '0' && *p <= '9')
      digits++, decimals += dot;
    else if (*p == '.' && !dot)
      dot = 1;
    else
      break;
  }
  long e = 0;
  if (*p == 'e' || *p == 'E')
    e = strtol(p + 1, NULL, 10);
  else if (*p || !digits)
    return DV_TRAJ_EXACT;
  e = e < -1000 ? -1000 : e > 1000 ? 1000 : e; /* strtol's LONG_MIN, LONG_MAX */
  e -= decimals;
  return (signed char)(e < -127 ? -127 : e > 127 ? 127 : e);
}

/* one row's numbers by column (NAN where the header has none), and each one's
 * last digit (last_digit) into digit */
static int read_row(const reader *rd, char *line, long lineno, double v[NCOLS],
                    signed char digit[NCOLS]) {
  char *f[MAX_FIELDS];
  const int n = split(line, f);
  if (n != rd->ncols)
    return fail_at(rd, lineno, n < 0 || n > rd->ncols ? rd->ncols + 1 : n,
                   "%s fields, the header has %d",
                   n < 0           ? "too many"
                   : n > rd->ncols ? "more"
                                   : "fewer",
                   rd->ncols);
  for (int c = 0; c < NCOLS; c++) {
    v[c] = NAN;
    digit[c] = DV_TRAJ_EXACT;
    const int i = rd->col[c];
    if (i < 0) continue;
    if (!*f[i]) return fail_at(rd, lineno, i + 1, "empty field for '%s'", names[c]);
    char *end;
    errno = 0;
    const double x = strtod(f[i], &end);
    if (*end || end == f[i])
      return fail_at(rd, lineno, i + 1, "'%.40s' is not a number (%s)", f[i], names[c]);
    if (!isfinite(x)) /* "nan", "inf", or out of range */
      return fail_at(rd, lineno, i + 1, "%s = '%.40s' is not finite", names[c], f[i]);
    v[c] = x;
    digit[c] = last_digit(f[i]);
  }
  return DV_OK;
}

/* a pose-form row into its sample (rates zero when the file gives none: derived later) */
static int pose_row(const reader *rd, const dv_scenario *sc, const dv_geometry *geom,
                    const double v[NCOLS], long lineno, dv_trajfile *f, int vel, dv_sample *s) {
  const double *prev = f->n ? f->s[f->n - 1].y : NULL;
  double q[4] = {v[C_QW], v[C_QX], v[C_QY], v[C_QZ]};
  const double norm = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(fabs(norm - 1.0) <= DV_TRAJ_QUAT_TOL))
    return fail_at(rd, lineno, rd->col[C_QW] + 1,
                   "the quaternion (qw,qx,qy,qz) has norm %.17g, not 1 within %g", norm,
                   DV_TRAJ_QUAT_TOL);
  for (int k = 0; k < 4; k++) q[k] /= norm;
  dv_pose p = {{v[C_X], v[C_Y], v[C_Z]}, {0}, {0}, {0}};
  dv_quat_to_matrix(q, p.R);
  for (int k = 0; vel && k < 3; k++) {
    p.vel[k] = v[C_VX + k];
    p.omega[k] = v[C_WX + k];
  }
  dv_sample_from_pose(&sc->disk, geom, &p, v[C_T], prev, s);
  f->line[f->n] = lineno;
  if (vel) { /* the centre's velocity against its steps, as the angles' rates are */
    int k;
    const double pos[2] = {v[C_X], v[C_Y]}, cv[2] = {v[C_VX], v[C_VY]};
    const double last[2] = {f->centre.pos[0], f->centre.pos[1]};
    const double last_v[2] = {f->centre.vel[0], f->centre.vel[1]};
    const double d = dv_run_trajcheck_centre(f, sc, pos, cv, &k);
    if (d > 1.0)
      return fail_at(rd, lineno, rd->col[k ? C_Y : C_X] + 1,
                     "the centre's %s moves by %.6g m from the line before, its velocity by "
                     "%.6g m (off by %.3g times what the step and the speed scale allow): the "
                     "columns disagree",
                     k ? "y" : "x", pos[k] - last[k],
                     0.5 * (s->t - f->s[f->n - 1].t) * (cv[k] + last_v[k]), d);
  }
  dv_run_trajcheck_ground(f, sc, p.pos[2] + dv_geometry_contact_height(geom, p.R));
  if (!vel) s->slip = s->energy = NAN; /* without velocities: derived from the rates later */
  return DV_OK;
}

/* a state-form row into its sample: what it gives (contact, energy: NAN where not) */
static void state_row(const reader *rd, const double v[NCOLS], dv_sample *s) {
  static const int at[RED_NSTATE] = {
      [RED_TH] = C_TH, [RED_VTH] = C_VTH, [RED_VPH] = C_VPH, [RED_VPS] = C_VPS,
      [RED_PH] = C_PH, [RED_PS] = C_PS,   [RED_X] = C_X,     [RED_Y] = C_Y};
  (void)rd;
  s->t = v[C_T];
  for (int k = 0; k < RED_NSTATE; k++) s->y[k] = v[at[k]];
  s->contact[0] = v[C_CX];
  s->contact[1] = v[C_CY];
  s->energy = v[C_E];
  s->slip = NAN; /* the state form's rates assume rolling: no slip to measure */
  s->penetration = 0.0;
  s->force[0] = s->force[1] = s->force[2] = NAN;
}

/* the rates of a file that gives none: the derivative of the Akima interpolant
 * of theta, phi and psi that serves the samples between rows (run_replay.h) */
static int derive_rates(dv_trajfile *f, dv_error *err) {
  double *t = malloc(f->n * sizeof *t), *y = malloc(f->n * sizeof *y);
  gsl_interp *in = gsl_interp_alloc(gsl_interp_akima, f->n);
  gsl_interp_accel *acc = gsl_interp_accel_alloc();
  int status = t && y && in && acc ? DV_OK : dv_fail(err, DV_ESYSTEM, "out of memory");
  static const int angle[3] = {RED_TH, RED_PH, RED_PS}, rate[3] = {RED_VTH, RED_VPH, RED_VPS};
  for (int k = 0; !status && k < 3; k++) {
    for (size_t i = 0; i < f->n; i++) t[i] = f->s[i].t, y[i] = f->s[i].y[angle[k]];
    if (isnan(y[0])) {
      for (size_t i = 0; i < f->n; i++) f->s[i].y[rate[k]] = NAN;
      continue;
    }
    gsl_interp_init(in, t, y, f->n);
    for (size_t i = 0; i < f->n; i++)
      f->s[i].y[rate[k]] = gsl_interp_eval_deriv(in, t, y, t[i], acc);
  }
  gsl_interp_free(in);
  gsl_interp_accel_free(acc);
  free(t);
  free(y);
  return status;
}

/* what a row does not give, from the pose of a rolling disk: the contact point, the energy */
static void complete(const dv_scenario *sc, const dv_geometry *geom, dv_trajfile *f, int contact,
                     int energy) {
  for (size_t i = 0; i < f->n; i++) {
    dv_sample *s = &f->s[i];
    if (isnan(s->y[RED_PH])) continue; /* no pose to compute them from */
    dv_pose p;
    dv_pose_from_state(geom, s->y, &p);
    if (contact) {
      double pt[3], slip;
      dv_pose_lowest_point(geom, &p, pt, &slip);
      s->contact[0] = pt[0], s->contact[1] = pt[1];
    }
    if (energy) s->energy = dv_pose_energy(&sc->disk, &p);
  }
}

/* the angle a - b wrapped into (-pi, pi] */
static double angle_diff(double a, double b) {
  return remainder(a - b, 2.0 * M_PI);
}

/* the first row against the scenario's initial state */
static int check_start(const reader *rd, const dv_scenario *sc, const dv_trajfile *f) {
  const dv_sample *s = &f->s[0];
  const double *y0 = sc->initial;
  if (fabs(s->t) > 1e-12)
    return fail_at(rd, f->line[0], rd->col[C_T] + 1,
                   "the file starts at t = %.17g s, the scenario at t = 0", s->t);
  const double rate_scale = dv_rows_rate_scale(&sc->disk, y0);
  const int pose = f->form == DV_TRAJ_POSE;
  struct {
    int k, col;
    double scale;
    int angle;
    const char *unit;
  } q[] = {
      {RED_TH, pose ? C_QW : C_TH, 1.0, 0, "rad"},
      {RED_PH, pose ? C_QW : C_PH, 1.0, 1, "rad"},
      {RED_PS, pose ? C_QW : C_PS, 1.0, 1, "rad"},
      {RED_X, C_X, sc->disk.r, 0, "m"},
      {RED_Y, C_Y, sc->disk.r, 0, "m"},
      {RED_VTH, pose ? C_WX : C_VTH, rate_scale, 0, "rad/s"},
      {RED_VPH, pose ? C_WX : C_VPH, rate_scale, 0, "rad/s"},
      {RED_VPS, pose ? C_WX : C_VPS, rate_scale, 0, "rad/s"},
  };
  for (size_t i = 0; i < sizeof q / sizeof *q; i++) {
    const int k = q[i].k;
    if (k >= RED_VTH && k <= RED_VPS && !f->has_rates) continue; /* derived, not given */
    if (isnan(s->y[k])) continue;                                /* not in the file */
    const double d = q[i].angle ? angle_diff(s->y[k], y0[k]) : s->y[k] - y0[k];
    if (fabs(d) > DV_TRAJ_START_TOL * q[i].scale) {
      return fail_at(rd, f->line[0], rd->col[q[i].col] + 1,
                     "the start does not match the scenario's initial state: %s = %.10g %s, the "
                     "scenario's %.10g (off by %.3g, tolerance %g %s)",
                     red_state_name(k), s->y[k], q[i].unit, y0[k], fabs(d),
                     DV_TRAJ_START_TOL * q[i].scale, q[i].unit);
    }
  }
  return DV_OK;
}

/* append the row v (by column) read at lineno, its values' last digits digit
 * (NULL: pushed in code, exact) */
static int add_row(const reader *rd, const dv_scenario *sc, const dv_geometry *geom, dv_trajfile *f,
                   const double v[NCOLS], const signed char *digit, long lineno) {
  const int printed = digit && f->form == DV_TRAJ_STATE;
  const size_t max_rows = dv_run_trajfile_max_rows(sc);
  if (f->n == max_rows)
    return fail_at(rd, lineno, 0,
                   "more than %zu rows: judged with the comparison they need more than "
                   "memory_budget = %g GiB (%d bytes a row; raise it with --set "
                   "scenario.memory_budget=GIB)",
                   f->n, sc->memory_budget, DV_TRAJ_ROW_BYTES);
  if (f->n == f->cap) {
    size_t cap = f->cap ? 2 * f->cap : 1024;
    if (cap > max_rows) cap = max_rows; /* reading takes no more than judging may */
    dv_sample *s = realloc(f->s, cap * sizeof *s);
    long *l = s ? realloc(f->line, cap * sizeof *l) : NULL;
    if (s) f->s = s;
    if (l) f->line = l;
    signed char(*d)[DV_TRAJ_NVALUES] = l && printed ? realloc(f->digit, cap * sizeof *d) : NULL;
    if (d) f->digit = d;
    if (!l || (printed && !d))
      return dv_fail(rd->err, DV_ESYSTEM, "%s: out of memory at line %ld", rd->path, lineno);
    f->cap = cap;
  }
  if (f->n && !(v[C_T] > f->s[f->n - 1].t))
    return fail_at(rd, lineno, rd->col[C_T] + 1,
                   "times must increase: t = %.17g s after t = %.17g s (line %ld)", v[C_T],
                   f->s[f->n - 1].t, f->line[f->n - 1]);
  dv_sample *s = &f->s[f->n];
  memset(s, 0, sizeof *s);
  if (f->form == DV_TRAJ_POSE) {
    const int vel = f->has_rates;
    if (pose_row(rd, sc, geom, v, lineno, f, vel, s)) return DV_EINPUT;
  } else {
    state_row(rd, v, s);
  }
  if (!(s->y[RED_TH] >= 0.0 && s->y[RED_TH] <= M_PI))
    return fail_at(rd, lineno, rd->col[f->form == DV_TRAJ_POSE ? C_QW : C_TH] + 1,
                   "theta = %.10g rad is outside [0, pi]", s->y[RED_TH]);
  s->contacts = 1;
  for (int k = 0; printed && k < DV_TRAJ_NVALUES; k++) f->digit[f->n][k] = digit[C_TH + k];
  f->line[f->n++] = lineno;
  return DV_OK;
}

/* a comment "# dt = H" into *step (the engine's time step, s); other comments
 * change nothing; a dt that is not a positive number, or a second one, is an error */
static int comment_step(const reader *rd, const char *line, long lineno, double *step) {
  const char *p = line + 1;
  while (*p == ' ' || *p == '\t') p++;
  if (strncmp(p, "dt", 2) != 0) return DV_OK;
  p += 2;
  while (*p == ' ' || *p == '\t') p++;
  if (*p != '=') return DV_OK;
  char *end;
  const double h = strtod(p + 1, &end);
  while (*end == ' ' || *end == '\t') end++;
  if (*end || end == p + 1 || !(h > 0.0) || !isfinite(h))
    return fail_at(rd, lineno, 0, "'%.60s': dt must be a positive number of seconds", line);
  if (!isnan(*step)) return fail_at(rd, lineno, 0, "a second dt (%.17g s after %.17g s)", h, *step);
  *step = h;
  return DV_OK;
}

/* read every row of fp after the header */
static int read_rows(reader *rd, FILE *fp, const dv_scenario *sc, const dv_geometry *geom,
                     dv_trajfile *f, long *lineno) {
  char line[MAX_LINE + 2];
  int past = 0; /* rows read past the scenario's duration */
  while (fgets(line, sizeof line, fp)) {
    ++*lineno;
    size_t len = strlen(line);
    if (len == sizeof line - 1 && line[len - 1] != '\n')
      return fail_at(rd, *lineno, 0, "a line longer than %d bytes", MAX_LINE);
    while (len && (line[len - 1] == '\n' || line[len - 1] == '\r')) line[--len] = '\0';
    if (line[0] == '#') { /* a comment, or the step: "# dt = H" */
      if (comment_step(rd, line, *lineno, &f->step)) return DV_EINPUT;
      continue;
    }
    if (!len) return fail_at(rd, *lineno, 0, "an empty line");
    double v[NCOLS];
    signed char digit[NCOLS];
    if (read_row(rd, line, *lineno, v, digit) || add_row(rd, sc, geom, f, v, digit, *lineno))
      return DV_EINPUT;
    if (f->s[f->n - 1].t > sc->duration && ++past == DV_TRAJ_ROWS_PAST) break; /* not judged */
  }
  if (ferror(fp))
    return dv_fail(rd->err, DV_ESYSTEM, "%s: cannot read: %s", rd->path, strerror(errno));
  return DV_OK;
}

/* every row read: enough of them, what they do not give derived, the start checked */
static int finish(const reader *rd, const dv_scenario *sc, const dv_geometry *geom, dv_trajfile *f,
                  long lineno) {
  if (f->n < DV_TRAJ_MIN_SAMPLES)
    return fail_at(rd, lineno, 0, "%zu samples: at least %d needed to interpolate", f->n,
                   DV_TRAJ_MIN_SAMPLES);
  f->given = 0;
  for (int k = 0; f->form == DV_TRAJ_STATE && k < DV_TRAJ_NVALUES; k++)
    if (rd->col[C_TH + k] >= 0) f->given |= 1u << k;
  if (!f->has_rates && derive_rates(f, rd->err)) return DV_ESYSTEM;
  const int contact = f->form == DV_TRAJ_STATE && rd->col[C_CX] < 0;
  const int energy = f->form == DV_TRAJ_POSE ? !f->has_rates : rd->col[C_E] < 0;
  complete(sc, geom, f, contact, energy);
  if (check_start(rd, sc, f)) return DV_EINPUT;
  const int pose = f->form == DV_TRAJ_POSE;
  const int cols[3] = {rd->col[pose ? C_QW : C_TH] + 1, rd->col[pose ? C_QW : C_PH] + 1,
                       rd->col[pose ? C_QW : C_PS] + 1};
  if (f->has_angles && dv_run_trajcheck_columns(f, sc, pose ? 0 : rd->col[C_CX] + 1, cols, rd->err))
    return DV_EINPUT;
  return DV_OK;
}

int dv_run_trajfile_read(const char *path, const dv_scenario *sc, dv_trajfile *f, dv_error *err) {
  memset(f, 0, sizeof *f);
  snprintf(f->path, sizeof f->path, "%s", path);
  reader rd = {path, err, {0}, 0};
  FILE *fp = dv_input_open(path); /* a FIFO with no writer is not waited for */
  if (!fp) return dv_fail(err, DV_EINPUT, "%s: cannot open: %s", path, strerror(errno));
  char line[MAX_LINE + 2];
  long lineno = 0;
  int status = DV_OK;
  f->step = NAN;
  do { /* the header: the first line that is not a comment */
    if (!fgets(line, sizeof line, fp)) {
      status = fail_at(&rd, lineno + 1, 0, "an empty file: no header");
      break;
    }
    lineno++;
    if (line[0] == '#') {
      line[strcspn(line, "\r\n")] = '\0';
      status = comment_step(&rd, line, lineno, &f->step);
    }
  } while (!status && line[0] == '#');
  if (!status) {
    line[strcspn(line, "\r\n")] = '\0';
    /* a spreadsheet's UTF-8 byte order mark is no part of the first column's name */
    const size_t bom = strncmp(line, "\xEF\xBB\xBF", 3) ? 0 : 3;
    status = read_header(&rd, line + bom, lineno, &f->form);
  }
  f->half_thickness = 0.5 * sc->thickness;
  const dv_geometry geom = {DV_SHAPE_CYLINDER, sc->disk.r, f->half_thickness};
  if (!status) {
    f->has_rates = f->form == DV_TRAJ_POSE ? rd.col[C_VX] >= 0 : rd.col[C_VTH] >= 0;
    f->has_angles = f->form == DV_TRAJ_POSE || rd.col[C_PH] >= 0;
    f->has_slip = f->form == DV_TRAJ_POSE && f->has_rates;
    f->has_energy = f->has_angles || rd.col[C_E] >= 0;
    f->energy_given = f->form == DV_TRAJ_STATE && rd.col[C_E] >= 0;
    status = read_rows(&rd, fp, sc, &geom, f, &lineno);
  }
  fclose(fp);
  if (!status) status = finish(&rd, sc, &geom, f, lineno + 1);
  if (status) dv_run_trajfile_free(f);
  return status;
}

double dv_run_trajfile_energy_gap(const dv_trajfile *f, const dv_scenario *sc, double t_end,
                                  size_t *row) {
  const dv_geometry geom = {DV_SHAPE_CYLINDER, sc->disk.r, f->half_thickness};
  double e0 = NAN, worst = 0.0;
  *row = 0;
  for (size_t i = 0; f->energy_given && i < f->n && f->s[i].t <= t_end; i++) {
    const dv_sample *s = &f->s[i];
    if (isnan(s->y[RED_PH]) || isnan(s->y[RED_VTH]) || isnan(s->energy)) continue;
    dv_pose p;
    dv_pose_from_state(&geom, s->y, &p);
    const double e = dv_pose_energy(&sc->disk, &p);
    if (isnan(e0)) e0 = e;
    const double d = fabs(s->energy - e) / fabs(e0);
    if (!(d <= worst)) worst = d, *row = i;
  }
  return worst;
}

size_t dv_run_trajfile_max_rows(const dv_scenario *sc) {
  double samples;
  const double left = sc->memory_budget - dv_scenario_memory_gib(sc, &samples);
  return left > 0.0 ? (size_t)(left * 1024.0 * 1024.0 * 1024.0 / DV_TRAJ_ROW_BYTES) : 0;
}

void dv_run_trajfile_free(dv_trajfile *f) {
  if (!f) return;
  free(f->s);
  free(f->line);
  free(f->digit);
  f->s = NULL;
  f->line = NULL;
  f->digit = NULL;
  f->n = 0;
}

/* a trajectory pushed in code: the columns its samples fill, as if a header
 * named them (the state form: the whole state with its rates; the pose form:
 * the pose, with the velocities when has_rates) */
static void pushed_header(const dv_trajfile *f, reader *rd) {
  static const int state[] = {C_T, C_TH, C_PH, C_PS, C_X, C_Y, C_VTH, C_VPH, C_VPS};
  static const int pose[] = {C_T,  C_X,  C_Y,  C_Z,  C_QW, C_QX, C_QY,
                             C_QZ, C_VX, C_VY, C_VZ, C_WX, C_WY, C_WZ};
  for (int c = 0; c < NCOLS; c++) rd->col[c] = -1;
  const int *cols = f->form == DV_TRAJ_POSE ? pose : state;
  const int n = f->form == DV_TRAJ_POSE ? (f->has_rates ? 14 : 8) : 9;
  for (int i = 0; i < n; i++) rd->col[cols[i]] = i;
  rd->ncols = n;
}

void dv_run_trajfile_begin(dv_trajfile *f, const char *label) {
  memset(f, 0, sizeof *f);
  f->step = NAN;
  snprintf(f->path, sizeof f->path, "%s", label);
}

/* the form of the first push; every later one must match it */
static int push_form(dv_trajfile *f, dv_traj_form form, int rates, dv_error *err) {
  if (!f->n) {
    f->form = form, f->has_rates = rates, f->has_angles = 1;
    f->has_slip = form == DV_TRAJ_POSE && rates;
    f->has_energy = 1;
  } else if (f->form != form || f->has_rates != rates) {
    return dv_fail(err, DV_EINPUT, "%s:%zu: a %s%s after %ss%s: one kind of sample a trajectory",
                   f->path, f->n + 1, form == DV_TRAJ_POSE ? "pose" : "state",
                   form == DV_TRAJ_POSE && !rates ? " without velocities" : "",
                   f->form == DV_TRAJ_POSE ? "pose" : "state",
                   f->form == DV_TRAJ_POSE && !f->has_rates ? " without velocities" : "");
  }
  return DV_OK;
}

int dv_run_trajfile_push_state(dv_trajfile *f, const dv_scenario *sc, double t,
                               const double y[RED_NSTATE], dv_error *err) {
  if (push_form(f, DV_TRAJ_STATE, 1, err)) return DV_EINPUT;
  reader rd = {f->path, err, {0}, 0};
  pushed_header(f, &rd);
  double v[NCOLS];
  for (int c = 0; c < NCOLS; c++) v[c] = NAN;
  v[C_T] = t, v[C_TH] = y[RED_TH], v[C_PH] = y[RED_PH], v[C_PS] = y[RED_PS];
  v[C_X] = y[RED_X], v[C_Y] = y[RED_Y];
  v[C_VTH] = y[RED_VTH], v[C_VPH] = y[RED_VPH], v[C_VPS] = y[RED_VPS];
  for (int c = 0; c < NCOLS; c++)
    if (rd.col[c] >= 0 && !isfinite(v[c]))
      return fail_at(&rd, (long)f->n + 1, rd.col[c] + 1, "%s = %g is not finite", names[c], v[c]);
  const dv_geometry geom = {DV_SHAPE_CYLINDER, sc->disk.r, 0.5 * sc->thickness};
  return add_row(&rd, sc, &geom, f, v, NULL, (long)f->n + 1);
}

int dv_run_trajfile_push_pose(dv_trajfile *f, const dv_scenario *sc, double t, const double pos[3],
                              const double q[4], const double *vel, const double *omega,
                              dv_error *err) {
  if (push_form(f, DV_TRAJ_POSE, vel && omega, err)) return DV_EINPUT;
  reader rd = {f->path, err, {0}, 0};
  pushed_header(f, &rd);
  double v[NCOLS];
  for (int c = 0; c < NCOLS; c++) v[c] = NAN;
  v[C_T] = t;
  v[C_X] = pos[0], v[C_Y] = pos[1], v[C_Z] = pos[2];
  for (int k = 0; vel && omega && k < 3; k++) v[C_VX + k] = vel[k], v[C_WX + k] = omega[k];
  v[C_QW] = q[0], v[C_QX] = q[1], v[C_QY] = q[2], v[C_QZ] = q[3];
  for (int c = 0; c < NCOLS; c++)
    if (rd.col[c] >= 0 && !isfinite(v[c]))
      return fail_at(&rd, (long)f->n + 1, rd.col[c] + 1, "%s = %g is not finite", names[c], v[c]);
  const dv_geometry geom = {DV_SHAPE_CYLINDER, sc->disk.r, 0.5 * sc->thickness};
  return add_row(&rd, sc, &geom, f, v, NULL, (long)f->n + 1);
}

int dv_run_trajfile_end(dv_trajfile *f, const dv_scenario *sc, dv_error *err) {
  reader rd = {f->path, err, {0}, 0};
  pushed_header(f, &rd);
  f->half_thickness = 0.5 * sc->thickness;
  const dv_geometry geom = {DV_SHAPE_CYLINDER, sc->disk.r, f->half_thickness};
  return finish(&rd, sc, &geom, f, (long)f->n + 1);
}
