// foresight for JavaScript: a thin layer over the C API (include/foresight/foresight_c.h)
// compiled to WebAssembly (dist/foresight_core.mjs). Structs are written to and read from the
// module's memory at the offsets foresight_c.h documents; nothing else is duplicated here.
//
// Units and axes are the library's: metres, seconds, radians; +Y up, +Z forward.

import createForesightCore from './dist/foresight_core.mjs';

/** The ABI version this layer was written for (FS_ABI_VERSION of foresight_c.h). */
const ABI_VERSION = 1;

/** fs_status values by name (foresight_c.h). */
export const Status = Object.freeze({
    OK: 0,
    NON_FINITE_INPUT: 1,
    NEGATIVE_TIME: 2,
    INVALID_STEP: 3,
    INVALID_ITERATIONS: 4,
    INVALID_RESTITUTION: 5,
    INVALID_FRICTION: 6,
    INVALID_RADIUS: 7,
    ZERO_QUATERNION: 8,
    ZERO_VECTOR: 9,
    DEGENERATE_SHAPE: 10,
    TOO_MANY_STEPS: 11,
    TOO_MANY_EVENTS: 12,
    NON_FINITE_RESULT: 13,
    INVALID_ALGORITHM: 14,
    INVALID_SPEED: 15,
    INVALID_FUSE: 16,
    INVALID_SETTING: 17,
    TIME_WENT_BACKWARDS: 18,
    NO_UPDATE: 19,
    OUT_OF_RANGE: 20,
    BUFFER_TOO_SMALL: 1000,
    NULL_POINTER: 1001,
    OUT_OF_MEMORY: 1002,
});
const statusNames = new Map(Object.entries(Status).map(([name, value]) => [value, name]));

/** Projectile integrators by name (FS_METHOD_*). */
export const Method = Object.freeze({ exact: 0, stepped: 1, engine: 2 });
/** Physics engines FS_METHOD_ENGINE follows, by name (FS_ENGINE_*). */
export const Engine = Object.freeze({
    custom: 0, jolt: 1, physx: 2, rapier: 3, bullet: 4, godot3: 5, godot3Bullet: 6, box2d: 7,
});
/** What a trajectory point marks (FS_EVENT_*), the values of `trajectory.event`. */
export const TrajectoryEvent = Object.freeze({ start: 0, step: 1, bounce: 2, rest: 3, hit: 4, end: 5 });
/** The axes of a vehicle's angular velocity (FS_FRAME_*). */
export const Frame = Object.freeze({ body: 0, world: 1 });
/** What fixes an aimed shot's launch velocity (FS_AIM_*). */
export const AimConstraint = Object.freeze({ speed: 0, horizontalSpeed: 1, apexAboveStart: 2, apexAboveTarget: 3 });
/** The DIS (IEEE 1278.1) dead-reckoning algorithms (FS_DR_*) by their DIS names. */
export const DeadReckoning = Object.freeze({
    STATIC: 1, FPW: 2, RPW: 3, RVW: 4, FVW: 5, FPB: 6, RPB: 7, RVB: 8, FVB: 9,
});
/** How a Receiver shows its entity (FS_DR_MODE_*). */
export const ReceiverMode = Object.freeze({ extrapolate: 0, interpolate: 1 });
/** How a Receiver hides corrections when extrapolating (FS_DR_SMOOTH_*). */
export const Smoothing = Object.freeze({ snap: 0, linearBlend: 1, projectiveVelocity: 2, exponentialDecay: 3 });
/** What Receiver.receive did with an update (FS_DR_ACCEPTED ... FS_DR_TOO_FAR_AHEAD), the names it returns. */
export const ReceiveOutcome = Object.freeze({
    accepted: 0, snapped: 1, buffered: 2, outOfOrder: 3, duplicate: 4, invalid: 5, tooFarAhead: 6,
});

/**
 * What the library refused, thrown by every call that gets a status other than OK. `message` is
 * "<function>: <the library's status message>", e.g. "predictLinear: time must be >= 0".
 */
export class ForesightError extends Error {
    /**
     * @param {string} operation  the function that failed.
     * @param {number} status     the fs_status value.
     * @param {string} text       the library's description of it.
     */
    constructor(operation, status, text) {
        super(`${operation}: ${text}`);
        this.name = 'ForesightError';
        /** The fs_status value (see Status). */
        this.status = status;
        /** Its name in Status, e.g. "NEGATIVE_TIME". */
        this.code = statusNames.get(status) ?? 'UNKNOWN';
    }
}

// ---- Reading the caller's values --------------------------------------------------------------

function num(value, name) {
    if (typeof value !== 'number') throw new TypeError(`${name} must be a number, got ${typeof value}`);
    return value;
}

function vec(v, name) {
    if (v !== null && typeof v === 'object') {
        if (typeof v.length === 'number') {
            if (v.length === 3) return [num(v[0], `${name}[0]`), num(v[1], `${name}[1]`), num(v[2], `${name}[2]`)];
        } else if ('x' in v) {
            return [num(v.x, `${name}.x`), num(v.y, `${name}.y`), num(v.z, `${name}.z`)];
        }
    }
    throw new TypeError(`${name} must be {x, y, z} or [x, y, z]`);
}

function quat(q, name) {
    if (q !== null && typeof q === 'object') {
        if (typeof q.length === 'number') {
            if (q.length === 4) {
                return [num(q[0], `${name}[0]`), num(q[1], `${name}[1]`), num(q[2], `${name}[2]`), num(q[3], `${name}[3]`)];
            }
        } else if ('w' in q) {
            return [num(q.x, `${name}.x`), num(q.y, `${name}.y`), num(q.z, `${name}.z`), num(q.w, `${name}.w`)];
        }
    }
    throw new TypeError(`${name} must be {x, y, z, w} or [x, y, z, w]`);
}

function uint32(value, name) {
    if (value === Infinity) return 0xffffffff;
    if (!Number.isInteger(value) || value < 0 || value > 0xffffffff) {
        throw new RangeError(`${name} must be an integer in 0 .. 4294967295 (or Infinity)`);
    }
    return value;
}

function int32(value, name) {
    if (!Number.isInteger(value) || value < -0x80000000 || value > 0x7fffffff) {
        throw new RangeError(`${name} must be a 32-bit integer`);
    }
    return value;
}

function enumValue(table, value, name) {
    if (typeof value === 'number') return int32(value, name);
    if (typeof value === 'string' && Object.hasOwn(table, value)) return table[value];
    throw new RangeError(`${name} must be one of ${Object.keys(table).join(', ')}`);
}

function checkKeys(object, allowed, name) {
    if (object === undefined || object === null) return {};
    if (typeof object !== 'object') throw new TypeError(`${name} must be an object`);
    for (const key of Object.keys(object)) {
        if (!allowed.includes(key)) throw new TypeError(`${name}: unknown field "${key}" (known: ${allowed.join(', ')})`);
    }
    return object;
}

const xyz = (a) => ({ x: a[0], y: a[1], z: a[2] });

const projectileKeys = ['method', 'engine', 'gravity', 'step', 'restitution', 'friction', 'radius', 'maxBounces',
    'maxSteps', 'maxEvents'];
const shotKeys = ['from', 'constraint', 'speed', 'apexHeight', 'gravity', 'maxTime'];
const drStateKeys = ['position', 'velocity', 'acceleration', 'orientation', 'angularVelocity', 'algorithm'];
const receiverKeys = ['mode', 'smoothing', 'blendTime', 'decayHalfLife', 'teleportDistance', 'extrapolationLimit',
    'interpolationDelay', 'maxFutureSkew', 'restartAfter'];
const counterNames = ['accepted', 'snaps', 'teleports', 'outOfOrder', 'duplicates', 'invalid', 'held', 'futureUpdates',
    'tooFarAhead', 'clockRestarts'];
const outcomeNames = Object.keys(ReceiveOutcome);
const vehicleBodyKeys = ['position', 'velocity', 'orientation', 'angularVelocity', 'frame', 'forward', 'halfExtents',
    'boxCenter'];
