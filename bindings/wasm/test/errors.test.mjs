// Refused input: the library's status comes back as a ForesightError whose message names the
// call and the problem; a malformed argument is a TypeError or RangeError before any call.
//
//   node --test test/

import { test } from 'node:test';
import assert from 'node:assert/strict';

import { loadForesight, ForesightError, Status } from '../index.mjs';

const fs = await loadForesight();
const state = { position: [0, 0, 0], velocity: [1, 0, 0] };

function refuses(call, status, text) {
    assert.throws(call, (error) => {
        assert.ok(error instanceof ForesightError, `${error}`);
        assert.ok(error instanceof Error);
        assert.equal(error.status, status);
        assert.equal(error.code, Object.keys(Status).find((k) => Status[k] === status));
        assert.match(error.message, text);
        return true;
    });
}

test('a negative time is refused with the library message', () => {
    refuses(() => fs.predictLinear(state, -1), Status.NEGATIVE_TIME, /^predictLinear: time must be >= 0$/);
    refuses(() => fs.predictAccelerated(state, [0, -9.81, 0], -0.5), Status.NEGATIVE_TIME, /^predictAccelerated: .*>= 0/);
    refuses(() => fs.predictProjectile([0, 1, 0], [0, 0, 1], -2), Status.NEGATIVE_TIME, /^predictProjectile: /);
    refuses(() => fs.predictVehicleExact({ ...state, angularVelocity: [0, 1, 0] }, -1), Status.NEGATIVE_TIME,
        /^predictVehicleExact: /);
});

test('NaN and infinities are refused as non-finite input', () => {
    refuses(() => fs.predictLinear({ position: [NaN, 0, 0], velocity: [1, 0, 0] }, 1), Status.NON_FINITE_INPUT,
        /^predictLinear: .*(finite|NaN)/i);
    refuses(() => fs.predictLinear(state, NaN), Status.NON_FINITE_INPUT, /predictLinear/);
    refuses(() => fs.predictAccelerated(state, [0, Infinity, 0], 1), Status.NON_FINITE_INPUT, /predictAccelerated/);
    refuses(() => fs.predictProjectile([0, 1, 0], [NaN, 0, 1], 2), Status.NON_FINITE_INPUT, /predictProjectile/);
    // Beyond float's range: infinite once rounded, refused.
    refuses(() => fs.predictLinear({ position: [1e39, 0, 0], velocity: [0, 0, 0] }, 1), Status.NON_FINITE_INPUT,
        /predictLinear/);
});

test('settings outside their range name the problem', () => {
    refuses(() => fs.predictProjectile([0, 1, 0], [0, 0, 1], 1, { settings: { restitution: 1.5 } }),
        Status.INVALID_RESTITUTION, /restitution/);
    refuses(() => fs.predictProjectile([0, 1, 0], [0, 0, 1], 1, { settings: { friction: -1 } }),
        Status.INVALID_FRICTION, /friction/);
    refuses(() => fs.predictProjectile([0, 1, 0], [0, 0, 1], 1, { settings: { step: 0 } }), Status.INVALID_STEP,
        /step/);
    refuses(() => fs.predictProjectile([0, 1, 0], [0, 0, 1], 1, { settings: { radius: -0.1 } }),
        Status.INVALID_RADIUS, /radius/);
    refuses(() => fs.predictProjectile([0, 1, 0], [0, 0, 1], 100, { settings: { method: 'stepped', step: 1e-5, maxSteps: 1000 } }),
        Status.TOO_MANY_STEPS, /predictProjectile/);
    refuses(() => fs.predictVehicleIterative({ ...state, angularVelocity: [0, 1, 0] }, 1, 0), Status.INVALID_ITERATIONS,
        /iteration/);
    refuses(() => fs.predictVehicleExact({ ...state, orientation: [0, 0, 0, 0], angularVelocity: [0, 1, 0] }, 1),
        Status.ZERO_QUATERNION, /quaternion/);
    refuses(() => fs.predictProjectile([0, 1, 0], [0, 0, 1], 1, { settings: { method: 7 } }), Status.INVALID_SETTING,
        /predictProjectile/);
    refuses(() => fs.predictProjectile([2e5, 1, 0], [0, 0, 1], 1), Status.OUT_OF_RANGE, /predictProjectile/);
});

