// Rapier (@dimforge/rapier3d-compat): a float32 WebAssembly build of the Rust engine.
// Its cylinder's axis is body y; the scene's is body z: the body frame is turned by
// +90 degrees about x (Y_TO_Z) between the two.
import { readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import RAPIER from '@dimforge/rapier3d-compat';
import { serve, number, quat } from '../common/protocol.mjs';

const Y_TO_Z = quat.axisAngle([1, 0, 0], Math.PI / 2);
const PKG = new URL('../node_modules/@dimforge/rapier3d-compat/package.json', import.meta.url);

const vec = (v) => ({ x: v[0], y: v[1], z: v[2] });
const arr = (v) => [v.x, v.y, v.z];

// compiles the embedded wasm, once (its warnings go to stderr)
let ready = null;
const init = () => (ready ??= RAPIER.init());

export async function version() {
  await init();
  const pkg = JSON.parse(readFileSync(PKG, 'utf8'));
  return `Rapier ${RAPIER.version()} (${pkg.name} ${pkg.version})`;
}

export async function create(scene) {
  await init();
  const h = number(scene, 'timestep');
  const mu = number(scene, 'friction');
  const softness = number(scene, 'contact_time');
  const { A, C, mass } = scene;
  const halfThickness = scene.half_thickness;

  const world = new RAPIER.World(vec([0, 0, -scene.gravity]));
  const p = world.integrationParameters;
  p.dt = h;
  p.numSolverIterations = number(scene, 'solver_iterations');
  p.numInternalPgsIterations = number(scene, 'pgs_iterations');
  // the engine takes the contact's stiffness as a natural frequency in Hz: softness = 1 / f
  p.contact_natural_frequency = 1 / softness;
  p.normalizedAllowedLinearError = number(scene, 'allowed_error');
  p.normalizedPredictionDistance = number(scene, 'prediction');

  const ground = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
  const groundCollider = world.createCollider(
    // this build has a half-space shape but no ColliderDesc.halfspace shortcut
    new RAPIER.ColliderDesc(new RAPIER.HalfSpace(vec([0, 0, 1])))
      .setFriction(mu)
      .setRestitution(0)
      .setFrictionCombineRule(RAPIER.CoefficientCombineRule.Max)
      .setRestitutionCombineRule(RAPIER.CoefficientCombineRule.Max),
    ground,
  );

  const q = quat.mul(scene.quaternion, Y_TO_Z);
  const body = world.createRigidBody(
    RAPIER.RigidBodyDesc.dynamic()
      .setTranslation(...scene.position)
      .setRotation({ w: q[0], x: q[1], y: q[2], z: q[3] })
      .setLinvel(...scene.velocity)
      .setAngvel(vec(scene.angular_velocity))
      .setLinearDamping(0)
      .setAngularDamping(0)
      .setGravityScale(1)
      .setCanSleep(false)
      .setCcdEnabled(false)
      // principal moments in the engine's body frame, whose y is the disk's axis
      .setAdditionalMassProperties(mass, vec([0, 0, 0]), vec([A, C, A]), { w: 1, x: 0, y: 0, z: 0 }),
  );
  const collider = world.createCollider(
    RAPIER.ColliderDesc.cylinder(halfThickness, scene.radius)
      .setDensity(0)
      .setFriction(mu)
      .setRestitution(0)
      .setFrictionCombineRule(RAPIER.CoefficientCombineRule.Max)
      .setRestitutionCombineRule(RAPIER.CoefficientCombineRule.Max),
    body,
  );

  const pose = () => {
    const r = body.rotation();
    return quat.mul([r.w, r.x, r.y, r.z], quat.conj(Y_TO_Z));
  };

  return {
    world,
    body,
    // no torque of ours: the engine keeps the world angular momentum of a free spinning body
    // (its gyroscopic term is in), and adding -omega x (I omega) would count it twice
    step() {
      world.step();
    },
    state() {
      let contacts = 0;
      world.contactPair(collider, groundCollider, (m) => (contacts += m.numContacts()));
      return {
        pos: arr(body.translation()),
        quat: pose(),
        vel: arr(body.linvel()),
        omega: arr(body.angvel()),
        contacts,
      };
    },
  };
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) serve({ version, create });
