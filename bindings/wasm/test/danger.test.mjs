// Danger (a predicted grenade's blast and path) and vehicle contact against closed forms, their
// refusals, and no heap growth over repeated calls.
//
//   node --test test/

import { test } from 'node:test';
import assert from 'node:assert/strict';

import { loadForesight, ForesightError, Status } from '../index.mjs';

const fs = await loadForesight();

// Positions and times are float inside the library: a closed form evaluated in double differs
// by a few float ulps of the magnitudes involved (|p| <= 30 here: 30 * 2^-23 ~ 3.6e-6; 2e-5
// covers that with margin).
const FLOAT_ABS = 2e-5;
function near(actual, expected, tolerance, what) {
    const a = typeof actual === 'number' ? [actual] : [actual.x, actual.y, actual.z];
    const e = typeof expected === 'number' ? [expected] : expected;
    for (let k = 0; k < a.length; ++k) {
        assert.ok(Math.abs(a[k] - e[k]) <= tolerance, `${what}[${k}]: ${a[k]} vs ${e[k]} (tolerance ${tolerance})`);
    }
}
function refuses(call, status, text) {
    assert.throws(call, (error) => {
        assert.ok(error instanceof ForesightError, `${error}`);
        assert.equal(error.status, status);
        assert.match(error.message, text);
        return true;
    });
}

// A grenade in free flight from the hand: x(t) = p0 + v0 t + g t^2 / 2.
const p0 = [0, 1.6, 0], v0 = [0, 4, 12], g = -9.81;
const at = (t) => [p0[0] + v0[0] * t, p0[1] + v0[1] * t + g * t * t / 2, p0[2] + v0[2] * t];
const { trajectory } = fs.predictProjectile(p0, v0, 2);
const danger = { fuseTime: 1.5, blastRadius: 5 };

test('the danger zone is the blast centred on the parabola at the fuse time', () => {
    const zone = fs.computeDangerZone(trajectory, danger);
    near(zone.center, at(1.5), FLOAT_ABS, 'center'); // (0, -3.43625, 18)
    assert.equal(zone.radius, 5);
    assert.equal(zone.time, 1.5);
});

test('isPointSafe: inside the blast from the fuse on, near the grenade before it', () => {
    const c = at(1.5);
    const inside = [c[0] + 4.9, c[1], c[2]], outside = [c[0] + 5.1, c[1], c[2]];
    assert.equal(fs.isPointSafe(trajectory, danger, inside, 1.6), false);
    assert.equal(fs.isPointSafe(trajectory, danger, inside, 1.4), true); // before the fuse, 5 m from the path
    assert.equal(fs.isPointSafe(trajectory, danger, outside, 1.6), true);
    // With a contact radius, the grenade's own path is unsafe as it passes.
    assert.equal(fs.isPointSafe(trajectory, { ...danger, contactRadius: 0.3 }, at(0.5), 0.5), false);
    assert.equal(fs.isPointSafe(trajectory, danger, at(0.5), 0.5), true);
});

test('findDangerStart: the fuse time in the blast, when the grenade comes close on its path, null far away', () => {
    const c = at(1.5);
    near(fs.findDangerStart(trajectory, danger, [c[0] + 1, c[1], c[2]]), 1.5, 0, 'in the blast');
    assert.equal(fs.findDangerStart(trajectory, danger, [100, 0, 0]), null);
    // A point on the path at 0.5 s with a contact radius of 0.5 m: danger starts when the grenade
    // is first 0.5 m from it. The reference is the parabola's own root, bisected in double.
    const point = at(0.5), radius = 0.5;
    const dist = (t) => Math.hypot(...at(t).map((x, k) => x - point[k]));
    let lo = 0, hi = 0.5;
    for (let i = 0; i < 60; ++i) {
        const mid = (lo + hi) / 2;
        if (dist(mid) <= radius) hi = mid; else lo = mid;
    }
    // Speed there ~12 m/s: a float ulp of the 6 m distances involved (~5e-7 m) is ~4e-8 s, and the
    // float time itself is within 3e-8 s; 1e-6 s allows the library's float solve with margin.
    near(fs.findDangerStart(trajectory, { ...danger, contactRadius: radius }, point), hi, 1e-6, 'path start');
});

test('findClosestPathApproach: 3 m beside the path at 1 s is 3 m at 1 s', () => {
    const p = at(1);
    const r = fs.findClosestPathApproach(trajectory, [p[0] + 3, p[1], p[2]]);
    // The path lies in the plane x = 0 and passes the point's foot there at 1 s: 3 m, exactly
    // up to float rounding of positions (FLOAT_ABS); the time, found from the float positions,
    // within 1e-4 s (the distance is flat at its minimum: sqrt(9 + 144 dt^2) - 3 < 3e-6 m for dt < 1e-4).
    near(r.distance, 3, FLOAT_ABS, 'distance');
    near(r.time, 1, 1e-4, 'time');
    const later = fs.findClosestPathApproach(trajectory, [p[0] + 3, p[1], p[2]], 1.5, 2);
    near(later.time, 1.5, 0, 'time clamped to the window');
});

