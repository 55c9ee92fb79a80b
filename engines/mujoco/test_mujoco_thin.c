/* test_mujoco_thin: MuJoCo's thin-disk collider (engine_mujoco_thin.c).
 *
 * 1. The collider against the closed form P = G + r d (DESIGN section 1) over
 *    a grid of poses and heights: contact point, depth and normal to 1e-12 m,
 *    one contact within the margin, none above it; the same through
 *    mj_collision; an unmarked cylinder still gets MuJoCo's own contacts;
 *    install and restore leave the table as it was.
 * 2. A disk leaning less than atan(h / r) of a cylinder stand-in, spinning
 *    below the critical rate, falls in MuJoCo (thin, defaults) as the
 *    reference does: the same lowest theta within 0.01 rad.
 * 3. The error against the reference on a steady circle and on upright
 *    rolling above the critical spin falls with the step (contact time
 *    constant 2 dt) at about the order measured, down to 1e-4 rad.
 */
#include <gsl/gsl_errno.h>
#include <math.h>
#include <mujoco/mujoco.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dv_engine.h"
#include "dv_pose.h"
#include "dv_reference.h"
#include "dv_test.h"
#include "dv_test_traj.h"
#include "engine_mujoco_thin.h"
#include "red_steady.h"

#define RADIUS 0.1 /* m, the collider's disk */

/* a plane and a disk of radius RADIUS (thin when mark is DV_MUJOCO_THIN_MARK) on a free joint */
static mjModel *load(double mark) {
  char xml[1024], err[300] = "";
  const int len = snprintf(xml, sizeof xml,
                           "<mujoco>\n"
                           "  <size nuser_geom=\"1\"/>\n"
                           "  <worldbody>\n"
                           "    <geom type=\"plane\" size=\"0 0 1\"/>\n"
                           "    <body>\n"
                           "      <freejoint/>\n"
                           "      <inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"1 1 2\"/>\n"
                           "      <geom type=\"cylinder\" size=\"%.17g %.17g\" user=\"%g\"/>\n"
                           "    </body>\n"
                           "  </worldbody>\n"
                           "</mujoco>\n",
                           RADIUS, dv_mujoco_thin_half_length(RADIUS), mark);
  mjVFS *vfs = calloc(1, sizeof *vfs);
  mjModel *m = NULL;
  if (!vfs) return NULL;
  mj_defaultVFS(vfs);
  if (!mj_makeEmptyFileVFS(vfs, "t.xml", len)) {
    memcpy(vfs->filedata[mj_findFileVFS(vfs, "t.xml")], xml, (size_t)len);
    m = mj_loadXML("t.xml", vfs, err, sizeof err);
  }
  CHECK(m, "MuJoCo cannot load the test model: %s", err);
  mj_deleteVFS(vfs);
  free(vfs);
  return m;
}

/* the disk in state y (thin: on the ground), raised by dz, its geoms placed */
static void place(const mjModel *m, mjData *d, const double y[RED_NSTATE], double dz) {
  const dv_geometry thin = {DV_SHAPE_CYLINDER, RADIUS, 0.0};
  dv_pose p;
  dv_pose_from_state(&thin, y, &p);
  mju_copy3(d->qpos, p.pos);
  d->qpos[2] += dz;
  mju_mat2Quat(d->qpos + 3, p.R);
  mj_kinematics(m, d);
}

/* P = G + r d on the ground, from the state */
static void closed_form(const double y[RED_NSTATE], double P[3]) {
  const double th = y[RED_TH], ph = y[RED_PH];
  P[0] = y[RED_X] + RADIUS * cos(th) * cos(ph);
  P[1] = y[RED_Y] + RADIUS * cos(th) * sin(ph);
  P[2] = 0.0;
}

/* one contact against the closed form at height dz: position (midpoint), depth, normal */
static void check_contact(const mjContact *c, const double y[RED_NSTATE], double dz,
                          const char *what) {
  double P[3];
  closed_form(y, P);
  const double want[3] = {P[0], P[1], 0.5 * dz}; /* half-way from the rim point (dz) down */
  char label[160];
  snprintf(label, sizeof label, "%s theta %.3f phi %.2f psi %.2f dz %g", what, y[RED_TH], y[RED_PH],
           y[RED_PS], dz);
  CHECK_NEAR(c->dist, dz, 1e-12, label);
  for (int i = 0; i < 3; i++) CHECK_NEAR(c->pos[i], want[i], 1e-12, label);
  CHECK(c->frame[0] == 0.0 && c->frame[1] == 0.0 && c->frame[2] == 1.0, "%s: normal %g %g %g",
        label, c->frame[0], c->frame[1], c->frame[2]);
}

