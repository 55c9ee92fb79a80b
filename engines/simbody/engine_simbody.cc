/* engine_simbody: the rolling disk in Simbody 3.7 as exact constraints, with
 * no contact geometry. The only Simbody code of diskval: the rest sees the
 * extern "C" table dv_engine_simbody (dv_engine.h) and nothing of Simbody.
 *
 * The model (DESIGN section 1's kinematics as a joint chain):
 *   ground -Planar-> H -Pin-> T -Pin-> D
 * H: a massless frame at the contact point P = (x_P, y_P, 0), turned by the
 *    heading phi about z (Planar's q = (phi, x_P, y_P), its u = q', the
 *    translation along the ground's axes);
 * T: a massless frame at P tilted by theta about H's y axis (= -t), so T is
 *    Rz(phi) Ry(theta): its x axis is d, its z axis the disk's axis n;
 * D: the disk (mass m, principal inertia A, A, C about its centre), its
 *    centre G = P - r d, spun by psi - pi/2 about n: R = Rz(phi) Ry(theta)
 *    Rz(psi - pi/2), DESIGN's body frame.
 * So the rim point P lies on the ground by construction (no height, no
 * penetration: the contact is bilateral). A cylinder of half-thickness h
 * (geom cylinder, from [disk] thickness as the contact engines' shape:
 * engine_shape.h) stands on its lower rim corner, P = G + r d - h s n with s
 * = sign(n.z): G = P - r d + h s n is as fixed in T, so only D's offset in T
 * changes, and the corner moves over the body as the thin rim point does (at
 * r psi' along t): the no-slip couplers below are the same. Where theta
 * crosses upright the corner switches sides (an impact the chain cannot
 * follow): the run ends there, an event that says so, as the matched
 * reference ends there; a cylinder started exactly upright (standing on
 * the line across its rim, which no corner holds) ends at once. No slip is
 * two nonholonomic
 * Constraint::SpeedCouplers: P moves along the ground at r psi' t (DESIGN
 * section 1), so
 *   x_P' - r psi' sin(phi) = 0,   y_P' + r psi' cos(phi) = 0,
 * and then the disk's material point at P is at rest (v_G = -omega x (r d)):
 * test_engine_simbody measures its speed, 1.4e-10 m/s at the default
 * constraint_tolerance and 4.8e-16 at 1e-14. Constraint::NoSlip1D does not
 * fit: two of them (case body H, its point P, directions H's x and y,
 * between the ground and the disk) hold the velocity but not its rate, as if
 * the contact point were fixed in the disk, while it moves over the rim: on
 * the steady circle theta went 1 -> 0.50 rad in 1 s at rk3 1e-3 s and the
 * energy changed by 0.078 J (the couplers: theta 1 to rounding, 8e-14 J).
 * H and T are Body::Massless: Simbody allows a massless body that is not
 * terminal where the articulated inertia its children give it is
 * nonsingular (here the disk's, through two pins: singular only lying flat,
 * theta = 0 or pi, outside the lying-down limit), so no mass is added and
 * nothing biases the dynamics.
 *
 * What it can and cannot do: the disk can neither slip nor lift off (no
 * contact is simulated), so it is the reduced equations' own model solved by
 * a general multibody integrator: what the comparison measures is Simbody's
 * integration and constraint projection, never a contact model. It ends
 * where the references end: lying down (theta_limit, an event), and at the
 * validity window, where the contact force the constraints need, F = m (a_G
 * + g ez) (the massless frames carry it to the disk whole), has F.z <= 0 or
 * |F_horizontal| > mu F.z (mu: [engines.simbody] friction, by default the
 * compared window's: [engines.matched] friction where given, else [disk] friction); F is every
 * sample's force[3].
 *
 * The integrators: Simbody's explicit Runge-Kutta at a fixed step (rk3:
 * RungeKutta3, third order; rkmerson: RungeKuttaMerson, fourth, as
 * measured in test_engine_simbody), or
 * error-controlled at [engines.simbody] accuracy (the integrator's own steps,
 * landing on every sample), each projecting u back onto the constraints
 * after a step whose constraint error exceeds constraint_tolerance (the only
 * drift: the chain has no holonomic constraint). Events are found on the
 * step grid (the first step past the limit), as Bullet's.
 *
 * Faults end the run, never the process: a non-finite state and a runaway
 * energy are diverged; a Simbody exception (an integrator or projection
 * failure, out of memory) is caught at each entry point and ends the run as
 * an error.
 */
#include <Simbody.h>

#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>

