#!/usr/bin/env node
// Engine harness: runs real physics engines (npm builds) on the throws described in a case
// file and writes the per-step state of the thrown sphere. Contract: README.md in this folder.
//
//   node harness.mjs CASES.json OUT.json      ("-" reads stdin / writes stdout)
//
// Engines driven here: jolt (jolt-physics), physx (@cocos/physx, PhysX 4.1),
// rapier (@dimforge/rapier3d-compat), ammo (ammo.js, Bullet). Cases for any other engine are
// listed in "skipped". Exit status: 0 ok, 2 bad usage or bad input (nothing is run),
// 1 an engine failed.
//
// Set-up policy: measure the engines as a game uses them. Solver iterations, contact offsets,
// speculative distances, CCD, restitution thresholds and material combine rules stay at each
// engine's defaults. Only what the case specifies is set: gravity, the sphere (radius, mass,
// pose, velocities, material, damping only when given), static boxes (pose, size, material).
// Sleeping/deactivation is turned off. Exactly one engine step of exactly `timestep` per step.

import { createRequire } from 'node:module';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import v8 from 'node:v8';

// Compile wasm with the baseline compiler only. Wasm arithmetic is exactly specified, so
// results do not depend on the tier; but with tier-up on, V8 recompiles the large engine
// modules in the background and the process waits for that at exit (~1 s per run).
v8.setFlagsFromString('--liftoff-only');

const require = createRequire(import.meta.url);
const HERE = path.dirname(fileURLToPath(import.meta.url));

// Engines print through console.log (emscripten's stdout); keep stdout clean for "-" output.
console.log = console.info = console.debug = (...a) => console.error(...a);

const ENGINE_PACKAGES = {
  jolt: 'jolt-physics',
  physx: '@cocos/physx',
  rapier: '@dimforge/rapier3d-compat',
  ammo: 'ammo.js',
};
const MAX_STEPS = 1000000;

class InputError extends Error {}
class EngineError extends Error {}

// ---------------------------------------------------------------- input validation

function describe(v) {
  const s = JSON.stringify(v);
  return s === undefined ? String(v) : s.length > 60 ? s.slice(0, 57) + '...' : s;
}

function makeChecker(where) {
  const bad = (field, what, v) => {
    throw new InputError(`${where}: field "${field}": ${what} (got ${describe(v)})`);
  };
  const num = (obj, field, { min = -Infinity, minExclusive = false, optional = false, dflt } = {}) => {
    const key = field.split('.').pop();
    if (!(key in obj) || obj[key] === undefined) {
      if (optional) return dflt;
      throw new InputError(`${where}: missing field "${field}"`);
    }
    const v = obj[key];
    if (typeof v !== 'number' || !Number.isFinite(v)) bad(field, 'must be a finite number', v);
    if (minExclusive ? !(v > min) : !(v >= min)) bad(field, `must be ${minExclusive ? '>' : '>='} ${min}`, v);
    return v;
  };
  const vec = (obj, field, n, { optional = false, dflt, positive = false } = {}) => {
    const key = field.split('.').pop();
    if (!(key in obj) || obj[key] === undefined) {
      if (optional) return dflt;
      throw new InputError(`${where}: missing field "${field}"`);
    }
    const v = obj[key];
    if (!Array.isArray(v) || v.length !== n) bad(field, `must be an array of ${n} numbers`, v);
    v.forEach((x, i) => {
      if (typeof x !== 'number' || !Number.isFinite(x)) bad(`${field}[${i}]`, 'must be a finite number', x);
      if (positive && !(x > 0)) bad(`${field}[${i}]`, 'must be > 0', x);
    });
    return v.slice();
  };
  const obj = (parent, field) => {
    const key = field.split('.').pop();
    if (!(key in parent)) throw new InputError(`${where}: missing field "${field}"`);
    const v = parent[key];
    if (v === null || typeof v !== 'object' || Array.isArray(v)) bad(field, 'must be an object', v);
    return v;
  };
  const known = (o, prefix, keys) => {
    for (const k of Object.keys(o)) {
      if (!keys.includes(k) && !['comment', 'description', 'note'].includes(k)) {
        throw new InputError(`${where}: unknown field "${prefix}${k}" (allowed: ${keys.join(', ')})`);
      }
    }
  };
  return { num, vec, obj, known, bad };
}

