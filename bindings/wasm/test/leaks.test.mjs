// No leaks: worlds made and deleted, predictions and refusals repeated many times leave the
// module's heap where it was. The heap's end (sbrk(0)) moves only when the allocator needs more
// than it has freed, so a leak of even a few bytes per cycle moves it within these loops.
//
//   node --test test/

import { test } from 'node:test';
import assert from 'node:assert/strict';

import { loadForesight } from '../index.mjs';

const fs = await loadForesight();
const CYCLES = 10000;

function cycle(i) {
    const world = fs.createWorld();
    world.addPlane({ normal: [0, 1, 0], distance: 0 });
    world.addBox({ center: [0, 1.5, 10], halfExtents: [5, 1.5, 0.25] });
    for (let k = 0; k < i % 8; ++k) world.addSphere({ center: [k, 0.5, 5], radius: 0.5 }); // vectors regrow
    world.addTriangle({ a: [-3, 0, 3], b: [-1, 0, 3], c: [-2, 1, 6] });
    try {
        world.addSphere({ center: [0, 0, 0], radius: -1 }); // a refusal allocates nothing
    } catch {
        // expected
    }
    fs.predictProjectile([0, 1.6, 0], [0, 4, 12], 0.5, { world, settings: { radius: 0.05 } });
    world.delete();
}

test(`${CYCLES} world create / add / predict / delete cycles leave the heap as it was`, () => {
    for (let i = 0; i < 100; ++i) cycle(i); // warm-up: the trajectory buffer and the allocator's bins
    const heapEnd = fs.heapEnd();
    for (let i = 0; i < CYCLES; ++i) cycle(i);
    // The amount a leak of 1 byte per cycle would have added, for the message.
    assert.equal(fs.heapEnd(), heapEnd, `the heap grew by ${fs.heapEnd() - heapEnd} bytes over ${CYCLES} cycles`);
});

test('many live worlds are freed by delete', () => {
    const before = fs.heapEnd();
    const worlds = [];
    for (let i = 0; i < 2000; ++i) worlds.push(fs.createWorld().addPlane({ normal: [0, 1, 0], distance: i }));
    assert.ok(fs.heapEnd() > before, 'the worlds took memory'); // 2000 worlds do not fit in what was free
    for (const world of worlds) world.delete();
    const after = fs.heapEnd();
    for (let i = 0; i < 2000; ++i) worlds[i] = fs.createWorld().addPlane({ normal: [0, 1, 0], distance: i });
    for (const world of worlds) world.delete();
    assert.equal(fs.heapEnd(), after, 'the second round reuses the memory the first freed');
});

test('errors and long trajectories do not grow the heap', () => {
    const state = { position: [0, 0, 0], velocity: [1, 0, 0] };
    fs.predictProjectile([0, 0, 0], [1, 100, 0], 20, { settings: { method: 'stepped', step: 0.001 } }); // grows the buffer once
    const heapEnd = fs.heapEnd();
    for (let i = 0; i < CYCLES / 10; ++i) {
        try {
            fs.predictLinear(state, -1);
        } catch {
            // expected
        }
        fs.predictProjectile([0, 0, 0], [1, 100, 0], 20, { settings: { method: 'stepped', step: 0.01 } });
        fs.aimProjectile({ from: [0, 1.5, 0], speed: 25 }, { position: [30, 0, 40] });
    }
    assert.equal(fs.heapEnd(), heapEnd);
});
