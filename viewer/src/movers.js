// The objects that move with the time slider: a ball for projectiles and characters, a box for
// vehicles (with ghost boxes along the path every ~0.25 s).
import * as THREE from 'three';
import { endTime, stateAt } from './motion.js';

const GHOST_INTERVAL = 0.25; // [s]

function vehicleBox(halfExtents, color, opacity) {
    const [x, y, z] = halfExtents;
    const geometry = new THREE.BoxGeometry(2 * x, 2 * y, 2 * z);
    const ghost = opacity < 1;
    const body = new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({
        color, roughness: 0.6, transparent: ghost, opacity, depthWrite: !ghost, flatShading: true,
    }));
    body.add(new THREE.LineSegments(new THREE.EdgesGeometry(geometry), new THREE.LineBasicMaterial({
        color: ghost ? color : 0x111111, transparent: ghost, opacity: ghost ? 0.6 : 1,
    })));
    if (!ghost) {
        // The front (+Z): a light stripe across the top, so the heading reads at a glance.
        const stripe = new THREE.Mesh(new THREE.BoxGeometry(2 * x * 0.9, y * 0.08, z * 0.25),
            new THREE.MeshBasicMaterial({ color: 0xffffff }));
        stripe.position.set(0, y * 1.04, z * 0.7);
        body.add(stripe);
    }
    return body;
}

function placeVehicle(object, state, frame) {
    object.position.copy(frame.toScene(state.position));
    const q = state.orientation;
    object.quaternion.set(q.x, q.y, q.z, q.w);
}

export function buildMover(prediction, color, gravity, frame) {
    const group = new THREE.Group();
    group.name = `mover ${prediction.id}`;
    let object;
    if (prediction.model === 'vehicle') {
        object = vehicleBox(prediction.halfExtents, color, 1);
        const end = endTime(prediction);
        const start = prediction.path[0].t;
        for (let t = start; t <= end + 1e-9; t += GHOST_INTERVAL) {
            const ghost = vehicleBox(prediction.halfExtents, color, 0.16);
            placeVehicle(ghost, stateAt(prediction, gravity, t), frame);
            group.add(ghost);
        }
    } else {
        const radius = Math.max(prediction.radius, frame.marker * (prediction.model === 'projectile' ? 2.4 : 3));
        object = new THREE.Mesh(new THREE.SphereGeometry(radius, 24, 12), new THREE.MeshStandardMaterial({
            color, roughness: 0.35, emissive: color, emissiveIntensity: 0.2,
        }));
    }
    group.add(object);
    let position = prediction.path[0].position.slice();
    return {
        prediction, group,
        /** Moves the object to its state at time t. */
        setTime(t) {
            const state = stateAt(prediction, gravity, t);
            position = state.position;
            if (prediction.model === 'vehicle') placeVehicle(object, state, frame);
            else object.position.copy(frame.toScene(state.position));
        },
        /** Its world position [x, y, z] at the last setTime (doubles, before the render origin). */
        position: () => position.slice(),
    };
}