function validateCase(raw, index) {
  const where = `case "${raw.id}" (cases[${index}])`;
  const C = makeChecker(where);
  C.known(raw, '', ['id', 'engine', 'timestep', 'steps', 'gravity', 'body', 'boxes']);
  const timestep = C.num(raw, 'timestep', { min: 0, minExclusive: true });
  if (!('steps' in raw)) throw new InputError(`${where}: missing field "steps"`);
  if (!Number.isInteger(raw.steps) || raw.steps < 0 || raw.steps > MAX_STEPS) {
    C.bad('steps', `must be an integer in [0, ${MAX_STEPS}]`, raw.steps);
  }
  const gravity = C.vec(raw, 'gravity', 3);

  const b = C.obj(raw, 'body');
  C.known(b, 'body.', ['radius', 'mass', 'position', 'velocity', 'angular_velocity',
    'linear_damping', 'angular_damping', 'restitution', 'friction']);
  const body = {
    radius: C.num(b, 'body.radius', { min: 0, minExclusive: true }),
    mass: C.num(b, 'body.mass', { min: 0, minExclusive: true, optional: true, dflt: 1 }),
    position: C.vec(b, 'body.position', 3),
    velocity: C.vec(b, 'body.velocity', 3),
    angular_velocity: C.vec(b, 'body.angular_velocity', 3, { optional: true, dflt: [0, 0, 0] }),
    linear_damping: C.num(b, 'body.linear_damping', { min: 0, optional: true }),
    angular_damping: C.num(b, 'body.angular_damping', { min: 0, optional: true }),
    restitution: C.num(b, 'body.restitution', { min: 0 }),
    friction: C.num(b, 'body.friction', { min: 0 }),
  };

  let boxes = [];
  if ('boxes' in raw) {
    if (!Array.isArray(raw.boxes)) C.bad('boxes', 'must be an array', raw.boxes);
    boxes = raw.boxes.map((bx, j) => {
      const p = `boxes[${j}]`;
      if (bx === null || typeof bx !== 'object' || Array.isArray(bx)) C.bad(p, 'must be an object', bx);
      C.known(bx, `${p}.`, ['center', 'half_extents', 'rotation', 'restitution', 'friction', 'rounding']);
      const rotation = C.vec(bx, `${p}.rotation`, 4, { optional: true, dflt: [0, 0, 0, 1] });
      const norm = Math.hypot(...rotation);
      if (Math.abs(norm - 1) > 1e-6) C.bad(`${p}.rotation`, 'must be a unit quaternion [x, y, z, w]', bx.rotation);
      return {
        center: C.vec(bx, `${p}.center`, 3),
        half_extents: C.vec(bx, `${p}.half_extents`, 3, { positive: true }),
        rotation,
        restitution: C.num(bx, `${p}.restitution`, { min: 0 }),
        friction: C.num(bx, `${p}.friction`, { min: 0 }),
        // Radius of the rounded edges (the box keeps its outer size); absent: the engine's own
        // default (Jolt's convex radius, Bullet's collision margin, sharp elsewhere).
        rounding: C.num(bx, `${p}.rounding`, { min: 0, optional: true, dflt: undefined }),
      };
    });
    boxes.forEach((bx, j) => {
      if (bx.rounding === undefined) return;
      const p = `boxes[${j}].rounding`;
      if (bx.rounding > Math.min(...bx.half_extents)) C.bad(p, 'must not exceed the smallest half extent', bx.rounding);
      if (bx.rounding > 0 && raw.engine !== 'jolt' && raw.engine !== 'rapier' && raw.engine !== 'ammo')
        C.bad(p, `must be 0: ${raw.engine} builds sharp boxes here`, bx.rounding);
    });
  }
  return { id: raw.id, engine: raw.engine, timestep, steps: raw.steps, gravity, body, boxes };
}

