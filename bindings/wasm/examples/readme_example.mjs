import { loadForesight, TrajectoryEvent } from '../index.mjs'; // in an app: from 'foresight-wasm'

const foresight = await loadForesight();

// Where will this character be in 0.5 s at constant velocity? (metres, seconds; +Y up)
const runner = foresight.predictLinear({ position: [1, 0, 2], velocity: { x: 3, y: 0, z: 4 } }, 0.5);
console.log('runner at', runner.position); // { x: 2.5, y: 0, z: 4 }

// A grenade thrown at a wall over a floor, bouncing for its 3 s fuse.
const world = foresight.createWorld()
    .addPlane({ normal: [0, 1, 0], distance: 0 })
    .addBox({ center: [0, 1.5, 10], halfExtents: [5, 1.5, 0.25] });
try {
    const grenade = foresight.predictProjectile([0, 1.6, 0], [0, 4, 12], 3, {
        world, settings: { restitution: 0.5, friction: 0.4, radius: 0.05 },
    });
    console.log(`${grenade.bounces} bounces, ends at z = ${grenade.position.z.toFixed(3)} m`);
    const { position, event, length } = grenade.trajectory; // Float64Array x, y, z per point: draw it
    const wall = event.indexOf(TrajectoryEvent.bounce);
    console.log(`${length} points, first bounce at z = ${position[3 * wall + 2].toFixed(2)} m`);
} finally {
    world.delete(); // worlds live in the module's memory: free them
}
