/* dvp_linear_ticks: a linear axis's step, scale and label digits
 * (report_plot_ticks.h). */
#include "report_plot_ticks.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "report_plot_internal.h"

#define LABEL_GAP 1.5  /* between two labels along an axis, character heights */
#define LABEL_PITCH 2.0 /* between two labels stacked across an axis, character heights */

/* the scale of labels every step over [lo, hi] into t, and their widest width */
static void scale_for(double lo, double hi, double step, dvp_ticks *t) {
  const int k = (int)floor(log10(step) + 1e-9);
  double mag = fmax(fabs(lo), fabs(hi));
  t->step = step;
  t->offset = 0.0;
  t->exponent = 0;
  if (mag / step >= pow(10.0, DVP_TICK_DIGITS)) { /* too many digits: labels count from a round value */
    const double p = pow(10.0, ceil(log10(hi - lo)));
    t->offset = round(0.5 * (lo + hi) / p) * p;
    mag = fmax(fabs(lo - t->offset), fabs(hi - t->offset));
  }
  const int lead = mag > 0.0 ? (int)floor(log10(mag) + 1e-9) : k;
  if (t->offset != 0.0 || lead >= DVP_TICK_DIGITS || k < -3) t->exponent = lead;
  t->decimals = t->exponent - k > 0 ? t->exponent - k : 0;
  t->width = 1;
  char label[64];
  for (double i = ceil(lo / step - 1e-9); i * step <= hi + 1e-9 * step; i++) {
    dvp_tick_label(t, i * step, label, sizeof label);
    if ((int)strlen(label) > t->width) t->width = (int)strlen(label);
  }
}

void dvp_linear_ticks(double lo, double hi, double length, int along, dvp_ticks *t) {
  static const double nice[3] = {1.0, 2.0, 5.0};
  const double span = hi - lo;
  const int k0 = (int)floor(log10(span)) - 2;
  for (int k = k0; k <= k0 + 3; k++)
    for (int m = 0; m < 3; m++) {
      scale_for(lo, hi, nice[m] * pow(10.0, k), t);
      const double pitch = t->step / span * length;
      if (pitch >= (along ? dvp_ticks_width(t) + LABEL_GAP : LABEL_PITCH)) return;
    }
}

void dvp_tick_label(const dvp_ticks *t, double v, char *out, size_t size) {
  double x = (v - t->offset) / pow(10.0, t->exponent);
  if (fabs(x) < 0.5 * pow(10.0, -t->decimals)) x = 0.0; /* no "-0" */
  snprintf(out, size, "%.*f", t->decimals, x);
}

void dvp_ticks_note(const dvp_ticks *t, char *out, size_t size) {
  int k = 0;
  out[0] = '\0';
  if (t->offset != 0.0)
    k = snprintf(out, size, " %s %.15g", t->offset > 0 ? "-" : "+", fabs(t->offset));
  if (t->exponent != 0 && k >= 0 && (size_t)k < size)
    snprintf(out + k, size - (size_t)k, ", \xc3\x97" "10#u%d#d", t->exponent);
}

double dvp_ticks_width(const dvp_ticks *t) {
  return DVP_TICK_CHAR_WIDTH * t->width;
}

/* plslabelfunc callback (data: a dvp_axes *): a linear axis's label, or a decade's 10^k */
static void axis_label(PLINT axis, PLFLT value, char *label, PLINT length, PLPointer data) {
  const dvp_axes *ax = data;
  const int k = axis == PL_Y_AXIS;
  if (ax->log[k])
    dvp_decade_label(axis, value, label, length, NULL);
  else
    dvp_tick_label(&ax->t[k], value, label, (size_t)length);
}

double dvp_ylabels_width(double lo, double hi, int log) {
  if (log) return 0.0;
  PLFLT def, ht, sx0, sx1, sy0, sy1;
  plgchr(&def, &ht);
  plgspa(&sx0, &sx1, &sy0, &sy1);
  dvp_ticks t;
  dvp_linear_ticks(lo, hi, 0.7 * (sy1 - sy0) / ht, 0, &t);
  return dvp_ticks_width(&t) + DVP_TICK_CHAR_WIDTH; /* a character to spare: the
                                                         path's equal aspect may widen the range */
}

/* plbox's options and step for axis k of ax over [lo, hi], length character heights long */
static const char *axis_opts(dvp_axes *ax, int k, double lo, double hi, double length,
                             double *step) {
  if (!ax->log[k]) {
    dvp_linear_ticks(lo, hi, length, k == 0, &ax->t[k]);
    *step = ax->t[k].step;
    return k ? "bcnostv" : "bcnost";
  }
  *step = ceil((hi - lo) / 8.0);
  if (*step > 1) return k ? "bcnotv" : "bcnot";
  *step = 0.0;
  return k ? "bcnstlv" : "bcnstl";
}

void dvp_draw_axes(const double r[4], int logx, int logy, dvp_axes *ax) {
  PLFLT def, ht, sx0, sx1, sy0, sy1, vx0, vx1, vy0, vy1;
  plgchr(&def, &ht);
  plgspa(&sx0, &sx1, &sy0, &sy1);
  plgvpd(&vx0, &vx1, &vy0, &vy1);
  ax->log[0] = logx, ax->log[1] = logy;
  double xstep, ystep;
  const char *xopt = axis_opts(ax, 0, r[0], r[1], (vx1 - vx0) * (sx1 - sx0) / ht, &xstep);
  const char *yopt = axis_opts(ax, 1, r[2], r[3], (vy1 - vy0) * (sy1 - sy0) / ht, &ystep);
  plcol0(DVP_COL_GRID);
  plwidth(1.0);
  plbox(logx ? "gl" : "g", xstep, 0, logy ? "gl" : "g", ystep, 0);
  plcol0(DVP_COL_FG);
  plslabelfunc(axis_label, ax);
  plbox(xopt, xstep, 0, yopt, ystep, 0);
  plslabelfunc(NULL, NULL);
}

void dvp_axis_titles(const dvp_axes *ax, const char *xlabel, const char *ylabel, double disp,
                     const char *title) {
  char note[2][96], x[512], y[512];
  for (int k = 0; k < 2; k++)
    if (ax->log[k])
      note[k][0] = '\0';
    else
      dvp_ticks_note(&ax->t[k], note[k], sizeof note[k]);
  snprintf(x, sizeof x, "%s%s", xlabel ? xlabel : "", note[0]);
  snprintf(y, sizeof y, "%s%s", ylabel ? ylabel : "", note[1]);
  pllab(x, "", title ? title : "");
  plmtex("l", disp, 0.5, 0.5, y);
}
