/* red_reference: the reduced equations packaged as a red_system with the
 * events that end a reference run (theta reaching theta_limit or
 * pi - theta_limit, where the disk lies down and the equations are singular).
 */
#ifndef RED_REFERENCE_H
#define RED_REFERENCE_H

#include "red_disk.h"
#include "red_solver.h"

enum { RED_EVENT_THETA_LOW = 0, RED_EVENT_THETA_HIGH = 1 };

typedef struct red_reference {
  red_disk disk;
  double theta_limit; /* rad, in (0, pi/2) */
  red_system sys;     /* params point back to this struct: do not copy after init */
} red_reference;

void red_reference_init(red_reference *ref, const red_disk *disk, double theta_limit);

#endif
