// Each prediction's path: a line through its points, the points themselves (what the pointer
// hovers), bounce/hit markers (small spheres) and rest markers (yellow diamonds).
import * as THREE from 'three';
import { Line2 } from 'three/examples/jsm/lines/Line2.js';
import { LineGeometry } from 'three/examples/jsm/lines/LineGeometry.js';
import { LineMaterial } from 'three/examples/jsm/lines/LineMaterial.js';
import { COLORS } from './colors.js';

export const BOUNCE_EVENTS = new Set(['bounce', 'hit']);

export function buildPath(prediction, color, frame) {
    const group = new THREE.Group();
    group.name = `path ${prediction.id}`;
    const scene = prediction.path.map((point) => frame.toScene(point.position));
    const lineMaterials = [];

    if (scene.length >= 2) {
        const geometry = new LineGeometry();
        geometry.setPositions(scene.flatMap((p) => [p.x, p.y, p.z]));
        const faithful = prediction.variant === 'faithful';
        // Screen-space widths: visible at any zoom. The faithful path is dashed as well as
        // warm-coloured and drawn thinner on top of the exact one, so that where the two
        // coincide both still show.
        const engine = prediction.variant === 'engine';
        const material = new LineMaterial({
            color, linewidth: faithful ? 2 : engine ? 3 : 4, dashed: faithful,
            dashSize: frame.marker * 4, gapSize: frame.marker * 2.5, worldUnits: false,
        });
        const line = new Line2(geometry, material);
        if (faithful) {
            line.computeLineDistances();
            line.renderOrder = 1;
            material.depthFunc = THREE.LessEqualDepth;
        }
        group.add(line);
        lineMaterials.push(material);
    }

    const pointGeometry = new THREE.BufferGeometry().setFromPoints(scene);
    const points = new THREE.Points(pointGeometry, new THREE.PointsMaterial({
        color, size: 4, sizeAttenuation: false,
    }));
    points.userData = { prediction };
    group.add(points);

    let bounceMarkers = 0;
    let restMarkers = 0;
    const bounceGeometry = new THREE.SphereGeometry(frame.marker * 1.6, 16, 8);
    const bounceMaterial = new THREE.MeshStandardMaterial({
        color: new THREE.Color(color).lerp(new THREE.Color(0xffffff), 0.45), roughness: 0.5,
        emissive: new THREE.Color(color), emissiveIntensity: 0.25,
    });
    const restGeometry = new THREE.OctahedronGeometry(frame.marker * 3.2);
    const restMaterial = new THREE.MeshStandardMaterial({
        color: COLORS.rest, emissive: COLORS.rest, emissiveIntensity: 0.35, flatShading: true,
    });
    prediction.path.forEach((point, k) => {
        if (BOUNCE_EVENTS.has(point.event)) {
            const marker = new THREE.Mesh(bounceGeometry, bounceMaterial);
            marker.position.copy(scene[k]);
            marker.name = `${point.event} marker`;
            group.add(marker);
            ++bounceMarkers;
        } else if (point.event === 'rest') {
            const marker = new THREE.Mesh(restGeometry, restMaterial);
            marker.position.copy(scene[k]);
            marker.name = 'rest marker';
            group.add(marker);
            ++restMarkers;
        }
    });
    return { group, points, lineMaterials, bounceMarkers, restMarkers };
}
