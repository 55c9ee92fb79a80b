/* dv_run_hausdorff: the Hausdorff distance between two polylines through a
 * tree of bounding boxes over each one's segments, split at the median along
 * the wider side. A vertex searches the other tree nearer child first and
 * skips a box no nearer than the best segment found; it stops as soon as it is
 * within the largest distance so far, which it can then no longer raise. */
#include "run_hausdorff.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

enum { LEAF_SEGMENTS = 4 };

/* segment index of a polyline, and its midpoint (the key it is split on) */
typedef struct segment_item {
  double mid[2];
  size_t index;
} segment_item;

/* a box over items [first, end); children left and right, or left == 0 for a leaf */
typedef struct box_node {
  double lo[2], hi[2];
  size_t first, end, left, right;
} box_node;

typedef struct segment_tree {
  const double (*p)[2];
  size_t np;
  segment_item *items;
  box_node *nodes;
  size_t nnodes;
} segment_tree;

/* one vertex's search: the best distance so far and the largest over earlier vertices */
typedef struct vertex_search {
  const segment_tree *tree;
  const double *q;
  double best, worst, margin;
  size_t evaluations, nearest; /* the segment that gave best */
} vertex_search;

/* the ends of segment i (a single point is a segment of length zero) */
static const double *segment_end(const segment_tree *t, size_t i) {
  return t->p[i + 1 < t->np ? i + 1 : i];
}

/* distance from p to the segment a-b */
static double segment_distance(const double p[2], const double a[2], const double b[2]) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
  double u = len2 > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0.0;
  u = fmin(1.0, fmax(0.0, u));
  return hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dy);
}

/* distance from p to the box of a node (0 inside) */
static double box_distance(const box_node *n, const double p[2]) {
  const double dx = fmax(0.0, fmax(n->lo[0] - p[0], p[0] - n->hi[0]));
  const double dy = fmax(0.0, fmax(n->lo[1] - p[1], p[1] - n->hi[1]));
  return hypot(dx, dy);
}

static void swap_items(segment_item *it, size_t i, size_t j) {
  const segment_item tmp = it[i];
  it[i] = it[j];
  it[j] = tmp;
}

/* reorder it[lo, hi) so that it[k] has its sorted place along axis (three-way
 * quickselect: a path that stands still gives many equal keys) */
static void select_nth(segment_item *it, size_t lo, size_t hi, size_t k, int axis) {
  while (hi - lo > 1) {
    const double a = it[lo].mid[axis], b = it[lo + (hi - lo) / 2].mid[axis],
                 c = it[hi - 1].mid[axis];
    const double pivot = fmax(fmin(a, b), fmin(fmax(a, b), c));
    size_t lt = lo, i = lo, gt = hi;
    while (i < gt) {
      const double v = it[i].mid[axis];
      if (v < pivot)
        swap_items(it, lt++, i++);
      else if (v > pivot)
        swap_items(it, i, --gt);
      else
        i++;
    }
    if (k < lt)
      hi = lt;
    else if (k >= gt)
      lo = gt;
    else
      return;
  }
}

static size_t build(segment_tree *t, size_t first, size_t end) {
  const size_t id = t->nnodes++;
  box_node *n = &t->nodes[id];
  n->lo[0] = n->lo[1] = INFINITY;
  n->hi[0] = n->hi[1] = -INFINITY;
  for (size_t i = first; i < end; i++) {
    const size_t s = t->items[i].index;
    const double *ends[2] = {t->p[s], segment_end(t, s)};
    for (int e = 0; e < 2; e++)
      for (int k = 0; k < 2; k++) {
        n->lo[k] = fmin(n->lo[k], ends[e][k]);
        n->hi[k] = fmax(n->hi[k], ends[e][k]);
      }
  }
  n->first = first;
  n->end = end;
  n->left = n->right = 0;
  if (end - first <= LEAF_SEGMENTS) return id;
  const int axis = n->hi[1] - n->lo[1] > n->hi[0] - n->lo[0];
  const size_t mid = first + (end - first) / 2;
  select_nth(t->items, first, end, mid, axis);
  const size_t left = build(t, first, mid), right = build(t, mid, end);
  t->nodes[id].left = left;
  t->nodes[id].right = right;
  return id;
}

static void tree_free(segment_tree *t) {
  free(t->items);
  free(t->nodes);
}

/* the tree over the segments of p[0, np), np >= 1; -1 out of memory. Every
 * leaf but a lone root holds at least 2 segments, so nseg nodes suffice */
