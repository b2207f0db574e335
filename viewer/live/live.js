// The viewer's live mode: the article's grenade scene (a floor, a wall 10 m ahead), predicted in
// the page by foresight's WebAssembly module (bindings/wasm) each time the throw or the target
// moves. Side view: +Z to the right, +Y up (metres). window.foresightLive is the test hook.
import * as THREE from 'three';
import { loadForesight, TrajectoryEvent } from 'foresight-wasm';

const HAND = [0, Math.fround(1.6), 0]; // the article's hand [m]
const FUSE = 3; // [s]
const SETTINGS = { restitution: 0.5, friction: 0.4, radius: 0.05 };
const AIM_SPEED = 15; // [m/s] the aimed throw's launch speed

const hook = { ready: false, errors: [], velocity: null, target: null, drawn: null, aimed: null, result: null };
window.foresightLive = hook;
window.addEventListener('error', (event) => hook.errors.push(String(event.message)));

const foresight = await loadForesight();
const world = foresight.createWorld()
    .addPlane({ normal: [0, 1, 0], distance: 0 })
    .addBox({ center: [0, 1.5, 10], halfExtents: [5, 1.5, 0.25] });

// Scene: an orthographic side view looking along -X at the z-y plane.
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x101418);
// From -X looking along +X: the view's right is +Z, its up +Y (camera x = world z).
const camera = new THREE.OrthographicCamera(-2, 42, 12, -2, -100, 100);
camera.position.set(-10, 0, 0);
camera.up.set(0, 1, 0);
camera.lookAt(0, 0, 0);

function box(center, half, color) {
    const mesh = new THREE.Mesh(new THREE.BoxGeometry(2 * half[0], 2 * half[1], 2 * half[2]),
        new THREE.MeshBasicMaterial({ color }));
    mesh.position.set(...center);
    scene.add(mesh);
}
box([0, -0.05, 20], [5, 0.05, 30], 0x394049); // the floor y = 0 (drawn 10 cm thick)
box([0, 1.5, 10], [5, 1.5, 0.25], 0x6b7280); // the wall

function line(color) {
    const geometry = new THREE.BufferGeometry();
    const object = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color }));
    scene.add(object);
    return object;
}
const thrown = line(0xffb020);
const aimed = line(0x40c0ff);
const arrow = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(...HAND), 1, 0xffffff);
scene.add(arrow);
const target = new THREE.Mesh(new THREE.SphereGeometry(0.3), new THREE.MeshBasicMaterial({ color: 0xff4060 }));
scene.add(target);
const bounceMarkers = new THREE.Group();
scene.add(bounceMarkers);

// z from -2 m to 28 m across the page, y from -1 m up at the same scale (hook.view).
const VIEW = { left: -2, bottom: -1, span: 30 };
hook.view = VIEW;
function resize() {
    const width = window.innerWidth, height = window.innerHeight;
    renderer.setSize(width, height);
    const h = VIEW.span * height / width;
    camera.left = VIEW.left;
    camera.right = VIEW.left + VIEW.span;
    camera.top = VIEW.bottom + h;
    camera.bottom = VIEW.bottom;
    camera.updateProjectionMatrix();
    render();
}

const $ = (id) => document.getElementById(id);
const state = { vy: 4, vz: 12, tz: 20, method: 'exact' };

function setLine(object, positions) {
    object.geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(positions), 3));
    object.geometry.computeBoundingSphere();
}