const characterKeys = ['position', 'velocity', 'acceleration', 'radius', 'halfAxis'];
const nameOf = (table, value) => Object.keys(table).find((k) => table[k] === value);

/**
 * Loads the WebAssembly module (embedded in dist/foresight_core.mjs: nothing is fetched) and
 * returns the API. Each call makes an instance with its own memory.
 * @returns {Promise<Foresight>}
 */
export async function loadForesight() {
    const core = await createForesightCore();
    return new Foresight(core);
}
export default loadForesight;

// Offsets in the scratch block (bytes; every struct at a multiple of 8).
const IN_A = 0; // first input struct (up to 80 bytes)
const IN_B = 128; // second input struct
const OUT = 256; // output struct (up to 80 bytes)
const MATERIAL = 384; // fs_material, then a size_t count at +16
const COUNT = 400;
const SOLUTIONS = 448; // FS_MAX_FIRING_SOLUTIONS fs_firing_solution (4 * 48 bytes)
const POSITION = 640; // fs_dvec3
const VELOCITY = 672; // fs_vec3
const SCRATCH_BYTES = 1024;
const POINT_BYTES = 56; // sizeof(fs_trajectory_point)
const MAX_SOLUTIONS = 4;
const DR_STATE_BYTES = 80; // sizeof(fs_dr_state)
const DR_RESULT_BYTES = 56; // sizeof(fs_dr_result)

/**
 * The API on one WebAssembly instance (made by loadForesight). Every function takes plain
 * objects or arrays and returns plain objects; a refused input throws ForesightError.
 */
export class Foresight {
    #core;
    #memory;
    #buffer = null;
    #f64;
    #f32;
    #i32;
    #u32;
    #scratch;
    #points = 0; // trajectory buffer
    #capacity = 0; // its size in points
    #messages = new Map();
    #projectileDefaults;
    #shotDefaults;
    #vehicleDefaults;
    #receiverDefaults;
    #vehicleBodyDefaults;
    #characterDefaults;
    #approachDefaults;
    #batch = 0; // dead-reckoning batch buffer: states, timestamps, results
    #batchCapacity = 0; // its size in entities

