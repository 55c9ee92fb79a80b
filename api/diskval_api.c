/* diskval_api: the public C API (include/diskval/diskval.h) over the run,
 * engines and scenario layers. Only the diskval_* functions are exported. */
#include "diskval/diskval.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "run_decided.h"
#include "run_judge.h"
#include "run_scenario.h"
#include "run_trajectory.h"

_Static_assert(DV_NMETRICS <= DISKVAL_MAX_METRICS, "DISKVAL_MAX_METRICS too small");
_Static_assert(sizeof(diskval_error) == sizeof(dv_error), "diskval_error is a dv_error");
_Static_assert(DISKVAL_EINPUT == DV_EINPUT && DISKVAL_ENUMERIC == DV_ENUMERIC &&
                   DISKVAL_ESYSTEM == DV_ESYSTEM && DISKVAL_EVENT == DV_EVENT,
               "the same status codes");

struct diskval_scenario {
  dv_scenario sc;
};

struct diskval_trajectory {
  dv_traj traj; /* an engine's run (diskval_run) */
  dv_engine_stats stats;
  /* the caller's samples (diskval_trajectory_new): the scenario they are
   * of, and the samples as judge reads them from a file; sc NULL for a run */
  const dv_scenario *sc;
  dv_trajfile file;
};

/* the internal error buffer of err (the same layout), or NULL */
static dv_error *as_dv(diskval_error *err) {
  return (dv_error *)err;
}

/* the library's version */
const char *diskval_version(void) {
  return DISKVAL_VERSION;
}

/* load a scenario file against every engine's settings table */
static int scenario_load(const char *path, const char *const *overrides, size_t n,
                         diskval_scenario **out, diskval_error *err) {
  if (!path || !out || (n && !overrides))
    return dv_fail(as_dv(err), DV_EINPUT, "diskval_scenario_load: NULL argument");
  diskval_scenario *s = calloc(1, sizeof *s);
  if (!s) return dv_fail(as_dv(err), DV_ESYSTEM, "out of memory: a scenario");
  const int status = dv_engine_load_scenario(path, overrides, n, &s->sc, as_dv(err));
  if (status < 0) {
    free(s);
    return status;
  }
  *out = s;
  return DV_OK;
}

/* a scenario from code: every key checked and derived as a file's would be */
static int scenario_new(const char *name, const diskval_disk *disk, const diskval_state *initial,
                        double duration, double output_dt, diskval_scenario **out,
                        diskval_error *err) {
  if (!name || !disk || !initial || !out)
    return dv_fail(as_dv(err), DV_EINPUT, "diskval_scenario_new: NULL %s",
                   !name      ? "name"
                   : !disk    ? "disk"
                   : !initial ? "initial state"
                              : "out");
  char what[160];
  if (strlen(name) >= sizeof((dv_scenario *)0)->name)
    return dv_fail(as_dv(err), DV_EINPUT, "scenario.name: '%.60s...' is too long", name);
  if (dv_scenario_check_name(name, what, sizeof what))
    return dv_fail(as_dv(err), DV_EINPUT, "scenario.name: '%s': %s", name, what);
  const char *nm = name;
  diskval_scenario *s = calloc(1, sizeof *s);
  if (!s) return dv_fail(as_dv(err), DV_ESYSTEM, "out of memory: a scenario");
  dv_scenario *sc = &s->sc;
  dv_engine_init_scenario(sc);
  dv_scenario_core_defaults(sc);
  snprintf(sc->name, sizeof sc->name, "%s", nm);
  const struct {
    const char *section, *key;
    double v;
  } keys[] = {
      {"scenario", "duration", duration},
      {"scenario", "output_dt", output_dt},
      {"disk", "radius", disk->radius},
      {"disk", "mass", disk->mass},
      {"disk", "gravity", disk->gravity},
      {"disk", "thickness", disk->thickness},
      {"disk", "A", disk->A},
      {"disk", "C", disk->C},
      {"initial", "theta", initial->theta},
      {"initial", "theta_dot", initial->theta_dot},
      {"initial", "phi_dot", initial->phi_dot},
      {"initial", "psi_dot", initial->psi_dot},
      {"initial", "phi", initial->phi},
      {"initial", "psi", initial->psi},
      {"initial", "x", initial->x},
      {"initial", "y", initial->y},
  };
  /* the header's convention: A = 0, the uniform disk's A (no body has A = 0), so an
   * error about the C given names C; both 0, both the uniform disk's (C = 0 with
   * an A given is a C of 0) */
  const int derive_a = disk->A == 0.0, derive_c = derive_a && disk->C == 0.0;
  int status = DV_OK;
  for (size_t i = 0; i < sizeof keys / sizeof keys[0] && !status; i++)
    if (!(!strcmp(keys[i].section, "disk") &&
          ((keys[i].key[0] == 'A' && derive_a) || (keys[i].key[0] == 'C' && derive_c))))
      status = dv_scenario_set_core(sc, keys[i].section, keys[i].key, keys[i].v, as_dv(err));
  if (!status) status = dv_scenario_check_core(sc, as_dv(err));
  if (!status) status = dv_engine_derive_settings(sc, as_dv(err)); /* as a load derives them */
  if (status < 0) {
    free(s);
    return status;
  }
  *out = s;
  return DV_OK;
}

