/* reference_theta SCENARIO.ini: integrate the scenario with the exact
 * reference (engine "reduced") and print theta at the end. */
#include <diskval/diskval.h>
#include <stdio.h>

/* load, run, print the last sample's tilt */
int main(int argc, char **argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: %s SCENARIO.ini\n", argv[0]);
    return 2;
  }
  diskval_error err;
  diskval_scenario *sc;
  if (diskval_scenario_load(argv[1], NULL, 0, &sc, &err) < 0) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  diskval_trajectory *tr;
  int status = diskval_run(sc, "reduced", &tr, &err);
  if (status < 0) {
    fprintf(stderr, "%s\n", err.msg);
    diskval_scenario_free(sc);
    return 1;
  }
  diskval_sample last;
  diskval_trajectory_sample(tr, diskval_trajectory_size(tr) - 1, &last);
  printf("%s: theta(%g s) = %.9f rad%s\n", diskval_scenario_name(sc), last.t, last.state.theta,
         status == DISKVAL_EVENT ? " (ended at an event)" : "");
  diskval_trajectory_free(tr);
  diskval_scenario_free(sc);
  return 0;
}