    /** @param {object} core  the emscripten module (use loadForesight). */
    constructor(core) {
        this.#core = core;
        this.#memory = core.asm.memory;
        if (core._fs_abi_version() !== ABI_VERSION) {
            throw new Error(`foresight: the module has ABI ${core._fs_abi_version()}, this layer ${ABI_VERSION}`);
        }
        this.#scratch = core._malloc(SCRATCH_BYTES);
        this.#reserve(256);
        const s = this.#scratch;
        core._fsw_projectile_settings_default(s + IN_A);
        this.#projectileDefaults = Object.freeze(this.#readProjectileSettings(s + IN_A));
        core._fsw_aim_shot_default(s + IN_A);
        this.#views();
        const b = (s + IN_A) >> 2;
        this.#shotDefaults = Object.freeze({
            constraint: this.#i32[b + 6], speed: this.#f32[b + 7], apexHeight: this.#f32[b + 8],
            gravity: Object.freeze(xyz(this.#f32.subarray(b + 9, b + 12))), maxTime: this.#f32[b + 12],
        });
        core._fsw_vehicle_settings_default(s + IN_A);
        this.#views();
        this.#vehicleDefaults = Object.freeze({
            frame: this.#i32[b], forward: Object.freeze(xyz(this.#f32.subarray(b + 1, b + 4))),
        });
        core._fsw_vehicle_body_default(s + IN_A);
        this.#views();
        this.#vehicleBodyDefaults = Object.freeze({
            halfExtents: Object.freeze(xyz(this.#f32.subarray(b + 20, b + 23))),
            boxCenter: Object.freeze(xyz(this.#f32.subarray(b + 23, b + 26))),
        });
        core._fsw_character_body_default(s + IN_A);
        this.#views();
        this.#characterDefaults = Object.freeze({ radius: this.#f32[b + 12] });
        core._fsw_approach_settings_default(s + IN_A);
        this.#views();
        this.#approachDefaults = Object.freeze({ tolerance: this.#f32[b], maxEvaluations: this.#u32[b + 1] });
        core._fsw_dr_receiver_settings_default(s + IN_A);
        this.#views();
        this.#receiverDefaults = Object.freeze({
            mode: nameOf(ReceiverMode, this.#i32[b]), smoothing: nameOf(Smoothing, this.#i32[b + 1]),
            blendTime: this.#f32[b + 2], decayHalfLife: this.#f32[b + 3], teleportDistance: this.#f32[b + 4],
            extrapolationLimit: this.#f32[b + 5], interpolationDelay: this.#f32[b + 6],
            maxFutureSkew: this.#f32[b + 7], restartAfter: this.#f32[b + 8],
        });
    }

    // The typed arrays on the module's memory (new ones after it grew).
    #views() {
        const buffer = this.#memory.buffer;
        if (buffer !== this.#buffer) {
            this.#buffer = buffer;
            this.#f64 = new Float64Array(buffer);
            this.#f32 = new Float32Array(buffer);
            this.#i32 = new Int32Array(buffer);
            this.#u32 = new Uint32Array(buffer);
        }
    }

    #reserve(points) {
        if (points <= this.#capacity) return;
        if (this.#points !== 0) this.#core._free(this.#points);
        this.#points = this.#core._malloc(points * POINT_BYTES);
        if (this.#points === 0) {
            this.#capacity = 0;
            throw new ForesightError('predictProjectile', Status.OUT_OF_MEMORY, 'out of memory');
        }
        this.#capacity = points;
    }

    /**
     * The library's description of a status value, e.g. "time must be >= 0".
     * @param {number} status  an fs_status value.
     * @returns {string}
     */
    statusMessage(status) {
        let text = this.#messages.get(status);
        if (text === undefined) {
            const pointer = this.#core._fs_status_message(status);
            this.#views();
            const bytes = new Uint8Array(this.#buffer, pointer);
            text = new TextDecoder().decode(bytes.subarray(0, bytes.indexOf(0)));
            this.#messages.set(status, text);
        }
        return text;
    }

    #check(status, operation) {
        if (status !== Status.OK) throw new ForesightError(operation, status, this.statusMessage(status));
    }

    /** The C API's ABI version (FS_ABI_VERSION). @returns {number} */
    abiVersion() {
        return this.#core._fs_abi_version();
    }

    /**
     * The end of the module's heap [bytes]: constant across calls that free what they allocate
     * (a diagnostic for leak checks).
     * @returns {number}
     */
    heapEnd() {
        return this.#core._fsw_heap_end() >>> 0;
    }

    // ---- Characters ---------------------------------------------------------------------------

    #writePointState(at, state, name) {
        if (state === null || typeof state !== 'object') throw new TypeError(`${name} must be {position, velocity}`);
        const p = vec(state.position, `${name}.position`);
        const v = vec(state.velocity, `${name}.velocity`);
        this.#views();
        const d = at >> 3, f = at >> 2;
        this.#f64[d] = p[0]; this.#f64[d + 1] = p[1]; this.#f64[d + 2] = p[2];
        this.#f32[f + 6] = v[0]; this.#f32[f + 7] = v[1]; this.#f32[f + 8] = v[2];
        this.#f32[f + 9] = 0;
    }

    #readPointState(at) {
        this.#views();
        const d = at >> 3, f = at >> 2;
        return {
            position: xyz(this.#f64.subarray(d, d + 3)),
            velocity: xyz(this.#f32.subarray(f + 6, f + 9)),
        };
    }

    /**
     * Constant velocity: position `p + v t`, velocity unchanged.
     * @param {{position: Vec3Like, velocity: Vec3Like}} state  position [m], velocity [m/s].
     * @param {number} time  horizon [s], >= 0 (rounded to float).
     * @returns {{position: Vec3, velocity: Vec3}}
     */
    predictLinear(state, time) {
        const s = this.#scratch;
        this.#writePointState(s + IN_A, state, 'state');
        this.#check(this.#core._fs_predict_linear(s + IN_A, num(time, 'time'), s + OUT), 'predictLinear');
        return this.#readPointState(s + OUT);
    }

    /**
     * Constant acceleration: position `p + v t + a t^2 / 2`, velocity `v + a t`.
     * @param {{position: Vec3Like, velocity: Vec3Like}} state  position [m], velocity [m/s].
     * @param {Vec3Like} acceleration  [m/s^2], world axes.
     * @param {number} time  horizon [s], >= 0.
     * @returns {{position: Vec3, velocity: Vec3}}
     */
    predictAccelerated(state, acceleration, time) {
        const s = this.#scratch;
        this.#writePointState(s + IN_A, state, 'state');
        const a = vec(acceleration, 'acceleration');
        const f = (s + IN_B) >> 2;
        this.#f32[f] = a[0]; this.#f32[f + 1] = a[1]; this.#f32[f + 2] = a[2];
        this.#check(this.#core._fsw_predict_accelerated(s + IN_A, s + IN_B, num(time, 'time'), s + OUT),
            'predictAccelerated');
        return this.#readPointState(s + OUT);
    }

    // ---- Vehicles -----------------------------------------------------------------------------

    #writeVehicle(at, state, settings) {
        if (state === null || typeof state !== 'object') {
            throw new TypeError('state must be {position, velocity, orientation, angularVelocity}');
        }
        const p = vec(state.position, 'state.position');
        const v = vec(state.velocity, 'state.velocity');
        const q = quat(state.orientation ?? [0, 0, 0, 1], 'state.orientation');
        const w = vec(state.angularVelocity, 'state.angularVelocity');
        const options = checkKeys(settings, ['frame', 'forward'], 'settings');
        const frame = enumValue(Frame, options.frame ?? this.#vehicleDefaults.frame, 'settings.frame');
        const forward = vec(options.forward ?? this.#vehicleDefaults.forward, 'settings.forward');
        this.#views();
        const d = at >> 3, f = at >> 2;
        this.#f64[d] = p[0]; this.#f64[d + 1] = p[1]; this.#f64[d + 2] = p[2];
        this.#f32.set(v, f + 6);
        this.#f32.set(q, f + 9);
        this.#f32.set(w, f + 13);
        const g = (this.#scratch + IN_B) >> 2;
        this.#i32[g] = frame;
        this.#f32.set(forward, g + 1);
    }

    #readVehicle(at) {
        this.#views();
        const d = at >> 3, f = at >> 2, q = this.#f32;
        return {
            position: xyz(this.#f64.subarray(d, d + 3)),
            velocity: xyz(q.subarray(f + 6, f + 9)),
            orientation: { x: q[f + 9], y: q[f + 10], z: q[f + 11], w: q[f + 12] },
            angularVelocity: xyz(q.subarray(f + 13, f + 16)),
        };
    }

    /**
     * The reference article's vehicle loop: `iterations` equal steps of moving, turning and
     * putting the velocity on the new forward axis.
     * @param {VehicleStateLike} state  position [m], velocity [m/s], orientation (local-to-world
     *     quaternion, default identity), angularVelocity [rad/s] in the settings' frame.
     * @param {number} time  [s], >= 0.
     * @param {number} [iterations=4]  1 .. 1048576.
     * @param {VehicleSettings} [settings]  frame ('body' default, or 'world') and forward axis (+Z).
     * @returns {VehicleState}
     */
    predictVehicleIterative(state, time, iterations = 4, settings = undefined) {
        const s = this.#scratch;
        this.#writeVehicle(s + IN_A, state, settings);
        this.#check(this.#core._fs_predict_vehicle_iterative(s + IN_A, num(time, 'time'),
            int32(iterations, 'iterations'), s + IN_B, s + OUT), 'predictVehicleIterative');
        return this.#readVehicle(s + OUT);
    }

    /**
     * The exact arc of the same motion: a circle of radius |v| / |w| when the angular velocity is
     * perpendicular to the forward axis.
     * @param {VehicleStateLike} state  as for predictVehicleIterative.
     * @param {number} time  [s], >= 0.
     * @param {VehicleSettings} [settings]  frame and forward axis.
     * @returns {VehicleState}
     */
    predictVehicleExact(state, time, settings = undefined) {
        const s = this.#scratch;
        this.#writeVehicle(s + IN_A, state, settings);
        this.#check(this.#core._fs_predict_vehicle_exact(s + IN_A, num(time, 'time'), s + IN_B, s + OUT),
            'predictVehicleExact');
        return this.#readVehicle(s + OUT);
    }

    // ---- Dead reckoning (netcode) -------------------------------------------------------------

    #writeDrState(at, state, name) {
        if (state === undefined || state === null) throw new TypeError(`${name} must be {position, velocity, algorithm, ...}`);
        const o = checkKeys(state, drStateKeys, name);
        const p = vec(o.position, `${name}.position`);
        const v = vec(o.velocity, `${name}.velocity`);
        const a = vec(o.acceleration ?? [0, 0, 0], `${name}.acceleration`);
        const q = quat(o.orientation ?? [0, 0, 0, 1], `${name}.orientation`);
        const w = vec(o.angularVelocity ?? [0, 0, 0], `${name}.angularVelocity`);
        const algorithm = enumValue(DeadReckoning, o.algorithm, `${name}.algorithm`);
        this.#views();
        const d = at >> 3, f = at >> 2;
        this.#f64[d] = p[0]; this.#f64[d + 1] = p[1]; this.#f64[d + 2] = p[2];
        this.#f32.set(v, f + 6);
        this.#f32.set(a, f + 9);
        this.#f32.set(q, f + 12);
        this.#f32.set(w, f + 16);
        this.#i32[f + 19] = algorithm;
    }

    // fs_dr_result and fs_dr_pose: position, velocity, orientation (and the pose's held flag).
    #readDrPose(at, pose) {
        this.#views();
        const d = at >> 3, f = at >> 2;
        const result = {
            position: xyz(this.#f64.subarray(d, d + 3)),
            velocity: xyz(this.#f32.subarray(f + 6, f + 9)),
            orientation: { x: this.#f32[f + 9], y: this.#f32[f + 10], z: this.#f32[f + 11], w: this.#f32[f + 12] },
        };
        if (pose) result.held = this.#i32[f + 13] !== 0;
        return result;
    }

    /**
     * The DIS name of a dead-reckoning algorithm: "STATIC", "FPW", ... "FVB"; "?" for another value.
     * @param {number|string} algorithm  a DeadReckoning value (or name).
     * @returns {string}
     */
    deadReckoningAlgorithmName(algorithm) {
        const pointer = this.#core._fs_dr_algorithm_name(enumValue(DeadReckoning, algorithm, 'algorithm'));
        this.#views();
        const bytes = new Uint8Array(this.#buffer, pointer);
        return new TextDecoder().decode(bytes.subarray(0, bytes.indexOf(0)));
    }

    /**
     * Extrapolates a remote entity's last update by `time` with its DIS algorithm
     * (foresight::predictDeadReckoning): FPW is `p + v t`, FVW `p + v t + a t^2 / 2`, the R*
     * models turn the orientation by the angular velocity, the *B models read velocity and
     * acceleration in body axes.
     * @param {DeadReckoningStateLike} state  position [m], velocity [m/s], acceleration [m/s^2]
     *     (default 0), orientation (body-to-world, default identity), angularVelocity [rad/s, body
     *     axes] (default 0), algorithm ('STATIC' ... 'FVB' or 1 ... 9).
     * @param {number} time  [s] since the update, >= 0.
     * @returns {{position: Vec3, velocity: Vec3, orientation: Quat}}  velocity in the input's axes.
     */
    predictDeadReckoning(state, time) {
        const s = this.#scratch;
        this.#writeDrState(s + IN_A, state, 'state');
        this.#check(this.#core._fs_dr_predict(s + IN_A, num(time, 'time'), s + OUT), 'predictDeadReckoning');
        return this.#readDrPose(s + OUT, false);
    }

    #reserveBatch(count) {
        if (count <= this.#batchCapacity) return;
        const capacity = Math.max(count, 2 * this.#batchCapacity);
        const pointer = this.#core._malloc(capacity * (DR_STATE_BYTES + 8 + DR_RESULT_BYTES));
        if (pointer === 0) throw new ForesightError('predictDeadReckoningBatch', Status.OUT_OF_MEMORY, 'out of memory');
        if (this.#batch !== 0) this.#core._free(this.#batch);
        this.#batch = pointer;
        this.#batchCapacity = capacity;
    }

    /**
     * Extrapolates many entities to one time (foresight::predictDeadReckoningBatch), arrays in
     * and out: entity i's result is predictDeadReckoning(state i, max(time - timestamp[i], 0))
     * bit for bit. A refused entity (NaN, zero quaternion, unknown algorithm, NaN timestamp) gets
     * its state as given and is counted in `refused`; nothing throws for it.
     * @param {DeadReckoningBatch} batch  timestamp [s] (n numbers: n is its length), position [m]
     *     (3n), velocity [m/s] (3n), algorithm (n), and optionally acceleration [m/s^2] (3n),
     *     orientation (4n, x y z w), angularVelocity [rad/s] (3n); any array-likes (typed arrays).
     * @param {number} time  [s] the time to extrapolate to.
     * @returns {DeadReckoningBatchResult}  position Float64Array (3n), velocity Float32Array (3n),
     *     orientation Float32Array (4n), refused.
     */
    predictDeadReckoningBatch(batch, time) {
        const o = checkKeys(batch, ['timestamp', ...drStateKeys], 'batch');
        const timestamps = o.timestamp;
        if (timestamps === null || typeof timestamps !== 'object' || typeof timestamps.length !== 'number') {
            throw new TypeError('batch.timestamp must be an array of numbers');
        }
        const n = timestamps.length;
        const field = (key, per, required) => {
            const a = o[key];
            if (a === undefined && !required) return null;
            if (a === null || typeof a !== 'object' || a.length !== per * n) {
                throw new RangeError(`batch.${key} must be an array of ${per * n} numbers (${per} per entity)`);
            }
            return a;
        };
        const position = field('position', 3, true), velocity = field('velocity', 3, true);
        const algorithm = field('algorithm', 1, true), acceleration = field('acceleration', 3, false);
        const orientation = field('orientation', 4, false), angularVelocity = field('angularVelocity', 3, false);
        const t = num(time, 'time');
        this.#reserveBatch(n);
        const states = this.#batch, stamps = states + n * DR_STATE_BYTES, out = stamps + 8 * n;
        this.#views();
        const f64 = this.#f64, f32 = this.#f32, i32 = this.#i32;
        for (let k = 0; k < n; ++k) {
            const d = (states + k * DR_STATE_BYTES) >> 3, f = d << 1;
            f64[d] = num(position[3 * k], 'batch.position[i]');
            f64[d + 1] = num(position[3 * k + 1], 'batch.position[i]');
            f64[d + 2] = num(position[3 * k + 2], 'batch.position[i]');
            for (let c = 0; c < 3; ++c) {
                f32[f + 6 + c] = num(velocity[3 * k + c], 'batch.velocity[i]');
                f32[f + 9 + c] = acceleration ? num(acceleration[3 * k + c], 'batch.acceleration[i]') : 0;
                f32[f + 16 + c] = angularVelocity ? num(angularVelocity[3 * k + c], 'batch.angularVelocity[i]') : 0;
            }
            for (let c = 0; c < 4; ++c) {
                f32[f + 12 + c] = orientation ? num(orientation[4 * k + c], 'batch.orientation[i]') : c === 3 ? 1 : 0;
            }
            i32[f + 19] = enumValue(DeadReckoning, algorithm[k], 'batch.algorithm[i]');
            f64[(stamps >> 3) + k] = num(timestamps[k], 'batch.timestamp[i]');
        }
        const s = this.#scratch;
        this.#check(this.#core._fs_dr_predict_batch(states, stamps, n, t, out, s + COUNT), 'predictDeadReckoningBatch');
        this.#views();
        const result = {
            position: new Float64Array(3 * n), velocity: new Float32Array(3 * n), orientation: new Float32Array(4 * n),
            refused: this.#u32[(s + COUNT) >> 2],
        };
        for (let k = 0; k < n; ++k) {
            const d = (out + k * DR_RESULT_BYTES) >> 3, f = d << 1;
            result.position[3 * k] = this.#f64[d];
            result.position[3 * k + 1] = this.#f64[d + 1];
            result.position[3 * k + 2] = this.#f64[d + 2];
            for (let c = 0; c < 3; ++c) result.velocity[3 * k + c] = this.#f32[f + 6 + c];
            for (let c = 0; c < 4; ++c) result.orientation[4 * k + c] = this.#f32[f + 9 + c];
        }
        return result;
    }

    /**
     * The library's default receiver settings: mode 'extrapolate', smoothing
     * 'projectiveVelocity', blendTime 0.2 s, decayHalfLife 0.1 s, teleportDistance 10 m,
     * extrapolationLimit 0.25 s, interpolationDelay 0.1 s, maxFutureSkew 1 s, restartAfter 10 s.
     * @returns {ReceiverSettingsResolved}
     */
    receiverSettings() {
        return { ...this.#receiverDefaults };
    }

    /**
     * A receiver of one remote entity (foresight::DeadReckoningReceiver): takes its updates,
     * drops stale or bad ones, and shows it extrapolated (corrections blended) or interpolated.
     * Free it with `delete()`: its memory is the module's.
     * @param {ReceiverSettings} [settings]  fields of receiverSettings(), defaults for the missing ones.
     * @returns {Receiver}
     */
    createReceiver(settings = undefined) {
        const o = checkKeys(settings, receiverKeys, 'settings');
        const d = this.#receiverDefaults;
        const mode = enumValue(ReceiverMode, o.mode ?? d.mode, 'settings.mode');
        const smoothing = enumValue(Smoothing, o.smoothing ?? d.smoothing, 'settings.smoothing');
        const floats = receiverKeys.slice(2).map((key) => num(o[key] ?? d[key], `settings.${key}`));
        const s = this.#scratch;
        this.#views();
        const f = (s + IN_A) >> 2;
        this.#i32[f] = mode;
        this.#i32[f + 1] = smoothing;
        this.#f32.set(floats, f + 2);
        this.#check(this.#core._fs_dr_receiver_create(s + IN_A, s + COUNT), 'createReceiver');
        this.#views();
        return new Receiver(this, this.#u32[(s + COUNT) >> 2], this.#core);
    }

    /** @internal Receiver.receive. */
    _receive(receiver, timestamp, state, receiveTime) {
        const s = this.#scratch;
        const stamp = num(timestamp, 'timestamp');
        this.#writeDrState(s + IN_A, state, 'state');
        const now = num(receiveTime, 'receiveTime');
        this.#check(this.#core._fs_dr_receiver_receive(receiver, stamp, s + IN_A, now, s + COUNT), 'receive');
        this.#views();
        return outcomeNames[this.#i32[(s + COUNT) >> 2]];
    }

    /** @internal Receiver.sample. */
    _sample(receiver, time) {
        const s = this.#scratch;
        this.#check(this.#core._fs_dr_receiver_sample(receiver, num(time, 'time'), s + OUT), 'sample');
        return this.#readDrPose(s + OUT, true);
    }

    /** @internal Receiver.counters. */
    _counters(receiver) {
        const s = this.#scratch;
        this.#check(this.#core._fs_dr_receiver_get_counters(receiver, s + OUT), 'counters');
        this.#views();
        const u = (s + OUT) >> 2, counters = {};
        counterNames.forEach((name, k) => {
            counters[name] = this.#u32[u + 2 * k] + this.#u32[u + 2 * k + 1] * 2 ** 32;
        });
        return counters;
    }

    // ---- Worlds -------------------------------------------------------------------------------

    /**
     * A new, empty static collision world (planes, spheres, boxes, triangles). Free it with
     * `delete()` (or `dispose()`, or a `using` declaration): its memory is the module's, which
     * JavaScript's garbage collector does not see.
     * @returns {World}
     */
    createWorld() {
        const pointer = this.#core._fs_world_create();
        if (pointer === 0) throw new ForesightError('createWorld', Status.OUT_OF_MEMORY, 'out of memory');
        return new World(this, pointer, this.#core);
    }

    /** @internal writes a material (or none) and returns its address or 0. */
    _material(material) {
        if (material === undefined || material === null) return 0;
        const m = checkKeys(material, ['restitution', 'friction'], 'material');
        const at = this.#scratch + MATERIAL;
        this.#views();
        this.#f32[at >> 2] = num(m.restitution ?? -1, 'material.restitution');
        this.#f32[(at >> 2) + 1] = num(m.friction ?? -1, 'material.friction');
        return at;
    }

    /** @internal the scratch block, typed arrays fresh. */
    _scratch() {
        this.#views();
        return { at: this.#scratch + IN_A, f64: this.#f64, f32: this.#f32 };
    }

    /** @internal */
    _check(status, operation) {
        this.#check(status, operation);
    }

    // ---- Projectiles --------------------------------------------------------------------------

    /**
     * The library's default projectile settings (the reference article's): method 'exact',
     * gravity (0, -9.81, 0) m/s^2, step 0.02 s, restitution 0.5, friction 0, radius 0 m, no bounce
     * limit (maxBounces 4294967295), maxSteps 1048576, maxEvents 65536, engine 'jolt'.
     * @returns {ProjectileSettings}
     */
    projectileSettings() {
        return { ...this.#projectileDefaults, gravity: { ...this.#projectileDefaults.gravity } };
    }

    #readProjectileSettings(at) {
        this.#views();
        const f = at >> 2;
        const methodName = Object.keys(Method).find((k) => Method[k] === this.#i32[f]);
        const engineName = Object.keys(Engine).find((k) => Engine[k] === this.#i32[f + 11]);
        return {
            method: methodName, gravity: xyz(this.#f32.subarray(f + 1, f + 4)), step: this.#f32[f + 4],
            restitution: this.#f32[f + 5], friction: this.#f32[f + 6], radius: this.#f32[f + 7],
            maxBounces: this.#u32[f + 8], maxSteps: this.#u32[f + 9], maxEvents: this.#u32[f + 10],
            engine: engineName,
        };
    }

    #writeProjectileSettings(at, settings) {
        const o = checkKeys(settings, projectileKeys, 'settings');
        const d = this.#projectileDefaults;
        const method = enumValue(Method, o.method ?? d.method, 'settings.method');
        const engine = enumValue(Engine, o.engine ?? d.engine, 'settings.engine');
        const gravity = vec(o.gravity ?? d.gravity, 'settings.gravity');
        const step = num(o.step ?? d.step, 'settings.step');
        const restitution = num(o.restitution ?? d.restitution, 'settings.restitution');
        const friction = num(o.friction ?? d.friction, 'settings.friction');
        const radius = num(o.radius ?? d.radius, 'settings.radius');
        const maxBounces = uint32(o.maxBounces ?? d.maxBounces, 'settings.maxBounces');
        const maxSteps = uint32(o.maxSteps ?? d.maxSteps, 'settings.maxSteps');
        const maxEvents = uint32(o.maxEvents ?? d.maxEvents, 'settings.maxEvents');
        this.#views();
        const f = at >> 2;
        this.#i32[f] = method;
        this.#f32.set(gravity, f + 1);
        this.#f32[f + 4] = step;
        this.#f32[f + 5] = restitution;
        this.#f32[f + 6] = friction;
        this.#f32[f + 7] = radius;
        this.#u32[f + 8] = maxBounces;
        this.#u32[f + 9] = maxSteps;
        this.#u32[f + 10] = maxEvents;
        this.#i32[f + 11] = engine;
    }

    /**
     * Predicts a projectile (a grenade, a thrown or fired object) under constant gravity, bouncing
     * off `options.world`.
     * @param {Vec3Like} position  start [m] (the sphere's centre when settings.radius > 0).
     * @param {Vec3Like} velocity  start velocity [m/s], at most 1e6 m/s.
     * @param {number} time  prediction time, e.g. a fuse [s], >= 0.
     * @param {ProjectileOptions} [options]  settings (fields of ProjectileSettings, defaults for
     *     the missing ones), world (null: free flight), trajectory (default true: return the points).
     * @returns {ProjectileResult}
     */
    predictProjectile(position, velocity, time, options = {}) {
        const o = checkKeys(options, ['settings', 'world', 'trajectory'], 'options');
        const p = vec(position, 'position');
        const v = vec(velocity, 'velocity');
        const t = num(time, 'time');
        const world = o.world === undefined || o.world === null ? 0 : worldPointer(o.world, this);
        const wantTrajectory = o.trajectory ?? true;
        const s = this.#scratch;
        this.#writeProjectileSettings(s + IN_B, o.settings);
        const d = (s + POSITION) >> 3, f = (s + VELOCITY) >> 2;
        this.#f64[d] = p[0]; this.#f64[d + 1] = p[1]; this.#f64[d + 2] = p[2];
        this.#f32[f] = v[0]; this.#f32[f + 1] = v[1]; this.#f32[f + 2] = v[2];
        const core = this.#core;
        const capacity = wantTrajectory ? this.#capacity : 0;
        let status = core._fsw_predict_projectile(s + POSITION, s + VELOCITY, t, s + IN_B, world,
            capacity ? this.#points : 0, capacity, s + OUT);
        if (status === Status.BUFFER_TOO_SMALL) {
            this.#views();
            const o32 = (s + OUT) >> 2;
            const needed = this.#u32[o32 + 18] + this.#u32[o32 + 19] * 2 ** 32;
            this.#reserve(Math.max(needed, 2 * this.#capacity));
            status = core._fsw_predict_projectile(s + POSITION, s + VELOCITY, t, s + IN_B, world, this.#points,
                this.#capacity, s + OUT);
        }
        this.#check(status, 'predictProjectile');
        this.#views();
        const r = (s + OUT) >> 2, rd = (s + OUT) >> 3, q = this.#f32, i = this.#i32;
        const result = {
            position: xyz(this.#f64.subarray(rd, rd + 3)),
            velocity: xyz(q.subarray(r + 6, r + 9)),
            time: q[r + 9],
            bounces: this.#u32[r + 10],
            atRest: i[r + 11] !== 0,
            stoppedAtHit: i[r + 12] !== 0,
            hitNormal: xyz(q.subarray(r + 13, r + 16)),
            trajectory: null,
        };
        if (wantTrajectory) result.trajectory = this.#readTrajectory(this.#u32[r + 16]);
        return result;
    }

    #readTrajectory(n) {
        const trajectory = {
            length: n,
            time: new Float32Array(n),
            event: new Int32Array(n),
            position: new Float64Array(3 * n),
            velocity: new Float32Array(3 * n),
            normal: new Float32Array(3 * n),
        };
        const f64 = this.#f64, f32 = this.#f32, i32 = this.#i32;
        for (let k = 0, at = this.#points; k < n; ++k, at += POINT_BYTES) {
            const f = at >> 2, d = (at + 8) >> 3;
            trajectory.time[k] = f32[f];
            trajectory.event[k] = i32[f + 1];
            trajectory.position[3 * k] = f64[d];
            trajectory.position[3 * k + 1] = f64[d + 1];
            trajectory.position[3 * k + 2] = f64[d + 2];
            trajectory.velocity[3 * k] = f32[f + 8];
            trajectory.velocity[3 * k + 1] = f32[f + 9];
            trajectory.velocity[3 * k + 2] = f32[f + 10];
            trajectory.normal[3 * k] = f32[f + 11];
            trajectory.normal[3 * k + 1] = f32[f + 12];
            trajectory.normal[3 * k + 2] = f32[f + 13];
        }
        return trajectory;
    }

    // ---- Danger -------------------------------------------------------------------------------

    // Writes a trajectory as predictProjectile returns it ({length, time, event, position,
    // velocity, normal}) to the trajectory buffer; returns its length.
    #writeTrajectory(trajectory, operation) {
        if (trajectory === null || typeof trajectory !== 'object' || !Number.isInteger(trajectory.length)) {
            throw new TypeError(`${operation}: trajectory must be a trajectory returned by predictProjectile`);
        }
        const n = trajectory.length;
        for (const [key, per] of [['time', 1], ['event', 1], ['position', 3], ['velocity', 3], ['normal', 3]]) {
            const a = trajectory[key];
            if (a === null || typeof a !== 'object' || a.length !== per * n) {
                throw new RangeError(`${operation}: trajectory.${key} must have ${per * n} numbers`);
            }
        }
        this.#reserve(n);
        this.#views();
        const f64 = this.#f64, f32 = this.#f32, i32 = this.#i32;
        const { time, event, position, velocity, normal } = trajectory;
        for (let k = 0, at = this.#points; k < n; ++k, at += POINT_BYTES) {
            const f = at >> 2, d = (at + 8) >> 3;
            f32[f] = time[k];
            i32[f + 1] = event[k];
            f64[d] = position[3 * k]; f64[d + 1] = position[3 * k + 1]; f64[d + 2] = position[3 * k + 2];
            f32[f + 8] = velocity[3 * k]; f32[f + 9] = velocity[3 * k + 1]; f32[f + 10] = velocity[3 * k + 2];
            f32[f + 11] = normal[3 * k]; f32[f + 12] = normal[3 * k + 1]; f32[f + 13] = normal[3 * k + 2];
        }
        return n;
    }

    #writeDanger(at, danger) {
        const o = checkKeys(danger, ['fuseTime', 'blastRadius', 'contactRadius'], 'danger');
        const fuse = num(o.fuseTime, 'danger.fuseTime');
        const blast = num(o.blastRadius, 'danger.blastRadius');
        const contact = num(o.contactRadius ?? 0, 'danger.contactRadius');
        this.#views();
        this.#f32[at >> 2] = fuse;
        this.#f32[(at >> 2) + 1] = blast;
        this.#f32[(at >> 2) + 2] = contact;
    }

    #writePoint(point, name) {
        const p = vec(point, name);
        this.#views();
        this.#f64.set(p, (this.#scratch + POSITION) >> 3);
        return this.#scratch + POSITION;
    }

    /**
     * Where and when a predicted grenade explodes (foresight::computeDangerZone): its position
     * on the trajectory at the fuse time, the blast radius, the fuse time.
     * @param {Trajectory} trajectory  as predictProjectile returns it (run long enough to reach the fuse).
     * @param {ProjectileDanger} danger  fuseTime [s] >= 0, blastRadius [m] >= 0, contactRadius [m]
     *     (default 0: nothing is dangerous before the fuse).
     * @returns {{center: Vec3, radius: number, time: number}}
     */
    computeDangerZone(trajectory, danger) {
        const n = this.#writeTrajectory(trajectory, 'computeDangerZone');
        const s = this.#scratch;
        this.#writeDanger(s + IN_A, danger);
        this.#check(this.#core._fs_compute_danger_zone(this.#points, n, s + IN_A, s + OUT), 'computeDangerZone');
        this.#views();
        const d = (s + OUT) >> 3, f = (s + OUT) >> 2;
        return { center: xyz(this.#f64.subarray(d, d + 3)), radius: this.#f32[f + 6], time: this.#f32[f + 7] };
    }

    /**
     * Whether `point` is safe at `time` (foresight::isPointSafe): outside the blast from the fuse
     * time on (exactly blastRadius away is unsafe), farther than contactRadius from the
     * projectile before it.
     * @param {Trajectory} trajectory  as predictProjectile returns it.
     * @param {ProjectileDanger} danger
     * @param {Vec3Like} point  [m].
     * @param {number} time  [s].
     * @returns {boolean}
     */
    isPointSafe(trajectory, danger, point, time) {
        const n = this.#writeTrajectory(trajectory, 'isPointSafe');
        const s = this.#scratch;
        this.#writeDanger(s + IN_A, danger);
        const at = this.#writePoint(point, 'point');
        this.#check(this.#core._fsw_is_point_safe(this.#points, n, s + IN_A, at, num(time, 'time'), s + COUNT),
            'isPointSafe');
        this.#views();
        return this.#i32[(s + COUNT) >> 2] !== 0;
    }

    /**
     * When danger starts at `point` (foresight::findDangerStart): the earliest time isPointSafe
     * says false, or null when it never does.
     * @param {Trajectory} trajectory  as predictProjectile returns it.
     * @param {ProjectileDanger} danger
     * @param {Vec3Like} point  [m].
     * @returns {number|null}  [s].
     */
    findDangerStart(trajectory, danger, point) {
        const n = this.#writeTrajectory(trajectory, 'findDangerStart');
        const s = this.#scratch;
        this.#writeDanger(s + IN_A, danger);
        const at = this.#writePoint(point, 'point');
        this.#check(this.#core._fsw_find_danger_start(this.#points, n, s + IN_A, at, s + OUT), 'findDangerStart');
        this.#views();
        const f = (s + OUT) >> 2;
        return this.#i32[f] !== 0 ? this.#f32[f + 1] : null;
    }

    /**
     * The projectile's closest approach to `point` over [fromTime, untilTime], exact per segment
     * (foresight::findClosestPathApproach).
     * @param {Trajectory} trajectory  as predictProjectile returns it.
     * @param {Vec3Like} point  [m].
     * @param {number} [fromTime]  [s] (default 0).
     * @param {number} [untilTime]  [s] (default the trajectory's last time).
     * @returns {{distance: number, time: number}}  [m], [s].
     */
    findClosestPathApproach(trajectory, point, fromTime = 0, untilTime = undefined) {
        const n = this.#writeTrajectory(trajectory, 'findClosestPathApproach');
        const s = this.#scratch;
        const at = this.#writePoint(point, 'point');
        const from = num(fromTime, 'fromTime');
        const until = untilTime === undefined ? (n > 0 ? trajectory.time[n - 1] : 0) : num(untilTime, 'untilTime');
        this.#check(this.#core._fsw_find_closest_path_approach(this.#points, n, at, from, until, s + OUT),
            'findClosestPathApproach');
        this.#views();
        const f = (s + OUT) >> 2;
        return { distance: this.#f32[f], time: this.#f32[f + 1] };
    }

    // ---- Vehicle contact ----------------------------------------------------------------------

    // fs_vehicle_body at IN_A, fs_character_body at IN_B, fs_approach_settings at POSITION.
    #writeContactQuery(vehicle, character, settings) {
        const v = checkKeys(vehicle, vehicleBodyKeys, 'vehicle');
        const c = checkKeys(character, characterKeys, 'character');
        const o = checkKeys(settings, ['tolerance', 'maxEvaluations'], 'settings');
        if (vehicle === undefined || vehicle === null) throw new TypeError('vehicle must be {position, velocity, ...}');
        if (character === undefined || character === null) throw new TypeError('character must be {position, ...}');
        const vd = this.#vehicleBodyDefaults, cd = this.#characterDefaults, ad = this.#approachDefaults;
        const vp = vec(v.position, 'vehicle.position');
        const vv = vec(v.velocity, 'vehicle.velocity');
        const q = quat(v.orientation ?? [0, 0, 0, 1], 'vehicle.orientation');
        const w = vec(v.angularVelocity ?? [0, 0, 0], 'vehicle.angularVelocity');
        const frame = enumValue(Frame, v.frame ?? this.#vehicleDefaults.frame, 'vehicle.frame');
        const forward = vec(v.forward ?? this.#vehicleDefaults.forward, 'vehicle.forward');
        const half = vec(v.halfExtents ?? vd.halfExtents, 'vehicle.halfExtents');
        const boxCenter = vec(v.boxCenter ?? vd.boxCenter, 'vehicle.boxCenter');
        const cp = vec(c.position, 'character.position');
        const cv = vec(c.velocity ?? [0, 0, 0], 'character.velocity');
        const ca = vec(c.acceleration ?? [0, 0, 0], 'character.acceleration');
        const radius = num(c.radius ?? cd.radius, 'character.radius');
        const halfAxis = vec(c.halfAxis ?? [0, 0, 0], 'character.halfAxis');
        const tolerance = num(o.tolerance ?? ad.tolerance, 'settings.tolerance');
        const maxEvaluations = uint32(o.maxEvaluations ?? ad.maxEvaluations, 'settings.maxEvaluations');
        const s = this.#scratch;
        this.#views();
        let d = (s + IN_A) >> 3, f = (s + IN_A) >> 2;
        this.#f64.set(vp, d);
        this.#f32.set(vv, f + 6);
        this.#f32.set(q, f + 9);
        this.#f32.set(w, f + 13);
        this.#i32[f + 16] = frame;
        this.#f32.set(forward, f + 17);
        this.#f32.set(half, f + 20);
        this.#f32.set(boxCenter, f + 23);
        d = (s + IN_B) >> 3; f = (s + IN_B) >> 2;
        this.#f64.set(cp, d);
        this.#f32.set(cv, f + 6);
        this.#f32.set(ca, f + 9);
        this.#f32[f + 12] = radius;
        this.#f32.set(halfAxis, f + 13);
        f = (s + POSITION) >> 2;
        this.#f32[f] = tolerance;
        this.#u32[f + 1] = maxEvaluations;
    }

    /**
     * The first time in [0, horizon] at which a vehicle (an oriented box on the exact arc of
     * predictVehicleExact) and a character (a sphere or capsule moving as p + v t + a t^2 / 2)
     * touch (foresight::findVehicleContact: never later than the true first overlap).
     * @param {VehicleBody} vehicle  position [m], velocity [m/s], orientation, angularVelocity
     *     [rad/s], frame, forward, halfExtents [m] (default 0.9, 0.7, 2.2), boxCenter [m] (default 0).
     * @param {CharacterBody} character  position [m], velocity [m/s], acceleration [m/s^2],
     *     radius [m] (default 0.4), halfAxis [m] (default 0: a sphere).
     * @param {number} horizon  [s] >= 0.
     * @param {ApproachSettings} [settings]  tolerance [m] (default 0.001), maxEvaluations (default 65536).
     * @returns {{contact: boolean, time: number, separation: number, evaluations: number}}
     */
    findVehicleContact(vehicle, character, horizon, settings = undefined) {
        this.#writeContactQuery(vehicle, character, settings);
        const s = this.#scratch;
        this.#check(this.#core._fs_find_vehicle_contact(s + IN_A, s + IN_B, num(horizon, 'horizon'), s + POSITION,
            s + OUT), 'findVehicleContact');
        this.#views();
        const f = (s + OUT) >> 2;
        return {
            contact: this.#i32[f] !== 0, time: this.#f32[f + 1], separation: this.#f32[f + 2],
            evaluations: this.#u32[f + 3],
        };
    }

    /**
     * The closest approach of a vehicle and a character in [0, horizon]
     * (foresight::findClosestVehicleApproach): the separation, negative when they overlap.
     * @param {VehicleBody} vehicle  as for findVehicleContact.
     * @param {CharacterBody} character  as for findVehicleContact.
     * @param {number} horizon  [s] >= 0.
     * @param {ApproachSettings} [settings]
     * @returns {{distance: number, time: number}}  [m], [s].
     */
    findClosestVehicleApproach(vehicle, character, horizon, settings = undefined) {
        this.#writeContactQuery(vehicle, character, settings);
        const s = this.#scratch;
        this.#check(this.#core._fs_find_closest_vehicle_approach(s + IN_A, s + IN_B, num(horizon, 'horizon'),
            s + POSITION, s + OUT), 'findClosestVehicleApproach');
        this.#views();
        const f = (s + OUT) >> 2;
        return { distance: this.#f32[f], time: this.#f32[f + 1] };
    }

    // ---- Aim ----------------------------------------------------------------------------------

    /**
     * The library's default shot: constraint 'speed', speed 0 m/s, apexHeight 0 m, gravity
     * (0, -9.81, 0) m/s^2, maxTime 60 s.
     * @returns {object}
     */
    aimShotDefaults() {
        return { ...this.#shotDefaults, gravity: { ...this.#shotDefaults.gravity } };
    }

    /**
     * Every way to hit a target moving as `p + v t + a t^2 / 2` from `shot.from` in free space,
     * earliest first (low arc before high arc); an empty array when nothing reaches it.
     * @param {AimShot} shot  from [m], constraint ('speed' default, 'horizontalSpeed',
     *     'apexAboveStart', 'apexAboveTarget'), speed [m/s], apexHeight [m], gravity [m/s^2],
     *     maxTime [s].
     * @param {AimTarget} target  position [m], velocity [m/s] (default 0), acceleration [m/s^2] (default 0).
     * @returns {FiringSolution[]}
     */
    aimProjectile(shot, target) {
        const o = checkKeys(shot, shotKeys, 'shot');
        const t = checkKeys(target, ['position', 'velocity', 'acceleration'], 'target');
        const d = this.#shotDefaults;
        const from = vec(o.from, 'shot.from');
        const constraint = enumValue(AimConstraint, o.constraint ?? d.constraint, 'shot.constraint');
        const speed = num(o.speed ?? d.speed, 'shot.speed');
        const apexHeight = num(o.apexHeight ?? d.apexHeight, 'shot.apexHeight');
        const gravity = vec(o.gravity ?? d.gravity, 'shot.gravity');
        const maxTime = num(o.maxTime ?? d.maxTime, 'shot.maxTime');
        const position = vec(t.position, 'target.position');
        const velocity = vec(t.velocity ?? [0, 0, 0], 'target.velocity');
        const acceleration = vec(t.acceleration ?? [0, 0, 0], 'target.acceleration');
        const s = this.#scratch;
        this.#views();
        let dd = (s + IN_A) >> 3, f = (s + IN_A) >> 2;
        this.#f64[dd] = from[0]; this.#f64[dd + 1] = from[1]; this.#f64[dd + 2] = from[2];
        this.#i32[f + 6] = constraint;
        this.#f32[f + 7] = speed;
        this.#f32[f + 8] = apexHeight;
        this.#f32.set(gravity, f + 9);
        this.#f32[f + 12] = maxTime;
        this.#f32[f + 13] = 0;
        dd = (s + IN_B) >> 3; f = (s + IN_B) >> 2;
        this.#f64[dd] = position[0]; this.#f64[dd + 1] = position[1]; this.#f64[dd + 2] = position[2];
        this.#f32.set(velocity, f + 6);
        this.#f32.set(acceleration, f + 9);
        this.#check(this.#core._fs_aim_projectile(s + IN_A, s + IN_B, s + SOLUTIONS, MAX_SOLUTIONS, s + COUNT),
            'aimProjectile');
        this.#views();
        const count = this.#u32[(s + COUNT) >> 2];
        const solutions = [];
        for (let k = 0; k < count; ++k) {
            const at = s + SOLUTIONS + 48 * k, q = at >> 2, h = (at + 16) >> 3;
            solutions.push({
                velocity: xyz(this.#f32.subarray(q, q + 3)),
                time: this.#f32[q + 3],
                hit: xyz(this.#f64.subarray(h, h + 3)),
                elevation: this.#f32[q + 10],
            });
        }
        return solutions;
    }
}

const worlds = new WeakMap(); // World -> {pointer, owner}

function worldPointer(world, owner) {
    const entry = worlds.get(world);
    if (entry === undefined) throw new TypeError('options.world must be a World made by createWorld');
    if (entry.owner !== owner) throw new TypeError('options.world belongs to another foresight instance');
    if (entry.pointer === 0) throw new Error('options.world has been deleted');
    return entry.pointer;
}

/**
 * A static collision world (foresight::StaticWorld) in the module's memory: free it with
 * `delete()`. Shapes are checked as the C++ checks them; a refused one throws ForesightError
 * and is not added.
 */
export class World {
    #owner;
    #core;

    /** @internal use Foresight.createWorld. */
    constructor(owner, pointer, core) {
        this.#owner = owner;
        this.#core = core;
        worlds.set(this, { pointer, owner });
    }

    #pointer(operation) {
        const entry = worlds.get(this);
        if (entry.pointer === 0) throw new Error(`${operation}: the world has been deleted`);
        return entry.pointer;
    }

    /** Whether delete() has been called. @returns {boolean} */
    get deleted() {
        return worlds.get(this).pointer === 0;
    }

    /**
     * Adds a one-sided infinite plane `dot(normal, x) = distance`, solid behind it.
     * @param {{normal: Vec3Like, distance: number}} plane  normal (non-zero, normalised here),
     *     distance [m].
     * @param {Material} [material]  the surface's own restitution and friction (method 'engine').
     * @returns {World} this world.
     */
    addPlane(plane, material = undefined) {
        const world = this.#pointer('addPlane');
        const o = checkKeys(plane, ['normal', 'distance'], 'plane');
        const n = vec(o.normal, 'plane.normal');
        const distance = num(o.distance ?? 0, 'plane.distance');
        const m = this.#owner._material(material);
        const { at, f64, f32 } = this.#owner._scratch();
        f32.set(n, at >> 2);
        f32[(at >> 2) + 3] = 0;
        f64[(at >> 3) + 2] = distance;
        this.#owner._check(this.#core._fs_world_add_plane(world, at, m), 'addPlane');
        return this;
    }

    /**
     * Adds a solid sphere.
     * @param {{center: Vec3Like, radius: number}} sphere  center [m], radius [m] > 0.
     * @param {Material} [material]
     * @returns {World} this world.
     */
    addSphere(sphere, material = undefined) {
        const world = this.#pointer('addSphere');
        const o = checkKeys(sphere, ['center', 'radius'], 'sphere');
        const c = vec(o.center, 'sphere.center');
        const radius = num(o.radius, 'sphere.radius');
        const m = this.#owner._material(material);
        const { at, f64, f32 } = this.#owner._scratch();
        f64.set(c, at >> 3);
        f32[(at >> 2) + 6] = radius;
        f32[(at >> 2) + 7] = 0;
        this.#owner._check(this.#core._fs_world_add_sphere(world, at, m), 'addSphere');
        return this;
    }

    /**
     * Adds a solid box rotated about its centre.
     * @param {{center: Vec3Like, halfExtents: Vec3Like, orientation?: QuatLike, rounding?: number}} box
     *     center [m], halfExtents [m] > 0 along its local axes, orientation (local-to-world,
     *     default identity), rounding radius of edges and corners [m] (default 0).
     * @param {Material} [material]
     * @returns {World} this world.
     */
    addBox(box, material = undefined) {
        const world = this.#pointer('addBox');
        const o = checkKeys(box, ['center', 'halfExtents', 'orientation', 'rounding'], 'box');
        const c = vec(o.center, 'box.center');
        const h = vec(o.halfExtents, 'box.halfExtents');
        const q = quat(o.orientation ?? [0, 0, 0, 1], 'box.orientation');
        const rounding = num(o.rounding ?? 0, 'box.rounding');
        const m = this.#owner._material(material);
        const { at, f64, f32 } = this.#owner._scratch();
        f64.set(c, at >> 3);
        f32.set(h, (at >> 2) + 6);
        f32.set(q, (at >> 2) + 9);
        f32[(at >> 2) + 13] = rounding;
        this.#owner._check(this.#core._fs_world_add_box(world, at, m), 'addBox');
        return this;
    }

    /**
     * Adds a two-sided triangle.
     * @param {{a: Vec3Like, b: Vec3Like, c: Vec3Like}} triangle  vertices [m] (an area of at
     *     least 1e-12 m^2).
     * @param {Material} [material]
     * @returns {World} this world.
     */
    addTriangle(triangle, material = undefined) {
        const world = this.#pointer('addTriangle');
        const o = checkKeys(triangle, ['a', 'b', 'c'], 'triangle');
        const a = vec(o.a, 'triangle.a'), b = vec(o.b, 'triangle.b'), c = vec(o.c, 'triangle.c');
        const m = this.#owner._material(material);
        const { at, f64 } = this.#owner._scratch();
        f64.set(a, at >> 3);
        f64.set(b, (at >> 3) + 3);
        f64.set(c, (at >> 3) + 6);
        this.#owner._check(this.#core._fs_world_add_triangle(world, at, m), 'addTriangle');
        return this;
    }

    /** Frees the world's memory; later calls with it throw. A second delete() does nothing. */
    delete() {
        const entry = worlds.get(this);
        if (entry.pointer !== 0) {
            this.#core._fs_world_destroy(entry.pointer);
            entry.pointer = 0;
        }
    }

    /** The same as delete(). */
    dispose() {
        this.delete();
    }
}
if (typeof Symbol.dispose === 'symbol') {
    World.prototype[Symbol.dispose] = World.prototype.delete;
}

/**
 * A receiver of one remote entity's dead-reckoning updates (foresight::DeadReckoningReceiver) in
 * the module's memory: free it with `delete()`. Made by Foresight.createReceiver.
 */
export class Receiver {
    #owner;
    #core;
    #pointer;

    /** @internal use Foresight.createReceiver. */
    constructor(owner, pointer, core) {
        this.#owner = owner;
        this.#core = core;
        this.#pointer = pointer;
    }

    #live(operation) {
        if (this.#pointer === 0) throw new Error(`${operation}: the receiver has been deleted`);
        return this.#pointer;
    }

    /** Whether delete() has been called. @returns {boolean} */
    get deleted() {
        return this.#pointer === 0;
    }

    /**
     * Takes an update stamped `timestamp` (the sender's clock) arriving at `receiveTime` (this
     * machine's clock); a correction starts there. Bad or stale updates are dropped and counted,
     * not thrown: the outcome says which.
     * @param {number} timestamp  [s] the sender's time of the state.
     * @param {DeadReckoningStateLike} state  as for predictDeadReckoning.
     * @param {number} receiveTime  [s] now, on the receiver's clock.
     * @returns {ReceiveOutcomeName}  'accepted', 'snapped', 'buffered', 'outOfOrder', 'duplicate',
     *     'invalid' or 'tooFarAhead'.
     */
    receive(timestamp, state, receiveTime) {
        return this.#owner._receive(this.#live('receive'), timestamp, state, receiveTime);
    }

    /**
     * The pose to show at `time` [s] on the receiver's clock (times may go backwards). Throws
     * ForesightError NO_UPDATE before the first accepted update.
     * @param {number} time  [s].
     * @returns {{position: Vec3, velocity: Vec3, orientation: Quat, held: boolean}}  velocity in
     *     world axes; held: extrapolationLimit stopped the extrapolation.
     */
    sample(time) {
        return this.#owner._sample(this.#live('sample'), time);
    }

    /**
     * The counters since creation or the last reset (numbers; exact up to 2^53).
     * @returns {ReceiverCounters}
     */
    counters() {
        return this.#owner._counters(this.#live('counters'));
    }

    /** Forgets every update and counter (the settings stay). */
    reset() {
        this.#core._fs_dr_receiver_reset(this.#live('reset'));
    }

    /** Frees the receiver's memory; later calls with it throw. A second delete() does nothing. */
    delete() {
        if (this.#pointer !== 0) {
            this.#core._fs_dr_receiver_destroy(this.#pointer);
            this.#pointer = 0;
        }
    }

    /** The same as delete(). */
    dispose() {
        this.delete();
    }
}
if (typeof Symbol.dispose === 'symbol') {
    Receiver.prototype[Symbol.dispose] = Receiver.prototype.delete;
}