function update() {
    const velocity = [0, state.vy, state.vz];
    const settings = { ...SETTINGS, method: state.method };
    const status = [];
    try {
        const r = foresight.predictProjectile(HAND, velocity, FUSE, { world, settings });
        const t = r.trajectory;
        setLine(thrown, t.position);
        bounceMarkers.clear();
        for (let i = 0; i < t.length; ++i) {
            if (t.event[i] !== TrajectoryEvent.bounce) continue;
            const marker = new THREE.Mesh(new THREE.CircleGeometry(0.12, 12), new THREE.MeshBasicMaterial({ color: 0xffe080, side: THREE.DoubleSide }));
            marker.position.set(t.position[3 * i], t.position[3 * i + 1], t.position[3 * i + 2]);
            marker.rotation.y = Math.PI / 2;
            bounceMarkers.add(marker);
        }
        hook.result = { bounces: r.bounces, position: r.position, atRest: r.atRest, points: t.length };
        status.push(`throw: ${r.bounces} bounces, ends at z ${r.position.z.toFixed(2)} m${r.atRest ? ', at rest' : ''}`);
    } catch (error) {
        setLine(thrown, []);
        hook.result = { error: error.message };
        status.push(`throw: ${error.message}`);
    }
    const speed = Math.hypot(state.vy, state.vz);
    arrow.setDirection(new THREE.Vector3(0, state.vy, state.vz).normalize());
    arrow.setLength(Math.max(0.2, speed / 4), 0.3, 0.2);
    target.position.set(0, 0, state.tz);
    const solutions = foresight.aimProjectile({ from: HAND, speed: AIM_SPEED }, { position: [0, 0, state.tz] });
    if (solutions.length) {
        const low = solutions[0];
        const flight = foresight.predictProjectile(HAND, low.velocity, low.time, { settings: { method: 'exact' } });
        setLine(aimed, flight.trajectory.position);
        hook.aimed = { velocity: low.velocity, time: low.time, positions: Array.from(flight.trajectory.position) };
        status.push(`aim at ${AIM_SPEED} m/s: ${(low.elevation * 180 / Math.PI).toFixed(1)} deg, ${low.time.toFixed(2)} s (free flight)`);
    } else {
        setLine(aimed, []);
        hook.aimed = null;
        status.push(`aim at ${AIM_SPEED} m/s: out of reach`);
    }
    hook.velocity = velocity;
    hook.target = [0, 0, state.tz];
    // What is drawn: the line's vertices, as the GPU gets them (float).
    const drawn = thrown.geometry.getAttribute('position');
    hook.drawn = drawn ? Array.from(drawn.array) : [];
    for (const key of ['vy', 'vz', 'tz']) {
        $(key).value = state[key];
        $(`${key}-value`).textContent = state[key].toFixed(1);
    }
    $('status').textContent = status.join('\n');
    render();
}

function render() {
    renderer.render(scene, camera);
}

// Pointer: the scene point under it (z, y) in the side view.
function scenePoint(event) {
    const rect = renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector3(((event.clientX - rect.left) / rect.width) * 2 - 1,
        -((event.clientY - rect.top) / rect.height) * 2 + 1, 0);
    ndc.unproject(camera);
    return { y: ndc.y, z: ndc.z };
}
let dragging = null;
renderer.domElement.addEventListener('contextmenu', (event) => event.preventDefault());
renderer.domElement.addEventListener('pointerdown', (event) => {
    dragging = event.button === 2 ? 'target' : 'velocity';
    renderer.domElement.setPointerCapture(event.pointerId);
    drag(event);
});
renderer.domElement.addEventListener('pointermove', (event) => dragging && drag(event));
renderer.domElement.addEventListener('pointerup', () => { dragging = null; });
function drag(event) {
    const p = scenePoint(event);
    if (dragging === 'target') {
        state.tz = Math.min(28, Math.max(2, p.z));
    } else {
        // The arrow from the hand to the pointer, 4 m/s per metre (the arrow's drawn scale).
        state.vz = Math.min(30, Math.max(0, (p.z - HAND[2]) * 4));
        state.vy = Math.min(20, Math.max(-5, (p.y - HAND[1]) * 4));
    }
    update();
}
for (const key of ['vy', 'vz', 'tz']) {
    $(key).addEventListener('input', () => {
        state[key] = Number($(key).value);
        update();
    });
}
$('method').addEventListener('change', () => {
    state.method = $('method').value;
    update();
});

/** Test hook: sets the launch velocity [m/s] (y, z) as a drag would, and redraws. */
hook.setVelocity = (vy, vz) => {
    state.vy = vy;
    state.vz = vz;
    update();
};
/** Test hook: sets the target's z [m] and redraws. */
hook.setTarget = (tz) => {
    state.tz = tz;
    update();
};

window.addEventListener('resize', resize);
resize();
update();
hook.ready = true;