/* [disk] friction, the one [disk] key diskval_disk leaves out: the scenario
 * derived anew with it, as a file giving it (sc is unchanged on error) */
static int set_disk(diskval_scenario *sc, const char *key, const char *value,
                    diskval_error *err) {
  if (strcmp(key, "friction"))
    return dv_fail(as_dv(err), DV_EINPUT,
                   "disk.%.40s: only friction is set here (the rest: diskval_scenario_new)", key);
  char set[160];
  if ((size_t)snprintf(set, sizeof set, "disk.friction=%s", value) >= sizeof set)
    return dv_fail(as_dv(err), DV_EINPUT, "disk.friction: '%.40s...' is too long", value);
  const char *overrides[] = {set};
  dv_scenario *trial = malloc(sizeof *trial);
  if (!trial) return dv_fail(as_dv(err), DV_ESYSTEM, "out of memory: a scenario's copy");
  const int status = dv_scenario_with(&sc->sc, overrides, 1, trial, as_dv(err));
  if (!status) sc->sc = *trial;
  free(trial);
  return status;
}

/* set one engine setting, checked as at load: its own range, then every
 * engine section's check on a copy (a theta_limit past the initial theta is refused
 * as a file or --set refuses it); sc is unchanged on error */
int diskval_scenario_set(diskval_scenario *sc, const char *engine, const char *key,
                         const char *value, diskval_error *err) {
  if (!sc || !engine || !key || !value)
    return dv_fail(as_dv(err), DV_EINPUT, "diskval_scenario_set: NULL argument");
  if (!strcmp(engine, "disk")) return set_disk(sc, key, value, err);
  dv_scenario *trial = malloc(sizeof *trial);
  if (!trial) return dv_fail(as_dv(err), DV_ESYSTEM, "out of memory: a scenario's copy");
  *trial = sc->sc;
  dv_error why;
  int status = dv_scenario_set(trial, engine, key, value, as_dv(err));
  if (!status && dv_engine_derive_settings(trial, &why))
    status = dv_fail(as_dv(err), DV_EINPUT, "engines.%s.%s = %s: %s", engine, key, value, why.msg);
  free(trial);
  return status ? status : dv_scenario_set(&sc->sc, engine, key, value, as_dv(err));
}

/* the disk as the scenario holds it, moments derived where they were not given */
void diskval_scenario_disk(const diskval_scenario *sc, diskval_disk *out) {
  if (!sc || !out) return;
  const red_disk *d = &sc->sc.disk;
  *out = (diskval_disk){d->r, d->m, d->A, d->C, d->g, sc->sc.thickness};
}

/* the scenario's name */
const char *diskval_scenario_name(const diskval_scenario *sc) {
  return sc ? sc->sc.name : "";
}

/* the scenario's duration, s */
double diskval_scenario_duration(const diskval_scenario *sc) {
  return sc ? sc->sc.duration : NAN;
}

/* copy a canonical state into the public layout */
static void state_out(const double y[RED_NSTATE], diskval_state *out) {
  *out = (diskval_state){y[RED_TH], y[RED_VTH], y[RED_VPH], y[RED_VPS],
                         y[RED_PH], y[RED_PS],  y[RED_X],   y[RED_Y]};
}

/* the scenario's resolved initial state */
void diskval_scenario_initial(const diskval_scenario *sc, diskval_state *out) {
  if (sc && out) state_out(sc->sc.initial, out);
}

/* free a scenario */
void diskval_scenario_free(diskval_scenario *sc) {
  free(sc);
}

/* the name of engine i of the registry */
const char *diskval_engine_name(size_t i) {
  for (size_t k = 0; dv_engine_list()[k]; k++)
    if (k == i) return dv_engine_list()[k]->name;
  return NULL;
}

