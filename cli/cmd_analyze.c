/* dv_cli_analyze: diskval analyze SCENARIO [--json] [--set k=v]: invariants,
 * steady motion and its stability, and the turning points of theta. */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cli_args.h"
#include "dv_reference.h"
#include "run_meta.h"
#include "scenario.h"
#include "red_invariants.h"
#include "red_orbit_thick.h"
#include "red_potential.h"
#include "red_steady.h"

static const char HELP[] =
    "usage: diskval analyze SCENARIO [--json] [--set section.key=value]...\n"
    "\n"
    "Analyse the initial state of SCENARIO with the reduced equations:\n"
    "energy E and the integrals f1, f2; the upright critical spin; the range of\n"
    "theta (turning points of the effective potential); and, when the initial\n"
    "state is a steady motion, its rates and linear stability (eigenvalues); else,\n"
    "where theta nutates between turning points, the nutation period and what phi\n"
    "and psi advance over it (quadratures over the effective potential). A disk\n"
    "with [disk] thickness > 0 is analysed as the cylinder it is, with the matched\n"
    "reference's equations: its energy, its steady motion, and the range of theta,\n"
    "the nutation period and the advances from its run over one period.\n"
    "  --json   one JSON object on stdout instead of text\n";

/* the nutation is shown where halving its quadrature's points moves it less */
#define NUTATION_RESOLUTION 1e-8

typedef struct analysis {
  double E, f1, f2, k, crit, range[2];
  int falls, steady, stable;
  double eig[RED_NREDUCED][2];
  double eig_uncertainty; /* how far the eigenvalues move with the Jacobian's step */
  int marginal;           /* the largest real part is within that of 0 */
  int nutates;            /* a nutation between two turning points, resolved */
  double nutation[3];     /* its period (s), the advances of phi and psi over it (rad) */
  double resolution;      /* relative: what halving the quadrature's points moves them by */
  char nutation_why[160]; /* why a nutation's numbers are not shown, or "" */
  double h;               /* half-thickness of the body analysed (m): 0, the thin disk */
  char ended[160];        /* the cylinder's run ended before a period: why, or "" */
} analysis;

/* the half-thickness of the scene's body: the matched reference's */
static double body_half_thickness(const dv_scenario *sc) {
  const double h = dv_matched_settings_of(sc)->half_thickness;
  return isnan(h) ? 0.5 * sc->thickness : h;
}

/* the cylinder of half-thickness an->h: its own equations (red_rolling.h) */
static int analyse_thick(const dv_scenario *sc, analysis *an, dv_error *err) {
  const dv_reduced_settings *ref = dv_reference_settings(sc);
  const double *y = sc->initial;
  red_rolling rr;
  red_rolling_init(&rr, &sc->disk, an->h, dv_matched_friction(sc), ref->theta_limit);
  double st[RR_NSTATE];
  red_rolling_from_state(&rr, y, st);
  an->E = red_rolling_energy(&rr, st);
  an->f1 = an->f2 = an->k = an->crit = NAN; /* the thin disk's: not this body's */
  /* one period at least: 100 of its slowest time scale, or the scene */
  const double t_max = fmax(sc->duration, 100.0 * 2.0 * M_PI * sqrt(sc->disk.r / sc->disk.g));
  red_orbit_thick o;
  int status = red_orbit_thick_run(&rr, red_steppers[ref->integrator], ref->rtol, ref->atol, y,
                                   t_max, &o, err);
  if (status) return status;
  an->steady = o.steady;
  an->range[0] = o.range[0];
  an->range[1] = o.range[1];
  an->falls = o.falls;
  an->nutates = o.nutates;
  an->resolution = 1e-9; /* above what 8x the samples moves it (red_orbit_thick.c) */
  memcpy(an->nutation, o.nutation, sizeof an->nutation);
  if (o.event >= 0 && !o.falls)
    snprintf(an->ended, sizeof an->ended, "the rolling model ends at t = %.6g s (%s)", o.t_event,
             red_rolling_event_names[o.event]);
  else if (!o.steady && !o.nutates && !o.falls)
    snprintf(an->ended, sizeof an->ended, "no whole period within %.6g s", o.t_end);
  if (an->ended[0])
    snprintf(an->nutation_why, sizeof an->nutation_why, "not seen: %.140s", an->ended);
  return DV_OK;
}

