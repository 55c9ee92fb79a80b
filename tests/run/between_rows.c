/* between_rows OUTPUT_DT T K < STATE.csv > OUT.csv: a dense state CSV (t,theta,phi,psi,x,y,
 * as the first six columns of simulate's) rewritten with those six columns, each row
 * between the sample times (multiples of OUTPUT_DT) moved in theta by T + K |a - b|: a and
 * b the Akima and Steffen interpolants (GSL's) through the rows at the sample times. judge
 * allows a row off by twice their disagreement (run_replay.c) beyond its threshold T; with K
 * under 2 the rows lie inside that allowance, over 2 outside (check_judge_between.sh). */
#include <gsl/gsl_interp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define MAX_ROWS 200000

static double row[MAX_ROWS][6];

int main(int argc, char **argv) {
  if (argc != 4) return fprintf(stderr, "usage: between_rows OUTPUT_DT T K\n"), 2;
  const double dt = atof(argv[1]), T = atof(argv[2]), K = atof(argv[3]);
  char line[4096];
  if (!fgets(line, sizeof line, stdin)) return 2; /* the header */
  size_t n = 0, m = 0;
  static double tg[MAX_ROWS], vg[MAX_ROWS];
  static int on_grid[MAX_ROWS];
  while (n < MAX_ROWS && fgets(line, sizeof line, stdin)) {
    char *p = line;
    for (int i = 0; i < 6; i++) row[n][i] = strtod(p, &p), p += *p == ',';
    const double k = round(row[n][0] / dt);
    on_grid[n] = fabs(row[n][0] - k * dt) <= 1e-9 * fmax(1.0, fabs(row[n][0]));
    if (on_grid[n]) tg[m] = row[n][0], vg[m++] = row[n][1];
    n++;
  }
  gsl_interp *akima = gsl_interp_alloc(gsl_interp_akima, m);
  gsl_interp *steffen = gsl_interp_alloc(gsl_interp_steffen, m);
  if (!akima || !steffen || gsl_interp_init(akima, tg, vg, m) ||
      gsl_interp_init(steffen, tg, vg, m))
    return fprintf(stderr, "between_rows: cannot interpolate %zu samples\n", m), 1;
  printf("t,theta,phi,psi,x,y\n");
  for (size_t i = 0; i < n; i++) {
    double th = row[i][1];
    if (!on_grid[i] && row[i][0] > tg[0] && row[i][0] < tg[m - 1]) {
      const double a = gsl_interp_eval(akima, tg, vg, row[i][0], NULL);
      const double b = gsl_interp_eval(steffen, tg, vg, row[i][0], NULL);
      th = a + T + K * fabs(a - b); /* off the Akima interpolant, as judge measures */
    }
    printf("%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", row[i][0], th, row[i][2], row[i][3], row[i][4],
           row[i][5]);
  }
  gsl_interp_free(akima);
  gsl_interp_free(steffen);
  return 0;
}
