/* dv_meta: what a run used and how it ended, as JSON beside its output:
 * engine, library versions, every setting of that engine, the run's stats. */
#ifndef DV_META_H
#define DV_META_H

#include "dv_engine.h"
#include "scenario.h"

/* a JSON object (cJSON *) describing engine's settings in sc */
void *dv_run_meta_settings(const dv_engine_type *engine, const dv_scenario *sc);

/* a JSON number (a cJSON *), or null where v is not finite */
void *dv_io_json_number(double v);

/* write dir/name atomically (name NULL: dir is the path) as the JSON object
 * json (a cJSON *), which is deleted */
int dv_io_json_write(const char *dir, const char *name, void *json, dv_error *err);

/* write path atomically: scenario, engine, version, settings, the settings
 * derived from the scene and why ("derived": {"keys", "reason"}, or null),
 * stats */
int dv_run_meta_write(const char *path, const dv_engine_type *engine, const dv_scenario *sc,
                      const dv_engine_stats *stats, dv_error *err);

/* path may take a run's metadata: it does not exist, is a device, or holds
 * metadata dv_run_meta_write wrote (its scenario, engine, settings and run);
 * a user's file there is DV_EINPUT, err naming it */
int dv_run_meta_check_replaceable(const char *path, dv_error *err);

#endif
