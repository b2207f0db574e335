// Types of foresight-wasm (index.mjs). Units: metres, seconds, radians; +Y up, +Z forward.

/** A vector in: `{x, y, z}` or `[x, y, z]` (any array-like of 3 numbers). */
export type Vec3Like = { x: number; y: number; z: number } | readonly [number, number, number] | ArrayLike<number>;
/** A vector out. */
export interface Vec3 {
    x: number;
    y: number;
    z: number;
}
/** A rotation in: `{x, y, z, w}` or `[x, y, z, w]` (identity: `[0, 0, 0, 1]`). */
export type QuatLike =
    | { x: number; y: number; z: number; w: number }
    | readonly [number, number, number, number]
    | ArrayLike<number>;
/** A rotation out (local-to-world, normalised by the library). */
export interface Quat {
    x: number;
    y: number;
    z: number;
    w: number;
}

/** fs_status values by name (foresight_c.h). */
export declare const Status: Readonly<{
    OK: 0;
    NON_FINITE_INPUT: 1;
    NEGATIVE_TIME: 2;
    INVALID_STEP: 3;
    INVALID_ITERATIONS: 4;
    INVALID_RESTITUTION: 5;
    INVALID_FRICTION: 6;
    INVALID_RADIUS: 7;
    ZERO_QUATERNION: 8;
    ZERO_VECTOR: 9;
    DEGENERATE_SHAPE: 10;
    TOO_MANY_STEPS: 11;
    TOO_MANY_EVENTS: 12;
    NON_FINITE_RESULT: 13;
    INVALID_ALGORITHM: 14;
    INVALID_SPEED: 15;
    INVALID_FUSE: 16;
    INVALID_SETTING: 17;
    TIME_WENT_BACKWARDS: 18;
    NO_UPDATE: 19;
    OUT_OF_RANGE: 20;
    BUFFER_TOO_SMALL: 1000;
    NULL_POINTER: 1001;
    OUT_OF_MEMORY: 1002;
}>;
/** Projectile integrators: exact (event driven), stepped (the article's loop), engine (a physics engine's steps). */
export declare const Method: Readonly<{ exact: 0; stepped: 1; engine: 2 }>;
export type MethodName = keyof typeof Method;
/** The physics engines the 'engine' method follows (docs/engines.md). */
export declare const Engine: Readonly<{
    custom: 0;
    jolt: 1;
    physx: 2;
    rapier: 3;
    bullet: 4;
    godot3: 5;
    godot3Bullet: 6;
    box2d: 7;
}>;
export type EngineName = keyof typeof Engine;
/** The values of `Trajectory.event`. */
export declare const TrajectoryEvent: Readonly<{ start: 0; step: 1; bounce: 2; rest: 3; hit: 4; end: 5 }>;
/** The axes of a vehicle's angular velocity: its own ('body', the article's) or the world's. */
export declare const Frame: Readonly<{ body: 0; world: 1 }>;
export type FrameName = keyof typeof Frame;
/** What fixes an aimed shot's launch velocity besides meeting the target. */
export declare const AimConstraint: Readonly<{
    speed: 0;
    horizontalSpeed: 1;
    apexAboveStart: 2;
    apexAboveTarget: 3;
}>;
export type AimConstraintName = keyof typeof AimConstraint;
/** The DIS (IEEE 1278.1) dead-reckoning algorithms by their DIS names (F/R fixed or rotating, P/V velocity or acceleration, W/B world or body axes). */
export declare const DeadReckoning: Readonly<{
    STATIC: 1;
    FPW: 2;
    RPW: 3;
    RVW: 4;
    FVW: 5;
    FPB: 6;
    RPB: 7;
    RVB: 8;
    FVB: 9;
}>;
export type DeadReckoningName = keyof typeof DeadReckoning;
/** How a Receiver shows its entity: the newest update extrapolated, or interpolationDelay in the past. */
export declare const ReceiverMode: Readonly<{ extrapolate: 0; interpolate: 1 }>;
export type ReceiverModeName = keyof typeof ReceiverMode;
/** How a Receiver hides corrections when extrapolating. */
export declare const Smoothing: Readonly<{ snap: 0; linearBlend: 1; projectiveVelocity: 2; exponentialDecay: 3 }>;
export type SmoothingName = keyof typeof Smoothing;
/** What Receiver.receive did with an update. */
export declare const ReceiveOutcome: Readonly<{
    accepted: 0;
    snapped: 1;
    buffered: 2;
    outOfOrder: 3;
    duplicate: 4;
    invalid: 5;
    tooFarAhead: 6;
}>;
export type ReceiveOutcomeName = keyof typeof ReceiveOutcome;