extern "C" {
#include "dv_engine.h"
#include "dv_pose.h"
#include "dv_reference.h"
#include "engine_module.h"
#include "simbody_settings.h"
#include "engine_scene.h"
#include "engine_shape.h"
}

/* |cos theta| below which a cylinder stands on its rim's line (the matched
 * reference's upright line is 1e-9: reduced/red_rolling.c) */
#define UPRIGHT_COS 1e-9

using namespace SimTK;

namespace {


/* one no-slip equation, f(u) = u_P - r psi' s(phi) = 0 with s = sin (x) or
 * -cos (y); arguments (u_P, psi', phi); derivatives up to second order, as
 * Constraint::SpeedCoupler needs */
class NoSlip : public Function {
 public:
  NoSlip(Real r, int axis) : r_(r), axis_(axis) {}
  Real calcValue(const Vector &x) const override {
    return x[0] - r_ * x[1] * s(x[2]);
  }
  Real calcDerivative(const Array_<int> &d, const Vector &x) const override {
    if (d.size() == 1) {
      if (d[0] == 0) return 1.0;
      if (d[0] == 1) return -r_ * s(x[2]);
      return -r_ * x[1] * ds(x[2]);
    }
    if (d.size() == 2) {
      const int a = d[0] < d[1] ? d[0] : d[1], b = d[0] < d[1] ? d[1] : d[0];
      if (a == 1 && b == 2) return -r_ * ds(x[2]);
      if (a == 2 && b == 2) return r_ * x[1] * s(x[2]); /* s'' = -s */
    }
    return 0.0;
  }
  int getArgumentSize() const override {
    return 3;
  }
  int getMaxDerivativeOrder() const override {
    return 2;
  }