static int tree_build(const double (*p)[2], size_t np, segment_tree *t) {
  const size_t nseg = np > 1 ? np - 1 : 1;
  *t = (segment_tree){p, np, malloc(nseg * sizeof *t->items), malloc(nseg * sizeof *t->nodes), 0};
  if (!t->items || !t->nodes) return tree_free(t), -1;
  for (size_t i = 0; i < nseg; i++) {
    const double *b = segment_end(t, i);
    t->items[i] = (segment_item){{0.5 * (p[i][0] + b[0]), 0.5 * (p[i][1] + b[1])}, i};
  }
  build(t, 0, nseg);
  return 0;
}

static void descend(vertex_search *s, size_t id) {
  const segment_tree *t = s->tree;
  const box_node *n = &t->nodes[id];
  if (!n->left) {
    for (size_t i = n->first; i < n->end && s->best > s->worst; i++) {
      const size_t seg = t->items[i].index;
      const double d = segment_distance(s->q, t->p[seg], segment_end(t, seg));
      s->evaluations++;
      if (d < s->best) s->best = d, s->nearest = seg;
    }
    return;
  }
  const size_t kids[2] = {n->left, n->right};
  /* box distances less the rounding margin: never above a computed segment distance */
  const double d[2] = {box_distance(&t->nodes[kids[0]], s->q) - s->margin,
                       box_distance(&t->nodes[kids[1]], s->q) - s->margin};
  s->evaluations += 2;
  const int nearer = d[1] < d[0];
  for (int k = 0; k < 2; k++) {
    const int c = k ? !nearer : nearer;
    if (s->best > s->worst && d[c] < s->best) descend(s, kids[c]);
  }
}

/* the larger of worst and the largest distance from a vertex of a to the
 * polyline of tree; each search starts from the segments next to the one
 * nearest the previous vertex: paths are continuous, so these are often near
 * enough to stop it at once */
static double directed(const double (*a)[2], size_t na, const segment_tree *tree, double worst,
                       double margin, size_t *evaluations) {
  const size_t nseg = tree->np > 1 ? tree->np - 1 : 1;
  size_t nearest = 0;
  for (size_t i = 0; i < na; i++) {
    vertex_search s = {tree, a[i], INFINITY, worst, margin, 0, nearest};
    for (size_t seg = nearest; seg < nearest + 2 && seg < nseg; seg++) {
      const double d = segment_distance(s.q, tree->p[seg], segment_end(tree, seg));
      s.evaluations++;
      if (d < s.best) s.best = d, s.nearest = seg;
    }
    if (s.best > worst) descend(&s, 0);
    *evaluations += s.evaluations;
    nearest = s.nearest;
    if (s.best > worst) worst = s.best;
  }
  return worst;
}

static double largest_coordinate(const double (*p)[2], size_t n) {
  double m = 0.0;
  for (size_t i = 0; i < n; i++) m = fmax(m, fmax(fabs(p[i][0]), fabs(p[i][1])));
  return m;
}

/* both directions, the tree of one built while the other is freed */
static double hausdorff(const double (*a)[2], size_t na, const double (*b)[2], size_t nb,
                        size_t *evaluations) {
  if (!na || !nb) return (na || nb) ? INFINITY : 0.0;
  /* a few rounding errors of the largest coordinate bound how far a computed
   * segment distance can fall below its box's */
  const double margin =
      64.0 * DBL_EPSILON * fmax(largest_coordinate(a, na), largest_coordinate(b, nb));
  const double(*from[2])[2] = {a, b}, (*to[2])[2] = {b, a};
  const size_t nfrom[2] = {na, nb}, nto[2] = {nb, na};
  /* the second direction starts from the first's result: only a larger value counts */
  double result = 0.0;
  for (int k = 0; k < 2; k++) {
    segment_tree tree;
    if (tree_build(to[k], nto[k], &tree)) return NAN;
    result = directed(from[k], nfrom[k], &tree, result, margin, evaluations);
    tree_free(&tree);
  }
  return result;
}

double dv_run_hausdorff(const double (*a)[2], size_t na, const double (*b)[2], size_t nb) {
  size_t evaluations = 0;
  return hausdorff(a, na, b, nb, &evaluations);
}

double dv_run_hausdorff_counted(const double (*a)[2], size_t na, const double (*b)[2], size_t nb,
                                size_t *evaluations) {
  return hausdorff(a, na, b, nb, evaluations);
}
