/* run_phase: how far along the reference's contact path the engine is.
 *
 * phase_err (m): at each compared time the engine's contact point is placed
 * on the reference's contact path (the polyline of its points) at the
 * nearest point, found by walking from the previous time's place: a circle
 * run round again is not taken for its first round, and an engine half a
 * round behind is half a round behind. The arc length from the path's start
 * to that place, against the reference's own arc length at that time; the
 * largest difference over the window. A point past the path's end is placed
 * on its last segment's extension. Unchanged by a rigid motion of the scene,
 * and scales as a length.
 */
#ifndef DV_RUN_PHASE_H
#define DV_RUN_PHASE_H

#include <stddef.h>

/* the phase error of the engine's points e against the reference's points
 * ref, both n, at equal times (m); points with a NaN coordinate are skipped;
 * 0 for n < 2; NAN when out of memory */
double dv_run_phase_err(const double (*e)[2], const double (*ref)[2], size_t n);

/* the same, with each sample's phase error into series (n; NAN where a
 * point was skipped) */
double dv_run_phase_series(const double (*e)[2], const double (*ref)[2], size_t n,
                           double *series);

#endif
