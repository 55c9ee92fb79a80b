/* test_hausdorff: the path Hausdorff distance equals the brute-force value of
 * its definition on random curves, and its work grows as n log n, not n^2:
 * the count of distances it computes at 8n samples is well under 64 times
 * the count at n. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "dv_test.h"
#include "run_hausdorff.h"

/* the definition, vertex by segment: the largest distance from a vertex of a to the polyline b */
static double segment_distance(const double p[2], const double a[2], const double b[2]) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
  double u = len2 > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0.0;
  u = fmin(1.0, fmax(0.0, u));
  return hypot(p[0] - a[0] - u * dx, p[1] - a[1] - u * dy);
}

static double brute_directed(const double (*a)[2], size_t na, const double (*b)[2], size_t nb) {
  double worst = 0.0;
  for (size_t i = 0; i < na; i++) {
    double best = nb == 1 ? hypot(a[i][0] - b[0][0], a[i][1] - b[0][1]) : INFINITY;
    for (size_t j = 0; j + 1 < nb; j++) best = fmin(best, segment_distance(a[i], b[j], b[j + 1]));
    worst = fmax(worst, best);
  }
  return worst;
}

static double brute_force(const double (*a)[2], size_t na, const double (*b)[2], size_t nb) {
  return fmax(brute_directed(a, na, b, nb), brute_directed(b, nb, a, na));
}

static uint64_t rng_state = 0x9e3779b97f4a7c15u;

/* uniform in [-1, 1) (xorshift64*) */
static double uniform(void) {
  rng_state ^= rng_state >> 12;
  rng_state ^= rng_state << 25;
  rng_state ^= rng_state >> 27;
  return (double)((rng_state * 2685821657736338717u) >> 11) * 0x1.0p-52 - 1.0;
}

enum { WALK, CLOUD, STILL, NSHAPES };

/* n points of a random shape around (cx, cy): a random walk, a cloud, or a
 * point that stands still but for rounding-size jitter and repeats */
static void random_curve(double (*p)[2], size_t n, int shape, double cx, double cy) {
  double x = cx, y = cy;
  for (size_t i = 0; i < n; i++) {
    if (shape == WALK) x += 0.01 * uniform(), y += 0.01 * uniform();
    if (shape == CLOUD) x = cx + uniform(), y = cy + uniform();
    if (shape == STILL && uniform() > 0.0) x = cx + 1e-12 * uniform(), y = cy;
    p[i][0] = x;
    p[i][1] = y;
  }
}

/* a contact point running k times round a circle of radius 0.5 m (k < 0:
 * the other way), phase lag, centre offset (dx, 0), and noise of amplitude
 * eps: an engine against its reference */
static void circle(double (*p)[2], size_t n, double k, double lag, double dx, double eps) {
  for (size_t i = 0; i < n; i++) {
    const double a = 2.0 * M_PI * k * (double)i / (double)n - lag;
    p[i][0] = dx + 0.5 * cos(a) + eps * uniform();
    p[i][1] = 0.5 * sin(a) + eps * uniform();
  }
}

/* distances computed for two circles of n samples each */
static size_t work(size_t n, double k, double lag, double dx, double eps) {
  double(*a)[2] = malloc(n * sizeof *a), (*b)[2] = malloc(n * sizeof *b);
  size_t evaluations = 0;
  if (!a || !b) return SIZE_MAX;
  circle(a, n, 3.0, 0.0, 0.0, 0.0);
  circle(b, n, k, lag, dx, eps);
  const double h =
      dv_run_hausdorff_counted((const double(*)[2])a, n, (const double(*)[2])b, n, &evaluations);
  CHECK(isfinite(h), "n %zu: Hausdorff %g", n, h);
  free(a);
  free(b);
  return evaluations;
}

int main(void) {
  enum { MAXN = 400 };
  static double a[MAXN][2], b[MAXN][2];
  const size_t sizes[] = {1, 2, 3, 5, 6, 9, 50, 400};
  int cases = 0;
  for (int shape_a = 0; shape_a < NSHAPES; shape_a++)
    for (int shape_b = 0; shape_b < NSHAPES; shape_b++)
      for (size_t ia = 0; ia < sizeof sizes / sizeof *sizes; ia++)
        for (size_t ib = 0; ib < sizeof sizes / sizeof *sizes; ib++) {
          /* far from the origin too: the rounding of large coordinates */
          const double cx = (ia + ib) % 2 ? 1e3 : 0.0;
          random_curve(a, sizes[ia], shape_a, cx, 0.0);
          random_curve(b, sizes[ib], shape_b, cx + 0.05 * uniform(), 0.05 * uniform());
          const double want = brute_force(a, sizes[ia], b, sizes[ib]);
          const double got = dv_run_hausdorff(a, sizes[ia], b, sizes[ib]);
          CHECK(got == want, "shapes %d, %d, sizes %zu, %zu: %.17g, brute force %.17g", shape_a,
                shape_b, sizes[ia], sizes[ib], got, want);
          cases++;
        }
  CHECK(dv_run_hausdorff(a, 0, b, 0) == 0.0, "two empty paths");
  CHECK(isinf(dv_run_hausdorff(a, 1, b, 0)), "one empty path");

  /* identical curves, a lagging one, an offset noisy one, and one run the
   * other way round (where a search cannot start from the previous vertex's
   * segment, so the tree does the work): counts at n and 8n. n log n gives
   * about 8 log(8n) / log(n) = 10 times, n^2 64 times (the counts, printed
   * below, grow 6.7 to 9.9 times) */
  const struct {
    const char *what;
    double turns, lag, dx, eps;
  } pairs[] = {{"identical", 3.0, 0.0, 0.0, 0.0},
               {"lagging", 3.0, 0.3, 0.0, 0.0},
               {"offset and noisy", 3.0, 0.0, 0.05, 1e-3},
               {"reversed", -3.0, 1e-4, 0.0, 0.0}};
  for (size_t k = 0; k < sizeof pairs / sizeof *pairs; k++) {
    const size_t n = 4000;
    const size_t small = work(n, pairs[k].turns, pairs[k].lag, pairs[k].dx, pairs[k].eps);
    const size_t large = work(8 * n, pairs[k].turns, pairs[k].lag, pairs[k].dx, pairs[k].eps);
    const double ratio = (double)large / (double)small;
    printf("%s: %zu distances at n = %zu, %zu at 8n: ratio %.2f\n", pairs[k].what, small, n, large,
           ratio);
    CHECK(ratio < 16.0, "%s: work grows %.1f times for 8 times the samples", pairs[k].what, ratio);
  }
  printf("%d random cases equal to brute force\n", cases);
  return TEST_RESULT();
}