function parseCaseFile(text, name) {
  let doc;
  try {
    doc = JSON.parse(text);
  } catch (e) {
    throw new InputError(`${name}: not valid JSON: ${e.message}`);
  }
  if (doc === null || typeof doc !== 'object' || Array.isArray(doc) || !Array.isArray(doc.cases)) {
    throw new InputError(`${name}: top level must be an object with a "cases" array`);
  }
  const ids = new Map();
  const run = [];
  const skipped = [];
  doc.cases.forEach((raw, i) => {
    if (raw === null || typeof raw !== 'object' || Array.isArray(raw)) {
      throw new InputError(`cases[${i}]: must be an object (got ${describe(raw)})`);
    }
    if (typeof raw.id !== 'string' || raw.id === '') {
      throw new InputError(`cases[${i}]: field "id": must be a non-empty string (got ${describe(raw.id)})`);
    }
    if (ids.has(raw.id)) {
      throw new InputError(`case "${raw.id}" (cases[${i}]): field "id": duplicate of cases[${ids.get(raw.id)}]`);
    }
    ids.set(raw.id, i);
    if (typeof raw.engine !== 'string' || raw.engine === '') {
      throw new InputError(`case "${raw.id}" (cases[${i}]): field "engine": must be a non-empty string (got ${describe(raw.engine)})`);
    }
    if (raw.engine in ENGINE_PACKAGES) run.push(validateCase(raw, i));
    else skipped.push(raw.id);
  });
  return { run, skipped };
}

// ---------------------------------------------------------------- engine loading (once per process)

function packageVersion(pkg) {
  const file = path.join(HERE, 'node_modules', ...pkg.split('/'), 'package.json');
  try {
    return JSON.parse(fs.readFileSync(file, 'utf8')).version;
  } catch {
    return null;
  }
}

const loaded = {};
async function loadEngine(name) {
  if (loaded[name]) return loaded[name];
  const print = (...a) => console.error(`[${name}]`, ...a);
  let mod;
  try {
    if (name === 'jolt') {
      const { default: initJolt } = await import('jolt-physics');
      mod = await initJolt({ print, printErr: print });
    } else if (name === 'rapier') {
      const { default: RAPIER } = await import('@dimforge/rapier3d-compat');
      await RAPIER.init();
      mod = RAPIER;
    } else if (name === 'physx') {
      const dir = path.join(path.dirname(require.resolve('@cocos/physx/package.json')), 'builds');
      const factory = require(path.join(dir, 'physx.release.wasm.js'));
      const PX = await factory({
        wasmBinary: fs.readFileSync(path.join(dir, 'physx.release.wasm.wasm')),
        print,
        printErr: print,
      });
      // Process-wide PhysX objects, as a game creates them once (Cocos Creator's set-up).
      const foundation = PX.PxCreateFoundation(PX.PX_PHYSICS_VERSION, new PX.PxDefaultAllocator(),
        new PX.PxDefaultErrorCallback());
      const physics = PX.PxCreatePhysics(PX.PX_PHYSICS_VERSION, foundation, new PX.PxTolerancesScale(), false, null);
      PX.PxInitExtensions(physics, null);
      // getDefaultSceneDesc is the binding's own scene factory (what Cocos Creator uses): a
      // default PxSceneDesc for the tolerances scale, a CPU dispatcher with 0 worker threads
      // (simulation runs on the calling thread) and the binding's filter shader, which keeps a
      // pair only if its shapes' filter words match (see makeShape below). One desc (and its
      // dispatcher) is shared by all scenes; each case gets its own scene. No event callback.
      const sceneDesc = PX.getDefaultSceneDesc(physics.getTolerancesScale(), 0, null);
      mod = { PX, physics, sceneDesc };
    } else if (name === 'ammo') {
      let A = require('ammo.js');
      if (typeof A === 'function') A = A();
      if (A && typeof A.then === 'function') A = await new Promise((res) => A.then((m) => { delete m.then; res(m); }));
      mod = A;
    }
  } catch (e) {
    throw new EngineError(`could not load engine "${name}" (npm ${ENGINE_PACKAGES[name]}): ${e && e.stack || e}`);
  }
  loaded[name] = mod;
  return mod;
}

// ---------------------------------------------------------------- recording helpers

function makeRecorder(c) {
  const rows = { positions: [], velocities: [], angular_velocities: [] };
  let k = 0;
  return {
    rows,
    push(p, v, w) {
      for (const [name, r] of [['position', p], ['velocity', v], ['angular velocity', w]]) {
        if (!r.every(Number.isFinite)) {
          throw new EngineError(`case "${c.id}" (${c.engine}): non-finite ${name} after step ${k}: ${JSON.stringify(r)}`);
        }
      }
      rows.positions.push(p);
      rows.velocities.push(v);
      rows.angular_velocities.push(w);
      k++;
    },
  };
}

// ---------------------------------------------------------------- Jolt