static void check_collider(void) {
  const mjfCollision original = mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER];
  mjModel *m = load(DV_MUJOCO_THIN_MARK), *plain = load(0.0);
  if (!m || !plain) return;
  mjData *d = mj_makeData(m);
  CHECK(m->geom_type[0] == mjGEOM_PLANE && m->geom_type[1] == mjGEOM_CYLINDER, "geom types");
  CHECK(fabs(m->geom_rbound[1] - RADIUS) < 1e-9 * RADIUS, "bounding radius %g, want %g",
        m->geom_rbound[1], RADIUS);
  dv_mujoco_thin_install();
  dv_mujoco_thin_install(); /* nested: the second restore puts the old entry back */
  CHECK(mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER] == dv_mujoco_thin_collide, "installed");
  const double phis[] = {-2.5, 0.0, 0.7, 2.0}, psis[] = {0.0, 1.3, -2.9};
  const double dzs[] = {2e-3, 1e-6, 1e-9, 0.0, -1e-9, -1e-5, -3e-3};
  const double margin = 5e-7;
  long n = 0;
  for (int k = 0; k <= 20; k++) {
    const double th = 0.05 + k * (M_PI - 0.1) / 20;
    for (size_t a = 0; a < 4; a++)
      for (size_t b = 0; b < 3; b++)
        for (size_t c = 0; c < sizeof dzs / sizeof dzs[0]; c++) {
          const double y[RED_NSTATE] = {th, 0, 0, 0, phis[a], psis[b], 0.3 * a - 0.2, -0.1 * b};
          mjContact con[mjMAXCONPAIR];
          place(m, d, y, dzs[c]);
          const int got = mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER](m, d, con, 0, 1, margin);
          CHECK(got == (dzs[c] <= margin), "theta %g dz %g: %d contacts", th, dzs[c], got);
          if (got == 1) check_contact(con, y, dzs[c], "collider"), n++;
          /* the pipeline: geom order, filters, one contact (margin 0: none above the plane;
           * at dz = 0 rounding decides) */
          mj_collision(m, d);
          CHECK(dzs[c] == 0.0 ? d->ncon <= 1 : d->ncon == (dzs[c] < 0.0),
                "theta %g dz %g: %d contacts in mj_collision", th, dzs[c], d->ncon);
          if (d->ncon == 1) {
            CHECK(d->contact[0].geom1 == 0 && d->contact[0].geom2 == 1, "geom order");
            check_contact(d->contact, y, dzs[c], "mj_collision");
          }
        }
  }
  printf("collider: %ld contacts against the closed form\n", n);
  /* lying flat: the rim point on the geom's x axis, at the centre's height */
  {
    const double y[RED_NSTATE] = {0.0, 0, 0, 0, 0.4, 0.9, 0.1, 0.2};
    mjContact con[mjMAXCONPAIR];
    place(m, d, y, -1e-4);
    const int got = mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER](m, d, con, 0, 1, 0.0);
    const double *x = d->geom_xmat + 9;
    const double rim[3] = {d->geom_xpos[3] + RADIUS * x[0], d->geom_xpos[4] + RADIUS * x[3],
                           d->geom_xpos[5] + RADIUS * x[6]};
    CHECK(got == 1, "flat: %d contacts", got);
    CHECK_NEAR(con[0].dist, rim[2], 1e-15, "flat: depth");
    CHECK_NEAR(con[0].pos[0], rim[0], 1e-15, "flat: x");
    CHECK_NEAR(con[0].pos[1], rim[1], 1e-15, "flat: y");
  }
  /* an unmarked cylinder gets MuJoCo's own collider: several contacts at its rim */
  {
    mjData *pd = mj_makeData(plain);
    const double y[RED_NSTATE] = {1.0, 0, 0, 0, 0.3, 0, 0, 0};
    place(plain, pd, y, -1e-4);
    mjContact mine[mjMAXCONPAIR], theirs[mjMAXCONPAIR];
    const int got = dv_mujoco_thin_collide(plain, pd, mine, 0, 1, 0.0);
    const int want = original(plain, pd, theirs, 0, 1, 0.0);
    CHECK(got == want && want > 1, "unmarked cylinder: %d contacts, MuJoCo's %d", got, want);
    for (int i = 0; i < got && i < want; i++) {
      CHECK(mine[i].dist == theirs[i].dist, "unmarked cylinder: contact %d depth", i);
      CHECK(!memcmp(mine[i].pos, theirs[i].pos, sizeof mine[i].pos), "contact %d position", i);
      CHECK(!memcmp(mine[i].frame, theirs[i].frame, 3 * sizeof(double)), "contact %d normal", i);
    }
    mj_deleteData(pd);
  }
  dv_mujoco_thin_restore();
  CHECK(mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER] == dv_mujoco_thin_collide,
        "restored while still installed");
  dv_mujoco_thin_restore();
  dv_mujoco_thin_restore(); /* one too many: no effect */
  CHECK(mjCOLLISIONFUNC[mjGEOM_PLANE][mjGEOM_CYLINDER] == original, "not restored");
  mj_deleteData(d);
  mj_deleteModel(m);
  mj_deleteModel(plain);
}

