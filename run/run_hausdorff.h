/* dv_run_hausdorff: the Hausdorff distance between two contact paths.
 *
 * Each path is a polyline of points (x, y) in metres. The directed distance
 * from a to b is the largest distance from a vertex of a to the polyline b
 * (its segments; a single point when b has one vertex); the Hausdorff
 * distance is the larger of the two directions. Computed in O(n log n) for
 * paths that lie near each other: each polyline's segments go into a tree of
 * bounding boxes (tests/run/test_hausdorff checks the cost growth and that it
 * equals the brute-force value).
 */
#ifndef DV_RUN_HAUSDORFF_H
#define DV_RUN_HAUSDORFF_H

#include <stddef.h>

/* Hausdorff distance between polylines a and b (m); 0 for two empty ones,
 * INFINITY when only one is empty, NAN when out of memory */
double dv_run_hausdorff(const double (*a)[2], size_t na, const double (*b)[2], size_t nb);

/* the same, adding to *evaluations the point-box and point-segment distances
 * it computed (the work, for tests of its cost) */
double dv_run_hausdorff_counted(const double (*a)[2], size_t na, const double (*b)[2], size_t nb,
                                size_t *evaluations);

#endif