const JOLT_DEFAULT_CONVEX_RADIUS = 0.05; // JPH::cDefaultConvexRadius

function runJolt(J, c) {
  const LAYER_STATIC = 0, LAYER_MOVING = 1;
  const settings = new J.JoltSettings();
  const objectFilter = new J.ObjectLayerPairFilterTable(2);
  objectFilter.EnableCollision(LAYER_STATIC, LAYER_MOVING);
  objectFilter.EnableCollision(LAYER_MOVING, LAYER_MOVING);
  const bpStatic = new J.BroadPhaseLayer(0), bpMoving = new J.BroadPhaseLayer(1);
  const bpInterface = new J.BroadPhaseLayerInterfaceTable(2, 2);
  bpInterface.MapObjectToBroadPhaseLayer(LAYER_STATIC, bpStatic);
  bpInterface.MapObjectToBroadPhaseLayer(LAYER_MOVING, bpMoving);
  J.destroy(bpStatic);
  J.destroy(bpMoving);
  settings.mObjectLayerPairFilter = objectFilter;
  settings.mBroadPhaseLayerInterface = bpInterface;
  settings.mObjectVsBroadPhaseLayerFilter = new J.ObjectVsBroadPhaseLayerFilterTable(bpInterface, 2, objectFilter, 2);
  const jolt = new J.JoltInterface(settings); // takes ownership of the three filter objects
  J.destroy(settings);
  const bodies = [];
  try {
    const system = jolt.GetPhysicsSystem();
    const bi = system.GetBodyInterface();
    const tmpV = new J.Vec3(c.gravity[0], c.gravity[1], c.gravity[2]);
    system.SetGravity(tmpV);
    J.destroy(tmpV);

    for (const bx of c.boxes) {
      const he = new J.Vec3(...bx.half_extents);
      const minHalf = Math.min(...bx.half_extents);
      // The given rounding as the convex radius; else the default convex radius unless the box
      // is too thin for it (Jolt requires radius <= half extent).
      let radius = Math.min(JOLT_DEFAULT_CONVEX_RADIUS, minHalf);
      if (bx.rounding !== undefined) radius = bx.rounding;
      const shape = new J.BoxShape(he, radius);
      J.destroy(he);
      const pos = new J.RVec3(...bx.center);
      const rot = new J.Quat(...bx.rotation);
      const bcs = new J.BodyCreationSettings(shape, pos, rot, J.EMotionType_Static, LAYER_STATIC);
      J.destroy(pos);
      J.destroy(rot);
      bcs.mFriction = bx.friction;
      bcs.mRestitution = bx.restitution;
      const body = bi.CreateBody(bcs);
      J.destroy(bcs);
      bi.AddBody(body.GetID(), J.EActivation_DontActivate);
      bodies.push(body);
    }

    const b = c.body;
    const shape = new J.SphereShape(b.radius);
    const pos = new J.RVec3(...b.position);
    const rot = new J.Quat(0, 0, 0, 1);
    const bcs = new J.BodyCreationSettings(shape, pos, rot, J.EMotionType_Dynamic, LAYER_MOVING);
    J.destroy(pos);
    J.destroy(rot);
    // Mass from the case, inertia computed from the shape for that mass (Jolt's own way).
    bcs.mOverrideMassProperties = J.EOverrideMassProperties_CalculateInertia;
    bcs.mMassPropertiesOverride.mMass = b.mass;
    bcs.mFriction = b.friction;
    bcs.mRestitution = b.restitution;
    if (b.linear_damping !== undefined) bcs.mLinearDamping = b.linear_damping;
    if (b.angular_damping !== undefined) bcs.mAngularDamping = b.angular_damping;
    bcs.mAllowSleeping = false;
    const v = new J.Vec3(...b.velocity), w = new J.Vec3(...b.angular_velocity);
    bcs.mLinearVelocity = v;
    bcs.mAngularVelocity = w;
    J.destroy(v);
    J.destroy(w);
    // CreateBody returns the Body; keep it (a returned BodyID would be a reused temporary).
    const body = bi.CreateBody(bcs);
    J.destroy(bcs);
    bi.AddBody(body.GetID(), J.EActivation_Activate);
    bodies.push(body);

    const rec = makeRecorder(c);
    const sample = () => {
      // Values are read at once: the binding returns them in reused temporaries.
      const p = body.GetPosition();
      const pv = [p.GetX(), p.GetY(), p.GetZ()];
      const lv = body.GetLinearVelocity();
      const lvv = [lv.GetX(), lv.GetY(), lv.GetZ()];
      const av = body.GetAngularVelocity();
      rec.push(pv, lvv, [av.GetX(), av.GetY(), av.GetZ()]);
    };
    sample();
    for (let k = 0; k < c.steps; k++) {
      jolt.Step(c.timestep, 1); // PhysicsSystem::Update(dt, 1 collision step, ...)
      sample();
    }
    for (const bd of bodies) {
      bi.RemoveBody(bd.GetID());
      bi.DestroyBody(bd.GetID());
    }
    return rec.rows;
  } finally {
    J.destroy(jolt);
  }
}

