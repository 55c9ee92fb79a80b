// MuJoCo 3 (the official WebAssembly build, mujoco-js): the disk as a free body
// with a cylinder geom on a plane, the model diskval's linked MuJoCo 2.2 engine
// writes for a cylinder (engines/mujoco/engine_mujoco.c, write_model).
import { readFileSync } from 'node:fs';
import load_mujoco from 'mujoco-js';
import { serve, number, text, quat } from '../common/protocol.mjs';

const INTEGRATORS = { euler: 'Euler', rk4: 'RK4', implicit: 'implicit', implicitfast: 'implicitfast' };
const CONES = ['pyramidal', 'elliptic'];
const SOLVERS = { pgs: 'PGS', cg: 'CG', newton: 'Newton' };

const g17 = (x) => x.toPrecision(17);

function choice(scene, key, values) {
  const v = text(scene, key);
  if (!values.includes(v)) throw new Error(`setting ${key}: ${v} is not one of ${values.join(', ')}`);
  return v;
}

function integer(scene, key) {
  const v = number(scene, key);
  if (!Number.isInteger(v)) throw new Error(`setting ${key}: ${v} is not an integer`);
  return v;
}

// the MJCF of engine_mujoco.c's write_model for geom = cylinder (less the
// user value that marks its own thin-disk collider)
function modelXml(scene) {
  const s = {
    timestep: number(scene, 'timestep'),
    integrator: INTEGRATORS[choice(scene, 'integrator', Object.keys(INTEGRATORS))],
    cone: choice(scene, 'cone', CONES),
    impratio: number(scene, 'impratio'),
    solver: SOLVERS[choice(scene, 'solver', Object.keys(SOLVERS))],
    tolerance: number(scene, 'tolerance'),
    iterations: integer(scene, 'iterations'),
    noslip: integer(scene, 'noslip_iterations'),
    friction: number(scene, 'friction'),
    solref: [number(scene, 'solref_timeconst'), number(scene, 'solref_dampratio')],
    solimp: ['solimp_dmin', 'solimp_dmax', 'solimp_width'].map((k) => number(scene, k)),
  };
  return `<mujoco model="diskval">
  <option timestep="${g17(s.timestep)}" gravity="0 0 ${g17(-scene.gravity)}" integrator="${s.integrator}" cone="${s.cone}"
          impratio="${g17(s.impratio)}" solver="${s.solver}" tolerance="${g17(s.tolerance)}" iterations="${s.iterations}"
          noslip_iterations="${s.noslip}"/>
  <default>
    <geom condim="3" friction="${g17(s.friction)} 0 0" solref="${s.solref.map(g17).join(' ')}"
          solimp="${s.solimp.map(g17).join(' ')} 0.5 2"/>
  </default>
  <worldbody>
    <geom name="ground" type="plane" size="0 0 1" contype="0" conaffinity="1"/>
    <body name="disk">
      <freejoint/>
      <inertial pos="0 0 0" mass="${g17(scene.mass)}" diaginertia="${g17(scene.A)} ${g17(scene.A)} ${g17(scene.C)}"/>
      <geom name="disk" type="cylinder" size="${g17(scene.radius)} ${g17(scene.half_thickness)}" contype="1"
            conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>
`;
}

let mj = null;
async function mujoco() {
  // MuJoCo prints its warnings: keep them off the protocol's standard output
  const toStderr = (line) => process.stderr.write(line + '\n');
  mj ??= await load_mujoco({ print: toStderr, printErr: toStderr });
  return mj;
}

function version() {
  const pkg = JSON.parse(readFileSync(new URL('../node_modules/mujoco-js/package.json', import.meta.url)));
  return mujoco().then((m) => `MuJoCo ${m.mj_versionString()} (mujoco-js ${pkg.version})`);
}

const unit = (q) => {
  const n = Math.hypot(...q);
  return q.map((x) => x / n);
};

async function create(scene) {
  const mj = await mujoco();
  mj.FS.writeFile('/disk.xml', modelXml(scene));
  let m;
  try {
    m = mj.MjModel.loadFromXML('/disk.xml');
  } catch (e) {
    // the build throws the compiler's exception type (mjCError) without its text
    throw new Error(`MuJoCo cannot load the disk model: ${e.message ?? e}`);
  }
  const d = new mj.MjData(m);
  process.on('exit', () => {
    d.delete();
    m.delete();
  });
  // the free joint: centre, quaternion (w x y z); centre velocity (world), angular velocity (body)
  const q = unit(scene.quaternion);
  d.qpos.set([...scene.position, ...q]);
  d.qvel.set([...scene.velocity, ...quat.rotate(quat.conj(q), scene.angular_velocity)]);
  mj.mj_forward(m, d);
  const BAD = ['mjWARN_BADQPOS', 'mjWARN_BADQVEL', 'mjWARN_BADQACC'].map((k) => mj.mjtWarning[k].value);
  // d.warning is a copy: read afresh
  const count = (i) => {
    const all = d.warning;
    const w = all.get(i);
    const n = w.number;
    w.delete();
    all.delete();
    return n;
  };
  const bad = () => BAD.reduce((n, i) => n + count(i), 0);
  return {
    step() {
      mj.mj_step(m, d);
    },
    state() {
      // MuJoCo resets a bad state and only counts a warning (counts never fall)
      if (bad()) throw new Error(`MuJoCo reset a bad qpos/qvel/qacc before t = ${d.time} s`);
      // views into wasm memory: taken afresh after the steps
      const p = d.qpos, v = d.qvel;
      const qw = unit([p[3], p[4], p[5], p[6]]);
      return {
        pos: [p[0], p[1], p[2]],
        quat: qw,
        vel: [v[0], v[1], v[2]],
        omega: quat.rotate(qw, [v[3], v[4], v[5]]),
        contacts: d.ncon,
      };
    },
  };
}

serve({ version, create });
