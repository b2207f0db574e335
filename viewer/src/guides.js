// A metre grid on the ground and the X, Y, Z axes with their letters.
import * as THREE from 'three';

// 1, 2 or 5 times a power of ten, near the wanted cell size.
function niceStep(wanted) {
    const power = 10 ** Math.floor(Math.log10(wanted));
    const mantissa = wanted / power;
    return (mantissa < 1.5 ? 1 : mantissa < 3.5 ? 2 : mantissa < 7.5 ? 5 : 10) * power;
}

function label(text, color, size) {
    const canvas = document.createElement('canvas');
    canvas.width = 64;
    canvas.height = 64;
    const context = canvas.getContext('2d');
    context.font = 'bold 44px system-ui, sans-serif';
    context.textAlign = 'center';
    context.textBaseline = 'middle';
    context.fillStyle = color;
    context.fillText(text, 32, 34);
    const texture = new THREE.CanvasTexture(canvas);
    texture.colorSpace = THREE.SRGBColorSpace;
    const sprite = new THREE.Sprite(new THREE.SpriteMaterial({ map: texture, depthTest: false }));
    sprite.scale.setScalar(size);
    return sprite;
}

export function buildGuides(planes, frame) {
    const group = new THREE.Group();
    group.name = 'guides';
    // The grid lies on the first horizontal plane (the floor), else under the bounds.
    const floor = planes.find((p) => p.normal[0] === 0 && p.normal[2] === 0 && p.normal[1] > 0);
    const groundY = floor ? floor.distance / floor.normal[1] : frame.min.y;
    const cell = niceStep(frame.extent / 16);
    const cells = 2 * Math.ceil((frame.extent * 0.75) / cell);
    const grid = new THREE.GridHelper(cells * cell, cells, 0xa3aec2, 0x7b8598);
    grid.position.set(Math.round(frame.center.x / cell) * cell - frame.origin.x, groundY - frame.origin.y,
        Math.round(frame.center.z / cell) * cell - frame.origin.z);
    grid.material.transparent = true;
    grid.material.opacity = 0.5;
    group.add(grid);

    // The axes at the world's origin when it is in view, else at the bounds' low corner.
    const near = frame.center.length() <= frame.extent * 1.5;
    const at = near ? new THREE.Vector3(0, groundY, 0) : frame.min.clone();
    const length = frame.extent * 0.14;
    const axes = new THREE.AxesHelper(length);
    axes.position.copy(at.clone().sub(frame.origin));
    axes.material.depthTest = false;
    axes.renderOrder = 3;
    group.add(axes);
    const letters = [['X', '#ff5a5a', [1, 0, 0]], ['Y', '#6bdc6b', [0, 1, 0]], ['Z', '#5aa0ff', [0, 0, 1]]];
    for (const [text, color, direction] of letters) {
        const sprite = label(text, color, length * 0.28);
        sprite.position.copy(axes.position).addScaledVector(new THREE.Vector3(...direction), length * 1.12);
        sprite.renderOrder = 3;
        group.add(sprite);
    }
    return { group, cell };
}