// ---------------------------------------------------------------- PhysX (@cocos/physx)

function runPhysX({ PX, physics, sceneDesc }, c) {
  const scene = physics.createScene(sceneDesc);
  const actors = [];
  const geoms = [];
  const shapeFlags = new PX.PxShapeFlags(PX.PxShapeFlag.eSIMULATION_SHAPE.value
    | PX.PxShapeFlag.eSCENE_QUERY_SHAPE.value | PX.PxShapeFlag.eVISUALIZATION.value); // PhysX default flags
  // The binding's filter shader suppresses a pair unless (w0a & w1b) && (w1a & w0b): all-zero
  // filter data (PhysX's default) would drop every contact.
  const filter = { word0: 1, word1: 1, word2: 0, word3: 0 };
  const makeShape = (geom, friction, restitution) => {
    const mat = physics.createMaterial(friction, friction, restitution); // static = dynamic friction
    const shape = physics.createShape(geom, mat, true, shapeFlags);
    mat.release(); // the shape holds a reference
    shape.setSimulationFilterData(filter);
    shape.setQueryFilterData(filter);
    return shape;
  };
  try {
    scene.setGravity({ x: c.gravity[0], y: c.gravity[1], z: c.gravity[2] });
    for (const bx of c.boxes) {
      const [qx, qy, qz, qw] = bx.rotation;
      const actor = physics.createRigidStatic({
        translation: { x: bx.center[0], y: bx.center[1], z: bx.center[2] },
        rotation: { x: qx, y: qy, z: qz, w: qw },
      });
      const geom = new PX.PxBoxGeometry({ x: bx.half_extents[0], y: bx.half_extents[1], z: bx.half_extents[2] });
      geoms.push(geom);
      const shape = makeShape(geom, bx.friction, bx.restitution);
      actor.attachShape(shape);
      shape.release(); // now owned by the actor
      scene.addActor(actor, null);
      actors.push(actor);
    }

    const b = c.body;
    const body = physics.createRigidDynamic({
      translation: { x: b.position[0], y: b.position[1], z: b.position[2] },
      rotation: { x: 0, y: 0, z: 0, w: 1 },
    });
    const geom = new PX.PxSphereGeometry(b.radius);
    geoms.push(geom);
    const shape = makeShape(geom, b.friction, b.restitution);
    body.attachShape(shape);
    shape.release();
    body.setMassAndUpdateInertia(b.mass); // PxRigidBodyExt: inertia of the shapes for that mass
    if (b.linear_damping !== undefined) body.setLinearDamping(b.linear_damping);
    if (b.angular_damping !== undefined) body.setAngularDamping(b.angular_damping);
    body.setSleepThreshold(0); // never falls asleep (no kinetic energy is below 0)
    body.setLinearVelocity({ x: b.velocity[0], y: b.velocity[1], z: b.velocity[2] }, true);
    body.setAngularVelocity({ x: b.angular_velocity[0], y: b.angular_velocity[1], z: b.angular_velocity[2] }, true);
    scene.addActor(body, null);
    actors.push(body);

    const rec = makeRecorder(c);
    const sample = () => {
      const p = body.getGlobalPose().translation;
      const v = body.getLinearVelocity();
      const w = body.getAngularVelocity();
      rec.push([p.x, p.y, p.z], [v.x, v.y, v.z], [w.x, w.y, w.z]);
    };
    sample();
    for (let k = 0; k < c.steps; k++) {
      scene.simulate(c.timestep, true);
      scene.fetchResults(true);
      sample();
    }
    return rec.rows;
  } finally {
    for (const a of actors) {
      scene.removeActor(a, false);
      a.release();
    }
    scene.release();
    for (const g of geoms) g.delete();
    shapeFlags.delete();
  }
}

