/* search_verify_suite: diskval suite --verify: every scenario's contact
 * engines verified (search_verify.h) in parallel, written as OUT/verify.md,
 * OUT/verify.json and a JUnit XML file (one test case per scenario and
 * engine; a failure unless it converges to the reference).
 */
#ifndef DV_SEARCH_VERIFY_SUITE_H
#define DV_SEARCH_VERIFY_SUITE_H

#include <stddef.h>

#include "dv_engine.h"
#include "search_verify.h"

#define DV_VERIFY_SUITE_MAX_ENGINES 8

/* one scenario x engine */
typedef struct dv_verify_case {
  char scenario[64];
  char engine[32];
  int status; /* of dv_search_verify: DV_OK, < 0 with message; DV_EVENT: skipped, the
               * scenario names other engines */
  char message[512];
  double wall_s;
  dv_verification v;
} dv_verify_case;

/* what dv_search_verify_suite returns besides DV_OK and errors */
enum {
  DV_VERIFY_SUITE_WORKER = 1,     /* an MPI worker rank: rank 0 has the cases */
  DV_VERIFY_SUITE_INTERRUPTED = 2 /* SIGINT or SIGTERM: the cases that ended are filled in */
};

/* verify every (scenario, engine) of scs[0..n) (loaded once: no case reads
 * a file); results in
 * cases[i * nengines + j] (the caller's, n x nengines); a case still running
 * after timeout s (<= 0: no limit; none under MPI) is an error, "timed out",
 * and a case with no result has NaN errors */
int dv_search_verify_suite(const dv_scenario *scs, size_t n, const dv_engine_type *const *engines,
                           size_t nengines, int jobs, double timeout, dv_verify_case *cases,
                           dv_error *err);

/* verify.md and verify.json in dir, and the JUnit XML at junit */
int dv_search_verify_write(const char *dir, const char *junit, const dv_verify_case *cases,
                           size_t n, dv_error *err);

#endif