test('bad shapes are refused and not added', () => {
    const world = fs.createWorld();
    try {
        refuses(() => world.addPlane({ normal: [0, 0, 0], distance: 0 }), Status.ZERO_VECTOR, /^addPlane: /);
        refuses(() => world.addSphere({ center: [0, 0, 0], radius: 0 }), Status.INVALID_RADIUS, /^addSphere: /);
        refuses(() => world.addBox({ center: [0, 0, 0], halfExtents: [1, 0, 1] }), Status.DEGENERATE_SHAPE, /^addBox: /);
        refuses(() => world.addTriangle({ a: [0, 0, 0], b: [1, 0, 0], c: [2, 0, 0] }), Status.DEGENERATE_SHAPE,
            /^addTriangle: /);
        refuses(() => world.addPlane({ normal: [0, 1, 0], distance: NaN }), Status.NON_FINITE_INPUT, /^addPlane: /);
        refuses(() => world.addSphere({ center: [0, 0, 0], radius: 1 }, { restitution: 2 }), Status.INVALID_RESTITUTION,
            /^addSphere: /);
        // Nothing was added: a drop falls through.
        const r = fs.predictProjectile([0, 1, 0], [0, 0, 0], 1, { world });
        assert.equal(r.bounces, 0);
        assert.ok(r.position.y < -3);
    } finally {
        world.delete();
    }
});

test('a deleted world is refused; delete twice does nothing', () => {
    const world = fs.createWorld();
    world.delete();
    world.delete();
    assert.equal(world.deleted, true);
    assert.throws(() => world.addPlane({ normal: [0, 1, 0], distance: 0 }), /addPlane: the world has been deleted/);
    assert.throws(() => fs.predictProjectile([0, 1, 0], [0, 0, 0], 1, { world }), /world has been deleted/);
    assert.throws(() => fs.predictProjectile([0, 1, 0], [0, 0, 0], 1, { world: {} }), TypeError);
});

test('malformed arguments are TypeErrors or RangeErrors naming the field', () => {
    assert.throws(() => fs.predictLinear({ position: [0, 0], velocity: [0, 0, 0] }, 1),
        { name: 'TypeError', message: 'state.position must be {x, y, z} or [x, y, z]' });
    assert.throws(() => fs.predictLinear({ position: { x: 0, y: '1', z: 0 }, velocity: [0, 0, 0] }, 1),
        { name: 'TypeError', message: 'state.position.y must be a number, got string' });
    assert.throws(() => fs.predictLinear(state), { name: 'TypeError', message: 'time must be a number, got undefined' });
    assert.throws(() => fs.predictProjectile([0, 0, 0], [0, 0, 0], 1, { settings: { methd: 'exact' } }),
        { name: 'TypeError', message: /unknown field "methd"/ });
    assert.throws(() => fs.predictProjectile([0, 0, 0], [0, 0, 0], 1, { settings: { method: 'euler' } }),
        { name: 'RangeError', message: /settings.method must be one of exact, stepped, engine/ });
    assert.throws(() => fs.predictProjectile([0, 0, 0], [0, 0, 0], 1, { settings: { maxBounces: -1 } }),
        { name: 'RangeError', message: /settings.maxBounces/ });
    assert.throws(() => fs.predictVehicleIterative({ ...state, angularVelocity: [0, 1, 0] }, 1, 2.5),
        { name: 'RangeError', message: /iterations/ });
});

test('after errors the module still computes', () => {
    for (let i = 0; i < 100; ++i) assert.throws(() => fs.predictLinear(state, -1));
    assert.deepEqual(fs.predictLinear(state, 2).position, { x: 2, y: 0, z: 0 });
});