// ---------------------------------------------------------------- Rapier

function runRapier(R, c) {
  const world = new R.World({ x: c.gravity[0], y: c.gravity[1], z: c.gravity[2] });
  try {
    world.timestep = c.timestep;
    for (const bx of c.boxes) {
      const [qx, qy, qz, qw] = bx.rotation;
      // A rounded box: Rapier's round cuboid is the inner box grown by its border radius.
      const r = bx.rounding ?? 0;
      const desc = (r > 0 ? R.ColliderDesc.roundCuboid(...bx.half_extents.map((h) => h - r), r)
                          : R.ColliderDesc.cuboid(...bx.half_extents))
        .setTranslation(...bx.center)
        .setRotation({ x: qx, y: qy, z: qz, w: qw })
        .setFriction(bx.friction)
        .setRestitution(bx.restitution);
      world.createCollider(desc); // parentless collider = static geometry
    }
    const b = c.body;
    const rbDesc = R.RigidBodyDesc.dynamic()
      .setTranslation(...b.position)
      .setLinvel(...b.velocity)
      .setAngvel({ x: b.angular_velocity[0], y: b.angular_velocity[1], z: b.angular_velocity[2] })
      .setCanSleep(false);
    if (b.linear_damping !== undefined) rbDesc.setLinearDamping(b.linear_damping);
    if (b.angular_damping !== undefined) rbDesc.setAngularDamping(b.angular_damping);
    const rb = world.createRigidBody(rbDesc);
    const colDesc = R.ColliderDesc.ball(b.radius)
      .setMass(b.mass) // inertia follows from the shape
      .setFriction(b.friction)
      .setRestitution(b.restitution);
    world.createCollider(colDesc, rb);

    const rec = makeRecorder(c);
    const sample = () => {
      const p = rb.translation(), v = rb.linvel(), w = rb.angvel();
      rec.push([p.x, p.y, p.z], [v.x, v.y, v.z], [w.x, w.y, w.z]);
    };
    sample();
    for (let k = 0; k < c.steps; k++) {
      world.step();
      sample();
    }
    return rec.rows;
  } finally {
    world.free();
  }
}

// ---------------------------------------------------------------- ammo.js (Bullet)

function runAmmo(A, c) {
  const trash = []; // every Emscripten object created here, destroyed in reverse order
  const mk = (o) => (trash.push(o), o);
  const v3 = (a) => mk(new A.btVector3(a[0], a[1], a[2]));
  const bodies = [];
  const cfg = mk(new A.btDefaultCollisionConfiguration());
  const dispatcher = mk(new A.btCollisionDispatcher(cfg));
  const broadphase = mk(new A.btDbvtBroadphase());
  const solver = mk(new A.btSequentialImpulseConstraintSolver());
  const world = mk(new A.btDiscreteDynamicsWorld(dispatcher, broadphase, solver, cfg));
  try {
    world.setGravity(v3(c.gravity));
    const makeBody = (shape, mass, pos, rot, friction, restitution, damping) => {
      const tr = mk(new A.btTransform());
      tr.setIdentity();
      tr.setOrigin(v3(pos));
      tr.setRotation(mk(new A.btQuaternion(rot[0], rot[1], rot[2], rot[3])));
      const motionState = mk(new A.btDefaultMotionState(tr));
      const inertia = v3([0, 0, 0]);
      if (mass > 0) shape.calculateLocalInertia(mass, inertia);
      const info = mk(new A.btRigidBodyConstructionInfo(mass, motionState, shape, inertia));
      info.set_m_friction(friction);
      info.set_m_restitution(restitution);
      if (damping && damping.linear !== undefined) info.set_m_linearDamping(damping.linear);
      if (damping && damping.angular !== undefined) info.set_m_angularDamping(damping.angular);
      const body = new A.btRigidBody(info);
      bodies.push(body);
      return body;
    };
    for (const bx of c.boxes) {
      const shape = mk(new A.btBoxShape(v3(bx.half_extents)));
      // The rounding is the box's collision margin (its outer size kept).
      if (bx.rounding !== undefined) shape.setMargin(bx.rounding);
      world.addRigidBody(makeBody(shape, 0, bx.center, bx.rotation, bx.friction, bx.restitution));
    }
    const b = c.body;
    const sphere = mk(new A.btSphereShape(b.radius));
    const body = makeBody(sphere, b.mass, b.position, [0, 0, 0, 1], b.friction, b.restitution,
      { linear: b.linear_damping, angular: b.angular_damping });
    body.setActivationState(4); // DISABLE_DEACTIVATION
    body.setLinearVelocity(v3(b.velocity));
    body.setAngularVelocity(v3(b.angular_velocity));
    world.addRigidBody(body);

    const rec = makeRecorder(c);
    const sample = () => {
      const p = body.getWorldTransform().getOrigin();
      const v = body.getLinearVelocity();
      const w = body.getAngularVelocity();
      rec.push([p.x(), p.y(), p.z()], [v.x(), v.y(), v.z()], [w.x(), w.y(), w.z()]);
    };
    sample();
    for (let k = 0; k < c.steps; k++) {
      // maxSubSteps 1, fixedTimeStep = timestep: the accumulator reaches exactly one step.
      const n = world.stepSimulation(c.timestep, 1, c.timestep);
      if (n !== 1) throw new EngineError(`case "${c.id}" (ammo): stepSimulation did ${n} internal steps at step ${k + 1}, expected 1`);
      sample();
    }
    return rec.rows;
  } finally {
    for (const body of bodies) {
      world.removeRigidBody(body);
      A.destroy(body);
    }
    for (const o of trash.reverse()) A.destroy(o);
  }
}

