/* mujoco_verdict SCENARIO.ini [section.key=value ...]: run MuJoCo on the
 * scenario and print its verdict and metrics against the reference; exit 0
 * when it agrees, 1 when it does not, 2 on an error. */
#include <diskval/diskval.h>
#include <stdio.h>

/* load with overrides, compare, print */
int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: %s SCENARIO.ini [section.key=value ...]\n", argv[0]);
    return 2;
  }
  diskval_error err;
  diskval_scenario *sc;
  if (diskval_scenario_load(argv[1], (const char *const *)argv + 2, (size_t)argc - 2, &sc, &err) <
      0) {
    fprintf(stderr, "%s\n", err.msg);
    return 2;
  }
  diskval_comparison c;
  if (diskval_compare(sc, "mujoco", &c, &err) < 0) {
    fprintf(stderr, "%s\n", err.msg);
    diskval_scenario_free(sc);
    return 2;
  }
  printf("%s: mujoco: %s (%s)\n", diskval_scenario_name(sc), c.verdict, c.decided);
  for (size_t i = 0; i < c.metrics.n; i++)
    printf("  %-18s %.3g (limit %.3g)\n", c.metrics.name[i], c.metrics.value[i], c.limit[i]);
  diskval_scenario_free(sc);
  return c.pass ? 0 : 1;
}
