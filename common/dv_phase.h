/* dv_phase: what a long command is doing now, named by the code doing it.
 *
 * The phases nest (a settings probe inside an attribution run): each is a
 * name, its item k of n (n 0: not counted) and what the item is ("rk4
 * 5e-05 s"). Code in any layer names them (engines/ its settings probes,
 * search/ its attribution and verification levels); the progress line
 * (run/run_progress.h) listens and says them. Without a listener this is
 * bookkeeping only: nothing is written.
 */
#ifndef DV_PHASE_H
#define DV_PHASE_H

#include <stddef.h>

#define DV_PHASE_DEPTH 4 /* phases nested at most (deeper ones are not named) */

typedef struct dv_phase {
  char name[32];    /* "settings probe" */
  size_t k, n;      /* item k (from 1) of n; n 0: not counted */
  char subject[64]; /* what item k is, may be "" */
  double began;     /* s (dv_clock_now): the phase's first item began */
  double item_began;
} dv_phase;

/* item k of n of phase name begins (a phase of that name and n already on
 * the stack: its next item; otherwise a new phase nested in the current) */
void dv_phase_item(const char *name, size_t k, size_t n, const char *subject);

/* phase name ends (and any nested in it); a name not on the stack: nothing */
void dv_phase_end(const char *name);

/* the phases now, outermost first; their number */
size_t dv_phase_stack(const dv_phase **stack);

/* called at each dv_phase_item and dv_phase_end (NULL: nobody listens) */
void dv_phase_listen(void (*on_change)(void));

#endif
