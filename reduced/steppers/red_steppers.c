/* red_steppers: the registry of integrators the reference can use. */
#include <string.h>

#include "red_solver.h"

/* the default first: settings tables name it by its index, 0 */
const red_stepper_type *const red_steppers[] = {
    &red_gsl_rk8pd,
    &red_gsl_rk8pd_stepped,
    &red_gsl_msadams,
    &red_cvode_adams,
    &red_cvode_bdf,
    &red_arkode_fehlberg13,
    NULL,
};

const red_stepper_type *red_stepper_find(const char *name) {
  for (const red_stepper_type *const *t = red_steppers; *t; t++)
    if (strcmp((*t)->name, name) == 0) return *t;
  return NULL;
}

/* measured by bench/bench_reduced: fastest at theta error <= 1e-10 */
const red_stepper_type *red_stepper_default(void) {
  return red_steppers[0];
}
