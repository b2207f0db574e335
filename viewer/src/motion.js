// Where each predicted object is at time t, from its path (docs/viewer-format.md).
// Before its first point an object is at its start; after its last, at its end.

// The index of the last point with point.t <= t (paths are time-ordered), or -1.
function segmentIndex(path, t) {
    let low = 0;
    let high = path.length - 1;
    if (t < path[0].t) return -1;
    while (low < high) {
        const middle = (low + high + 1) >> 1;
        if (path[middle].t <= t) low = middle;
        else high = middle - 1;
    }
    return low;
}

const lerp3 = (a, b, s) => [a[0] + (b[0] - a[0]) * s, a[1] + (b[1] - a[1]) * s, a[2] + (b[2] - a[2]) * s];
const isZero = (v) => v[0] === 0 && v[1] === 0 && v[2] === 0;

// Projectile: between two points it flies p + v dt + g dt^2 / 2 from the first. That is exact
// for free flight; where the path is not free flight over a segment (the article's loop cuts a
// step short at a hit, sliding contact), the parabola misses the next point, so the miss is
// spread linearly over the segment: the object stays continuous and meets every point at its
// time, and a parabola that does meet the next point is left unchanged. From a rest point (or a
// point with zero velocity) it stays put rather than fall through the surface it rests on.
export function projectilePosition(path, gravity, t) {
    const k = segmentIndex(path, t);
    if (k < 0) return path[0].position.slice();
    const a = path[k];
    if (k === path.length - 1) return a.position.slice();
    const b = path[k + 1];
    const span = b.t - a.t;
    if (span <= 0) return a.position.slice();
    const s = (t - a.t) / span;
    if (a.event === 'rest' || isZero(a.velocity)) return lerp3(a.position, b.position, s);
    const dt = t - a.t;
    const out = [0, 0, 0];
    for (let i = 0; i < 3; ++i) {
        const flight = (time) => a.position[i] + a.velocity[i] * time + 0.5 * gravity[i] * time * time;
        out[i] = flight(dt) + (b.position[i] - flight(span)) * s;
    }
    return out;
}

// Samples (vehicle, linear, accelerated): straight between samples.
export function samplePosition(path, t) {
    const k = segmentIndex(path, t);
    if (k < 0) return path[0].position.slice();
    if (k === path.length - 1) return path[k].position.slice();
    const a = path[k];
    const b = path[k + 1];
    const span = b.t - a.t;
    return span > 0 ? lerp3(a.position, b.position, (t - a.t) / span) : a.position.slice();
}

// Vehicle orientation: slerp between samples. Returns {w, x, y, z}, unit length.
export function sampleOrientation(path, t) {
    const k = Math.max(0, segmentIndex(path, t));
    const a = normalized(path[k].orientation);
    if (k === path.length - 1 || t <= path[k].t) return a;
    const b = normalized(path[k + 1].orientation);
    const span = path[k + 1].t - path[k].t;
    return span > 0 ? slerp(a, b, (t - path[k].t) / span) : a;
}

function normalized(q) {
    const n = Math.hypot(q.w, q.x, q.y, q.z);
    return { w: q.w / n, x: q.x / n, y: q.y / n, z: q.z / n };
}

function slerp(a, b, s) {
    let cos = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
    let sign = 1;
    if (cos < 0) { // the shorter way round: q and -q are the same rotation
        cos = -cos;
        sign = -1;
    }
    let wa;
    let wb;
    if (cos > 0.9995) { // nearly parallel: lerp (then normalise) avoids dividing by sin ~ 0
        wa = 1 - s;
        wb = s;
    } else {
        const angle = Math.acos(cos);
        const sin = Math.sin(angle);
        wa = Math.sin((1 - s) * angle) / sin;
        wb = Math.sin(s * angle) / sin;
    }
    wb *= sign;
    return normalized({ w: wa * a.w + wb * b.w, x: wa * a.x + wb * b.x,
        y: wa * a.y + wb * b.y, z: wa * a.z + wb * b.z });
}

// The object's state at t: {position, orientation (vehicles only)}.
export function stateAt(prediction, gravity, t) {
    const path = prediction.path;
    if (prediction.model === 'projectile') return { position: projectilePosition(path, gravity, t) };
    if (prediction.model === 'vehicle') {
        return { position: samplePosition(path, t), orientation: sampleOrientation(path, t) };
    }
    return { position: samplePosition(path, t) };
}

// The time an object stops: its last point (or its prediction time, if later).
export function endTime(prediction) {
    return Math.max(prediction.time, prediction.path[prediction.path.length - 1].t);
}