/* the engine called name, or NULL with err set */
static const dv_engine_type *find_engine(const char *name, diskval_error *err) {
  const dv_engine_type *e = name ? dv_engine_find(name) : NULL;
  if (!e) dv_fail(as_dv(err), DV_EINPUT, "unknown engine '%s'", name ? name : "(null)");
  return e;
}

/* dv_run_collect's sink: append the sample */
static int push(void *ctx, const dv_sample *s) {
  return dv_run_traj_push(ctx, s);
}

/* run engine over sc into a new trajectory */
static int run(const diskval_scenario *sc, const char *engine, diskval_trajectory **out,
               diskval_error *err) {
  if (!sc || !out) return dv_fail(as_dv(err), DV_EINPUT, "diskval_run: NULL argument");
  const dv_engine_type *e = find_engine(engine, err);
  if (!e) return DV_EINPUT;
  diskval_trajectory *tr = calloc(1, sizeof *tr);
  if (!tr) return dv_fail(as_dv(err), DV_ESYSTEM, "out of memory: a trajectory");
  const int status = dv_run_collect(e, &sc->sc, push, &tr->traj, &tr->stats, as_dv(err));
  if (status < 0) {
    diskval_trajectory_free(tr);
    return status;
  }
  *out = tr;
  return status;
}

/* the number of samples */
size_t diskval_trajectory_size(const diskval_trajectory *tr) {
  return !tr ? 0 : tr->sc ? tr->file.n : tr->traj.n;
}

/* sample i in the public layout */
int diskval_trajectory_sample(const diskval_trajectory *tr, size_t i, diskval_sample *out) {
  if (!tr || !out || i >= diskval_trajectory_size(tr)) return -1;
  const dv_sample *s = tr->sc ? &tr->file.s[i] : &tr->traj.s[i];
  out->t = s->t;
  state_out(s->y, &out->state);
  out->contact_x = s->contact[0];
  out->contact_y = s->contact[1];
  out->energy = s->energy;
  return 0;
}

/* free a trajectory */
void diskval_trajectory_free(diskval_trajectory *tr) {
  if (!tr) return;
  dv_run_traj_free(&tr->traj);
  dv_run_trajfile_free(&tr->file);
  free(tr);
}

/* copy metrics into the public layout */
static void metrics_out(const dv_metrics *m, diskval_metrics *out) {
  memset(out, 0, sizeof *out);
  out->n = DV_NMETRICS;
  for (size_t i = 0; i < DV_NMETRICS; i++) {
    out->name[i] = dv_metric_names[i];
    out->value[i] = m->value[i];
  }
  for (size_t i = DV_NMETRICS; i < DISKVAL_MAX_METRICS; i++) out->value[i] = NAN;
  out->n_window = m->n_window;
  out->t_window = m->t_window;
}

/* metrics that hold nothing: no names, every value NAN (diskval_metric gives NAN) */
static void metrics_none(diskval_metrics *out) {
  memset(out, 0, sizeof *out);
  for (size_t i = 0; i < DISKVAL_MAX_METRICS; i++) out->value[i] = NAN;
  out->t_window = NAN;
}

/* tr's samples as a run: a run's own, or those pushed (diskval_trajectory_new),
 * ended on a copy (what they do not give derived, the start checked) into *copy */
static int as_run(const diskval_trajectory *tr, dv_trajfile *copy, dv_traj *view,
                  diskval_error *err) {
  memset(copy, 0, sizeof *copy);
  if (!tr->sc) {
    *view = tr->traj;
    return DV_OK;
  }
  *copy = tr->file;
  copy->s = malloc((copy->n ? copy->n : 1) * sizeof *copy->s);
  copy->line = malloc((copy->n ? copy->n : 1) * sizeof *copy->line);
  if (!copy->s || !copy->line) {
    dv_run_trajfile_free(copy);
    return dv_fail(as_dv(err), DV_ESYSTEM, "out of memory");
  }
  memcpy(copy->s, tr->file.s, copy->n * sizeof *copy->s);
  memcpy(copy->line, tr->file.line, copy->n * sizeof *copy->line);
  copy->cap = copy->n;
  const int status = dv_run_trajfile_end(copy, tr->sc, as_dv(err));
  if (status) return dv_run_trajfile_free(copy), status;
  memset(view, 0, sizeof *view);
  view->s = copy->s;
  view->n = copy->n;
  return DV_OK;
}

