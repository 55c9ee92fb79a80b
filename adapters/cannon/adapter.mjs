// diskval adapter: cannon-es (float64 JavaScript).
// cannon's Cylinder is an N-gon prism along its y axis: it is turned onto the
// body's z, so the body frame is the scene's and the inertia stays diagonal.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { World, Body, Plane, Cylinder, Vec3, Quaternion, GSSolver } from 'cannon-es';
import { serve, number, flag, quat, gyroscopicTorque } from '../common/protocol.mjs';

const require = createRequire(import.meta.url);

function create(scene) {
  const dt = number(scene, 'timestep');
  const mu = number(scene, 'friction');
  const gyro = flag(scene, 'gyroscopic');
  const segments = number(scene, 'segments');
  const contactTime = number(scene, 'contact_time');
  const stiffness = number(scene, 'stiffness');
  const { radius: r, mass: m, A, C } = scene;
  const h = scene.half_thickness;
  if (!Number.isInteger(segments) || segments < 3) throw new Error(`setting segments: ${segments} is not an integer >= 3`);

  const world = new World({ gravity: new Vec3(0, 0, -scene.gravity), allowSleep: false });
  world.quatNormalizeSkip = 0;
  world.quatNormalizeFast = false;
  const solver = new GSSolver();
  solver.iterations = number(scene, 'iterations');
  solver.tolerance = number(scene, 'tolerance');
  world.solver = solver;
  // both bodies use the default material: its contact material is the disk-ground one
  const cm = world.defaultContactMaterial;
  cm.friction = mu;
  cm.restitution = 0;
  // the softness: the constraints relax over contact_time (in steps: cannon's relaxation)
  cm.contactEquationStiffness = stiffness;
  cm.contactEquationRelaxation = contactTime / dt;
  cm.frictionEquationStiffness = stiffness;
  cm.frictionEquationRelaxation = contactTime / dt;

  const ground = new Body({ mass: 0, shape: new Plane() });
  world.addBody(ground);

  const disk = new Body({ mass: m, linearDamping: 0, angularDamping: 0, allowSleep: false });
  const turn = new Quaternion();
  turn.setFromAxisAngle(new Vec3(1, 0, 0), Math.PI / 2);
  disk.addShape(new Cylinder(r, r, 2 * h, segments), new Vec3(0, 0, 0), turn);
  // addShape set a box's inertia from the bounding box: the disk's own, exactly
  disk.inertia.set(A, A, C);
  disk.invInertia.set(1 / A, 1 / A, 1 / C);
  const [qw, qx, qy, qz] = scene.quaternion;
  disk.position.set(...scene.position);
  disk.quaternion.set(qx, qy, qz, qw);
  disk.velocity.set(...scene.velocity);
  disk.angularVelocity.set(...scene.angular_velocity);
  disk.updateInertiaWorld(true);
  world.addBody(disk);

  let last = scene.quaternion;
  const orientation = () => {
    const { w, x, y, z } = disk.quaternion;
    const sign = w * last[0] + x * last[1] + y * last[2] + z * last[3] < 0 ? -1 : 1;
    return [w, x, y, z].map((c) => sign * c);
  };
  const omega = () => disk.angularVelocity.toArray();

  return {
    step() {
      if (gyro) {
        // cannon leaves -omega x (I omega) out of its integration: add it as a torque
        const tau = gyroscopicTorque(A, C, quat.rotate(orientation(), [0, 0, 1]), omega());
        disk.torque.vadd(new Vec3(...tau), disk.torque);
      }
      world.step(dt);
    },
    state() {
      last = orientation();
      return {
        pos: disk.position.toArray(),
        quat: last,
        vel: disk.velocity.toArray(),
        omega: omega(),
        contacts: world.contacts.length,
      };
    },
  };
}

function version() {
  const pkg = JSON.parse(readFileSync(require.resolve('cannon-es/package.json'), 'utf8'));
  return `cannon-es ${pkg.version}`;
}

serve({ version, create });