static int analyse(const dv_scenario *sc, analysis *an, dv_error *err) {
  const red_disk *d = &sc->disk;
  const double *y = sc->initial;
  memset(an, 0, sizeof *an);
  if ((an->h = body_half_thickness(sc)) > 0.0) return analyse_thick(sc, an, err);
  an->E = red_energy(d, y);
  an->k = red_legendre_k(d);
  an->crit = red_upright_critical_spin(d);
  if (red_invariants(d, y, &an->f1, &an->f2))
    return dv_fail(err, DV_ENUMERIC, "f1, f2 could not be evaluated at theta = %g", y[RED_TH]);
  dv_error e = {{0}};
  /* what failed, and from which part of the file */
  int status =
      red_theta_range(d, y, dv_reference_settings(sc)->theta_limit, an->range, &an->falls, &e);
  if (status) return dv_fail(err, status, "[initial]: the turning points of theta: %s", e.msg);
  an->steady = red_is_steady(d, y, 1e-9);
  if (an->steady) {
    if ((status = red_linear_stability(d, y, an->eig, &an->stable, &e)))
      return dv_fail(err, status, "[initial]: the stability of the steady start: %s", e.msg);
    an->eig_uncertainty = red_eigen_uncertainty(d, y, an->eig);
    /* two eigenvalues are always 0 (the family of steady motions); a third
     * within the uncertainty of 0 puts the motion on the stability boundary */
    int near_zero = 0;
    for (int i = 0; i < RED_NREDUCED; i++)
      near_zero += hypot(an->eig[i][0], an->eig[i][1]) <= an->eig_uncertainty;
    an->marginal = near_zero > 2;
    return DV_OK;
  }
  if (an->falls || !(an->range[0] < an->range[1])) return DV_OK;
  /* 256 points: within 1.6e-10 of the integrated period on nutations of
   * 0.1 rad and more (test_period_quadrature), less on small ones, shown to the
   * digits their resolution holds; one too small for E - U to stand above
   * rounding is said, not failed */
  dv_error why = {{0}};
  double resolution = NAN;
  an->nutates = red_nutation(d, y, an->range, an->nutation, &resolution, &why) == DV_OK &&
                resolution <= NUTATION_RESOLUTION;
  an->resolution = resolution;
  if (!an->nutates && !why.msg[0])
    snprintf(why.msg, sizeof why.msg, "the quadrature moves by %.2g with half its points",
             resolution);
  if (!an->nutates)
    snprintf(an->nutation_why, sizeof an->nutation_why, "not resolved over %.3g rad: %.100s",
             an->range[1] - an->range[0], why.msg);
  return DV_OK;
}

/* the significant digits a relative resolution holds (4 to 10) */
static int digits(double resolution) {
  const double d = floor(-log10(fmax(resolution, 1e-300)));
  return d < 4.0 ? 4 : d > 10.0 ? 10 : (int)d;
}

static const char *branch(double k) {
  return k == 0.0 ? "closed form (C = 0)"
                  : (k <= 0.25 ? "real parameters" : "complex-conjugate parameters");
}

static char *to_json(const dv_scenario *sc, const analysis *an) {
  const double *y = sc->initial;
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "scenario", sc->name);
  cJSON_AddStringToObject(o, "body", an->h > 0.0 ? "cylinder" : "thin disk");
  cJSON_AddNumberToObject(o, "half_thickness", an->h);
  cJSON_AddNumberToObject(o, "energy", an->E);
  cJSON_AddItemToObject(o, "f1", dv_io_json_number(an->f1));
  cJSON_AddItemToObject(o, "f2", dv_io_json_number(an->f2));
  cJSON_AddItemToObject(o, "legendre_k", dv_io_json_number(an->k));
  if (an->h > 0.0)
    cJSON_AddNullToObject(o, "hypergeometric_branch");
  else
    cJSON_AddStringToObject(o, "hypergeometric_branch", branch(an->k));
  cJSON_AddItemToObject(o, "upright_critical_spin", dv_io_json_number(an->crit));
  cJSON_AddItemToObject(o, "theta_range", cJSON_CreateDoubleArray(an->range, 2));
  cJSON_AddBoolToObject(o, "falls", an->falls);
  cJSON *init = cJSON_AddObjectToObject(o, "initial");
  for (int i = 0; i < RED_NSTATE; i++) cJSON_AddNumberToObject(init, red_state_name(i), y[i]);
  if (an->steady) {
    cJSON *s = cJSON_AddObjectToObject(o, "steady");
    cJSON_AddNumberToObject(s, "phi_dot", y[RED_VPH]);
    cJSON_AddNumberToObject(s, "psi_dot", y[RED_VPS]);
    cJSON_AddItemToObject(s, "contact_radius",
                          dv_io_json_number(fabs(sc->disk.r * y[RED_VPS] / y[RED_VPH])));
    if (an->h > 0.0) { /* the linearisation is the thin disk's reduced system */
      cJSON_AddNullToObject(s, "stable");
      cJSON_AddNullToObject(s, "eigenvalues");
      cJSON_AddNullToObject(s, "eigenvalue_uncertainty");
      cJSON_AddNullToObject(s, "marginal");
    } else {
      cJSON_AddBoolToObject(s, "stable", an->stable);
      cJSON *ev = cJSON_AddArrayToObject(s, "eigenvalues");
      for (int i = 0; i < RED_NREDUCED; i++)
        cJSON_AddItemToArray(ev, cJSON_CreateDoubleArray(an->eig[i], 2));
      cJSON_AddItemToObject(s, "eigenvalue_uncertainty", dv_io_json_number(an->eig_uncertainty));
      cJSON_AddBoolToObject(s, "marginal", an->marginal);
    }
  } else {
    cJSON_AddNullToObject(o, "steady");
  }
  if (an->nutates) {
    cJSON *n = cJSON_AddObjectToObject(o, "nutation");
    cJSON_AddNumberToObject(n, "period", an->nutation[0]);
    cJSON_AddNumberToObject(n, "phi_advance", an->nutation[1]);
    cJSON_AddNumberToObject(n, "psi_advance", an->nutation[2]);
    cJSON_AddNumberToObject(n, "resolution", an->resolution);
  } else {
    cJSON_AddNullToObject(o, "nutation");
  }
  if (an->nutation_why[0]) cJSON_AddStringToObject(o, "nutation_note", an->nutation_why);
  char *text = cJSON_Print(o);
  cJSON_Delete(o);
  return text;
}

