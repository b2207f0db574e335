// Builds the 3D view of a checked picture document and wires the test hook.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { COLORS, makePalette } from './colors.js';
import { makeFrame } from './frame.js';
import { buildWorld } from './world.js';
import { buildPath } from './paths.js';
import { buildMover } from './movers.js';
import { endTime } from './motion.js';
import { buildGuides } from './guides.js';
import { buildControls, buildHint, buildLegend, buildTooltip } from './ui.js';

const HOVER_PIXELS = 7; // how near the pointer a path point must be to show its state

export function createViewer(doc, hook) {
    const root = document.createElement('div');
    root.id = 'fv-root';
    document.body.appendChild(root);

    let renderer;
    try {
        // preserveDrawingBuffer: the picture stays readable after a frame (screenshots, tests).
        renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    } catch (error) {
        root.remove();
        throw new Error(`WebGL is not available in this browser (${error.message}).`);
    }
    renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    renderer.setSize(window.innerWidth, window.innerHeight);
    root.appendChild(renderer.domElement);

    const frame = makeFrame(doc.bounds);
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(COLORS.background);
    scene.add(new THREE.HemisphereLight(0xdfe8ff, 0x3a3228, 1.4));
    const sun = new THREE.DirectionalLight(0xffffff, 1.8);
    sun.position.set(-0.5, 1, -0.3);
    scene.add(sun);

    const camera = new THREE.PerspectiveCamera(45, window.innerWidth / window.innerHeight,
        frame.extent / 2000, frame.extent * 200);
    const controls = new OrbitControls(camera, renderer.domElement);
    frameCamera(camera, controls, frame);

    scene.add(buildWorld(doc.world, frame));
    const guides = buildGuides(doc.world.planes, frame);
    scene.add(guides.group);

    // Paths and moving objects.
    const palette = makePalette();
    const entries = [];
    const counts = { paths: 0, bounceMarkers: 0, restMarkers: 0, vehicles: 0,
        dangerZones: 0, meshes: doc.world.meshes.length };
    const pickables = [];
    const movers = [];
    const moverById = new Map(); // positionOf(id): the first prediction with that id
    for (const prediction of doc.predictions) {
        const color = palette(prediction.variant);
        const path = buildPath(prediction, color, frame);
        const mover = buildMover(prediction, color, doc.gravity, frame);
        scene.add(path.group, mover.group);
        entries.push({ prediction, color, objects: [path.group, mover.group] });
        pickables.push(path.points);
        movers.push(mover);
        if (!moverById.has(prediction.id)) moverById.set(prediction.id, mover);
        counts.paths += 1;
        counts.bounceMarkers += path.bounceMarkers;
        counts.restMarkers += path.restMarkers;
        if (prediction.model === 'vehicle') counts.vehicles += 1;
    }

    // Danger zones: faint until their time, stronger from it on.
    const zones = doc.dangerZones.map((zone) => {
        const material = new THREE.MeshStandardMaterial({
            color: COLORS.danger, transparent: true, opacity: 0.08, depthWrite: false, roughness: 1,
        });
        const sphere = new THREE.Mesh(new THREE.SphereGeometry(zone.radius, 40, 20), material);
        sphere.position.copy(frame.toScene(zone.center));
        sphere.renderOrder = 2;
        const ring = new THREE.LineLoop(
            new THREE.BufferGeometry().setFromPoints(new THREE.EllipseCurve(0, 0, zone.radius, zone.radius)
                .getPoints(72).map((p) => new THREE.Vector3(p.x, 0, p.y))),
            new THREE.LineBasicMaterial({ color: COLORS.danger, transparent: true, opacity: 0.8 }));
        sphere.add(ring);
        scene.add(sphere);
        counts.dangerZones += 1;
        return { zone, material };
    });

    const maxTime = Math.max(0, ...doc.predictions.map(endTime), ...doc.dangerZones.map((z) => z.time));
    const render = () => renderer.render(scene, camera);

    let time = 0;
    const controlsBar = buildControls(root, maxTime, (t) => setTime(t), (playing) => {
        if (playing) play();
        else pause();
    });
    function setTime(t) {
        time = THREE.MathUtils.clamp(Number.isFinite(t) ? t : 0, 0, maxTime);
        for (const mover of movers) mover.setTime(time);
        for (const { zone, material } of zones) material.opacity = time >= zone.time ? 0.2 : 0.06;
        controlsBar.show(time);
        render();
    }
    let playing = null;
    function play() {
        if (time >= maxTime) setTime(0);
        let last = performance.now();
        const step = (now) => {
            if (!playing) return;
            setTime(time + (now - last) / 1000);
            last = now;
            if (time >= maxTime) {
                playing = null;
                controlsBar.stopped();
                return;
            }
            playing = requestAnimationFrame(step);
        };
        playing = requestAnimationFrame(step);
    }
    function pause() {
        if (playing) cancelAnimationFrame(playing);
        playing = null;
    }

    buildLegend(root, doc.title, entries, {
        bounce: counts.bounceMarkers > 0, rest: counts.restMarkers > 0, restColor: COLORS.rest,
        vehicle: counts.vehicles > 0, danger: counts.dangerZones > 0, gridCell: guides.cell,
    }, (index, visible) => {
        for (const object of entries[index].objects) object.visible = visible;
        render();
    });
    buildHint(root);

    // Hovering a path point: ray cast against the points, with a threshold of a few pixels.
    const tooltip = buildTooltip(root);
    const raycaster = new THREE.Raycaster();
    const pointer = new THREE.Vector2();
    renderer.domElement.addEventListener('pointermove', (event) => {
        const rect = renderer.domElement.getBoundingClientRect();
        pointer.set(((event.clientX - rect.left) / rect.width) * 2 - 1,
            -((event.clientY - rect.top) / rect.height) * 2 + 1);
        raycaster.setFromCamera(pointer, camera);
        const distance = camera.position.distanceTo(controls.target);
        const pixel = (2 * distance * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2)) / rect.height;
        raycaster.params.Points.threshold = HOVER_PIXELS * pixel;
        const hits = raycaster.intersectObjects(pickables.filter((p) => p.parent.visible), false);
        if (hits.length === 0) {
            tooltip.hide();
            return;
        }
        hits.sort((a, b) => a.distanceToRay - b.distanceToRay || a.distance - b.distance);
        const { object, index } = hits[0];
        tooltip.show(event.clientX, event.clientY, object.userData.prediction,
            object.userData.prediction.path[index]);
    });
    renderer.domElement.addEventListener('pointerleave', () => tooltip.hide());

    controls.addEventListener('change', render);
    window.addEventListener('resize', () => {
        camera.aspect = window.innerWidth / window.innerHeight;
        camera.updateProjectionMatrix();
        renderer.setSize(window.innerWidth, window.innerHeight);
        render();
    });

    setTime(0);
    Object.assign(hook, {
        counts,
        timeRange: [0, maxTime],
        setTime: (t) => {
            pause();
            controlsBar.stopped();
            setTime(Number(t));
            return time;
        },
        positionOf: (id) => (moverById.has(id) ? moverById.get(id).position() : null),
        time: () => time,
        // Where a world position [x, y, z] appears in the page (CSS pixels), to hover it.
        screenOf: (p) => {
            const v = frame.toScene(p).project(camera);
            const rect = renderer.domElement.getBoundingClientRect();
            return [rect.left + ((v.x + 1) / 2) * rect.width, rect.top + ((1 - v.y) / 2) * rect.height];
        },
    });
    requestAnimationFrame(() => {
        render();
        hook.ready = true;
    });
}

// An orbit camera looking at the bounds' centre from the side and above (+Z to the right),
// far enough for the whole box to fit the narrower of the two fields of view.
function frameCamera(camera, controls, frame) {
    const radius = Math.max(frame.size.length() / 2, frame.extent / 2);
    const vertical = THREE.MathUtils.degToRad(camera.fov) / 2;
    const horizontal = Math.atan(Math.tan(vertical) * camera.aspect);
    // The bounding sphere is loose for a flat box: come a little closer than it says.
    const distance = (radius / Math.sin(Math.min(vertical, horizontal))) * 0.85;
    const target = frame.center.clone().sub(frame.origin);
    const direction = new THREE.Vector3(-1, 0.75, -0.5).normalize();
    camera.position.copy(target).addScaledVector(direction, distance);
    controls.target.copy(target);
    camera.lookAt(target);
    controls.update();
}