/** Thrown when the library refuses an input: message "<function>: <the library's message>". */
export declare class ForesightError extends Error {
    readonly name: 'ForesightError';
    /** The fs_status value. */
    readonly status: number;
    /** Its name in Status, e.g. "NEGATIVE_TIME". */
    readonly code: keyof typeof Status | 'UNKNOWN';
}

/** A moving point: position [m], velocity [m/s]. */
export interface PointStateLike {
    position: Vec3Like;
    velocity: Vec3Like;
}
export interface PointState {
    /** [m] */
    position: Vec3;
    /** [m/s] */
    velocity: Vec3;
}

/** A vehicle turning at a constant angular velocity, its velocity along its forward axis. */
export interface VehicleStateLike {
    /** [m] */
    position: Vec3Like;
    /** [m/s] */
    velocity: Vec3Like;
    /** local-to-world, non-zero; default identity. */
    orientation?: QuatLike;
    /** [rad/s] in the settings' frame. */
    angularVelocity: Vec3Like;
}
export interface VehicleState {
    /** [m] */
    position: Vec3;
    /** [m/s] */
    velocity: Vec3;
    orientation: Quat;
    /** [rad/s] */
    angularVelocity: Vec3;
}
export interface VehicleSettings {
    /** 'body' (default) or 'world'. */
    frame?: FrameName | number;
    /** Local forward axis, non-zero; default +Z. */
    forward?: Vec3Like;
}

/** Fields of fs_projectile_settings; a missing field takes the library's default. */
export interface ProjectileSettings {
    /** default 'exact'. */
    method?: MethodName | number;
    /** for method 'engine'; default 'jolt'. */
    engine?: EngineName | number;
    /** [m/s^2], default (0, -9.81, 0). */
    gravity?: Vec3Like;
    /** time step [s] > 0, default 0.02. */
    step?: number;
    /** coefficient of restitution in [0, 1], default 0.5. */
    restitution?: number;
    /** Coulomb friction >= 0, default 0. */
    friction?: number;
    /** 0: a point, > 0: a sphere [m]; default 0. */
    radius?: number;
    /** bounces allowed, the next impact ends the prediction; default 4294967295 (Infinity accepted). */
    maxBounces?: number;
    /** refuse predictions of more steps (TOO_MANY_STEPS); default 1048576. */
    maxSteps?: number;
    /** refuse exact predictions of more impacts and contact changes; default 65536. */
    maxEvents?: number;
}
/** The defaults, as returned by projectileSettings(). */
export interface ProjectileSettingsResolved {
    method: MethodName;
    engine: EngineName;
    gravity: Vec3;
    step: number;
    restitution: number;
    friction: number;
    radius: number;
    maxBounces: number;
    maxSteps: number;
    maxEvents: number;
}
export interface ProjectileOptions {
    settings?: ProjectileSettings;
    /** What to bounce off; null or missing: free flight. */
    world?: World | null;
    /** Return the trajectory's points (default true). */
    trajectory?: boolean;
}
/** A predicted trajectory, point i at index i (positions and vectors at 3i, 3i+1, 3i+2). */
export interface Trajectory {
    length: number;
    /** since the start [s]. */
    time: Float32Array;
    /** TrajectoryEvent values. */
    event: Int32Array;
    /** [m], x y z per point. */
    position: Float64Array;
    /** [m/s], after the bounce for bounce points. */
    velocity: Float32Array;
    /** surface normal of bounce and hit points, else 0. */
    normal: Float32Array;
}
export interface ProjectileResult {
    /** final position [m]. */
    position: Vec3;
    /** final velocity [m/s]. */
    velocity: Vec3;
    /** time reached [s] (the impact time when stoppedAtHit). */
    time: number;
    bounces: number;
    /** came to rest on a surface (exact method). */
    atRest: boolean;
    /** ended at an impact (maxBounces reached). */
    stoppedAtHit: boolean;
    /** normal of the last impact, zero if none. */
    hitNormal: Vec3;
    /** null when options.trajectory is false. */
    trajectory: Trajectory | null;
}

