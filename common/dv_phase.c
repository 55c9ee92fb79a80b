/* dv_phase: the phases of a long command (dv_phase.h). */
#include "dv_phase.h"

#include <stdio.h>
#include <string.h>

#include "dv_clock.h"

static dv_phase stack[DV_PHASE_DEPTH];
static size_t depth; /* phases on the stack */
static void (*listener)(void);

static size_t find(const char *name) {
  for (size_t i = depth; i-- > 0;)
    if (!strcmp(stack[i].name, name)) return i;
  return depth;
}

void dv_phase_item(const char *name, size_t k, size_t n, const char *subject) {
  const double now = dv_clock_now();
  size_t i = find(name);
  if (i < depth && stack[i].n == n) {
    depth = i + 1; /* phases nested in its last item have ended with it */
  } else if (depth < DV_PHASE_DEPTH) {
    i = depth++;
    snprintf(stack[i].name, sizeof stack[i].name, "%s", name);
    stack[i].n = n;
    stack[i].began = now;
  } else {
    return; /* nested too deep to name */
  }
  stack[i].k = k;
  stack[i].item_began = now;
  snprintf(stack[i].subject, sizeof stack[i].subject, "%s", subject ? subject : "");
  if (listener) listener();
}

void dv_phase_end(const char *name) {
  const size_t i = find(name);
  if (i >= depth) return;
  depth = i;
  if (listener) listener();
}

size_t dv_phase_stack(const dv_phase **out) {
  *out = stack;
  return depth;
}

void dv_phase_listen(void (*on_change)(void)) { listener = on_change; }
