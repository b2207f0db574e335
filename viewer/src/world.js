// The static world: planes (large finite quads sized from the bounds), boxes, spheres, meshes.
import * as THREE from 'three';
import { COLORS } from './colors.js';

const toQuaternion = (q) => (q ? new THREE.Quaternion(q.x, q.y, q.z, q.w).normalize() : new THREE.Quaternion());

function withEdges(mesh, geometry) {
    const edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 20),
        new THREE.LineBasicMaterial({ color: COLORS.edges }));
    mesh.add(edges);
    return mesh;
}

export function buildWorld(world, frame) {
    const group = new THREE.Group();
    group.name = 'world';
    const solid = new THREE.MeshStandardMaterial({ color: COLORS.solid, roughness: 0.85, flatShading: true });

    // Planes: a quad around the bounds' centre projected on the plane, a few times the scene's
    // size; pushed back in depth so that the grid and paths on it stay visible.
    const planeMaterial = new THREE.MeshStandardMaterial({
        color: COLORS.ground, roughness: 1, side: THREE.DoubleSide,
        polygonOffset: true, polygonOffsetFactor: 2, polygonOffsetUnits: 2,
    });
    for (const plane of world.planes) {
        const normal = new THREE.Vector3(...plane.normal);
        const length = normal.length();
        normal.divideScalar(length);
        const distance = plane.distance / length;
        const center = frame.center.clone();
        center.addScaledVector(normal, distance - normal.dot(center));
        const side = frame.extent * 4;
        const quad = new THREE.Mesh(new THREE.PlaneGeometry(side, side), planeMaterial);
        quad.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), normal);
        quad.position.copy(center.sub(frame.origin));
        quad.renderOrder = -1;
        group.add(quad);
    }
    for (const box of world.boxes) {
        const [x, y, z] = box.half_extents;
        const geometry = new THREE.BoxGeometry(2 * x, 2 * y, 2 * z);
        const mesh = withEdges(new THREE.Mesh(geometry, solid), geometry);
        mesh.position.copy(frame.toScene(box.center));
        mesh.quaternion.copy(toQuaternion(box.orientation));
        group.add(mesh);
    }
    for (const sphere of world.spheres) {
        const mesh = new THREE.Mesh(new THREE.SphereGeometry(sphere.radius, 32, 16), solid);
        mesh.position.copy(frame.toScene(sphere.center));
        group.add(mesh);
    }
    const meshMaterial = new THREE.MeshStandardMaterial({
        color: COLORS.mesh, roughness: 0.9, flatShading: true, side: THREE.DoubleSide,
    });
    for (const source of world.meshes) {
        const positions = new Float32Array(source.positions.length);
        for (let i = 0; i < positions.length; i += 3) {
            positions[i] = source.positions[i] - frame.origin.x;
            positions[i + 1] = source.positions[i + 1] - frame.origin.y;
            positions[i + 2] = source.positions[i + 2] - frame.origin.z;
        }
        const geometry = new THREE.BufferGeometry();
        geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
        geometry.setIndex(source.indices);
        geometry.computeVertexNormals();
        const mesh = withEdges(new THREE.Mesh(geometry, meshMaterial), geometry);
        mesh.name = String(source.name ?? 'mesh');
        group.add(mesh);
    }
    return group;
}