/** A surface's own material, used by method 'engine'; negative: none. */
export interface Material {
    restitution?: number;
    friction?: number;
}

export interface AimShot {
    /** launch point [m]. */
    from: Vec3Like;
    /** default 'speed'. */
    constraint?: AimConstraintName | number;
    /** launch speed (or lateral speed) [m/s]. */
    speed?: number;
    /** apex height for the apex constraints [m]. */
    apexHeight?: number;
    /** [m/s^2], default (0, -9.81, 0). */
    gravity?: Vec3Like;
    /** latest flight time [s], default 60. */
    maxTime?: number;
}
export interface AimTarget {
    /** at t = 0 [m]. */
    position: Vec3Like;
    /** [m/s], default 0. */
    velocity?: Vec3Like;
    /** [m/s^2], default 0. */
    acceleration?: Vec3Like;
}
export interface FiringSolution {
    /** launch velocity [m/s]. */
    velocity: Vec3;
    /** flight time [s]. */
    time: number;
    /** where projectile and target meet [m]. */
    hit: Vec3;
    /** launch angle above the plane across gravity [rad]. */
    elevation: number;
}

/** A predicted grenade as a danger. */
export interface ProjectileDanger {
    /** when it explodes [s] >= 0. */
    fuseTime: number;
    /** the blast's radius [m] >= 0. */
    blastRadius: number;
    /** before the fuse, closer than this to the grenade is unsafe [m] (default 0). */
    contactRadius?: number;
}
export interface DangerZone {
    /** the grenade at the fuse time [m]. */
    center: Vec3;
    /** [m] */
    radius: number;
    /** the fuse time [s]. */
    time: number;
}
export interface ClosestApproach {
    /** [m]; for vehicles the separation, negative when they overlap. */
    distance: number;
    /** [s] */
    time: number;
}
/** A vehicle as an oriented box on the exact arc of predictVehicleExact. */
export interface VehicleBody extends Omit<VehicleStateLike, 'angularVelocity'>, VehicleSettings {
    /** [rad/s] in `frame`; default 0. */
    angularVelocity?: Vec3Like;
    /** [m] > 0, local axes (default 0.9, 0.7, 2.2). */
    halfExtents?: Vec3Like;
    /** the box's centre from position, local axes [m] (default 0). */
    boxCenter?: Vec3Like;
}
/** A character: a sphere, or a capsule of constant direction, moving as p + v t + a t^2 / 2. */
export interface CharacterBody {
    /** [m] */
    position: Vec3Like;
    /** [m/s], default 0. */
    velocity?: Vec3Like;
    /** [m/s^2], default 0. */
    acceleration?: Vec3Like;
    /** [m] >= 0 (default 0.4). */
    radius?: number;
    /** half the capsule's inner segment, world axes [m]; default 0 (a sphere). */
    halfAxis?: Vec3Like;
}
export interface ApproachSettings {
    /** [m] > 0 (default 0.001). */
    tolerance?: number;
    /** separations computed per query at most (default 65536). */
    maxEvaluations?: number;
}
export interface VehicleContact {
    /** they come within the tolerance before the horizon. */
    contact: boolean;
    /** first contact [s], valid when contact. */
    time: number;
    /** the separation at time (at the horizon if no contact) [m]. */
    separation: number;
    /** separations computed. */
    evaluations: number;
}

