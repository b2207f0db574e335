// The JavaScript API against closed forms and, when CTest gives the native reference program
// (FORESIGHT_NATIVE_REFERENCE, test/native_reference.c built on the native C API), against the
// native library's numbers bit for bit.
//
//   node --test test/

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';

import { loadForesight, TrajectoryEvent, Status } from '../index.mjs';

const fs = await loadForesight();
const f = Math.fround;

// The library computes in float (positions are rounded to float in the default build, velocities
// and times are float): a closed form evaluated in float arithmetic step by step is what it
// returns, but the order of operations may differ, so these checks allow a few float ulps of the
// magnitudes involved (|p| <= 100 here: 100 * 2^-23 ~ 1.2e-5; 2e-5 covers that with margin).
const FLOAT_ABS = 2e-5;
function near(actual, expected, tolerance, what) {
    for (const axis of ['x', 'y', 'z']) {
        assert.ok(Math.abs(actual[axis] - expected[axis]) <= tolerance,
            `${what}.${axis}: ${actual[axis]} vs ${expected[axis]} (tolerance ${tolerance})`);
    }
}

test('loads, ABI version 1', () => {
    assert.equal(fs.abiVersion(), 1);
});

test('predictLinear is p + v t', () => {
    const r = fs.predictLinear({ position: { x: 1, y: 2, z: 3 }, velocity: [4, -5, 6] }, 1.5);
    // 1 + 4 * 1.5 = 7, 2 - 7.5 = -5.5, 3 + 9 = 12: exact in float.
    assert.deepEqual(r.position, { x: 7, y: -5.5, z: 12 });
    assert.deepEqual(r.velocity, { x: 4, y: -5, z: 6 });
    const p = [10.3, -4.7, 88.1], v = [1.1, 2.2, -3.3], t = 0.7;
    const s = fs.predictLinear({ position: p, velocity: v }, t);
    near(s.position, { x: p[0] + v[0] * t, y: p[1] + v[1] * t, z: p[2] + v[2] * t }, FLOAT_ABS, 'position');
    assert.deepEqual(s.velocity, { x: f(1.1), y: f(2.2), z: f(-3.3) }); // unchanged, rounded to float
});

test('predictAccelerated is p + v t + a t^2 / 2, velocity v + a t', () => {
    const r = fs.predictAccelerated({ position: [0, 10, 0], velocity: [2, 0, 3] }, [0, -10, 0], 1);
    // Exact in float: y = 10 + 0 - 5 = 5.
    assert.deepEqual(r.position, { x: 2, y: 5, z: 3 });
    assert.deepEqual(r.velocity, { x: 2, y: -10, z: 3 });
    const p = [1.25, 3.5, -7.75], v = [0.3, 4.1, -2.2], a = [0.5, -9.81, 1.5], t = 1.3;
    const s = fs.predictAccelerated({ position: p, velocity: v }, a, t);
    near(s.position, {
        x: p[0] + v[0] * t + a[0] * t * t / 2, y: p[1] + v[1] * t + a[1] * t * t / 2, z: p[2] + v[2] * t + a[2] * t * t / 2,
    }, FLOAT_ABS, 'position');
    near(s.velocity, { x: v[0] + a[0] * t, y: v[1] + a[1] * t, z: v[2] + a[2] * t }, FLOAT_ABS, 'velocity');
});

test('predictVehicleExact follows the arc of radius |v| / |w|', () => {
    // Speed 10 m/s along +Z, turning at 0.5 rad/s about +Y (body frame): after t the heading is
    // 0.5 t, the position (R (1 - cos), 0, R sin) with R = 20 m.
    const start = { position: [0, 0, 0], velocity: [0, 0, 10], orientation: [0, 0, 0, 1], angularVelocity: [0, 0.5, 0] };
    for (const t of [0.5, 2, 3]) {
        const r = fs.predictVehicleExact(start, t);
        const heading = 0.5 * t;
        near(r.position, { x: 20 * (1 - Math.cos(heading)), y: 0, z: 20 * Math.sin(heading) }, FLOAT_ABS, `position(${t})`);
        near(r.velocity, { x: 10 * Math.sin(heading), y: 0, z: 10 * Math.cos(heading) }, FLOAT_ABS, `velocity(${t})`);
        // The orientation: a rotation by the heading about +Y, (0, sin(h/2), 0, cos(h/2)).
        assert.ok(Math.abs(r.orientation.y - Math.sin(heading / 2)) <= 1e-6, 'orientation.y'); // float ulps of 1
        assert.ok(Math.abs(r.orientation.w - Math.cos(heading / 2)) <= 1e-6, 'orientation.w');
        assert.deepEqual(r.angularVelocity, { x: 0, y: 0.5, z: 0 });
    }
});

