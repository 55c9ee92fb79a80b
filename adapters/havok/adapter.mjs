// diskval adapter: Havok (@babylonjs/havok, float32 WebAssembly).
// Havok's cylinder is a prism (16 sides) with rounded edges; the disk's axis
// is the cylinder's segment, so body z is the scene's axis without a turn.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import HavokPhysics from '@babylonjs/havok';
import { serve, number, text, flag, quat, gyroscopicTorque } from '../common/protocol.mjs';

const require = createRequire(import.meta.url);
const WASM = require.resolve('@babylonjs/havok/lib/esm/HavokPhysics.wasm');
// the package exports no package.json: read it beside lib/
const PKG = join(dirname(WASM), '..', '..', 'package.json');

async function load() {
  // under Node the module cannot fetch its .wasm: hand it the bytes
  const wasmBinary = readFileSync(WASM);
  return HavokPhysics({ wasmBinary });
}

function check(result, what) {
  const r = Array.isArray(result) ? result[0] : result;
  if (r !== undefined && r.value !== undefined && r.value !== 0) throw new Error(`Havok ${what}: result ${r.value}`);
  return result;
}

// a convex hull of an N-gon prism: radius r at the vertices, axis z
function hull(hk, r, h, n) {
  const ptr = hk._malloc(n * 2 * 3 * 4);
  const v = new Float32Array(hk.HEAPU8.buffer, ptr, n * 2 * 3);
  for (let k = 0; k < n; k++) {
    const a = (2 * Math.PI * k) / n;
    v.set([r * Math.cos(a), r * Math.sin(a), -h, r * Math.cos(a), r * Math.sin(a), h], 6 * k);
  }
  const shape = check(hk.HP_Shape_CreateConvexHull(ptr, 2 * n), 'convex hull')[1];
  hk._free(ptr);
  return shape;
}

async function create(scene) {
  const hk = await load();
  const dt = number(scene, 'timestep');
  const mu = number(scene, 'friction');
  const gyro = flag(scene, 'gyroscopic');
  const shapeKind = text(scene, 'shape');
  const segments = number(scene, 'segments');
  const { radius: r, mass: m, A, C } = scene;
  const h = scene.half_thickness;

  const world = check(hk.HP_World_Create(), 'world')[1];
  check(hk.HP_World_SetGravity(world, [0, 0, -scene.gravity]), 'gravity');
  check(hk.HP_World_SetIdealStepTime(world, dt), 'ideal step');
  check(hk.HP_World_SetSpeedLimit(world, 1e6, 1e6), 'speed limit');
  const material = [mu, mu, 0, hk.MaterialCombine.MINIMUM, hk.MaterialCombine.MINIMUM];

  // the ground: a box 100 m wide, 10 m deep, its top at z = 0 (Havok has no plane)
  const groundShape = check(hk.HP_Shape_CreateBox([0, 0, -5], [0, 0, 0, 1], [100, 100, 10]), 'box')[1];
  check(hk.HP_Shape_SetMaterial(groundShape, material), 'ground material');
  const ground = check(hk.HP_Body_Create(), 'ground')[1];
  check(hk.HP_Body_SetShape(ground, groundShape), 'ground shape');
  check(hk.HP_Body_SetMotionType(ground, hk.MotionType.STATIC), 'ground motion');
  check(hk.HP_Body_SetQTransform(ground, [[0, 0, 0], [0, 0, 0, 1]]), 'ground pose');
  check(hk.HP_World_AddBody(world, ground, false), 'add ground');

  let diskShape;
  if (shapeKind === 'cylinder') diskShape = check(hk.HP_Shape_CreateCylinder([0, 0, -h], [0, 0, h], r), 'cylinder')[1];
  else if (shapeKind === 'hull') diskShape = hull(hk, r, h, segments);
  else throw new Error(`setting shape: ${shapeKind} is neither cylinder nor hull`);
  check(hk.HP_Shape_SetMaterial(diskShape, material), 'disk material');
  const disk = check(hk.HP_Body_Create(), 'disk')[1];
  check(hk.HP_Body_SetShape(disk, diskShape), 'disk shape');
  check(hk.HP_Body_SetMotionType(disk, hk.MotionType.DYNAMIC), 'disk motion');
  // inertia is given per unit mass
  check(hk.HP_Body_SetMassProperties(disk, [[0, 0, 0], m, [A / m, A / m, C / m], [0, 0, 0, 1]]), 'mass');
  check(hk.HP_Body_SetLinearDamping(disk, 0), 'linear damping');
  check(hk.HP_Body_SetAngularDamping(disk, 0), 'angular damping');
  check(hk.HP_Body_SetActivationControl(disk, hk.ActivationControl.ALWAYS_ACTIVE), 'activation');
  const [qw, qx, qy, qz] = scene.quaternion;
  check(hk.HP_Body_SetQTransform(disk, [scene.position, [qx, qy, qz, qw]]), 'disk pose');
  check(hk.HP_World_AddBody(world, disk, false), 'add disk');
  check(hk.HP_Body_SetLinearVelocity(disk, scene.velocity), 'velocity');
  check(hk.HP_Body_SetAngularVelocity(disk, scene.angular_velocity), 'angular velocity');

  let last = scene.quaternion;
  const pose = () => {
    const [p, [x, y, z, w]] = check(hk.HP_Body_GetQTransform(disk), 'pose')[1];
    // float32 to unit length in double, and the sign kept continuous between rows
    const norm = Math.hypot(w, x, y, z);
    const sign = w * last[0] + x * last[1] + y * last[2] + z * last[3] < 0 ? -1 : 1;
    return { pos: p, quat: [w, x, y, z].map((c) => (sign * c) / norm) };
  };
  const omega = () => check(hk.HP_Body_GetAngularVelocity(disk), 'angular velocity')[1];

  return {
    step() {
      if (gyro) {
        // Havok leaves -omega x (I omega) out: add its impulse over the step
        const n = quat.rotate(pose().quat, [0, 0, 1]);
        const tau = gyroscopicTorque(A, C, n, omega());
        check(hk.HP_Body_ApplyAngularImpulse(disk, tau.map((t) => t * dt)), 'angular impulse');
      }
      check(hk.HP_World_Step(world, dt), 'step');
    },
    state() {
      const { pos, quat: q } = pose();
      last = q;
      const vel = check(hk.HP_Body_GetLinearVelocity(disk), 'velocity')[1];
      return { pos, quat: q, vel, omega: omega(), contacts: -1 };
    },
  };
}

function version() {
  return `Havok (@babylonjs/havok ${JSON.parse(readFileSync(PKG, 'utf8')).version})`;
}

serve({ version, create });