/** A remote entity's last update for dead reckoning. */
export interface DeadReckoningStateLike {
    /** [m], world axes. */
    position: Vec3Like;
    /** [m/s]; world axes (*W) or body axes (*B). */
    velocity: Vec3Like;
    /** [m/s^2], axes as velocity; default 0; used by RVW, FVW, RVB, FVB. */
    acceleration?: Vec3Like;
    /** body-to-world, non-zero; default identity. */
    orientation?: QuatLike;
    /** [rad/s], body axes; default 0; used by RPW, RVW, RPB, RVB. */
    angularVelocity?: Vec3Like;
    /** 'STATIC' ... 'FVB' or 1 ... 9; another number is refused (INVALID_ALGORITHM). */
    algorithm: DeadReckoningName | number;
}
export interface DeadReckoningResult {
    /** [m] */
    position: Vec3;
    /** [m/s], in the input velocity's axes. */
    velocity: Vec3;
    orientation: Quat;
}
/** Many entities, n = timestamp.length, as flat arrays (typed arrays or plain arrays). */
export interface DeadReckoningBatch {
    /** n update times [s]. */
    timestamp: ArrayLike<number>;
    /** 3n [m]. */
    position: ArrayLike<number>;
    /** 3n [m/s]. */
    velocity: ArrayLike<number>;
    /** n algorithms (numbers, or names in a plain array). */
    algorithm: ArrayLike<number | DeadReckoningName>;
    /** 3n [m/s^2]; default 0. */
    acceleration?: ArrayLike<number>;
    /** 4n, x y z w; default identity. */
    orientation?: ArrayLike<number>;
    /** 3n [rad/s]; default 0. */
    angularVelocity?: ArrayLike<number>;
}
export interface DeadReckoningBatchResult {
    /** 3n [m]. */
    position: Float64Array;
    /** 3n [m/s]. */
    velocity: Float32Array;
    /** 4n, x y z w. */
    orientation: Float32Array;
    /** Entities refused (returned as given). */
    refused: number;
}
/** Fields of fs_dr_receiver_settings; a missing field takes the library's default. */
export interface ReceiverSettings {
    /** default 'extrapolate'. */
    mode?: ReceiverModeName | number;
    /** default 'projectiveVelocity'. */
    smoothing?: SmoothingName | number;
    /** [s] > 0 (default 0.2). */
    blendTime?: number;
    /** [s] > 0 (default 0.1). */
    decayHalfLife?: number;
    /** [m] > 0, Infinity disables (default 10). */
    teleportDistance?: number;
    /** [s] >= 0, Infinity disables (default 0.25). */
    extrapolationLimit?: number;
    /** [s] > 0 (default 0.1). */
    interpolationDelay?: number;
    /** [s] >= 0, Infinity disables (default 1). */
    maxFutureSkew?: number;
    /** [s] > 0, Infinity disables (default 10). */
    restartAfter?: number;
}
export type ReceiverSettingsResolved = Required<ReceiverSettings> & {
    mode: ReceiverModeName;
    smoothing: SmoothingName;
};
/** The pose a Receiver shows. */
export interface ReceivedPose {
    /** [m] */
    position: Vec3;
    /** [m/s], world axes. */
    velocity: Vec3;
    orientation: Quat;
    /** extrapolationLimit stopped the extrapolation. */
    held: boolean;
}
export interface ReceiverCounters {
    accepted: number;
    snaps: number;
    teleports: number;
    outOfOrder: number;
    duplicates: number;
    invalid: number;
    held: number;
    futureUpdates: number;
    tooFarAhead: number;
    clockRestarts: number;
}
/** A receiver of one remote entity's updates in the module's memory: call delete() when done. */
export declare class Receiver {
    private constructor();
    /** Whether delete() has been called. */
    readonly deleted: boolean;
    /** An update stamped timestamp [s] arriving at receiveTime [s]; bad or stale ones are dropped, not thrown. */
    receive(timestamp: number, state: DeadReckoningStateLike, receiveTime: number): ReceiveOutcomeName;
    /** The pose to show at time [s]; throws NO_UPDATE before the first accepted update. */
    sample(time: number): ReceivedPose;
    /** The counters since creation or the last reset. */
    counters(): ReceiverCounters;
    /** Forgets every update and counter (the settings stay). */
    reset(): void;
    /** Frees the receiver; a second call does nothing. */
    delete(): void;
    /** The same as delete() (also Receiver.prototype[Symbol.dispose] where the runtime has it). */
    dispose(): void;
}

/** A static collision world in the module's memory: call delete() when done. */
export declare class World {
    private constructor();
    /** Whether delete() has been called. */
    readonly deleted: boolean;
    /** A one-sided plane dot(normal, x) = distance [m], solid behind. */
    addPlane(plane: { normal: Vec3Like; distance?: number }, material?: Material): this;
    /** A solid sphere: center [m], radius [m] > 0. */
    addSphere(sphere: { center: Vec3Like; radius: number }, material?: Material): this;
    /** A solid box: center [m], halfExtents [m] > 0, orientation (default identity), rounding [m]. */
    addBox(
        box: { center: Vec3Like; halfExtents: Vec3Like; orientation?: QuatLike; rounding?: number },
        material?: Material,
    ): this;
    /** A two-sided triangle, vertices [m]. */
    addTriangle(triangle: { a: Vec3Like; b: Vec3Like; c: Vec3Like }, material?: Material): this;
    /** Frees the world; a second call does nothing. */
    delete(): void;
    /** The same as delete() (also World.prototype[Symbol.dispose] where the runtime has it, for `using`). */
    dispose(): void;
}