test('predictVehicleIterative: one iteration moves straight, then turns', () => {
    const start = { position: [0, 0, 0], velocity: [0, 0, 10], angularVelocity: [0, 0.5, 0] };
    const r = fs.predictVehicleIterative(start, 2, 1);
    // One step: moves 20 m along +Z with the start velocity, then turns by 1 rad.
    near(r.position, { x: 0, y: 0, z: 20 }, FLOAT_ABS, 'position');
    near(r.velocity, { x: 10 * Math.sin(1), y: 0, z: 10 * Math.cos(1) }, FLOAT_ABS, 'velocity');
    // The world frame gives the same numbers when the orientation is the identity.
    const w = fs.predictVehicleIterative(start, 2, 1, { frame: 'world' });
    assert.deepEqual(w, r);
});

test('predictProjectile in free flight is p + v t + g t^2 / 2 with Float64Array positions', () => {
    const r = fs.predictProjectile([0, 2, 0], [3, 4, 5], 0.8);
    near(r.position, { x: 3 * 0.8, y: 2 + 4 * 0.8 - 9.81 * 0.32, z: 5 * 0.8 }, FLOAT_ABS, 'position');
    near(r.velocity, { x: 3, y: 4 - 9.81 * 0.8, z: 5 }, FLOAT_ABS, 'velocity');
    assert.equal(r.time, f(0.8));
    assert.equal(r.bounces, 0);
    assert.equal(r.atRest, false);
    const t = r.trajectory;
    assert.ok(t.position instanceof Float64Array && t.time instanceof Float32Array && t.event instanceof Int32Array);
    assert.equal(t.position.length, 3 * t.length);
    assert.equal(t.event[0], TrajectoryEvent.start);
    assert.equal(t.event[t.length - 1], TrajectoryEvent.end);
    // Exact method: a point every `step` (0.02 s): 0.8 / 0.02 = 40 steps, start, 39 step points, end.
    assert.equal(t.length, 41);
    for (let i = 0; i < t.length; ++i) {
        const s = t.time[i];
        const y = 2 + 4 * s - 9.81 * s * s / 2;
        assert.ok(Math.abs(t.position[3 * i + 1] - y) <= FLOAT_ABS, `y(${s}) = ${t.position[3 * i + 1]}, not ${y}`);
    }
    assert.equal(fs.predictProjectile([0, 2, 0], [3, 4, 5], 0.8, { trajectory: false }).trajectory, null);
});

test('a floor bounces the projectile with the restitution', () => {
    const world = fs.createWorld().addPlane({ normal: [0, 1, 0], distance: 0 });
    try {
        // Dropped from 5 m: hits at sqrt(2 * 5 / 9.81) s with speed sqrt(2 * 9.81 * 5), leaves
        // with half of it (restitution 0.5).
        const r = fs.predictProjectile([0, 5, 0], [0, 0, 0], 1.2, { world, settings: { maxBounces: 1 } });
        const t = r.trajectory;
        const bounce = Array.from(t.event).indexOf(TrajectoryEvent.bounce);
        assert.ok(bounce > 0);
        const hit = Math.sqrt(2 * 5 / 9.81);
        assert.ok(Math.abs(t.time[bounce] - hit) <= 1e-6, `impact at ${t.time[bounce]}, not ${hit}`); // float ulps of 1 s
        assert.ok(Math.abs(t.position[3 * bounce + 1]) <= FLOAT_ABS);
        assert.ok(Math.abs(t.velocity[3 * bounce + 1] - 0.5 * 9.81 * hit) <= 1e-4, // float ulps of 10 m/s
            `rebound ${t.velocity[3 * bounce + 1]}`);
        assert.deepEqual(Array.from(t.normal.subarray(3 * bounce, 3 * bounce + 3)), [0, 1, 0]);
        // Stopped at the second impact (maxBounces 1).
        const stopped = fs.predictProjectile([0, 5, 0], [0, 0, 0], 10, { world, settings: { maxBounces: 1 } });
        assert.equal(stopped.stoppedAtHit, true);
        assert.equal(stopped.bounces, 1);
        assert.deepEqual(stopped.hitNormal, { x: 0, y: 1, z: 0 });
    } finally {
        world.delete();
    }
});

test('a long trajectory grows the buffer and keeps every point', () => {
    // Stepped, 0.001 s steps for 20 s: 20000 steps, more than the initial buffer.
    const r = fs.predictProjectile([0, 0, 0], [1, 100, 0], 20, { settings: { method: 'stepped', step: 0.001 } });
    assert.equal(r.trajectory.length, 20001);
    assert.equal(r.trajectory.event[20000], TrajectoryEvent.end);
});

