// Dead reckoning for netcode: predictDeadReckoning against the DIS closed forms,
// predictDeadReckoningBatch against the single call, a Receiver taking updates, refusals, no
// leaks, and (when CTest gives FORESIGHT_NATIVE_REFERENCE, test/native_reference.c) the native
// library's numbers bit for bit for every algorithm.
//
//   node --test test/

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';

import { loadForesight, DeadReckoning, ForesightError, Receiver, Status } from '../index.mjs';

const fs = await loadForesight();
const f = Math.fround;
const list = (v) => ('w' in v ? [v.x, v.y, v.z, v.w] : [v.x, v.y, v.z]);

// The library computes in float (positions rounded to float in the default build): a closed form
// evaluated in double differs from it by the float roundings of its few operations, a few ulps of
// the magnitudes involved (|p| <= 50 here: 50 * 2^-23 ~ 6e-6; 2e-5 covers that with margin).
const FLOAT_ABS = 2e-5;
// A rotation computed in float (quaternion exp, product, vector rotation): each component is off
// by a few float ulps of 1 (2^-23 ~ 1.2e-7); 1e-6 allows some eight of them.
const ROTATION_ABS = 1e-6;
function near(actual, expected, tolerance, what) {
    const a = list(actual);
    assert.equal(a.length, expected.length, what);
    for (let k = 0; k < a.length; ++k) {
        assert.ok(Math.abs(a[k] - expected[k]) <= tolerance,
            `${what}[${k}]: ${a[k]} vs ${expected[k]} (tolerance ${tolerance})`);
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

const p = [12.5, 1.25, -40], v = [6, 0.5, 9], a = [-1.5, 0.25, 2];

test('algorithm names: the DIS names, "?" for another value', () => {
    assert.deepEqual(Object.keys(DeadReckoning).map((name) => fs.deadReckoningAlgorithmName(name)),
        ['STATIC', 'FPW', 'RPW', 'RVW', 'FVW', 'FPB', 'RPB', 'RVB', 'FVB']);
    assert.equal(fs.deadReckoningAlgorithmName(4), 'RVW');
    assert.equal(fs.deadReckoningAlgorithmName(0), '?');
    assert.equal(fs.deadReckoningAlgorithmName(10), '?');
});

test('STATIC leaves the state as given', () => {
    const r = fs.predictDeadReckoning({ position: p, velocity: v, algorithm: 'STATIC' }, 2);
    assert.deepEqual(list(r.position), p); // exact: 12.5, 1.25, -40 are floats
    assert.deepEqual(list(r.velocity), v); // echoed
    assert.deepEqual(list(r.orientation), [0, 0, 0, 1]);
});

test('FPW is p + v t', () => {
    // 12.5 + 6 * 1.5 = 21.5, 1.25 + 0.75 = 2, -40 + 13.5 = -26.5: exact in float.
    const r = fs.predictDeadReckoning({ position: p, velocity: v, algorithm: 'FPW' }, 1.5);
    assert.deepEqual(list(r.position), [21.5, 2, -26.5]);
    assert.deepEqual(list(r.velocity), v);
    const t = 0.7;
    const s = fs.predictDeadReckoning({ position: [1.1, 2.2, 3.3], velocity: [4.4, -5.5, 6.6], algorithm: DeadReckoning.FPW }, t);
    near(s.position, [1.1 + 4.4 * t, 2.2 - 5.5 * t, 3.3 + 6.6 * t], FLOAT_ABS, 'position');
});

test('FVW and RVW are p + v t + a t^2 / 2, velocity v + a t', () => {
    const t = 1.3;
    for (const algorithm of ['FVW', 'RVW']) {
        const r = fs.predictDeadReckoning({ position: p, velocity: v, acceleration: a, algorithm }, t);
        near(r.position, p.map((x, k) => x + v[k] * t + a[k] * t * t / 2), FLOAT_ABS, `${algorithm} position`);
        near(r.velocity, v.map((x, k) => x + a[k] * t), FLOAT_ABS, `${algorithm} velocity`);
    }
    // The acceleration is ignored by the constant-velocity models.
    const r = fs.predictDeadReckoning({ position: p, velocity: v, acceleration: a, algorithm: 'FPW' }, 1.5);
    assert.deepEqual(list(r.position), [21.5, 2, -26.5]);
});

test('FPB moves along the body axes; RPW turns the orientation by the angular velocity', () => {
    const quarterY = [0, Math.SQRT1_2, 0, Math.SQRT1_2]; // 90 degrees about +Y: body +Z is world +X
    const r = fs.predictDeadReckoning({ position: [0, 0, 0], velocity: [0, 0, 2], orientation: quarterY, algorithm: 'FPB' }, 3);
    near(r.position, [6, 0, 0], FLOAT_ABS, 'FPB position');
    assert.deepEqual(list(r.velocity), [0, 0, 2]); // body axes
    // 1 rad/s about body +Y for pi/2 s: a quarter turn about +Y from identity.
    const s = fs.predictDeadReckoning({ position: [0, 0, 0], velocity: [1, 0, 0], angularVelocity: [0, 1, 0], algorithm: 'RPW' },
        Math.PI / 2);
    near(s.orientation, quarterY, ROTATION_ABS, 'RPW orientation');
    near(s.position, [Math.PI / 2, 0, 0], FLOAT_ABS, 'RPW position'); // world velocity: a straight line
});

test('refused input: ForesightError with the library message', () => {
    const state = { position: p, velocity: v, algorithm: 'FPW' };
    refuses(() => fs.predictDeadReckoning(state, -1), Status.NEGATIVE_TIME, /^predictDeadReckoning: time must be >= 0$/);
    refuses(() => fs.predictDeadReckoning(state, NaN), Status.NON_FINITE_INPUT, /^predictDeadReckoning: /);
    refuses(() => fs.predictDeadReckoning({ ...state, position: [NaN, 0, 0] }, 1), Status.NON_FINITE_INPUT,
        /^predictDeadReckoning: .*(finite|NaN)/i);
    // Every field is checked, used or not: FPW ignores the angular velocity but refuses it infinite.
    refuses(() => fs.predictDeadReckoning({ ...state, angularVelocity: [0, Infinity, 0] }, 1), Status.NON_FINITE_INPUT,
        /predictDeadReckoning/);
    refuses(() => fs.predictDeadReckoning({ ...state, algorithm: 0 }, 1), Status.INVALID_ALGORITHM,
        /^predictDeadReckoning: .*algorithm/i);
    refuses(() => fs.predictDeadReckoning({ ...state, algorithm: 10 }, 1), Status.INVALID_ALGORITHM,
        /^predictDeadReckoning: .*algorithm/i);
    refuses(() => fs.predictDeadReckoning({ ...state, orientation: [0, 0, 0, 0] }, 1), Status.ZERO_QUATERNION,
        /^predictDeadReckoning: .*quaternion/i);
    // Malformed arguments fail before any call.
    assert.throws(() => fs.predictDeadReckoning({ position: p, velocity: v }, 1), RangeError); // no algorithm
    assert.throws(() => fs.predictDeadReckoning({ ...state, algorithm: 'FPX' }, 1), /state.algorithm must be one of STATIC/);
    assert.throws(() => fs.predictDeadReckoning({ ...state, speed: 3 }, 1), /unknown field "speed"/);
    assert.throws(() => fs.predictDeadReckoning(null, 1), TypeError);
    assert.throws(() => fs.predictDeadReckoning(state, '1'), /time must be a number/);
});

test('predictDeadReckoningBatch equals predictDeadReckoning at each age, bit for bit', () => {
    const n = 5, time = 10.25;
    const batch = {
        timestamp: new Float64Array([9.5, 10, 10.25, 11, 8.125]), // the fourth is in the future: age 0
        position: new Float64Array(3 * n), velocity: new Float32Array(3 * n), acceleration: new Float32Array(3 * n),
        orientation: new Float32Array(4 * n), angularVelocity: new Float32Array(3 * n),
        algorithm: new Int32Array([2, 4, 6, 7, 9]),
    };
    for (let k = 0; k < n; ++k) {
        batch.position.set([k, 2 * k + 0.5, -k], 3 * k);
        batch.velocity.set([1 + k, 0.5, -2], 3 * k);
        batch.acceleration.set([0.25, -9.81, k], 3 * k);
        batch.orientation.set([0, Math.sin(0.1 * k), 0, Math.cos(0.1 * k)], 4 * k);
        batch.angularVelocity.set([0.1, 0.3 * k, 0], 3 * k);
    }
    const r = fs.predictDeadReckoningBatch(batch, time);
    assert.equal(r.refused, 0);
    assert.ok(r.position instanceof Float64Array && r.velocity instanceof Float32Array && r.orientation instanceof Float32Array);
    assert.equal(r.orientation.length, 4 * n);
    for (let k = 0; k < n; ++k) {
        const one = fs.predictDeadReckoning({
            position: batch.position.subarray(3 * k, 3 * k + 3), velocity: batch.velocity.subarray(3 * k, 3 * k + 3),
            acceleration: batch.acceleration.subarray(3 * k, 3 * k + 3), orientation: batch.orientation.subarray(4 * k, 4 * k + 4),
            angularVelocity: batch.angularVelocity.subarray(3 * k, 3 * k + 3), algorithm: batch.algorithm[k],
        }, Math.max(time - batch.timestamp[k], 0));
        assert.deepEqual(Array.from(r.position.subarray(3 * k, 3 * k + 3)), list(one.position), `entity ${k} position`);
        assert.deepEqual(Array.from(r.velocity.subarray(3 * k, 3 * k + 3)), list(one.velocity), `entity ${k} velocity`);
        assert.deepEqual(Array.from(r.orientation.subarray(4 * k, 4 * k + 4)), list(one.orientation), `entity ${k} orientation`);
    }
    // Plain arrays work too; the optional fields default to 0 and identity; FPW at age 2: p + 2 v.
    const plain = fs.predictDeadReckoningBatch({ timestamp: [1], position: [1, 2, 3], velocity: [1, 0, -1], algorithm: ['FPW'] }, 3);
    assert.deepEqual(Array.from(plain.position), [3, 2, 1]);
    assert.deepEqual(Array.from(plain.orientation), [0, 0, 0, 1]);
});

test('predictDeadReckoningBatch counts refused entities and returns their state as given', () => {
    const r = fs.predictDeadReckoningBatch({
        timestamp: [0, 0, NaN, 0], position: [0, 0, 0, NaN, 1, 2, 5, 6, 7, 1, 1, 1], velocity: [1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0],
        algorithm: [2, 2, 2, 10],
    }, 2);
    assert.equal(r.refused, 3); // a NaN position, a NaN timestamp, algorithm 10
    assert.deepEqual(Array.from(r.position.subarray(0, 3)), [2, 0, 0]); // the good one: p + v t
    assert.deepEqual(Array.from(r.position.subarray(6, 9)), [5, 6, 7]); // as given
    assert.deepEqual(Array.from(r.position.subarray(9, 12)), [1, 1, 1]);
    assert.equal(fs.predictDeadReckoningBatch({ timestamp: [], position: [], velocity: [], algorithm: [] }, 1).refused, 0);
    assert.throws(() => fs.predictDeadReckoningBatch({ timestamp: [0, 1], position: [0, 0, 0], velocity: [0, 0, 0, 0, 0, 0], algorithm: [2, 2] }, 1),
        /batch.position must be an array of 6 numbers/);
    assert.throws(() => fs.predictDeadReckoningBatch({ position: [] }, 1), /batch.timestamp/);
});

test('a Receiver snaps to its first update, extrapolates it, holds past extrapolationLimit', () => {
    const defaults = fs.receiverSettings();
    assert.deepEqual(defaults, {
        mode: 'extrapolate', smoothing: 'projectiveVelocity', blendTime: f(0.2), decayHalfLife: f(0.1),
        teleportDistance: 10, extrapolationLimit: 0.25, interpolationDelay: f(0.1), maxFutureSkew: 1, restartAfter: 10,
    });
    const receiver = fs.createReceiver();
    try {
        assert.ok(receiver instanceof Receiver);
        refuses(() => receiver.sample(1), Status.NO_UPDATE, /^sample: /);
        const state = { position: [10, 0, 5], velocity: [4, 0, -2], algorithm: 'FPW' };
        assert.equal(receiver.receive(1, state, 1.05), 'snapped');
        // Shown: the update extrapolated to the age time - timestamp (rounded to float), no offset after a snap.
        const shown = receiver.sample(1.125);
        const expected = fs.predictDeadReckoning(state, 0.125);
        assert.deepEqual(list(shown.position), list(expected.position)); // 10.5, 0, 4.75: exact
        assert.deepEqual(list(shown.position), [10.5, 0, 4.75]);
        assert.deepEqual(list(shown.velocity), [4, 0, -2]);
        assert.equal(shown.held, false);
        // Past extrapolationLimit (0.25 s) the pose stops at the limit and says so.
        const held = receiver.sample(3);
        assert.deepEqual(list(held.position), [11, 0, 4.5]); // p + v 0.25
        assert.equal(held.held, true);
        // An update on the same line: accepted; stale and bad ones dropped and counted.
        assert.equal(receiver.receive(1.5, { ...state, position: [12, 0, 4] }, 1.55), 'accepted');
        assert.equal(receiver.receive(1.5, { ...state, position: [12, 0, 4] }, 1.56), 'duplicate');
        assert.equal(receiver.receive(1.25, state, 1.6), 'outOfOrder');
        assert.equal(receiver.receive(1.75, { ...state, velocity: [NaN, 0, 0] }, 1.8), 'invalid');
        assert.equal(receiver.receive(1.8, { ...state, algorithm: 10 }, 1.8), 'invalid');
        assert.deepEqual(receiver.counters(), {
            accepted: 2, snaps: 1, teleports: 0, outOfOrder: 1, duplicates: 1, invalid: 2, held: 1, futureUpdates: 0,
            tooFarAhead: 0, clockRestarts: 0,
        });
        refuses(() => receiver.sample(NaN), Status.NON_FINITE_INPUT, /^sample: /);
        receiver.reset();
        assert.equal(receiver.counters().accepted, 0);
        refuses(() => receiver.sample(2), Status.NO_UPDATE, /^sample: /);
    } finally {
        receiver.delete();
    }
    assert.equal(receiver.deleted, true);
    assert.throws(() => receiver.sample(1), /sample: the receiver has been deleted/);
    receiver.delete(); // a second delete does nothing
});

test('receiver settings are checked', () => {
    refuses(() => fs.createReceiver({ blendTime: 0 }), Status.INVALID_SETTING, /^createReceiver: /);
    refuses(() => fs.createReceiver({ interpolationDelay: NaN }), Status.INVALID_SETTING, /^createReceiver: /);
    refuses(() => fs.createReceiver({ mode: 7 }), Status.INVALID_SETTING, /^createReceiver: /);
    assert.throws(() => fs.createReceiver({ mode: 'sideways' }), /settings.mode must be one of extrapolate, interpolate/);
    assert.throws(() => fs.createReceiver({ delay: 1 }), /unknown field "delay"/);
    const r = fs.createReceiver({ mode: 'interpolate', smoothing: 'snap', extrapolationLimit: Infinity });
    assert.equal(r.receive(1, { position: [0, 0, 0], velocity: [1, 0, 0], algorithm: 'FPW' }, 1), 'buffered');
    r.delete();
});

test('10000 receiver create / receive / sample / delete cycles leave the heap as it was', () => {
    const state = { position: [0, 1, 0], velocity: [3, 0, 1], algorithm: 'RVW', angularVelocity: [0, 0.5, 0] };
    const cycle = (i) => {
        const receiver = fs.createReceiver({ mode: i % 2 ? 'interpolate' : 'extrapolate' });
        for (let k = 0; k < i % 4; ++k) receiver.receive(0.1 * k, state, 0.1 * k + 0.02);
        try {
            receiver.sample(0.5);
        } catch {
            // NO_UPDATE when nothing was received: expected
        }
        receiver.delete();
    };
    const batch = { timestamp: new Float64Array(300), position: new Float64Array(900), velocity: new Float32Array(900),
        algorithm: new Int32Array(300).fill(2) };
    // Warm-up: the batch buffer grows once (taking the top of the heap), then the allocator's bins
    // settle around it (the receivers' first round after it takes one more page, then no more).
    fs.predictDeadReckoningBatch(batch, 1);
    for (let i = 0; i < 1000; ++i) cycle(i);
    const heapEnd = fs.heapEnd();
    for (let i = 0; i < 10000; ++i) cycle(i);
    for (let i = 0; i < 100; ++i) fs.predictDeadReckoningBatch(batch, i); // reuses it
    assert.equal(fs.heapEnd(), heapEnd, `the heap grew by ${fs.heapEnd() - heapEnd} bytes`);
});

const native = process.env.FORESIGHT_NATIVE_REFERENCE;
test('dead reckoning equals the native library bit for bit', { skip: !native && 'FORESIGHT_NATIVE_REFERENCE not set' }, () => {
    const reference = JSON.parse(execFileSync(native, { encoding: 'utf8', maxBuffer: 64 << 20 }));
    assert.equal(reference.deadReckoning.length, 18); // 9 algorithms, 2 times
    for (const c of reference.deadReckoning) {
        const what = `${fs.deadReckoningAlgorithmName(c.algorithm)} at ${c.time} s`;
        assert.equal(c.status, 0, `${what}: native refused`);
        const { position, velocity, acceleration, orientation, angularVelocity, algorithm } = c;
        const r = fs.predictDeadReckoning({ position, velocity, acceleration, orientation, angularVelocity, algorithm }, c.time);
        assert.deepEqual(list(r.position), c.result.position, `${what} position`);
        assert.deepEqual(list(r.velocity), c.result.velocity, `${what} velocity`);
        assert.deepEqual(list(r.orientation), c.result.orientation, `${what} orientation`);
    }
});
