/* test_settings_reach: every key of every engine's settings table reaches the
 * engine. Each key is set to a second value and the run must differ from the
 * base run (a setting replaced by a constant, or never passed on, leaves it
 * the same); the few keys that cannot change a run say why in the table, and
 * the test checks that too (an inert key's run is the same, bit for bit). A
 * key of a table without an entry here fails: a new setting needs one.
 * Usage: test_settings_reach CIRCLE FALLING (a steady circle, a disk that falls). */
#include <math.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_reference.h"
#include "dv_test.h"
#include "dv_test_traj.h"

enum expect {
  DIFFERS,  /* the run differs */
  MORE_SLIP, /* ... and slips more (a friction lowered) */
  SAME,     /* inert in this engine: the run is the same (why says so) */
  FAILS,    /* the run ends in an error (a budget) */
  VALIDITY, /* the run is the same; the validity window it gives ends earlier */
  FALLING   /* on the falling disk (the second scenario), the run ends earlier */
};

/* DART's Bullet detector is opened with RTLD_DEEPBIND, which AddressSanitizer
 * refuses: in a sanitizer build the run fails and says so */
#if defined(__SANITIZE_ADDRESS__)
#define DART_BULLET FAILS
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DART_BULLET FAILS
#endif
#endif
#ifndef DART_BULLET
#define DART_BULLET DIFFERS
#endif

typedef struct reach {
  const char *engine, *key, *value; /* the second value */
  const char *both;                 /* set in both runs: what makes key matter, or NULL */
  enum expect expect;
  const char *why; /* for SAME, FAILS and VALIDITY */
} reach;

/* every run: short and at given steps, so no choice is probed */
static const char *const BASE[] = {
    "scenario.duration=0.2",         "engines.mujoco.timestep=1e-4",
    "engines.mujoco.integrator=rk4", "engines.ode.timestep=1e-4",
    "engines.bullet.timestep=1e-4",  "engines.bullet.body=multibody",
    "engines.simbody.timestep=1e-3", "engines.simbody.integrator=rk3",
    "engines.dart.timestep=1e-4",    "engines.dart.lcp=pgs",
};
#define NBASE (sizeof BASE / sizeof BASE[0])

