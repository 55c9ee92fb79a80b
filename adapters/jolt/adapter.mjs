// Jolt Physics (jolt-physics, WebAssembly, single precision) as a diskval adapter.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { serve, number, flag, quat } from '../common/protocol.mjs';

const require = createRequire(import.meta.url);
const pkg = require.resolve('jolt-physics/package.json');
// the single-threaded build with its wasm embedded: no file to locate, no worker headers
const { default: initJolt } = await import('jolt-physics/wasm-compat');

const GROUND = 0;
const MOVING = 1;

// Jolt's cylinder axis is y, the scene's body axis z: body(scene) = body(Jolt) * TO_Z
const TO_Z = quat.axisAngle([1, 0, 0], -Math.PI / 2);

function version() {
  return `Jolt Physics (jolt-physics ${JSON.parse(readFileSync(pkg, 'utf8')).version})`;
}

async function create(scene) {
  const J = await initJolt();
  const h = number(scene, 'timestep');
  const friction = number(scene, 'friction');
  const collisionSteps = number(scene, 'collision_steps');
  if (!(h > 0)) throw new Error('timestep must be > 0');
  if (!(collisionSteps >= 1 && Number.isInteger(collisionSteps))) throw new Error('collision_steps must be an integer >= 1');

  const settings = new J.JoltSettings();
  settings.mMaxWorkerThreads = 0;
  const layers = new J.ObjectLayerPairFilterTable(2);
  layers.EnableCollision(GROUND, MOVING);
  const bpl = new J.BroadPhaseLayerInterfaceTable(2, 2);
  bpl.MapObjectToBroadPhaseLayer(GROUND, new J.BroadPhaseLayer(0));
  bpl.MapObjectToBroadPhaseLayer(MOVING, new J.BroadPhaseLayer(1));
  settings.mObjectLayerPairFilter = layers;
  settings.mBroadPhaseLayerInterface = bpl;
  settings.mObjectVsBroadPhaseLayerFilter = new J.ObjectVsBroadPhaseLayerFilterTable(bpl, 2, layers, 2);
  const jolt = new J.JoltInterface(settings);
  const system = jolt.GetPhysicsSystem();
  const bodies = system.GetBodyInterface();

  const ps = system.GetPhysicsSettings();
  ps.mUseBodyPairContactCache = flag(scene, 'body_pair_cache');
  ps.mSpeculativeContactDistance = number(scene, 'speculative_distance');
  ps.mPenetrationSlop = number(scene, 'penetration_slop');
  ps.mNumVelocitySteps = number(scene, 'velocity_steps');
  ps.mNumPositionSteps = number(scene, 'position_steps');
  ps.mBaumgarte = number(scene, 'baumgarte');
  ps.mAllowSleeping = false;
  system.SetPhysicsSettings(ps);
  system.SetGravity(new J.Vec3(0, 0, -scene.gravity));

  // the ground: the plane z = 0, friction 1 (the combined value is set per contact below)
  const plane = new J.PlaneShapeSettings(new J.Plane(new J.Vec3(0, 0, 1), 0), null, 1000).Create().Get();
  const ground = new J.BodyCreationSettings(plane, new J.RVec3(0, 0, 0), new J.Quat(0, 0, 0, 1), J.EMotionType_Static, GROUND);
  ground.mFriction = 1;
  ground.mRestitution = 0;
  bodies.CreateAndAddBody(ground, J.EActivation_DontActivate);

  const convexRadius = number(scene, 'convex_radius');
  if (!(convexRadius >= 0 && convexRadius <= scene.half_thickness)) throw new Error('convex_radius must lie in [0, half_thickness]');
  const cyl = new J.CylinderShapeSettings(scene.half_thickness, scene.radius, convexRadius);
  const made = cyl.Create();
  if (made.HasError()) throw new Error(`cylinder: ${made.GetError().c_str()}`);
  const q = quat.mul(scene.quaternion, quat.conj(TO_Z));
  const [px, py, pz] = scene.position;
  const disk = new J.BodyCreationSettings(made.Get(), new J.RVec3(px, py, pz), new J.Quat(q[1], q[2], q[3], q[0]), J.EMotionType_Dynamic, MOVING);
  const mp = new J.MassProperties();
  mp.mMass = scene.mass;
  mp.mInertia = J.Mat44.prototype.sScaleVec3(new J.Vec3(scene.A, scene.C, scene.A));
  disk.mMassPropertiesOverride = mp;
  disk.mOverrideMassProperties = J.EOverrideMassProperties_MassAndInertiaProvided;
  disk.mLinearVelocity = new J.Vec3(...scene.velocity);
  disk.mAngularVelocity = new J.Vec3(...scene.angular_velocity);
  disk.mApplyGyroscopicForce = flag(scene, 'gyroscopic');
  disk.mLinearDamping = 0;
  disk.mAngularDamping = 0;
  disk.mMaxLinearVelocity = 1e15;
  disk.mMaxAngularVelocity = 1e15; // default 47 rad/s: a cap, not physics
  disk.mAllowSleeping = false;
  disk.mFriction = friction * friction; // sqrt(1 * f^2): Jolt's own combination, overridden exactly below
  disk.mRestitution = 0;
  const id = bodies.CreateAndAddBody(disk, J.EActivation_Activate);
  const body = system.GetBodyLockInterfaceNoLock().TryGetBody(id);

  // count the contact points of each step; set the combined friction to the scene's exactly
  let points = 0;
  const listener = new J.ContactListenerJS();
  const contact = (b1, b2, manifold, io) => {
    points += J.wrapPointer(manifold, J.ContactManifold).mRelativeContactPointsOn1.size();
    const cs = J.wrapPointer(io, J.ContactSettings);
    cs.mCombinedFriction = friction;
    cs.mCombinedRestitution = 0;
  };
  listener.OnContactValidate = () => J.ValidateResult_AcceptAllContactsForThisBodyPair;
  listener.OnContactAdded = contact;
  listener.OnContactPersisted = contact;
  listener.OnContactRemoved = () => {};
  system.SetContactListener(listener);

  let contacts = 0;
  return {
    step() {
      points = 0;
      jolt.Step(h, collisionSteps);
      contacts = Math.round(points / collisionSteps); // the listener runs once per collision step
    },
    state() {
      const p = body.GetPosition();
      const r = body.GetRotation();
      const v = body.GetLinearVelocity();
      const w = body.GetAngularVelocity();
      const qs = quat.mul([r.GetW(), r.GetX(), r.GetY(), r.GetZ()], TO_Z);
      const n = Math.hypot(...qs);
      return {
        pos: [p.GetX(), p.GetY(), p.GetZ()],
        quat: qs.map((c) => c / n), // float32 storage: renormalised in double for the row check
        vel: [v.GetX(), v.GetY(), v.GetZ()],
        omega: [w.GetX(), w.GetY(), w.GetZ()],
        contacts,
      };
    },
  };
}

serve({ version, create });
