/* dv_plot: the plots of one scenario's comparison, drawn with PLplot (SVG).
 *
 * Files written into dir:
 *   theta.svg        theta(t) of every engine over the reference's
 *   theta_error.svg  |theta - theta_ref|(t) per engine, log axis (against
 *                    each engine's own reference: matched, or thin)
 *   path.svg         contact paths, equal aspect, start and end marked
 *   energy.svg       (E(t) - E(0)) / |E(0)| per engine and reference
 *
 * Each engine has its colour (dv_report_plot_engine_colour), the thin
 * reference is black; series that would share a colour are told apart
 * (dv_report_plot_distinct_colours): another palette colour while one is
 * free, then a dashed line in their own; legends take more columns, then
 * smaller text, as many series need. A series without a drawable point is
 * left out and the title says "(no data: NAME, ...)". What the verdict used is drawn strongly,
 * the rest faintly (the same colour, translucent, thinner): each engine's
 * curve up to the end of its compared window (on the error plot: to its
 * horizon, where its pointwise metrics stop), a reference's up to the latest
 * window's end; a window that compared nothing draws no strong curve. Marked
 * over time: the latest window's end (black, dash-dotted, "window end"; on
 * the path, a diamond at the reference's contact point there) when the runs
 * go on after it, an engine's own window end where it ends earlier
 * (dash-dotted, its colour), each engine's horizon before its window's end
 * (dotted, its colour, labelled "NAME horizon"), on the error plot each
 * engine's own theta limit (dashed, its colour, labelled; one black line,
 * "limit", when all agree; past three engines, one line per value, black and
 * "(N engines)" where several share it), on theta.svg the turning points compared (up
 * and down triangles at maxima and minima, in each run's colour, to its
 * window's end; on a reference, those an engine's theta_turning_err was
 * judged against). A reference that judged no engine (the thin disk in a
 * thick scene, where each engine is judged against its cylinder's matched
 * reference) is drawn faintly throughout, "not compared", and sets no axis
 * range. Legends are outside the frame, right of it (below it when they
 * would leave the frame too narrow), and list those marks' line styles.
 * Linear axes are labelled with the digits their ticks need, scaled (the
 * factor, and an offset, in the axis title) where that would be many.
 *
 * and, separately, dv_report_plot_xy: one generic x-y plot (see below).
 */
#ifndef DV_PLOT_H
#define DV_PLOT_H

#include <stddef.h>

#include "run_compare.h"
#include "run_scenario.h"
#include "dv_error.h"

/* every engine of a comparison and the matched reference drawn beside them */
#define DV_PLOT_MAX_SERIES (DV_MAX_ENGINES + 1)

typedef struct dv_plot_series {
  const char *label;        /* the engine's name, e.g. "mujoco": legend text and colour */
  const dv_traj *traj;      /* the engine's samples */
  const dv_traj *reference; /* what its error is measured against (same times); NULL: the
                               series is a reference itself, drawn but not on the error plot */
  double window_end;        /* s: its compared window's end, drawn strongly to there
                               (INFINITY: the whole run; -INFINITY: nothing compared) */
  double horizon;           /* s: where its pointwise metrics stop (dv_engine_result's
                               pointwise_end); marked when before window_end (INFINITY: none) */
  double theta_limit;       /* rad: its own limit of theta_max_err, on the error plot
                               (NAN: none) */
  int turns_unjudged;       /* its theta_turning_err was not judged: no turning points
                               marked on it (0: they are) */
} dv_plot_series;

typedef struct dv_plot_input {
  const char *title;   /* scenario name */
  const dv_traj *thin; /* the thin-disk reference, drawn in every plot */
  size_t nseries;
  dv_plot_series series[DV_PLOT_MAX_SERIES];
  double window_end; /* s, the latest compared window's end: the references are drawn
                        strongly to there, and it is marked when the runs go on after it
                        (INFINITY: the whole run) */
} dv_plot_input;

/* the colour (dv_plot_curve.colour) of an engine in every plot: 0 (black) for
 * the thin-disk reference, a palette colour of its own for each other engine
 * of the registry, a stable one for any other name */
int dv_report_plot_engine_colour(const char *name);

/* colours (dv_plot_curve.colour) for n curves of one plot that ask for want[k]
 * (>= 1; 0 or less: any), no two alike, into colour[k]: the first to ask for
 * a colour keeps it; the others, in order, take the palette's first colour
 * nobody asked for or was given, and once none is left, the colour they asked
 * for (any: the first) with the first dashed line it has not drawn */
void dv_report_plot_distinct_colours(const int *want, size_t n, int *colour);