/* run e on sc; a failed run is a failed check */
static int run(const dv_engine_type *e, const dv_scenario *sc, traj *tr) {
  dv_test_run(e, sc, tr);
  CHECK(tr->status == DV_OK, "%s: %s (%s)", e->name, tr->msg, tr->stats.detail);
  return tr->status;
}

/* a uniform disk of radius r (m, 1 kg) from y, every engine setting at its default */
static dv_scenario scene(double r, const double y[RED_NSTATE], double duration, double output_dt) {
  dv_scenario sc;
  dv_engine_init_scenario(&sc);
  sc.duration = duration;
  sc.output_dt = output_dt;
  sc.disk = red_disk_uniform(r, 1.0, 9.81);
  memcpy(sc.initial, y, sizeof sc.initial);
  return sc;
}

/* lowest theta over a run, and when */
static double lowest(const traj *tr, double *when) {
  double th = INFINITY;
  for (long i = 0; i < tr->n; i++)
    if (tr->s[i].y[RED_TH] < th) th = tr->s[i].y[RED_TH], *when = tr->s[i].t;
  return th;
}

/* A uniform disk (r 0.06 m) leaning 0.005 rad, spinning at 0.3 of the
 * critical rate: the reference falls to theta 0.2281 at t = 0.590 s and rises
 * again. The default cylinder stand-in (h 5e-4 m, atan(h / r) = 8.3e-3 rad)
 * rests on its rim corners and rocks about upright instead. Measured (this
 * test's printout): thin 0.22811 at 0.590 s against the reference's 0.22812. */
static void check_fall(void) {
  static traj ref, thin, cyl;
  const red_disk disk = red_disk_uniform(0.06, 1.0, 9.81);
  const double tilt = 0.005, spin = 0.3 * red_upright_critical_spin(&disk);
  const double y[RED_NSTATE] = {M_PI / 2 - tilt, 0, 0, spin, 0, 0, 0, 0};
  dv_scenario sc = scene(0.06, y, 1.0, 0.001);
  const double h = dv_scenario_get(&sc, "mujoco", "half_thickness");
  CHECK(tilt < atan(h / 0.06), "tilt %g is not below the stand-in's atan(h/r) %g", tilt,
        atan(h / 0.06));
  run(&dv_engine_reduced, &sc, &ref);
  run(&dv_engine_mujoco, &sc, &thin);
  dv_scenario_set(&sc, "mujoco", "geom", "cylinder", NULL);
  run(&dv_engine_mujoco, &sc, &cyl);
  double t_ref = 0, t_thin = 0, t_cyl = 0;
  const double th_ref = lowest(&ref, &t_ref), th_thin = lowest(&thin, &t_thin);
  const double th_cyl = lowest(&cyl, &t_cyl);
  printf(
      "fall from %g rad off upright at %.3f rad/s: lowest theta reference %.5f (t %.3f s), "
      "thin %.5f (t %.3f s), cylinder %.5f\n",
      tilt, spin, th_ref, t_ref, th_thin, t_thin, th_cyl);
  CHECK(th_ref < 0.5 && ref.n == thin.n, "the reference does not fall (%g), %ld/%ld samples",
        th_ref, ref.n, thin.n);
  CHECK(dv_reference_valid_until(&sc, ref.s, (size_t)ref.n) >= ref.s[ref.n - 1].t,
        "the fall leaves the reference's validity window");
  CHECK(fabs(th_thin - th_ref) < 1e-3 && fabs(t_thin - t_ref) < 0.01,
        "lowest theta %g at %g s, the reference's %g at %g s", th_thin, t_thin, th_ref, t_ref);
  CHECK(th_cyl >= M_PI / 2 - atan(h / 0.06), "the cylinder stand-in fell to %g", th_cyl);
}

