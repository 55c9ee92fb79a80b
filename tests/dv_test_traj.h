/* dv_test_traj: an engine run through the engine interface, sampled every
 * output_dt to the duration or an event, for the engine tests. */
#ifndef DV_TEST_TRAJ_H
#define DV_TEST_TRAJ_H

#include "dv_engine.h"

#define DV_TEST_MAXS 4001 /* samples kept at most */

typedef struct traj {
  long n;
  dv_sample s[DV_TEST_MAXS];
  int status;
  dv_engine_stats stats;
  char msg[512]; /* the engine's error, when status < 0 */
} traj;

/* run e on sc into tr; tr->status (DV_OK, DV_EVENT, or < 0 with msg) */
int dv_test_run(const dv_engine_type *e, const dv_scenario *sc, traj *tr);

#endif
