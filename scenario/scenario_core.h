/* scenario_core: the sections every scenario file has (not public API). */
#ifndef DV_SCENARIO_CORE_H
#define DV_SCENARIO_CORE_H

#include "scenario.h"

#define DV_NCORE_SECTIONS 3

/* [scenario], [disk], [initial]: offsets into dv_scenario, checked in this order */
extern const dv_settings_section dv_scenario_core[DV_NCORE_SECTIONS];

#endif
