// article_scenarios.mjs: the WebAssembly package's twin of examples/article_scenarios.cpp. It
// must print exactly the same text (CTest compares the two): the reference article's three
// scenarios, numbers with 6 decimals as printf's "%.6f". Metres, seconds, radians; +Y up, +Z
// forward.
//
//   node examples/article_scenarios.mjs

import { loadForesight, TrajectoryEvent } from '../index.mjs';

// printf's "%.6f" of a double: the exact binary value rounded to 6 decimals, an exact tie to
// even. (Number.prototype.toFixed rounds a tie away from zero: 0.0078125 gives "0.007813" where
// printf gives "0.007812".) -0 prints as 0, as the C++ program's `value + 0.0`.
function number(value) {
    if (!Number.isFinite(value)) return value > 0 ? 'inf' : value < 0 ? '-inf' : 'nan';
    const bits = new DataView(new ArrayBuffer(8));
    bits.setFloat64(0, value);
    const hi = bits.getUint32(0), lo = bits.getUint32(4);
    const negative = hi >>> 31 === 1;
    const biased = (hi >>> 20) & 0x7ff;
    let mantissa = (BigInt(hi & 0xfffff) << 32n) | BigInt(lo);
    if (biased !== 0) mantissa |= 1n << 52n;
    const exponent = (biased === 0 ? 1 : biased) - 1075; // value = mantissa * 2^exponent
    let scaled; // round(|value| * 10^6), ties to even
    if (exponent >= 0) {
        scaled = (mantissa << BigInt(exponent)) * 1000000n;
    } else {
        const numerator = mantissa * 1000000n, denominator = 1n << BigInt(-exponent);
        scaled = numerator / denominator;
        const twice = 2n * (numerator % denominator);
        if (twice > denominator || (twice === denominator && scaled % 2n === 1n)) scaled += 1n;
    }
    const digits = scaled.toString().padStart(7, '0');
    const text = `${digits.slice(0, -6)}.${digits.slice(-6)}`;
    return negative && value !== 0 ? `-${text}` : text;
}

const vec = (label, v) => `${label} (${number(v.x)}, ${number(v.y)}, ${number(v.z)})`;
const out = [];

function character(fs) {
    const now = { position: [1, 0, 2], velocity: [3, 0, 4] };
    const linear = fs.predictLinear(now, 0.5);
    const accelerated = fs.predictAccelerated(now, [0, 0, -2], 0.5);
    out.push('character');
    out.push(vec('  linear      position', linear.position) + vec(' velocity', linear.velocity));
    out.push(vec('  accelerated position', accelerated.position) + vec(' velocity', accelerated.velocity));
}

function grenade(fs, name, settings, world) {
    const hand = [0, Math.fround(1.6), 0]; // the C++ program's RVec3(0, 1.6f, 0)
    const result = fs.predictProjectile(hand, [0, 4, 12], 3, { settings, world });
    const t = result.trajectory;
    out.push(`grenade ${name}: ${result.bounces} bounces, ${t.length} points`);
    let shown = 0;
    for (let i = 0; i < t.length && shown < 3; ++i) {
        if (t.event[i] !== TrajectoryEvent.bounce) continue;
        ++shown;
        const p = t.position, n = t.normal;
        out.push(`  bounce t ${number(t.time[i])}` + vec(' position', { x: p[3 * i], y: p[3 * i + 1], z: p[3 * i + 2] }) +
            vec(' normal', { x: n[3 * i], y: n[3 * i + 1], z: n[3 * i + 2] }));
    }
    out.push(`  end    t ${number(result.time)}` + vec(' position', result.position) +
        vec(' velocity', result.velocity) + (result.atRest ? ' at rest' : ''));
}

function grenades(fs) {
    const world = fs.createWorld();
    try {
        world.addPlane({ normal: [0, 1, 0], distance: 0 });
        world.addBox({ center: [0, 1.5, 10], halfExtents: [5, 1.5, 0.25] });
        const settings = { restitution: 0.5, friction: 0.4, radius: 0.05 };
        grenade(fs, 'stepped', { ...settings, method: 'stepped' }, world);
        grenade(fs, 'exact', { ...settings, method: 'exact' }, world);
        grenade(fs, 'jolt', { ...settings, method: 'engine', engine: 'jolt' }, world);
    } finally {
        world.delete();
    }
}

function vehicle(label, state) {
    const q = state.orientation;
    out.push(vec(label, state.position) + vec(' velocity', state.velocity) +
        ` orientation (${number(q.w)}, ${number(q.x)}, ${number(q.y)}, ${number(q.z)})`);
}

function car(fs) {
    const start = { position: [0, 0, 0], velocity: [0, 0, 10], orientation: [0, 0, 0, 1], angularVelocity: [0, 0.5, 0] };
    const iterated = fs.predictVehicleIterative(start, 2, 4);
    const exact = fs.predictVehicleExact(start, 2);
    out.push('car');
    vehicle('  iterative', iterated);
    vehicle('  exact    ', exact);
}

const fs = await loadForesight();
character(fs);
grenades(fs);
car(fs);
process.stdout.write(out.join('\n') + '\n');