/* largest |theta - reference| over sc's samples with MuJoCo at step dt and contact time
 * constant tc */
static double theta_error(dv_scenario sc, double dt, double tc) {
  static traj ref, mj;
  dv_scenario_set_number(&sc, "mujoco", "timestep", dt, NULL);
  dv_scenario_set_number(&sc, "mujoco", "solref_timeconst", tc, NULL);
  run(&dv_engine_reduced, &sc, &ref);
  run(&dv_engine_mujoco, &sc, &mj);
  CHECK(ref.n == mj.n, "%ld vs %ld samples", mj.n, ref.n);
  double err = 0.0;
  for (long i = 0; i < ref.n && i < mj.n; i++)
    err = fmax(err, fabs(mj.s[i].y[RED_TH] - ref.s[i].y[RED_TH]));
  return err;
}

/* Over 1 s (r 0.1 m), the thin disk's theta error with the contact time
 * constant at 2 dt (MuJoCo's floor), measured with this test's printout:
 *   dt      1e-3     5e-4     2.5e-4   1.25e-4  6.25e-5
 *   circle  4.15e-4  2.01e-4  9.92e-5  4.94e-5  2.46e-5
 *   upright 2.40e-7  9.54e-8  4.43e-8  2.14e-8  1.06e-8
 * First order, with RK4 (the default) as with Euler and implicit (25x larger
 * on the circle): the error is the soft contact's, proportional to the time
 * constant (circle at dt 1.5625e-5: 1.59e-4, 7.92e-5, 3.94e-5 at time
 * constants 8e-4, 4e-4, 2e-4), not RK4's fourth-order step error. Checked:
 * each halving of dt (and the time constant) divides the error by 1.7 to 2.6;
 * halving the time constant alone at dt 6.25e-5 halves the circle's error;
 * the circle is within 1e-4 rad at dt 1.25e-4. */
static void check_convergence(void) {
  const double circle[RED_NSTATE] = {1.0, 0, 3.038043841609511, -15.190219208047555, 0, 0, 0, 0};
  const double upright[RED_NSTATE] = {M_PI / 2, 0.01, 0, 1.5 * 5.718391382198319, 0, 0, 0, 0};
  const struct {
    const char *name;
    const double *y;
    double at_finest; /* rad */
  } cases[] = {{"circle", circle, 1e-4}, {"upright", upright, 1e-6}};
  const double dts[] = {5e-4, 2.5e-4, 1.25e-4};
  for (size_t c = 0; c < 2; c++) {
    const dv_scenario sc = scene(0.1, cases[c].y, 1.0, 0.01);
    double err[3];
    for (int k = 0; k < 3; k++) err[k] = theta_error(sc, dts[k], 2 * dts[k]);
    printf("%-7s theta error, dt %g %g %g (time constant 2 dt): %.3e %.3e %.3e\n", cases[c].name,
           dts[0], dts[1], dts[2], err[0], err[1], err[2]);
    for (int k = 1; k < 3; k++)
      CHECK(err[k - 1] / err[k] > 1.7 && err[k - 1] / err[k] < 2.6,
            "%s: error %g at dt %g, %g at dt %g: not first order", cases[c].name, err[k - 1],
            dts[k - 1], err[k], dts[k]);
    CHECK(err[2] < cases[c].at_finest, "%s: error %g at dt %g (limit %g)", cases[c].name, err[2],
          dts[2], cases[c].at_finest);
  }
  /* the contact's share: the time constant alone, at a fixed step */
  const dv_scenario sc = scene(0.1, circle, 1.0, 0.01);
  const double stiff = theta_error(sc, 6.25e-5, 2.5e-4), soft = theta_error(sc, 6.25e-5, 5e-4);
  printf("circle  theta error at dt 6.25e-5, time constant 5e-4 -> 2.5e-4: %.3e -> %.3e\n", soft,
         stiff);
  CHECK(soft / stiff > 1.7 && soft / stiff < 2.6, "time constant: %g -> %g", soft, stiff);
}

int main(void) {
  gsl_set_error_handler_off();
  check_collider();
  check_fall();
  check_convergence();
  return TEST_RESULT();
}