static const reach TABLE[] = {
    {"reduced", "integrator", "cvode-bdf", NULL, DIFFERS, NULL},
    {"reduced", "rtol", "1e-6", NULL, DIFFERS, NULL},
    {"reduced", "atol", "1e-4", NULL, DIFFERS, NULL},
    {"reduced", "theta_limit", "1.46", NULL, FALLING, NULL},
    {"reduced", "max_steps", "3", NULL, FAILS, "a budget of 3 steps ends the run in an error"},
    {"reduced", "fold", "off", NULL, DIFFERS, NULL},
    {"matched", "half_thickness", "0.01", NULL, DIFFERS, NULL},
    {"matched", "friction", "0.05", NULL, VALIDITY,
     "it only ends the validity window, where the contact force leaves its cone"},
    {"mujoco", "timestep", "5e-5", NULL, DIFFERS, NULL},
    {"mujoco", "integrator", "implicit", NULL, DIFFERS, NULL},
    {"mujoco", "cone", "pyramidal", NULL, DIFFERS, NULL},
    {"mujoco", "impratio", "1", NULL, DIFFERS, NULL},
    {"mujoco", "solver", "pgs", NULL, DIFFERS, NULL},
    {"mujoco", "tolerance", "0.5", "engines.mujoco.solver=cg", DIFFERS, NULL},
    {"mujoco", "iterations", "1", NULL, DIFFERS, NULL},
    {"mujoco", "noslip_iterations", "10", NULL, DIFFERS, NULL},
    {"mujoco", "solref_timeconst", "0.01", NULL, DIFFERS, NULL},
    {"mujoco", "solref_dampratio", "0.3", NULL, DIFFERS, NULL},
    {"mujoco", "solimp_dmin", "0.5", NULL, DIFFERS, NULL},
    {"mujoco", "solimp_dmax", "0.99", NULL, DIFFERS, NULL},
    {"mujoco", "solimp_width", "0.1", NULL, DIFFERS, NULL},
    {"mujoco", "friction", "0.05", NULL, MORE_SLIP, NULL},
    {"mujoco", "geom", "cylinder", NULL, DIFFERS, NULL},
    {"mujoco", "half_thickness", "0.01", "engines.mujoco.geom=cylinder", DIFFERS, NULL},
    {"ode", "timestep", "5e-5", NULL, DIFFERS, NULL},
    {"ode", "stepper", "quickstep", NULL, DIFFERS, NULL},
    {"ode", "iterations", "2", "engines.ode.stepper=quickstep", DIFFERS, NULL},
    {"ode", "erp", "0.8", NULL, SAME,
     "the world's ERP corrects joint errors; the contact's normal row takes soft_erp, its friction "
     "rows correct none"},
    {"ode", "cfm", "1e-3", NULL, DIFFERS, NULL}, /* the contact's friction rows take it */
    /* a coefficient of 0.5 against a force limit of 0.5 N (the limit derived from [disk]
     * friction, mu m g, would roll as the coefficient does) */
    {"ode", "friction_model", "force_limit", "engines.ode.friction=0.5", DIFFERS, NULL},
    {"ode", "friction", "0.05", NULL, MORE_SLIP, NULL},
    {"ode", "soft_erp", "0.8", NULL, DIFFERS, NULL},
    {"ode", "soft_cfm", "1e-3", NULL, DIFFERS, NULL},
    {"ode", "geom", "cylinder", NULL, DIFFERS, NULL},
    {"ode", "half_thickness", "0.01", "engines.ode.geom=cylinder", DIFFERS, NULL},
    {"bullet", "timestep", "5e-5", NULL, DIFFERS, NULL},
    {"bullet", "body", "rigidbody", NULL, DIFFERS, NULL},
    {"bullet", "solver_iterations", "1", "engines.bullet.solver=si", DIFFERS, NULL},
    {"bullet", "friction", "0.05", NULL, MORE_SLIP, NULL},
    /* the rigid body takes it by its own path (the base runs the multibody) */
    {"bullet", "friction", "0.05", "engines.bullet.body=rigidbody", MORE_SLIP, NULL},
    {"bullet", "cfm", "1e-3", NULL, DIFFERS, NULL},
    {"bullet", "gyroscopic", "off", NULL, DIFFERS, NULL},
    {"bullet", "geom", "cylinder", NULL, DIFFERS, NULL},
    {"bullet", "half_thickness", "0.01", "engines.bullet.geom=cylinder", DIFFERS, NULL},
    {"bullet", "solver", "si", NULL, DIFFERS, NULL},
    {"simbody", "timestep", "5e-4", NULL, DIFFERS, NULL},
    {"simbody", "integrator", "rkmerson", NULL, DIFFERS, NULL},
    {"simbody", "accuracy", "1e-6", NULL, DIFFERS, NULL},
    {"simbody", "constraint_tolerance", "1e-14", NULL, DIFFERS, NULL},
    /* Simbody cannot slip: its friction ends the run where rolling needs more */
    {"simbody", "friction", "0.05", NULL, FALLING, NULL},
    {"simbody", "geom", "cylinder", NULL, DIFFERS, NULL},
    {"simbody", "half_thickness", "0.01", "engines.simbody.geom=cylinder", DIFFERS, NULL},
    {"dart", "timestep", "5e-5", NULL, DIFFERS, NULL},
    {"dart", "lcp", "dantzig", NULL, DIFFERS, NULL},
    {"dart", "detector", "bullet", NULL, DART_BULLET, "no Bullet detector under AddressSanitizer"},
    {"dart", "friction", "0.05", NULL, MORE_SLIP, NULL},
    {"dart", "erp", "0.01", NULL, DIFFERS, NULL},
    {"dart", "erv", "1e-6", NULL, DIFFERS, NULL},
    {"dart", "cfm", "1e-3", NULL, DIFFERS, NULL},
    {"dart", "geom", "cylinder", NULL, DIFFERS, NULL},
    {"dart", "half_thickness", "0.01", "engines.dart.geom=cylinder", DIFFERS, NULL},
};
#define NTABLE (sizeof TABLE / sizeof TABLE[0])