test('danger refusals name the problem', () => {
    refuses(() => fs.computeDangerZone(trajectory, { fuseTime: -1, blastRadius: 5 }), Status.INVALID_FUSE,
        /^computeDangerZone: .*fuse/i);
    refuses(() => fs.computeDangerZone(trajectory, { fuseTime: 1, blastRadius: -5 }), Status.INVALID_RADIUS,
        /^computeDangerZone: .*radius/i);
    refuses(() => fs.isPointSafe(trajectory, danger, [NaN, 0, 0], 1), Status.NON_FINITE_INPUT, /^isPointSafe: /);
    const empty = { length: 0, time: [], event: [], position: [], velocity: [], normal: [] };
    refuses(() => fs.findDangerStart(empty, danger, [0, 0, 0]), Status.INVALID_STEP, /^findDangerStart: /);
    assert.throws(() => fs.computeDangerZone({ length: 2 }, danger), /trajectory.time must have 2 numbers/);
    assert.throws(() => fs.computeDangerZone(null, danger), TypeError);
    assert.throws(() => fs.computeDangerZone(trajectory, { fuse: 1 }), /unknown field "fuse"/);
});

// A car at the origin facing +Z at 10 m/s, its default box (half extents 0.9, 0.7, 2.2 m).
const car = { position: [0, 0, 0], velocity: [0, 0, 10] };

test('findVehicleContact: a car reaches a standing character at (30 - 0.4 - 2.2) / 10 s', () => {
    const r = fs.findVehicleContact(car, { position: [0, 0, 30] }, 5);
    assert.equal(r.contact, true);
    // Never later than the true first overlap, within the tolerance (1e-3 m at 10 m/s: 1e-4 s)
    // earlier; 1e-6 s more for the float time.
    const exact = (30 - 0.4 - 2.2) / 10;
    assert.ok(r.time <= exact + 1e-6 && r.time >= exact - 1e-4 - 1e-6, `time ${r.time} vs ${exact}`);
    assert.ok(r.separation <= 1e-3 && r.separation >= -1e-6, `separation ${r.separation}`);
    assert.ok(r.evaluations >= 1);
    const miss = fs.findVehicleContact(car, { position: [5, 0, 30] }, 5);
    assert.equal(miss.contact, false);
    near(miss.separation, Math.hypot(5 - 0.9, 50 - 2.2 - 30) - 0.4, FLOAT_ABS * 10, 'separation at the horizon'); // |p| ~ 50: 10x the ulp margin
});

test('findClosestVehicleApproach: a character 5 m beside the lane is 5 - 0.9 - 0.4 m away', () => {
    const r = fs.findClosestVehicleApproach(car, { position: [5, 0, 30], radius: 0.4 }, 5);
    // Within the approach tolerance (1e-3 m) of the exact 3.7 m.
    near(r.distance, 3.7, 1e-3, 'distance');
    // The box's side passes the character between (30 - 2.2) / 10 and (30 + 2.2) / 10 s; within
    // the 1e-3 m tolerance a time up to sqrt(4.101^2 - 4.1^2) = 0.0906 m of travel (0.00906 s)
    // outside that is as close, so the window is widened by 0.0091 s.
    assert.ok(r.time >= 2.78 - 0.0091 && r.time <= 3.22 + 0.0091, `time ${r.time}`);
});

test('vehicle refusals name the problem', () => {
    refuses(() => fs.findVehicleContact(car, { position: [0, 0, 30] }, -1), Status.NEGATIVE_TIME, /^findVehicleContact: /);
    refuses(() => fs.findVehicleContact(car, { position: [0, 0, 30], radius: -1 }, 1), Status.INVALID_RADIUS,
        /^findVehicleContact: .*radius/i);
    refuses(() => fs.findVehicleContact({ ...car, position: [NaN, 0, 0] }, { position: [0, 0, 30] }, 1),
        Status.NON_FINITE_INPUT, /^findVehicleContact: /);
    refuses(() => fs.findClosestVehicleApproach(car, { position: [0, 0, 30] }, 1, { tolerance: 0 }), Status.INVALID_STEP,
        /^findClosestVehicleApproach: /);
    assert.throws(() => fs.findVehicleContact(car, { position: [0, 0, 30], size: 1 }, 1), /unknown field "size"/);
});

test('repeated danger and contact queries leave the heap as it was', () => {
    fs.computeDangerZone(trajectory, danger); // the library's per-thread buffer for this size, once
    const heapEnd = fs.heapEnd();
    for (let i = 0; i < 1000; ++i) {
        fs.isPointSafe(trajectory, danger, [i % 7, 0, 10], 1.6);
        fs.findDangerStart(trajectory, { ...danger, contactRadius: 0.2 }, [0, 1, 10]);
        fs.findClosestPathApproach(trajectory, [1, 1, 1]);
        fs.findVehicleContact(car, { position: [i % 3, 0, 30] }, 5);
    }
    assert.equal(fs.heapEnd(), heapEnd);
});
