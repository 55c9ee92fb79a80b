/* dv_dart: what the DART engine (engine_dart.cc) shows its tests beyond the
 * engine table: a symbol of its module (dv_engine_module_symbol, engine_module.h). */
#ifndef DV_DART_H
#define DV_DART_H

#include "dv_engine.h"

#ifdef __cplusplus
extern "C" {
#endif

/* the contacts DART's collision detector ([engines.dart] detector of sc)
 * reports for the disk of sc at state y lowered by sink (m): their number
 * (< 0 on an error, err set), their points' mean (m, world) and the largest
 * penetration depth (m) */
int dv_dart_contacts(const dv_scenario *sc, const double y[RED_NSTATE], double sink,
                     double mean[3], double *depth, dv_error *err);
typedef int dv_dart_contacts_fn(const dv_scenario *sc, const double y[RED_NSTATE], double sink,
                                double mean[3], double *depth, dv_error *err);

#ifdef __cplusplus
}
#endif

#endif