test('aimProjectile: the speed constraint hits a still target at that speed', () => {
    const solutions = fs.aimProjectile({ from: [0, 1.5, 0], speed: 25 }, { position: [30, 0, 40] });
    assert.equal(solutions.length, 2); // low and high arc
    assert.ok(solutions[0].time < solutions[1].time);
    for (const s of solutions) {
        const v = s.velocity;
        assert.ok(Math.abs(Math.hypot(v.x, v.y, v.z) - 25) <= 1e-4, 'speed'); // float ulps of 25 m/s
        // Where the free flight is at that time: the target.
        const t = s.time;
        near({ x: v.x * t, y: 1.5 + v.y * t - 9.81 * t * t / 2, z: v.z * t }, { x: 30, y: 0, z: 40 }, 1e-3, 'flight'); // float ulps of 50 m times a few
    }
    assert.deepEqual(fs.aimProjectile({ from: [0, 0, 0], speed: 5 }, { position: [100, 0, 0] }), []); // out of reach
});

test('projectileSettings gives the library defaults', () => {
    const d = fs.projectileSettings();
    assert.equal(d.method, 'exact');
    assert.equal(d.engine, 'jolt');
    assert.deepEqual(d.gravity, { x: 0, y: f(-9.81), z: 0 });
    assert.equal(d.step, f(0.02));
    assert.equal(d.restitution, 0.5);
    assert.equal(d.maxBounces, 0xffffffff);
    assert.equal(Status.NEGATIVE_TIME, 2);
});

const native = process.env.FORESIGHT_NATIVE_REFERENCE;
test('projectiles, vehicles and aim equal the native library bit for bit', { skip: !native && 'FORESIGHT_NATIVE_REFERENCE not set' }, () => {
    const reference = JSON.parse(execFileSync(native, { encoding: 'utf8', maxBuffer: 64 << 20 }));
    const world = fs.createWorld()
        .addPlane({ normal: [0, 1, 0], distance: 0 })
        .addBox({ center: [0, 1.5, 10], halfExtents: [5, 1.5, 0.25], orientation: [0, 0.130526, 0, 0.991445] },
            { restitution: 0.8, friction: 0.1 })
        .addSphere({ center: [2, 0.5, 5], radius: 0.5 })
        .addTriangle({ a: [-3, 0, 3], b: [-1, 0, 3], c: [-2, 1, 6] });
    try {
        assert.ok(reference.projectiles.length >= 40);
        for (const [i, p] of reference.projectiles.entries()) {
            const what = `projectile ${i} (${p.settings.method} ${p.settings.engine})`;
            const options = { settings: p.settings, world: p.world ? world : null };
            let r;
            try {
                r = fs.predictProjectile(p.position, p.velocity, p.time, options);
            } catch (error) {
                assert.equal(error.status, p.status, `${what}: ${error.message}`);
                continue;
            }
            assert.equal(p.status, 0, `${what}: native refused with ${p.status}`);
            const x = p.result;
            assert.deepEqual([r.position.x, r.position.y, r.position.z], x.position, `${what} position`);
            assert.deepEqual([r.velocity.x, r.velocity.y, r.velocity.z], x.velocity, `${what} velocity`);
            assert.deepEqual([r.time, r.bounces, r.atRest, r.stoppedAtHit], [x.time, x.bounces, x.atRest, x.stoppedAtHit], what);
            assert.deepEqual([r.hitNormal.x, r.hitNormal.y, r.hitNormal.z], x.hitNormal, `${what} hit normal`);
            const t = r.trajectory;
            assert.equal(t.length, p.trajectory.length, `${what} points`);
            for (let k = 0; k < t.length; ++k) {
                const row = [t.time[k], t.event[k], Array.from(t.position.subarray(3 * k, 3 * k + 3)),
                    Array.from(t.velocity.subarray(3 * k, 3 * k + 3)), Array.from(t.normal.subarray(3 * k, 3 * k + 3))];
                assert.deepEqual(row, p.trajectory[k], `${what} point ${k}`);
            }
        }
    } finally {
        world.delete();
    }
    const list = (v) => [v.x, v.y, v.z];
    for (const v of reference.vehicles) {
        const state = { position: v.position, velocity: v.velocity, orientation: v.orientation, angularVelocity: v.angularVelocity };
        const iterated = fs.predictVehicleIterative(state, v.time, v.iterations, { frame: v.frame });
        const exact = fs.predictVehicleExact(state, v.time, { frame: v.frame });
        for (const [got, want] of [[iterated, v.iterative], [exact, v.exact]]) {
            assert.deepEqual(list(got.position), want.position);
            assert.deepEqual(list(got.velocity), want.velocity);
            const q = got.orientation;
            assert.deepEqual([q.x, q.y, q.z, q.w], want.orientation);
        }
    }
    for (const a of reference.aims) {
        const solutions = fs.aimProjectile({ from: a.from, constraint: a.constraint, speed: a.speed, apexHeight: a.apexHeight },
            { position: a.target, velocity: a.targetVelocity });
        assert.ok(a.solutions.length > 0);
        assert.deepEqual(solutions.map((s) => ({ velocity: list(s.velocity), time: s.time, hit: list(s.hit), elevation: s.elevation })),
            a.solutions, `aim ${a.constraint}`);
    }
});