/* the colour numbers (dv_plot_curve's) of in's series in every plot
 * dv_report_plot_scenario draws, into colour[k]: their labels'
 * (dv_report_plot_engine_colour), kept apart (dv_report_plot_distinct_colours);
 * in->nseries <= DV_PLOT_MAX_SERIES */
void dv_report_plot_series_colours(const dv_plot_input *in, int *colour);

/* the names of the files dv_report_plot_scenario writes, NULL-terminated */
extern const char *const dv_report_plot_files[];

/* write the plots into the existing directory dir; DV_EINPUT (nothing
 * written) for a NULL argument or more than DV_PLOT_MAX_SERIES series */
int dv_report_plot_scenario(const char *dir, const dv_plot_input *in, dv_error *err);

/* ---- generic x-y plot ------------------------------------------------------
 *
 * dv_report_plot_xy draws up to DV_PLOT_MAX_CURVES curves into one SVG file, with a
 * legend right of the frame (it hides no point) listing every labelled curve in the order given; a curve with nothing
 * drawable is left out of it and named in the title, "(no data: label)".
 * Uses: work-precision diagrams (log-log, Pareto points marked), error against time step, U(theta),
 * phase planes (a black reference level set under coloured trajectories).
 *
 * flags:
 *   DV_PLOT_LOGX, DV_PLOT_LOGY  log10 axis, labelled with decades (10^k);
 *                               values <= 0 are skipped on it
 *   DV_PLOT_EQUAL               one unit (one decade on a log axis) is as long
 *                               on both axes
 * Ranges cover every drawn point with a small margin (log axes: whole
 * decades); a degenerate range is padded. Without any drawable point the plot
 * gets axes and "no data".
 *
 * Curves: black ones (colour 0) are drawn first, wider, underneath the
 * coloured ones. A point with a non-finite coordinate (or one that is <= 0 on
 * a log axis, or of magnitude >= 1e150) is skipped: it breaks a line. A lone
 * point of a line, or a line whose points are all one (a steady motion), gets a dot.
 *   DV_CURVE_LINE         a line through the points
 *   DV_CURVE_POINTS       a dot per point, not connected
 *   DV_CURVE_LINE_POINTS  a line through the points and a dot on each
 * marked: points with marked[i] != 0 get a large star (the curve's colour,
 * outlined black) drawn above all curves; when any drawn point is marked,
 * the legend ends with a black star entry "Pareto-optimal".
 *
 * Text: title, xlabel and ylabel are PLplot text: UTF-8, with '#' starting a
 * PLplot escape (#gh: theta, #d...#u: subscript, #u...#d: superscript, ##: '#').
 * Curve labels are shown literally (their '#' are escaped). NULL: no text.
 *
 * Errors: DV_EINPUT for bad arguments (NULL path or curves with n > 0, more
 * than DV_PLOT_MAX_CURVES curves, x or y NULL with n > 0, unknown flag or
 * style, negative colour); DV_ESYSTEM when the file cannot be written (the
 * temporary file is removed, path is left as it was). Nothing is printed.
 * PLplot's state is global: not thread-safe.
 */
/* a phase plane's: its level set's two halves, the reference and every engine */
#define DV_PLOT_MAX_CURVES (DV_MAX_ENGINES + 3)

enum { DV_PLOT_LOGX = 1, DV_PLOT_LOGY = 2, DV_PLOT_EQUAL = 4 };
enum { DV_CURVE_LINE = 0, DV_CURVE_POINTS = 1, DV_CURVE_LINE_POINTS = 2 };

typedef struct dv_plot_curve {
  const char *label; /* legend text */
  size_t n;
  const double *x, *y; /* n values each; non-finite (and, on a log axis, <= 0) skipped */
  const int *marked;   /* optional, n flags: marked points drawn with a larger distinct
                          symbol (e.g. Pareto points) */
  int style;           /* DV_CURVE_* */
  int colour;          /* 0 black (references), >= 1 the palette of the other plots;
                          an engine's is dv_report_plot_engine_colour (1 blue, 2 orange,
                          3 green, 4 red, 5 purple, 6 brown, 7 pink, 8 grey, 9 olive,
                          10 cyan, 11 navy, 12 dark green, 13 ochre, 14 maroon,
                          15 magenta, 16 teal); 17 to 32 are 1 to 16 dashed, 33 to 48
                          dashed otherwise, ...: 8 line patterns in turn */
} dv_plot_curve;

/* one SVG at path (written under a temporary name in path's directory and renamed) */
int dv_report_plot_xy(const char *path, const char *title, const char *xlabel, const char *ylabel,
                      const dv_plot_curve *curves, size_t n, int flags, dv_error *err);

#endif