static void print_text(const dv_scenario *sc, const analysis *an) {
  const double *y = sc->initial;
  printf("scenario          %s\n", sc->name);
  if (an->h > 0.0)
    printf(
        "body              cylinder, half-thickness %g m: the matched reference's equations "
        "(rolling on the rim corner)\n",
        an->h);
  else
    printf("body              thin disk: the reduced equations\n");
  printf("energy            %.15g J\n", an->E);
  if (an->h > 0.0) {
    printf(
        "f1, f2            n/a: the thin disk's integrals; the range and period below are "
        "the cylinder's run\n");
  } else {
    printf("f1, f2            %.15g, %.15g kg m^2/s  (k = %.6g, %s)\n", an->f1, an->f2, an->k,
           branch(an->k));
    printf("upright critical  %.15g rad/s\n", an->crit);
  }
  printf("theta range       [%.12g, %.12g] rad%s\n", an->range[0], an->range[1],
         an->falls ? "  (reaches the theta limit: the disk lies down)" : "");
  if (!an->steady) {
    printf("steady            no (theta_dot = %g rad/s)\n", y[RED_VTH]);
    if (an->nutates)
      printf("nutation          period %.*g s; phi advances %.*g rad, psi %.*g rad a period\n",
             digits(an->resolution), an->nutation[0], digits(an->resolution), an->nutation[1],
             digits(an->resolution), an->nutation[2]);
    else if (an->nutation_why[0])
      printf("nutation          %s\n", an->nutation_why);
    return;
  }
  printf("steady            phi_dot %.15g, psi_dot %.15g rad/s, contact radius %.12g m\n",
         y[RED_VPH], y[RED_VPS], fabs(sc->disk.r * y[RED_VPS] / y[RED_VPH]));
  if (an->h > 0.0) {
    printf("stability         n/a: the eigenvalues are the thin disk's reduced system's\n");
    return;
  }
  printf("stability         %s; eigenvalues", an->marginal ? "marginal"
                                              : an->stable ? "linearly stable"
                                                           : "unstable");
  for (int i = 0; i < RED_NREDUCED; i++) printf(" (%.6g%+.6gi)", an->eig[i][0], an->eig[i][1]);
  printf(", each within %.1e (finite differences)\n", an->eig_uncertainty);
  if (an->marginal)
    printf(
        "                  more than the two structural eigenvalues are within that of 0: "
        "on the stability boundary\n");
}

int dv_cli_analyze(int argc, char **argv) {
  int json = 0;
  const dv_cli_option options[] = {{"json", DV_CLI_FLAG, &json, 0, 0}};
  const dv_cli_command cmd = {"analyze", HELP, options, 1, 1, 1};
  dv_cli_args a;
  const int parsed = dv_cli_parse(&cmd, argc, argv, &a);
  if (parsed != DV_CLI_RUN) return parsed;
  dv_scenario sc;
  dv_error err = {{0}};
  analysis an;
  int code = DV_EXIT_OK;
  if (dv_cli_load_scenario("analyze", a.args.items[0], &a.sets, &sc, &err)) {
    fprintf(stderr, "%s\n", err.msg);
    code = DV_EXIT_ERROR;
  } else if (analyse(&sc, &an, &err)) {
    code = dv_cli_error("analyze", "%s: %s", a.args.items[0], err.msg);
  } else if (!json) {
    print_text(&sc, &an);
  } else {
    char *text = to_json(&sc, &an);
    if (text) puts(text);
    code = text ? DV_EXIT_OK : dv_cli_error("analyze", "out of memory");
    free(text);
  }
  dv_cli_args_free(&cmd, &a);
  return code;
}