static int load(const char *path, const reach *r, int changed, dv_scenario *sc) {
  char both[128], key[160];
  const char *sets[NBASE + 2];
  size_t n = 0;
  for (; n < NBASE; n++) sets[n] = BASE[n];
  if (r->both) snprintf(both, sizeof both, "%s", r->both), sets[n++] = both;
  if (changed) snprintf(key, sizeof key, "engines.%s.%s=%s", r->engine, r->key, r->value),
      sets[n++] = key;
  dv_error err = {{0}};
  const int status = dv_engine_load_scenario(path, sets, n, sc, &err);
  CHECK(status == DV_OK, "%s.%s: %s", r->engine, r->key, err.msg);
  return status;
}

static int same_run(const traj *a, const traj *b) {
  if (a->n != b->n || a->status != b->status) return 0;
  for (long i = 0; i < a->n; i++)
    if (memcmp(a->s[i].y, b->s[i].y, sizeof a->s[i].y)) return 0;
  return 1;
}

static double max_slip(const traj *t) {
  double m = 0.0;
  for (long i = 0; i < t->n; i++) m = fmax(m, t->s[i].slip);
  return m;
}

static void check_key(const char *path, const char *falling, const reach *r) {
  if (r->expect == FALLING) path = falling;
  static dv_scenario base, changed;
  static traj a, b;
  if (load(path, r, 0, &base) || load(path, r, 1, &changed)) return;
  const dv_engine_type *e = dv_engine_find(r->engine);
  dv_test_run(e, &base, &a);
  dv_test_run(e, &changed, &b);
  CHECK(a.status >= 0, "%s.%s: the base run failed: %s", r->engine, r->key, a.msg);
  switch (r->expect) {
    case FALLING:
      CHECK(b.n < a.n, "%s.%s = %s: the fall ended at %ld samples, at the base %ld", r->engine,
            r->key, r->value, b.n, a.n);
      break;
    case DIFFERS:
    case MORE_SLIP:
      CHECK(b.status >= 0 && !same_run(&a, &b), "%s.%s = %s: the run did not change (%s)",
            r->engine, r->key, r->value, b.status < 0 ? b.msg : "same samples");
      if (r->expect == MORE_SLIP)
        CHECK(max_slip(&b) > 10.0 * max_slip(&a), "%s.%s = %s: slip %.3g, at the base %.3g",
              r->engine, r->key, r->value, max_slip(&b), max_slip(&a));
      break;
    case SAME:
      CHECK(same_run(&a, &b), "%s.%s: said inert (%s), but the run changed", r->engine, r->key,
            r->why);
      break;
    case FAILS:
      CHECK(b.status < 0, "%s.%s = %s: the run did not fail (%s)", r->engine, r->key, r->value,
            r->why);
      break;
    case VALIDITY: {
      CHECK(same_run(&a, &b), "%s.%s: the run changed (%s)", r->engine, r->key, r->why);
      const double ta = dv_reference_valid_until(&base, a.s, (size_t)a.n);
      const double tb = dv_reference_valid_until(&changed, b.s, (size_t)b.n);
      CHECK(tb < ta, "%s.%s = %s: the validity window ends at %g s, at the base %g s", r->engine,
            r->key, r->value, tb, ta);
      break;
    }
  }
}

/* every key of every engine's table has an entry */
static void check_covered(void) {
  for (const dv_engine_type *const *e = dv_engine_list(); *e; e++) {
    const dv_settings_section *sec = (*e)->settings;
    if ((*e)->outside) continue; /* an adapter is sent every key: check_adapter_faults.sh */
    for (size_t k = 0; sec && k < sec->nspecs; k++) {
      int found = 0;
      for (size_t i = 0; i < NTABLE && !found; i++)
        found = !strcmp(TABLE[i].engine, (*e)->name) && !strcmp(TABLE[i].key, sec->specs[k].key);
      CHECK(found, "engines.%s.%s: no entry in this test's table", (*e)->name, sec->specs[k].key);
    }
  }
}

int main(int argc, char **argv) {
  if (argc != 3) return fprintf(stderr, "usage: test_settings_reach CIRCLE FALLING\n"), 2;
  check_covered();
  for (size_t i = 0; i < NTABLE; i++) check_key(argv[1], argv[2], &TABLE[i]);
  return TEST_RESULT();
}