 private:
  Real s(Real phi) const {
    return axis_ == 0 ? std::sin(phi) : -std::cos(phi);
  }
  Real ds(Real phi) const {
    return axis_ == 0 ? std::cos(phi) : std::sin(phi);
  }
  Real r_;
  int axis_;
};

struct simbody_engine {
  simbody_settings set;
  red_disk disk;
  dv_geometry geom; /* the thin disk, or the cylinder of half-thickness h */
  int side;         /* the rim corner the chain holds: sign(n.z) at the start */
  int on_line;      /* a cylinder started upright: on its rim's line, no corner */
  MultibodySystem *sys;
  SimbodyMatterSubsystem *matter;
  GeneralForceSubsystem *forces;
  MobilizedBody::Planar *H;
  MobilizedBody::Pin *T;
  MobilizedBody::Pin *D;
  Integrator *integ;
  State *initial; /* the topology's default state */
  long steps0;    /* integrator steps before this run (not reset by initialize) */
  double t_event;
  double prev_y[RED_NSTATE];
  double e0, e_max;
  double theta_limit;
  int status;
  dv_engine_stats st;
};

/* "Simbody 3.7" */
const char *simbody_version(void) {
  static char text[64];
  if (!text[0]) {
    int major = 0, minor = 0, build = 0;
    SimTK_version_simbody(&major, &minor, &build);
    if (build)
      snprintf(text, sizeof text, "Simbody %d.%d.%d", major, minor, build);
    else
      snprintf(text, sizeof text, "Simbody %d.%d", major, minor);
  }
  return text;
}

__attribute__((format(printf, 4, 5))) int failed(simbody_engine *e, dv_failure failure,
                                                 dv_error *err, const char *fmt, ...) {
  const dv_outcome outcome = dv_failure_outcome(failure);
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(e->st.detail, sizeof e->st.detail, fmt, ap);
  va_end(ap);
  e->st.outcome = outcome;
  e->st.failure = failure;
  e->status = outcome == DV_OUTCOME_ERROR ? DV_ESYSTEM : DV_ENUMERIC;
  return dv_fail(err, e->status, "%s: %s", dv_outcome_name(outcome), e->st.detail);
}

void read_pose(const simbody_engine *e, const State &s, dv_pose *p) {
  const Transform &X = e->D->getBodyTransform(s);
  const Vec3 &w = e->D->getBodyAngularVelocity(s);
  const Vec3 &v = e->D->getBodyOriginVelocity(s);
  for (int i = 0; i < 3; i++) {
    p->pos[i] = X.p()[i];
    p->vel[i] = v[i];
    p->omega[i] = w[i];
    for (int j = 0; j < 3; j++) p->R[3 * i + j] = X.R()[i][j];
  }
}

/* the canonical state from the coordinates (continuous: no unwrapping) */
void read_state(const simbody_engine *e, const State &s, double y[RED_NSTATE]) {
  const Vec3 qh = e->H->getQ(s), uh = e->H->getU(s);
  const Vec3 &G = e->D->getBodyOriginLocation(s);
  y[RED_TH] = e->T->getQ(s);
  y[RED_VTH] = e->T->getU(s);
  y[RED_VPH] = uh[0];
  y[RED_VPS] = e->D->getU(s);
  y[RED_PH] = qh[0];
  y[RED_PS] = e->D->getQ(s) + 0.5 * M_PI;
  y[RED_X] = G[0];
  y[RED_Y] = G[1];
}

/* the contact force the constraints apply, m (a_G + g ez), N */
void contact_force(const simbody_engine *e, const State &s, double F[3]) {
  e->sys->realize(s, Stage::Acceleration);
  const Vec3 &a = e->D->getBodyOriginAcceleration(s);
  for (int i = 0; i < 3; i++) F[i] = e->disk.m * a[i];
  F[2] += e->disk.m * e->disk.g;
}

void destroy(simbody_engine *e) {
  delete e->integ;
  delete e->initial;
  delete e->H; /* handles: the system owns the bodies and constraints */
  delete e->T;
  delete e->D;
  delete e->forces;
  delete e->matter;
  delete e->sys;
  e->integ = nullptr;
  e->initial = nullptr;
  e->H = nullptr;
  e->T = nullptr;
  e->D = nullptr;
  e->forces = nullptr;
  e->matter = nullptr;
  e->sys = nullptr;
}

void simbody_free(void *p) {
  simbody_engine *e = static_cast<simbody_engine *>(p);
  if (!e) return;
  try {
    destroy(e);
  } catch (...) {
  }
  delete e;
}

void build(simbody_engine *e) {
  const double r = e->disk.r;
  e->sys = new MultibodySystem();
  e->matter = new SimbodyMatterSubsystem(*e->sys);
  e->forces = new GeneralForceSubsystem(*e->sys);
  Force::Gravity(*e->forces, *e->matter, Vec3(0.0, 0.0, -e->disk.g));
  e->H = new MobilizedBody::Planar(e->matter->Ground(), Transform(), Body::Massless(), Transform());
  /* the pin's z axis along H's y: F and M frames turned by -pi/2 about x */
  const Rotation z_to_y(-0.5 * M_PI, XAxis);
  e->T = new MobilizedBody::Pin(*e->H, Transform(z_to_y), Body::Massless(), Transform(z_to_y));
  const MassProperties mp(e->disk.m, Vec3(0.0), Inertia(e->disk.A, e->disk.A, e->disk.C));
  /* G = P - r d + h s n: the thin disk's rim point at h = 0 */
  e->D = new MobilizedBody::Pin(*e->T, Transform(Vec3(-r, 0.0, e->side * e->geom.half_thickness)),
                                Body::Rigid(mp), Transform());
  for (int axis = 0; axis < 2; axis++) {
    Array_<MobilizedBodyIndex> ub(2), qb(1);
    Array_<MobilizerUIndex> ui(2);
    Array_<MobilizerQIndex> qi(1);
    ub[0] = e->H->getMobilizedBodyIndex();
    ui[0] = MobilizerUIndex(1 + axis); /* x_P' or y_P' */
    ub[1] = e->D->getMobilizedBodyIndex();
    ui[1] = MobilizerUIndex(0); /* psi' */
    qb[0] = e->H->getMobilizedBodyIndex();
    qi[0] = MobilizerQIndex(0); /* phi */
    Constraint::SpeedCoupler(*e->matter, new NoSlip(r, axis), ub, ui, qb, qi);
  }
  e->initial = new State(e->sys->realizeTopology());
  if (e->set.integrator == INTEG_MERSON)
    e->integ = new RungeKuttaMersonIntegrator(*e->sys);
  else
    e->integ = new RungeKutta3Integrator(*e->sys);
  if (e->set.accuracy > 0.0) { /* its own steps, landing on every sample */
    e->integ->setAccuracy(e->set.accuracy);
  } else {
    e->integ->setFixedStepSize(e->set.timestep);
  }
  e->integ->setConstraintTolerance(e->set.tolerance);
  e->integ->setReturnEveryInternalStep(true);
  e->integ->setAllowInterpolation(false);
}

void *simbody_alloc(const dv_scenario *sc, dv_error *err) {
  if (!(sc->disk.A > 0.0 && sc->disk.C > 0.0))
    return dv_fail(err, DV_EINPUT, "Simbody needs a positive definite inertia (A = %g, C = %g)",
                   sc->disk.A, sc->disk.C),
           nullptr;
  simbody_engine *e = new (std::nothrow) simbody_engine();
  if (!e) return dv_fail(err, DV_ESYSTEM, "out of memory: the Simbody engine's state"), nullptr;
  e->set = *static_cast<const simbody_settings *>(dv_scenario_settings(sc, "simbody"));
  /* a scenario built in code leaves the step to the scene, the friction to the disk's */
  dv_engine_derive_step(sc, &dv_simbody_models[e->set.integrator], &e->set.timestep, NULL, NULL, 0, NULL);
  dv_reference_derive_friction(sc, "simbody", &e->set.friction, NULL, 0, NULL);
  dv_engine_derive_shape(sc, &dv_simbody_shape, &e->set.geom, &e->set.half_thickness, NULL, 0, NULL);
  e->disk = sc->disk;
  e->geom = dv_geometry{DV_SHAPE_CYLINDER, sc->disk.r,
                        e->set.geom == GEOM_CYLINDER ? e->set.half_thickness : 0.0};
  e->side = 1;
  e->theta_limit = dv_reference_settings(sc)->theta_limit;
  try {
    build(e);
  } catch (const std::exception &ex) {
    dv_fail(err, DV_ESYSTEM, "Simbody: %s", ex.what());
    simbody_free(e);
    return nullptr;
  }
  return e;
}

int reset(simbody_engine *e, const double y[RED_NSTATE], dv_error *err) {
  const double r = e->disk.r, h = e->geom.half_thickness, th = y[RED_TH], ph = y[RED_PH],
               vps = y[RED_VPS];
  const int side = std::cos(th) < 0.0 ? -1 : 1;
  if (side != e->side) { /* the other corner: D's offset in T is fixed at build */
    destroy(e);
    e->side = side;
    build(e);
  }
  /* P - G along the heading: r cos(theta) - h s sin(theta) */
  const double reach = r * std::cos(th) - h * side * std::sin(th);
  State s = *e->initial;
  e->H->setQ(s, Vec3(ph, y[RED_X] + reach * std::cos(ph), y[RED_Y] + reach * std::sin(ph)));
  e->T->setQ(s, th);
  e->D->setQ(s, y[RED_PS] - 0.5 * M_PI);
  e->H->setU(s, Vec3(y[RED_VPH], r * vps * std::sin(ph), -r * vps * std::cos(ph)));
  e->T->setU(s, y[RED_VTH]);
  e->D->setU(s, vps);
  e->integ->initialize(s); /* projects: the state above meets the constraints already */
  e->steps0 = e->integ->getNumStepsTaken();
  const State &now = e->integ->getState();
  e->sys->realize(now, Stage::Acceleration);
  dv_pose pose;
  read_pose(e, now, &pose);
  e->e0 = dv_pose_energy(&e->disk, &pose);
  e->e_max = e->e0 + 0.5 * std::fabs(e->e0) + e->disk.m * e->disk.g * e->disk.r;
  if (!std::isfinite(e->e0))
    return failed(e, DV_FAILURE_SETUP, err, "the initial pose or energy is not finite");
  e->on_line = h > 0.0 && std::fabs(std::cos(th)) < UPRIGHT_COS;
  return DV_OK;
}

int simbody_reset(void *p, const double state[RED_NSTATE], dv_error *err) {
  simbody_engine *e = static_cast<simbody_engine *>(p);
  memset(&e->st, 0, sizeof e->st);
  e->status = DV_OK;
  e->t_event = NAN;
  memcpy(e->prev_y, state, sizeof e->prev_y);
  for (int i = 0; i < RED_NSTATE; i++)
    if (!std::isfinite(state[i]))
      return failed(e, DV_FAILURE_SETUP, err, "non-finite initial state");
  try {
    return reset(e, state, err);
  } catch (const std::exception &ex) {
    return failed(e, DV_FAILURE_SETUP, err, "Simbody: %s", ex.what());
  }
}

/* after a step: the events (lying down, the validity window) and the faults */
int check_step(simbody_engine *e, dv_error *err) {
  const State &s = e->integ->getState();
  const double t = s.getTime();
  const double th = e->T->getQ(s);
  const double rates = e->T->getU(s) + e->D->getU(s) + e->H->getU(s)[0];
  if (!std::isfinite(th + rates))
    return failed(e, DV_FAILURE_NAN, err, "non-finite state at t = %g s", t);
  if (th < e->theta_limit || th > M_PI - e->theta_limit) {
    dv_engine_lay_down(&e->st, th < e->theta_limit, e->theta_limit, t);
  } else if (e->geom.half_thickness > 0.0 && !(e->side * std::cos(th) > 0.0)) {
    snprintf(e->st.detail, sizeof e->st.detail,
             "the cylinder crossed upright at t = %.9g s: its rim corner switches sides (an "
             "impact the chain, holding one corner, cannot follow)",
             t);
  } else {
    double F[3];
    contact_force(e, s, F);
    const double mu = e->set.friction;
    if (!(F[2] > 0.0))
      snprintf(e->st.detail, sizeof e->st.detail,
               "the normal force reached zero at t = %.9g s (the constraints hold the disk "
               "down: %g N)",
               t, F[2]);
    else if (std::hypot(F[0], F[1]) > mu * F[2])
      snprintf(e->st.detail, sizeof e->st.detail,
               "the friction needed reached mu times the normal force at t = %.9g s (|F_h| / F_z "
               "= %g > mu = %g)",
               t, std::hypot(F[0], F[1]) / F[2], mu);
    else {
      dv_pose p;
      read_pose(e, s, &p);
      const double energy = dv_pose_energy(&e->disk, &p);
      if (!(energy <= e->e_max))
        return failed(e, DV_FAILURE_ENERGY, err,
                      "runaway energy at t = %g s: %g J > %g J (E0 = %g J)", t, energy, e->e_max,
                      e->e0);
      return DV_OK;
    }
  }
  e->st.outcome = DV_OUTCOME_EVENT;
  e->status = DV_EVENT;
  e->t_event = t;
  return DV_EVENT;
}

int advance(simbody_engine *e, double t, dv_error *err) {
  /* fixed steps: the step that lands on t, within a hundredth of a step of it
   * (k steps of h add up to k h only to rounding), is there; the integrator's
   * own steps (accuracy > 0) may end anywhere, and land on t exactly */
  const double slack =
      e->set.accuracy > 0.0 ? 1e-13 * (1.0 + std::fabs(t)) : 1e-2 * e->set.timestep;
  if (e->on_line) {
    snprintf(e->st.detail, sizeof e->st.detail,
             "the cylinder starts upright, on the line across its rim, which the chain (one rim "
             "corner) cannot hold");
    e->st.outcome = DV_OUTCOME_EVENT;
    e->status = DV_EVENT;
    e->t_event = e->integ->getTime();
    return DV_EVENT;
  }
  while (e->integ->getTime() < t - slack) {
    const Integrator::SuccessfulStepStatus st = e->integ->stepTo(t);
    if (st == Integrator::EndOfSimulation || e->integ->isSimulationOver())
      return failed(
          e, DV_FAILURE_LIBRARY, err, "Simbody's integrator stopped at t = %g s: %s",
          e->integ->getTime(),
          Integrator::getTerminationReasonString(e->integ->getTerminationReason()).c_str());
    if (st == Integrator::StartOfContinuousInterval) continue;
    const int status = check_step(e, err);
    if (status != DV_OK) return status;
  }
  return DV_OK;
}

int simbody_advance(void *p, double t, dv_sample *out, dv_error *err) {
  simbody_engine *e = static_cast<simbody_engine *>(p);
  if (e->status < 0)
    return dv_fail(err, e->status, "%s: %s", dv_outcome_name(e->st.outcome), e->st.detail);
  if (e->status == DV_EVENT) return DV_EVENT;
  int status;
  dv_pose pose;
  try {
    status = advance(e, t, err);
    if (status < 0) return status;
    const State &s = e->integ->getState();
    read_pose(e, s, &pose);
    dv_sample_from_pose(&e->disk, &e->geom, &pose, status == DV_EVENT ? e->t_event : t, e->prev_y,
                        out);
    read_state(e, s, out->y); /* the integrated coordinates, not their round trip */
    contact_force(e, s, out->force);
  } catch (const std::exception &ex) {
    return failed(e, DV_FAILURE_LIBRARY, err, "Simbody: %s", ex.what());
  }
  e->st.steps = e->integ->getNumStepsTaken() - e->steps0;
  out->contacts = 1;
  memcpy(e->prev_y, out->y, sizeof e->prev_y);
  dv_stats_add_sample(&e->st, out);
  return status;
}

void simbody_stats(const void *p, dv_engine_stats *out) {
  *out = static_cast<const simbody_engine *>(p)->st;
}


}  // namespace

extern "C" {
DV_ENGINE_MODULE_EXPORT(simbody_version, simbody_alloc, simbody_reset, simbody_advance, simbody_stats, simbody_free);
}
