// The diskval adapter protocol, version 1 (docs/adapters.md), for adapters on Node.
//
// An adapter calls serve({version, create}): version() returns the engine's
// library and version ("MuJoCo 3.3.8 (mujoco-js 0.0.7)"); create(scene)
// builds the model and returns a simulation with step() (one timestep) and
// state() ({pos, quat, vel, omega, contacts}: the disk's centre, its
// body-to-world quaternion [w, x, y, z] with body z along the disk's axis, the
// centre's velocity and the angular velocity, both in the world frame, and the
// contact points the engine holds, -1 when it does not say). serve() answers
// `--version`, reads the scene, and steps to every time diskval asks for.
import { writeSync } from 'node:fs';
import { createInterface } from 'node:readline';

export const PROTOCOL = 1;

function say(line) {
  writeSync(1, line + '\n');
}

function fail(message) {
  say('error ' + String(message).replace(/\s+/g, ' ').trim());
  process.exit(1);
}

const VECTORS = { position: 3, quaternion: 4, velocity: 3, angular_velocity: 3, inertia: 2 };
const SCALARS = ['radius', 'mass', 'half_thickness', 'gravity', 'friction'];

// the scene's lines up to `start` as an object; settings stay text
function parseScene(lines) {
  const scene = { settings: {} };
  for (const line of lines) {
    const [key, ...rest] = line.trim().split(/\s+/);
    if (key === 'set') {
      scene.settings[rest[0]] = rest.slice(1).join(' ');
    } else if (key in VECTORS || SCALARS.includes(key)) {
      const v = rest.map(Number);
      const n = VECTORS[key] || 1;
      if (v.length !== n || v.some((x) => !Number.isFinite(x))) throw new Error(`bad scene line: ${line}`);
      scene[key] = n === 1 ? v[0] : v;
    } else {
      throw new Error(`unknown scene line: ${line}`);
    }
  }
  for (const key of [...SCALARS, ...Object.keys(VECTORS)])
    if (!(key in scene)) throw new Error(`the scene gives no ${key}`);
  [scene.A, scene.C] = scene.inertia;
  if (!(scene.half_thickness > 0)) throw new Error('half_thickness: every adapter models a cylinder of some thickness');
  return scene;
}

// a setting as a number, refusing what is not one
export function number(scene, key) {
  const v = Number(scene.settings[key]);
  if (!(key in scene.settings) || !Number.isFinite(v)) throw new Error(`setting ${key}: not a number`);
  return v;
}

export function text(scene, key) {
  if (!(key in scene.settings)) throw new Error(`setting ${key}: not given`);
  return scene.settings[key];
}

export function flag(scene, key) {
  const v = text(scene, key);
  if (v !== 'on' && v !== 'off') throw new Error(`setting ${key}: ${v} is neither on nor off`);
  return v === 'on';
}

const fmt = (x) => (Number.isInteger(x) ? String(x) : x.toPrecision(17));

export async function serve(adapter) {
  if (process.argv.includes('--version')) {
    say(await adapter.version());
    return;
  }
  const rl = createInterface({ input: process.stdin, crlfDelay: Infinity, terminal: false });
  const lines = [];
  let sim = null;
  let dt = 0;
  let steps = 0;
  try {
    for await (const line of rl) {
      if (!sim) {
        if (lines.length === 0 && line.trim() !== `diskval-adapter ${PROTOCOL}`)
          throw new Error(`expected "diskval-adapter ${PROTOCOL}", got: ${line}`);
        if (line.trim() !== 'start') {
          lines.push(line);
          continue;
        }
        const scene = parseScene(lines.slice(1));
        dt = number(scene, 'timestep');
        sim = await adapter.create(scene);
        say('ready');
        continue;
      }
      const [verb, arg] = line.trim().split(/\s+/);
      if (verb !== 'advance') throw new Error(`expected "advance T", got: ${line}`);
      const target = Math.round(Number(arg) / dt);
      if (!Number.isFinite(target)) throw new Error(`bad time: ${line}`);
      while (steps < target) {
        sim.step();
        steps++;
      }
      const s = sim.state();
      const row = [steps * dt, ...s.pos, ...s.quat, ...s.vel, ...s.omega].map(fmt);
      say(`${row.join(' ')} ${s.contacts ?? -1} ${steps}`);
    }
  } catch (e) {
    fail(e && e.message ? e.message : e);
  }
}

// quaternions [w, x, y, z]
export const quat = {
  mul: (a, b) => [
    a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
    a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
    a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
    a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
  ],
  conj: (q) => [q[0], -q[1], -q[2], -q[3]],
  axisAngle: (axis, angle) => {
    const s = Math.sin(angle / 2);
    return [Math.cos(angle / 2), axis[0] * s, axis[1] * s, axis[2] * s];
  },
  // q v q*
  rotate: (q, v) => quat.mul(quat.mul(q, [0, ...v]), quat.conj(q)).slice(1),
};

// the gyroscopic torque -omega x (I omega) in the world frame, for a body whose
// principal moments are (A, A, C) about its axis n (world): the term an engine
// without one leaves out of the rigid body's equations
export function gyroscopicTorque(A, C, n, omega) {
  const along = omega[0] * n[0] + omega[1] * n[1] + omega[2] * n[2];
  const L = omega.map((w, i) => A * w + (C - A) * along * n[i]);
  return [
    -(omega[1] * L[2] - omega[2] * L[1]),
    -(omega[2] * L[0] - omega[0] * L[2]),
    -(omega[0] * L[1] - omega[1] * L[0]),
  ];
}
