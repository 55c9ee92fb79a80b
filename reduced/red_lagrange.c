/* red_lagrange: Pars's Lagrange-multiplier equations on the full
 * configuration space, the multipliers eliminated by an LU solve (GSL) of
 *
 *   [ M  -a^T ] [ q'' ]   [ dT/dq - M' q' - dV/dq ]
 *   [ a   0   ] [ lam ] = [ -a' q'                ]
 *
 * with T = 1/2 m (x'^2 + y'^2) + 1/2 (m r^2 c^2 + A) th'^2 + 1/2 A s^2 ph'^2
 *        + 1/2 C (ph' c + ps')^2   and V = m g r s.                          */
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <string.h>

#include "red_formulations.h"

enum { QX, QY, QTH, QPH, QPS, NQ = 5, NK = NQ + 2 };

void red_lagrange_from_state(const red_disk *dk, const double y[RED_NSTATE],
                             double q[RED_LAGRANGE_DIM]) {
  double f[RED_NSTATE];
  red_rhs(dk, y, f);
  const double v[NQ] = {f[RED_X], f[RED_Y], y[RED_VTH], y[RED_VPH], y[RED_VPS]};
  const double p[NQ] = {y[RED_X], y[RED_Y], y[RED_TH], y[RED_PH], y[RED_PS]};
  memcpy(q, p, sizeof p);
  memcpy(q + NQ, v, sizeof v);
}

void red_state_from_lagrange(const double q[RED_LAGRANGE_DIM], double y[RED_NSTATE]) {
  y[RED_TH] = q[QTH];
  y[RED_VTH] = q[NQ + QTH];
  y[RED_VPH] = q[NQ + QPH];
  y[RED_VPS] = q[NQ + QPS];
  y[RED_PH] = q[QPH];
  y[RED_PS] = q[QPS];
  y[RED_X] = q[QX];
  y[RED_Y] = q[QY];
}

void red_lagrange_constraints(const red_disk *dk, const double q[RED_LAGRANGE_DIM], double res[2]) {
  const double *v = q + NQ, sp = sin(q[QPH]), cp = cos(q[QPH]);
  res[0] = cp * v[QX] + sp * v[QY] - dk->r * sin(q[QTH]) * v[QTH];
  res[1] = -sp * v[QX] + cp * v[QY] + dk->r * cos(q[QTH]) * v[QPH] + dk->r * v[QPS];
}

int red_lagrange_rhs(double t, const double *q, double *f, void *params) {
  const red_disk *dk = params;
  const double *v = q + NQ, s = sin(q[QTH]), c = cos(q[QTH]), sp = sin(q[QPH]), cp = cos(q[QPH]);
  const double m = dk->m, r = dk->r, A = dk->A, C = dk->C, mr2 = m * r * r;
  const double th_d = v[QTH], ph_d = v[QPH], ps_d = v[QPS], w3 = ph_d * c + ps_d;
  if (!(s > 0.0)) return -1;
  double K[NK * NK] = {0}, rhs[NK] = {0}, sol[NK];
  /* mass matrix */
  K[QX * NK + QX] = m;
  K[QY * NK + QY] = m;
  K[QTH * NK + QTH] = mr2 * c * c + A;
  K[QPH * NK + QPH] = A * s * s + C * c * c;
  K[QPH * NK + QPS] = K[QPS * NK + QPH] = C * c;
  K[QPS * NK + QPS] = C;
  /* constraint rows a and columns -a^T */
  const double a[2][NQ] = {{cp, sp, -r * s, 0.0, 0.0}, {-sp, cp, 0.0, r * c, r}};
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < NQ; j++) {
      K[(NQ + i) * NK + j] = a[i][j];
      K[j * NK + NQ + i] = -a[i][j];
    }
  /* generalised forces: dT/dq - M' q' - dV/dq */
  rhs[QTH] =
      mr2 * c * s * th_d * th_d + A * s * c * ph_d * ph_d - C * w3 * ph_d * s - m * dk->g * r * c;
  rhs[QPH] = -2.0 * (A - C) * s * c * th_d * ph_d + C * s * th_d * ps_d;
  rhs[QPS] = C * s * th_d * ph_d;
  /* -a' q' */
  rhs[NQ] = -(-sp * ph_d * v[QX] + cp * ph_d * v[QY] - r * c * th_d * th_d);
  rhs[NQ + 1] = -(-cp * ph_d * v[QX] - sp * ph_d * v[QY] - r * s * th_d * ph_d);

  gsl_matrix_view Km = gsl_matrix_view_array(K, NK, NK);
  gsl_vector_view b = gsl_vector_view_array(rhs, NK), x = gsl_vector_view_array(sol, NK);
  gsl_permutation perm;
  size_t pdata[NK];
  perm.size = NK;
  perm.data = pdata;
  int sign;
  if (gsl_linalg_LU_decomp(&Km.matrix, &perm, &sign) ||
      gsl_linalg_LU_solve(&Km.matrix, &perm, &b.vector, &x.vector))
    return -1;
  memcpy(f, v, NQ * sizeof(double));
  memcpy(f + NQ, sol, NQ * sizeof(double));
  return isfinite(sol[QTH] + sol[QPH] + sol[QPS]) ? 0 : -1;
}
