/* plot_svg: what the plot tests (test_plot, test_plot_marks, test_plot_reading)
 * share: the synthetic trajectories they plot, and readers of the SVG files
 * PLplot writes (the text of its <text> elements, an element's attributes, its
 * polylines by colour and opacity, the legend's frame) and of the plot
 * directories. Nothing here checks anything: dv_test.h counts a program's
 * failed checks in a static of its own, so the checks stay in the programs. */
#ifndef PLOT_SVG_H
#define PLOT_SVG_H

#include <stddef.h>

#include "report_plot.h"

#define PT_N 200 /* samples in a synthetic run */

/* a sample at time t on a small circle, tilt 1 + 0.1 sin t + offset */
dv_sample pt_sample(double t, double offset);

/* the runs the tests plot, PT_N samples over [0, 10] s: ref, close_by 1e-6 off
 * it, holed 1e-3 off it with a NaN hole at samples 50 and 51 (tilt; contact
 * and energy at 50): 0, or -1 out of memory */
int pt_make_runs(dv_traj *ref, dv_traj *close_by, dv_traj *holed);

/* a series compared over its whole run, no horizon, no limit */
dv_plot_series pt_whole_run(const char *label, const dv_traj *traj, const dv_traj *ref);

/* the whole file at path and its size, or NULL (caller frees) */
char *pt_slurp(const char *path, long *size);

/* the scenario plot file of dir/name as text (caller frees), NULL if missing */
char *pt_plot_text(const char *dir, const char *name);

/* remove the plots and dir */
void pt_remove_dir(const char *dir);

/* the value of attribute name (e.g. "stroke=\"") in the element starting at el, copied */
int pt_attr_of(const char *el, const char *name, char *out, size_t size);

/* the text of the <text> element at el: PLplot writes each character as &#xNN; (non-ASCII: '?') */
void pt_decode_text(const char *el, char *out, size_t size);

/* every text element's text, one per line (caller frees) */
char *pt_svg_text(const char *svg);

/* the polylines of svg stroked in colour ("": any but black, white and the grid's)
 * with more than min_pts points and an opacity in [op_lo, op_hi]: their count,
 * the box (x0, x1, y0, y1) of their points into box */
int pt_svg_lines(const char *svg, const char *colour, size_t min_pts, double op_lo, double op_hi,
                 double box[4]);

/* the box of the legend's frame: the black closed polyline of 5 points */
int pt_svg_legend_box(const char *svg, double box[4]);

/* occurrences of needle in hay */
int pt_count_of(const char *hay, const char *needle);

#endif
