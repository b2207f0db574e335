// overhead.mjs: microseconds per projectile prediction through JavaScript and WebAssembly, the
// best of 5 rounds, for the scenarios of test/overhead_native.c (the native figure). README.md
// gives the ratio.
//
//   node examples/overhead.mjs

import { loadForesight } from '../index.mjs';

const fs = await loadForesight();
const hand = [0, Math.fround(1.6), 0];

function best(options, time, n) {
    let fastest = Infinity, sink = 0;
    for (let round = 0; round < 5; ++round) {
        const start = performance.now();
        for (let i = 0; i < n; ++i) sink += fs.predictProjectile(hand, [0, 4, 12], time, options).position.z;
        fastest = Math.min(fastest, (performance.now() - start) / n * 1e3);
    }
    if (sink === 0) console.log('?');
    return fastest.toFixed(3);
}

const world = fs.createWorld()
    .addPlane({ normal: [0, 1, 0], distance: 0 })
    .addBox({ center: [0, 1.5, 10], halfExtents: [5, 1.5, 0.25] });
const settings = { restitution: 0.5, friction: 0.4, radius: 0.05 };
console.log(`free flight 0.5 s, no trajectory: ${best({ trajectory: false }, 0.5, 200000)} us`);
console.log(`article grenade, exact, 3 s, with trajectory: ${best({ world, settings }, 3, 5000)} us`);
console.log(`article grenade, jolt, 3 s, with trajectory: ${best({ world, settings: { ...settings, method: 'engine' } }, 3, 5000)} us`);
world.delete();
