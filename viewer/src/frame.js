// The scene's frame: the bounds, a render origin (the bounds' centre when coordinates are large,
// so that float32 on the GPU keeps its precision) and a length scale for markers.
import * as THREE from 'three';

export function makeFrame(bounds) {
    const min = new THREE.Vector3(...bounds.min);
    const max = new THREE.Vector3(...bounds.max);
    const center = min.clone().add(max).multiplyScalar(0.5);
    const size = max.clone().sub(min);
    // A flat or empty box still needs a size to frame and to scale markers by.
    const extent = Math.max(size.x, size.y, size.z, 1);
    const origin = center.length() > 1e4 ? center.clone() : new THREE.Vector3();
    return {
        min, max, center, size, extent, origin,
        /** A world position [x, y, z] (doubles) as a scene position. */
        toScene: (p) => new THREE.Vector3(p[0] - origin.x, p[1] - origin.y, p[2] - origin.z),
        /** Marker sizes: a small fraction of the scene, whatever its scale. */
        marker: THREE.MathUtils.clamp(extent * 0.008, 0.03, 1e6),
    };
}