/* metrics of one trajectory against another */
int diskval_compare_trajectories(const diskval_trajectory *engine,
                                 const diskval_trajectory *reference, diskval_metrics *out,
                                 diskval_error *err) {
  if (out) metrics_none(out); /* safe to read whatever happens */
  if (!engine || !reference || !out)
    return dv_fail(as_dv(err), DV_EINPUT, "diskval_compare_trajectories: NULL argument");
  if (!diskval_trajectory_size(engine) || !diskval_trajectory_size(reference))
    return dv_fail(as_dv(err), DV_EINPUT,
                   "diskval_compare_trajectories: the %s trajectory is empty",
                   diskval_trajectory_size(engine) ? "reference" : "engine");
  dv_trajfile ce, cr;
  dv_traj e, r;
  int status = as_run(engine, &ce, &e, err);
  if (!status) status = as_run(reference, &cr, &r, err);
  if (!status) {
    dv_metrics m;
    dv_run_compare(&e, &r, INFINITY, &m);
    metrics_out(&m, out);
    dv_run_trajfile_free(&cr);
  }
  dv_run_trajfile_free(&ce);
  return status;
}

/* a comparison's result for engine result r in the public layout */
static void comparison_out(const dv_engine_result *r, diskval_comparison *out) {
  memset(out, 0, sizeof *out);
  out->pass = r->pass;
  snprintf(out->verdict, sizeof out->verdict, "%s", dv_run_verdict_name(r->verdict));
  snprintf(out->decided, sizeof out->decided, "%.*s", (int)sizeof out->decided - 1, r->decided);
  metrics_out(&r->vs_ref, &out->metrics);
  for (size_t i = 0; i < DISKVAL_MAX_METRICS; i++)
    out->limit[i] = i < DV_NMETRICS ? r->tolerance[i] : NAN;
  out->wall_s = r->wall_s;
  const int deciding = dv_run_deciding_metric(r);
  out->decided_metric = deciding < 0 ? NULL : dv_metric_names[deciding];
  snprintf(out->decided_why, sizeof out->decided_why, "%.*s", (int)sizeof out->decided_why - 1,
           r->decided_why);
}

int diskval_trajectory_new(const diskval_scenario *sc, const char *name, diskval_trajectory **out,
                           diskval_error *err) {
  if (!sc || !out) return dv_fail(as_dv(err), DV_EINPUT, "diskval_trajectory_new: NULL argument");
  diskval_trajectory *tr = calloc(1, sizeof *tr);
  if (!tr) return dv_fail(as_dv(err), DV_ESYSTEM, "out of memory: a trajectory");
  tr->sc = &sc->sc;
  dv_run_trajfile_begin(&tr->file, name ? name : "trajectory");
  *out = tr;
  return DV_OK;
}

int diskval_trajectory_push(diskval_trajectory *tr, double t, const diskval_state *s,
                            diskval_error *err) {
  if (!tr || !s || !tr->sc)
    return dv_fail(
        as_dv(err), DV_EINPUT,
        "diskval_trajectory_push: NULL, or a trajectory not from diskval_trajectory_new");
  double y[RED_NSTATE];
  y[RED_TH] = s->theta, y[RED_VTH] = s->theta_dot, y[RED_VPH] = s->phi_dot;
  y[RED_VPS] = s->psi_dot, y[RED_PH] = s->phi, y[RED_PS] = s->psi, y[RED_X] = s->x, y[RED_Y] = s->y;
  return dv_run_trajfile_push_state(&tr->file, tr->sc, t, y, as_dv(err));
}

int diskval_trajectory_push_pose(diskval_trajectory *tr, double t, const diskval_pose *p,
                                 int with_velocity, diskval_error *err) {
  if (!tr || !p || !tr->sc)
    return dv_fail(as_dv(err), DV_EINPUT,
                   "diskval_trajectory_push_pose: NULL, or a trajectory not from "
                   "diskval_trajectory_new");
  return dv_run_trajfile_push_pose(&tr->file, tr->sc, t, p->pos, p->quat,
                                   with_velocity ? p->vel : NULL, with_velocity ? p->omega : NULL,
                                   as_dv(err));
}

/* a comparison that holds nothing: not judged, no metrics (an error's out) */
static void comparison_none(diskval_comparison *out) {
  memset(out, 0, sizeof *out);
  snprintf(out->verdict, sizeof out->verdict, "%s", dv_run_verdict_name(DV_VERDICT_NOT_JUDGED));
  metrics_none(&out->metrics);
  for (size_t i = 0; i < DISKVAL_MAX_METRICS; i++) out->limit[i] = NAN;
}