const RUNNERS = { jolt: runJolt, physx: runPhysX, rapier: runRapier, ammo: runAmmo };

// ---------------------------------------------------------------- output

function formatResults(out) {
  const rowsText = (rows) => '[\n    ' + rows.map((r) => JSON.stringify(r)).join(',\n    ') + ']';
  const parts = out.results.map((r) =>
    `  {"id": ${JSON.stringify(r.id)}, "engine": ${JSON.stringify(r.engine)},\n` +
    `   "positions": ${rowsText(r.positions)},\n` +
    `   "velocities": ${rowsText(r.velocities)},\n` +
    `   "angular_velocities": ${rowsText(r.angular_velocities)}}`);
  return `{"engine_versions": ${JSON.stringify(out.engine_versions)},\n` +
    ` "skipped": ${JSON.stringify(out.skipped)},\n` +
    (parts.length ? ` "results": [\n${parts.join(',\n')}\n ]}\n` : ' "results": []}\n');
}

// ---------------------------------------------------------------- main

async function main(argv) {
  if (argv.length !== 2 || argv.some((a) => a === '-h' || a === '--help')) {
    throw new InputError('usage: node harness.mjs CASES.json OUT.json   ("-" = stdin / stdout)');
  }
  const [inName, outName] = argv;
  let text;
  try {
    text = inName === '-' ? fs.readFileSync(0, 'utf8') : fs.readFileSync(inName, 'utf8');
  } catch (e) {
    throw new InputError(`cannot read ${inName}: ${e.message}`);
  }
  const { run, skipped } = parseCaseFile(text, inName === '-' ? 'stdin' : inName);

  const engine_versions = {};
  for (const [name, pkg] of Object.entries(ENGINE_PACKAGES)) engine_versions[name] = packageVersion(pkg);

  const results = [];
  for (const c of run) {
    const mod = await loadEngine(c.engine);
    let rows;
    try {
      rows = RUNNERS[c.engine](mod, c);
    } catch (e) {
      if (e instanceof EngineError) throw e;
      throw new EngineError(`case "${c.id}" (${c.engine}): engine failed: ${e && e.stack || e}`);
    }
    results.push({ id: c.id, engine: c.engine, ...rows });
  }

  const text_out = formatResults({ engine_versions, skipped, results });
  if (outName === '-') {
    await new Promise((res, rej) => process.stdout.write(text_out, (err) => (err ? rej(err) : res())));
  } else {
    try {
      fs.writeFileSync(outName, text_out);
    } catch (e) {
      throw new EngineError(`cannot write ${outName}: ${e.message}`);
    }
  }
}

main(process.argv.slice(2)).then(
  () => process.exit(0),
  (e) => {
    if (e instanceof InputError) {
      process.stderr.write(`harness.mjs: bad input: ${e.message}\n`);
      process.exit(2);
    }
    process.stderr.write(`harness.mjs: ${e instanceof EngineError ? e.message : (e && e.stack) || e}\n`);
    process.exit(1);
  },
);