/** The API on one WebAssembly instance. */
export declare class Foresight {
    private constructor();
    /** The C API's ABI version (1). */
    abiVersion(): number;
    /** The library's text for a status value. */
    statusMessage(status: number): string;
    /** The end of the module's heap [bytes] (for leak checks). */
    heapEnd(): number;
    /** p + v t. time [s] >= 0. */
    predictLinear(state: PointStateLike, time: number): PointState;
    /** p + v t + a t^2 / 2; acceleration [m/s^2], time [s] >= 0. */
    predictAccelerated(state: PointStateLike, acceleration: Vec3Like, time: number): PointState;
    /** The article's loop: `iterations` (default 4) steps over time [s]. */
    predictVehicleIterative(
        state: VehicleStateLike,
        time: number,
        iterations?: number,
        settings?: VehicleSettings,
    ): VehicleState;
    /** The exact arc over time [s]. */
    predictVehicleExact(state: VehicleStateLike, time: number, settings?: VehicleSettings): VehicleState;
    /** A new, empty collision world. */
    createWorld(): World;
    /** The library's default projectile settings. */
    projectileSettings(): ProjectileSettingsResolved;
    /** A projectile from position [m] with velocity [m/s] for time [s]. */
    predictProjectile(
        position: Vec3Like,
        velocity: Vec3Like,
        time: number,
        options?: ProjectileOptions,
    ): ProjectileResult;
    /** The library's default shot. */
    aimShotDefaults(): Required<Omit<AimShot, 'from' | 'constraint' | 'gravity'>> & {
        constraint: number;
        gravity: Vec3;
    };
    /** Every firing solution, earliest first; [] when unreachable. */
    aimProjectile(shot: AimShot, target: AimTarget): FiringSolution[];
    /** Where and when a predicted grenade explodes (trajectory as predictProjectile returns it). */
    computeDangerZone(trajectory: Trajectory, danger: ProjectileDanger): DangerZone;
    /** Whether point [m] is safe at time [s]. */
    isPointSafe(trajectory: Trajectory, danger: ProjectileDanger, point: Vec3Like, time: number): boolean;
    /** When danger starts at point [m] [s]; null: never. */
    findDangerStart(trajectory: Trajectory, danger: ProjectileDanger, point: Vec3Like): number | null;
    /** The path's closest approach to point over [fromTime, untilTime] [s] (defaults: 0, the last point's time). */
    findClosestPathApproach(trajectory: Trajectory, point: Vec3Like, fromTime?: number, untilTime?: number): ClosestApproach;
    /** The first contact of a vehicle and a character within horizon [s]. */
    findVehicleContact(
        vehicle: VehicleBody,
        character: CharacterBody,
        horizon: number,
        settings?: ApproachSettings,
    ): VehicleContact;
    /** The closest approach of a vehicle and a character within horizon [s]. */
    findClosestVehicleApproach(
        vehicle: VehicleBody,
        character: CharacterBody,
        horizon: number,
        settings?: ApproachSettings,
    ): ClosestApproach;
    /** The DIS name of an algorithm ("STATIC" ... "FVB"; "?" for another value). */
    deadReckoningAlgorithmName(algorithm: DeadReckoningName | number): string;
    /** A remote entity's last update extrapolated by time [s] >= 0 with its algorithm. */
    predictDeadReckoning(state: DeadReckoningStateLike, time: number): DeadReckoningResult;
    /** Many entities extrapolated to one time [s], each by max(time - timestamp, 0). */
    predictDeadReckoningBatch(batch: DeadReckoningBatch, time: number): DeadReckoningBatchResult;
    /** The library's default receiver settings. */
    receiverSettings(): ReceiverSettingsResolved;
    /** A receiver of one remote entity (extrapolates or interpolates, blends corrections). */
    createReceiver(settings?: ReceiverSettings): Receiver;
}

/** Loads the module (the wasm is embedded: nothing is fetched). */
export declare function loadForesight(): Promise<Foresight>;
export default loadForesight;