/* judge the caller's samples as diskval judge judges a file */
static int judge(const diskval_scenario *sc, const diskval_trajectory *tr, diskval_comparison *out,
                 diskval_error *err) {
  if (out) comparison_none(out);
  if (!sc || !tr || !out || !tr->sc)
    return dv_fail(as_dv(err), DV_EINPUT,
                   "diskval_judge: NULL, or a trajectory not from diskval_trajectory_new");
  dv_trajfile f = tr->file; /* ended on a copy: the caller may push on */
  f.s = malloc((f.n ? f.n : 1) * sizeof *f.s);
  f.line = malloc((f.n ? f.n : 1) * sizeof *f.line);
  dv_comparison *c = calloc(1, sizeof *c);
  dv_replay *rp = malloc(sizeof *rp);
  int status = f.s && f.line && c && rp ? DV_OK : dv_fail(as_dv(err), DV_ESYSTEM, "out of memory");
  if (!status) {
    memcpy(f.s, tr->file.s, f.n * sizeof *f.s);
    memcpy(f.line, tr->file.line, f.n * sizeof *f.line);
    f.cap = f.n;
    status = dv_run_trajfile_end(&f, &sc->sc, as_dv(err));
  }
  if (!status) {
    dv_run_replay_init(rp, &f, f.path);
    status = dv_run_judge(&sc->sc, rp, 1, c, as_dv(err));
  }
  if (!status) comparison_out(&c->r[0], out);
  if (c) dv_run_comparison_free(c);
  free(c);
  free(rp);
  dv_run_trajfile_free(&f);
  return status < 0 ? status : DV_OK;
}

int diskval_judge(const diskval_scenario *sc, const diskval_trajectory *tr, diskval_comparison *out,
                  diskval_error *err) {
  gsl_error_handler_t *handler = gsl_set_error_handler_off();
  const int status = judge(sc, tr, out, err);
  gsl_set_error_handler(handler);
  return status;
}

/* run engine on sc and judge it against its reference */
static int compare(const diskval_scenario *sc, const char *engine, diskval_comparison *out,
                   diskval_error *err) {
  if (out) comparison_none(out);
  if (!sc || !out) return dv_fail(as_dv(err), DV_EINPUT, "diskval_compare: NULL argument");
  const dv_engine_type *e[2] = {find_engine(engine, err), NULL};
  if (!e[0]) return DV_EINPUT;
  dv_comparison *c = calloc(1, sizeof *c);
  if (!c) return dv_fail(as_dv(err), DV_ESYSTEM, "out of memory: a comparison");
  const int status = dv_run_scenario(&sc->sc, NULL, e, 1, c, as_dv(err));
  if (status >= 0) comparison_out(&c->r[0], out);
  dv_run_comparison_free(c);
  free(c);
  return status < 0 ? status : DV_OK;
}

/* a metric's value by name */
double diskval_metric(const diskval_metrics *m, const char *name) {
  if (!m || !name) return NAN;
  for (size_t i = 0; i < m->n && i < DISKVAL_MAX_METRICS; i++)
    if (m->name[i] && strcmp(m->name[i], name) == 0) return m->value[i];
  return NAN;
}

/* the exported entry points that compute: GSL reports its errors as statuses there
 * (its default handler would abort the caller's process), the caller's handler
 * is back on return */
int diskval_scenario_load(const char *path, const char *const *overrides, size_t n,
                          diskval_scenario **out, diskval_error *err) {
  gsl_error_handler_t *handler = gsl_set_error_handler_off();
  const int status = scenario_load(path, overrides, n, out, err);
  gsl_set_error_handler(handler);
  return status;
}

int diskval_scenario_new(const char *name, const diskval_disk *disk, const diskval_state *initial,
                         double duration, double output_dt, diskval_scenario **out,
                         diskval_error *err) {
  gsl_error_handler_t *handler = gsl_set_error_handler_off();
  const int status = scenario_new(name, disk, initial, duration, output_dt, out, err);
  gsl_set_error_handler(handler);
  return status;
}

int diskval_run(const diskval_scenario *sc, const char *engine, diskval_trajectory **out,
                diskval_error *err) {
  gsl_error_handler_t *handler = gsl_set_error_handler_off();
  const int status = run(sc, engine, out, err);
  gsl_set_error_handler(handler);
  return status;
}

int diskval_compare(const diskval_scenario *sc, const char *engine, diskval_comparison *out,
                    diskval_error *err) {
  gsl_error_handler_t *handler = gsl_set_error_handler_off();
  const int status = compare(sc, engine, out, err);
  gsl_set_error_handler(handler);
  return status;
}
