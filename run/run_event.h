/* run_event: an engine's lying down against the reference's.
 *
 * Every engine ends its run where the disk lies down (theta reaches
 * [engines.reduced] theta_limit or pi - theta_limit: dv_engine_stats
 * lay_down). When it does is timing-insensitive, and the reference nudged by
 * +- the engine's early error (run_horizon.h) bounds how far it may move: on the
 * side the engine lies down, the reference and its nudged runs that lie
 * down there give the times [from, to], widened by one output_dt. An engine
 * inside the compared window (before the reference's end and its validity
 * limit) that lies down where none of them does, or before from, has
 * failed; so has one that runs on past to where all of them lie down.
 * Past the validity limit nothing is judged.
 */
#ifndef DV_RUN_EVENT_H
#define DV_RUN_EVENT_H

#include <stddef.h>

#include "scenario.h"

/* how a run ended, as the event rule needs it */
typedef struct dv_run_end {
  double nudge; /* rad: a nudged reference's offset of theta(0); 0: the run itself */
  int ran;      /* 0: a nudged run not made (its start lies past the lying-down limit) */
  double t;     /* s: its last sample */
  int lay_down; /* dv_engine_stats.lay_down: -1, +1, or 0 (did not lie down) */
} dv_run_end;

typedef struct dv_event_verdict {
  int judged;      /* the engine or its reference lay down inside the window */
  int agrees;      /* the engine's end is inside [from, to] (1 when not judged) */
  double from, to; /* s: where the engine may lie down; NAN: nowhere, to INFINITY: no latest */
  char why[96];    /* a disagreement, in a few words ("" when it agrees) */
  char note[400];  /* every run's end in words: the engine's, the reference's, the nudged ones */
} dv_event_verdict;

/* the engine's end against its reference's and the nudged runs' (nudged[k].ran
 * 0: not made); valid_end (s): the reference's validity limit (INFINITY: none) */
void dv_run_event_judge(const dv_scenario *sc, const char *engine_name, const dv_run_end *engine,
                        const dv_run_end *ref, const dv_run_end nudged[2], double valid_end,
                        dv_event_verdict *out);

#endif
