#ifndef FORESIGHT_C_H
#define FORESIGHT_C_H
/// @file foresight_c.h
/// foresight's C API: a plain C99 interface over the C++ library, for bindings (C#, Python,
/// WebAssembly) and for C programs. It is the shared library `foresight_c` (CMake target
/// `foresight::foresight_c`). docs/c-api.md describes it as a whole.
///
/// Units and axes are the library's: metres, seconds, radians; +Y is up, +Z forward by default.
///
/// Layout rule (what a binding may rely on): every struct is made of 4-byte fields (float,
/// int32_t, uint32_t) and 8-byte fields (double, uint64_t) at their natural alignment, in the
/// order written, with any padding spelled out as a `reserved` field (ignored on input, written
/// as 0 on output). There is no bool, no size_t, no pointer and no C enum type inside a struct:
/// enumerations are int32_t fields holding the FS_* constants. Sizes and offsets are the same on
/// every 32-bit and 64-bit platform with IEEE floats; the implementation checks them at compile
/// time, and each struct's comment gives its size.
///
/// Positions are always double here (fs_dvec3); a library built with float positions (the
/// default) rounds them to float on the way in and widens its results on the way out. Values
/// beyond float's range become infinite, and are refused (FS_STATUS_NON_FINITE_INPUT) wherever
/// the C++ refuses an infinite position.
///
/// Every function that can refuse its input returns an fs_status; outputs are written only when
/// FS_STATUS_OK is returned (fs_predict_projectile also on FS_STATUS_BUFFER_TOO_SMALL, and it
/// uses its trajectory buffer as scratch space). A NULL
/// pointer where one is required gives FS_STATUS_NULL_POINTER; an int32_t enumeration field
/// outside its constants gives FS_STATUS_INVALID_SETTING (fs_dr_state::algorithm: as in C++,
/// FS_STATUS_INVALID_ALGORITHM). Nothing throws, nothing aborts. Only fs_world_create, the
/// fs_world_add_* functions and fs_dr_receiver_create allocate. Every function is safe to call
/// from several threads at once, except that a world must not be changed (add, destroy) while
/// another thread uses it, and a receiver is used by one thread at a time.

#include <stddef.h>
#include <stdint.h>

/// Marks an exported function (the shared library exports these and nothing else).
#if defined(_WIN32) || defined(__CYGWIN__)
#if defined(FORESIGHT_C_BUILDING)
#define FS_API __declspec(dllexport)
#else
#define FS_API __declspec(dllimport)
#endif
#elif defined(__GNUC__) || defined(__clang__)
#define FS_API __attribute__((visibility("default")))
#else
#define FS_API
#endif

/// `noexcept` for C++ callers: no function of this API throws.
#ifdef __cplusplus
#define FS_NOEXCEPT noexcept
#else
#define FS_NOEXCEPT
#endif

#ifdef __cplusplus
extern "C" {
#endif

/// The ABI version of this header: changes whenever a struct, a constant's value or a
/// function's signature changes. A binding compares it with fs_abi_version() when it loads
/// the library and refuses to run on a mismatch.
#define FS_ABI_VERSION 1

/// The ABI version the loaded library was built with (FS_ABI_VERSION of its header).
FS_API uint32_t fs_abi_version(void) FS_NOEXCEPT;

/// The outcome of a call: FS_STATUS_OK (zero) or why the input was refused. Values 0 to 20 are
/// foresight::Status's, in the same order (status.h documents each); values from 1000 on are
/// the C API's own.
typedef int32_t fs_status;

/// The fs_status values.
enum {
    FS_STATUS_OK = 0,                    ///< Success.
    FS_STATUS_NON_FINITE_INPUT = 1,      ///< A position, vector, quaternion or scalar is NaN or infinite.
    FS_STATUS_NEGATIVE_TIME = 2,         ///< A prediction time is below zero.
    FS_STATUS_INVALID_STEP = 3,          ///< A time step is zero, negative or not finite.
    FS_STATUS_INVALID_ITERATIONS = 4,    ///< An iteration count is below 1 or above 1048576.
    FS_STATUS_INVALID_RESTITUTION = 5,   ///< Restitution is outside [0, 1].
    FS_STATUS_INVALID_FRICTION = 6,      ///< Friction is negative.
    FS_STATUS_INVALID_RADIUS = 7,        ///< A radius is negative (projectiles) or not positive (spheres).
    FS_STATUS_ZERO_QUATERNION = 8,       ///< A quaternion has zero length and cannot be normalised.
    FS_STATUS_ZERO_VECTOR = 9,           ///< A vector that must have a direction (normal, forward axis) is zero.
    FS_STATUS_DEGENERATE_SHAPE = 10,     ///< A triangle with no area, a box with a non-positive half extent.
    FS_STATUS_TOO_MANY_STEPS = 11,       ///< The prediction would take more steps than max_steps.
    FS_STATUS_TOO_MANY_EVENTS = 12,      ///< The prediction hit max_events (bounces and contact changes).
    FS_STATUS_NON_FINITE_RESULT = 13,    ///< The inputs are valid but so large that the result overflows.
    FS_STATUS_INVALID_ALGORITHM = 14,    ///< A dead-reckoning algorithm outside 1 to 9.
    FS_STATUS_INVALID_SPEED = 15,        ///< A speed is zero, negative or not finite.
    FS_STATUS_INVALID_FUSE = 16,         ///< A fuse time is zero, negative or not finite.
    FS_STATUS_INVALID_SETTING = 17,      ///< A settings field (an enumeration too) is outside its range.
    FS_STATUS_TIME_WENT_BACKWARDS = 18,  ///< A time is earlier than the previous call's (not used yet here).
    FS_STATUS_NO_UPDATE = 19,            ///< A dead-reckoning receiver has no update yet.
    FS_STATUS_OUT_OF_RANGE = 20,         ///< Beyond the precision envelope: a position farther than 1e5 m
                                         ///< (1e8 m in a double-precision build) on an axis, a speed above 1e6 m/s.
    /// C API only: the prediction succeeded but the trajectory has more points than the buffer
    /// holds; the result is written, the first `capacity` points too, and
    /// fs_projectile_result::trajectory_needed says how many a complete trajectory needs.
    FS_STATUS_BUFFER_TOO_SMALL = 1000,
    /// C API only: a required pointer argument is NULL. Nothing is written.
    FS_STATUS_NULL_POINTER = 1001,
    /// C API only: memory ran out while adding a shape; the world is then emptied (as if new).
    FS_STATUS_OUT_OF_MEMORY = 1002,
};

/// A short English description of `status`, e.g. "time must be >= 0". Never NULL: values that
/// are no fs_status give "unknown status". The string is static; do not free it.
FS_API const char* fs_status_message(fs_status status) FS_NOEXCEPT;

/// A direction, velocity [m/s], acceleration [m/s^2] or angular velocity [rad/s], in world axes
/// unless said otherwise. 12 bytes, alignment 4.
typedef struct fs_vec3 {
    float x, y, z;
} fs_vec3;

/// A position [Units: m]. 24 bytes, alignment 8.
typedef struct fs_dvec3 {
    double x, y, z;
} fs_dvec3;

/// A rotation (local-to-world) as a quaternion `w + xi + yj + zk`; normalised by the functions
/// that take one, which refuse a zero one. The identity is {0, 0, 0, 1}. 16 bytes, alignment 4.
typedef struct fs_quat {
    float x, y, z, w;
} fs_quat;

/* ---- Characters ------------------------------------------------------------------------- */

/// Position and velocity of a moving point (a character, a target). 40 bytes, alignment 8:
/// position at 0, velocity at 24, reserved at 36.
typedef struct fs_point_state {
    fs_dvec3 position;  ///< [Units: m]
    fs_vec3 velocity;   ///< [Units: m/s]
    float reserved;     ///< padding: ignored, written as 0.
} fs_point_state;

/// Constant velocity: position `p + v t`, velocity unchanged.
/// @param start  the current state (finite).
/// @param time   prediction horizon [Units: s] [Limit: >= 0, finite].
/// @param out    receives the predicted state (may be `start`).
/// @return OK, NULL_POINTER, NON_FINITE_INPUT, NEGATIVE_TIME or NON_FINITE_RESULT.
FS_API fs_status fs_predict_linear(const fs_point_state* start, float time, fs_point_state* out) FS_NOEXCEPT;

/// Constant acceleration: position `p + v t + a t^2 / 2`, velocity `v + a t`.
/// @param start         the current state (finite).
/// @param acceleration  constant, world axes [Units: m/s^2].
/// @param time          prediction horizon [Units: s] [Limit: >= 0, finite].
/// @param out           receives the predicted state (may be `start`).
/// @return OK, NULL_POINTER, NON_FINITE_INPUT, NEGATIVE_TIME or NON_FINITE_RESULT.
FS_API fs_status fs_predict_accelerated(const fs_point_state* start, fs_vec3 acceleration, float time,
                                        fs_point_state* out) FS_NOEXCEPT;

/* ---- Vehicles --------------------------------------------------------------------------- */

/// The axes of a vehicle's angular velocity (fs_vehicle_settings::frame).
enum {
    FS_FRAME_BODY = 0,   ///< the vehicle's own axes: `q' = q r` (the reference article).
    FS_FRAME_WORLD = 1,  ///< world axes: `q' = r q`.
};

/// The kinematic state of a vehicle (a car, a tank, a boat): it turns at a constant angular
/// velocity and its velocity follows its forward axis. 64 bytes, alignment 8: position at 0,
/// velocity at 24, orientation at 36, angular_velocity at 52.
typedef struct fs_vehicle_state {
    fs_dvec3 position;         ///< [Units: m], world axes.
    fs_vec3 velocity;          ///< [Units: m/s], world axes.
    fs_quat orientation;       ///< local-to-world; non-zero (normalised here).
    fs_vec3 angular_velocity;  ///< [Units: rad/s], in the axes of fs_vehicle_settings::frame.
} fs_vehicle_state;

/// How to read an fs_vehicle_state. 16 bytes, alignment 4: frame at 0, forward at 4.
typedef struct fs_vehicle_settings {
    int32_t frame;    ///< FS_FRAME_BODY (default) or FS_FRAME_WORLD.
    fs_vec3 forward;  ///< local forward axis [Limit: non-zero, finite]; default +Z {0, 0, 1}.
} fs_vehicle_settings;

/// The defaults: FS_FRAME_BODY, forward +Z.
FS_API fs_vehicle_settings fs_vehicle_settings_default(void) FS_NOEXCEPT;

/// The reference article's loop: `iterations` equal steps, each moving with the current
/// velocity, turning, then putting the velocity on the new forward axis with the same speed.
/// The speed is `|velocity|`, negative when the vehicle moves backwards along its forward axis.
/// @param start       the current state (finite, non-zero orientation).
/// @param time        [Units: s] [Limit: >= 0, finite].
/// @param iterations  [Limit: 1 .. 1048576]; the article uses 4.
/// @param settings    frame and forward axis (fs_vehicle_settings_default()).
/// @param out         receives the state after `time` (may be `start`).
/// @return OK, NULL_POINTER, INVALID_SETTING (frame), NON_FINITE_INPUT, NEGATIVE_TIME,
///         INVALID_ITERATIONS, ZERO_QUATERNION, ZERO_VECTOR or NON_FINITE_RESULT.
FS_API fs_status fs_predict_vehicle_iterative(const fs_vehicle_state* start, float time, int32_t iterations,
                                              const fs_vehicle_settings* settings, fs_vehicle_state* out) FS_NOEXCEPT;

/// The exact arc of the same motion (velocity on the forward axis from the start): a circle of
/// radius `|v| / |w|` when the angular velocity is perpendicular to the forward axis.
/// @param start     the current state (finite, non-zero orientation).
/// @param time      [Units: s] [Limit: >= 0, finite].
/// @param settings  frame and forward axis (fs_vehicle_settings_default()).
/// @param out       receives the state after `time` (may be `start`).
/// @return OK, NULL_POINTER, INVALID_SETTING (frame), NON_FINITE_INPUT, NEGATIVE_TIME,
///         ZERO_QUATERNION, ZERO_VECTOR or NON_FINITE_RESULT.
FS_API fs_status fs_predict_vehicle_exact(const fs_vehicle_state* start, float time,
                                          const fs_vehicle_settings* settings, fs_vehicle_state* out) FS_NOEXCEPT;

/* ---- Collision worlds ------------------------------------------------------------------- */

/// A static collision world (foresight::StaticWorld): infinite planes, spheres, oriented boxes
/// and two-sided triangles, tested exactly, brute force (tens to a few thousands of shapes).
/// Opaque: made by fs_world_create, freed by fs_world_destroy.
typedef struct fs_world fs_world;

/// A surface's own material. Only FS_METHOD_ENGINE uses it (combined with the projectile's
/// values by the engine's rule); the other methods use the projectile's. 8 bytes, alignment 4.
typedef struct fs_material {
    float restitution;  ///< [Limit: 0 .. 1, or negative: none (the projectile's value alone)]
    float friction;     ///< [Limit: >= 0, or negative: none]
} fs_material;

/// A one-sided infinite plane: the points x with `dot(normal, x) = distance`; solid behind it.
/// 24 bytes, alignment 8: normal at 0, reserved at 12, distance at 16.
typedef struct fs_plane {
    fs_vec3 normal;   ///< [Limit: non-zero, finite]; normalised when added (distance with it).
    float reserved;   ///< padding: ignored.
    double distance;  ///< `dot(normal, x)` on the plane [Units: m with a unit normal].
} fs_plane;

/// A solid sphere. 32 bytes, alignment 8: center at 0, radius at 24, reserved at 28.
typedef struct fs_sphere {
    fs_dvec3 center;  ///< [Units: m]
    float radius;     ///< [Units: m] [Limit: > 0]
    float reserved;   ///< padding: ignored.
} fs_sphere;

/// A solid box rotated about its centre. 56 bytes, alignment 8: center at 0, half_extents at
/// 24, orientation at 36, rounding at 52.
typedef struct fs_box {
    fs_dvec3 center;       ///< [Units: m]
    fs_vec3 half_extents;  ///< along the box's local axes [Units: m] [Limit: > 0]
    fs_quat orientation;   ///< local-to-world; non-zero, normalised when added.
    /// Radius of rounded edges and corners (faces stay) [Units: m] [Limit: 0 .. smallest half extent].
    float rounding;
} fs_box;

/// A two-sided triangle. 72 bytes, alignment 8: a at 0, b at 24, c at 48.
typedef struct fs_triangle {
    fs_dvec3 a, b, c;  ///< vertices [Units: m]; must span an area of at least 1e-12 m^2 and not be a sliver.
} fs_triangle;

/// A new, empty world; NULL when memory runs out. Free it with fs_world_destroy.
FS_API fs_world* fs_world_create(void) FS_NOEXCEPT;

/// Frees a world and its shapes. NULL is allowed (does nothing). No prediction may be using it.
FS_API void fs_world_destroy(fs_world* world) FS_NOEXCEPT;

/// Adds a plane after checking it as the C++ StaticWorld does; nothing is added unless OK.
/// @param material  the surface's material, or NULL for none.
/// @return OK, NULL_POINTER (world, plane), NON_FINITE_INPUT (also a material's NaN),
///         ZERO_VECTOR, INVALID_RESTITUTION (material above 1) or OUT_OF_MEMORY.
FS_API fs_status fs_world_add_plane(fs_world* world, const fs_plane* plane, const fs_material* material) FS_NOEXCEPT;

/// Adds a sphere (see fs_world_add_plane).
/// @return OK, NULL_POINTER, NON_FINITE_INPUT, INVALID_RADIUS, INVALID_RESTITUTION or
///         OUT_OF_MEMORY.
FS_API fs_status fs_world_add_sphere(fs_world* world, const fs_sphere* sphere, const fs_material* material) FS_NOEXCEPT;

/// Adds a box (see fs_world_add_plane).
/// @return OK, NULL_POINTER, NON_FINITE_INPUT, DEGENERATE_SHAPE (a half extent <= 0),
///         INVALID_RADIUS (rounding), ZERO_QUATERNION, INVALID_RESTITUTION or OUT_OF_MEMORY.
FS_API fs_status fs_world_add_box(fs_world* world, const fs_box* box, const fs_material* material) FS_NOEXCEPT;

/// Adds a triangle (see fs_world_add_plane).
/// @return OK, NULL_POINTER, NON_FINITE_INPUT, DEGENERATE_SHAPE, INVALID_RESTITUTION or
///         OUT_OF_MEMORY.
FS_API fs_status fs_world_add_triangle(fs_world* world, const fs_triangle* triangle,
                                       const fs_material* material) FS_NOEXCEPT;

/* ---- Projectiles ------------------------------------------------------------------------ */

/// The projectile integrators (fs_projectile_settings::method).
enum {
    /// Event driven: exact impact times on the parabola, sliding and resting (default).
    FS_METHOD_EXACT = 0,
    /// The reference article's fixed-step loop: ceil(time / step) steps.
    FS_METHOD_STEPPED = 1,
    /// Step for step as the physics engine `engine` computes it (its own timestep; `step` unused).
    FS_METHOD_ENGINE = 2,
};

/// The engines FS_METHOD_ENGINE follows, each with its documented defaults
/// (fs_projectile_settings::engine; docs/engines.md).
enum {
    FS_ENGINE_CUSTOM = 0,         ///< plain semi-implicit Euler at 60 Hz (the profile's defaults).
    FS_ENGINE_JOLT = 1,           ///< Jolt Physics 5 (default).
    FS_ENGINE_PHYSX = 2,          ///< PhysX 4/5 with Unity's defaults.
    FS_ENGINE_RAPIER = 3,         ///< Rapier, 4 solver sub-steps.
    FS_ENGINE_BULLET = 4,         ///< Bullet's btDiscreteDynamicsWorld.
    FS_ENGINE_GODOT3 = 5,         ///< Godot 3 with GodotPhysics.
    FS_ENGINE_GODOT3_BULLET = 6,  ///< Godot 3 with Bullet.
    FS_ENGINE_BOX2D = 7,          ///< Box2D v2.4 (motion in the x-y plane).
};

/// How to predict a projectile; fs_projectile_settings_default() gives the C++ defaults (the
/// reference article's). 48 bytes, alignment 4: method 0, gravity 4, step 16, restitution 20,
/// friction 24, radius 28, max_bounces 32, max_steps 36, max_events 40, engine 44.
typedef struct fs_projectile_settings {
    int32_t method;        ///< FS_METHOD_* (default FS_METHOD_EXACT).
    fs_vec3 gravity;       ///< [Units: m/s^2], world axes (default {0, -9.81, 0}).
    float step;            ///< time step [Units: s] [Limit: > 0] (default 0.02).
    float restitution;     ///< coefficient of restitution [Limit: 0 .. 1] (default 0.5).
    float friction;        ///< Coulomb friction [Limit: >= 0] (default 0: frictionless).
    float radius;          ///< 0: a point; > 0: a sphere [Units: m] [Limit: >= 0] (default 0).
    uint32_t max_bounces;  ///< bounces allowed, the next impact ends the prediction (default 0xFFFFFFFF: no limit).
    uint32_t max_steps;    ///< work cap: more steps are refused, TOO_MANY_STEPS (default 1048576).
    uint32_t max_events;   ///< work cap (Exact): impacts and contact changes (default 65536).
    int32_t engine;        ///< FS_ENGINE_* for FS_METHOD_ENGINE (default FS_ENGINE_JOLT); checked always.
} fs_projectile_settings;

/// The defaults of foresight::ProjectileSettings (see fs_projectile_settings).
FS_API fs_projectile_settings fs_projectile_settings_default(void) FS_NOEXCEPT;

/// What an fs_trajectory_point marks (fs_trajectory_point::event).
enum {
    FS_EVENT_START = 0,   ///< the initial state (t = 0).
    FS_EVENT_STEP = 1,    ///< a step boundary (Exact: a multiple of `step`).
    FS_EVENT_BOUNCE = 2,  ///< an impact (velocity after it); has a normal.
    FS_EVENT_REST = 3,    ///< came to rest (Exact only); stays there until the end.
    FS_EVENT_HIT = 4,     ///< the prediction stopped at this impact (max_bounces); has a normal.
    FS_EVENT_END = 5,     ///< the final state at the prediction time.
};

/// A point of a predicted trajectory. 56 bytes, alignment 8: time 0, event 4, position 8,
/// velocity 32, normal 44.
typedef struct fs_trajectory_point {
    float time;         ///< since the start [Units: s].
    int32_t event;      ///< FS_EVENT_*.
    fs_dvec3 position;  ///< [Units: m]
    fs_vec3 velocity;   ///< [Units: m/s]; after the bounce for FS_EVENT_BOUNCE.
    fs_vec3 normal;     ///< surface normal for BOUNCE and HIT (and a Stepped END whose step hit); else 0.
} fs_trajectory_point;

/// The outcome of fs_predict_projectile. 80 bytes, alignment 8: position 0, velocity 24, time
/// 36, bounces 40, at_rest 44, stopped_at_hit 48, hit_normal 52, trajectory_size 64,
/// trajectory_needed 72.
typedef struct fs_projectile_result {
    fs_dvec3 position;           ///< final position [Units: m].
    fs_vec3 velocity;            ///< final velocity [Units: m/s].
    float time;                  ///< time reached [Units: s]: `time` (Exact), steps * step (Stepped,
                                 ///< Engine), or the impact time when stopped_at_hit.
    uint32_t bounces;            ///< bounces applied.
    int32_t at_rest;             ///< 1: (Exact) came to rest on a surface; else 0.
    int32_t stopped_at_hit;      ///< 1: ended at an impact (max_bounces reached); else 0.
    fs_vec3 hit_normal;          ///< normal of the last impact (zero if none).
    uint64_t trajectory_size;    ///< points written into the buffer (at most its capacity).
    uint64_t trajectory_needed;  ///< points of the whole trajectory; > trajectory_size if truncated.
} fs_projectile_result;

/// A buffer size that always holds a Stepped or Engine trajectory of `time`, and an Exact one
/// with up to 64 bounces and contact changes: `min(steps, max_steps) + 3 + 128`. 0 when the
/// input is refused (settings NULL or invalid, `time` negative or not finite).
FS_API size_t fs_trajectory_capacity(float time, const fs_projectile_settings* settings) FS_NOEXCEPT;

/// Predicts a projectile (a grenade, a thrown or fired object) under constant gravity, bouncing
/// off `world`. Allocates nothing: the trajectory goes into the caller's buffer.
/// @param position  start position [Units: m] (the sphere's centre when radius > 0).
/// @param velocity  start velocity [Units: m/s] [Limit: <= 1e6 m/s].
/// @param time      prediction time, e.g. a grenade's fuse [Units: s] [Limit: >= 0, finite].
/// @param settings  method and physical parameters (required).
/// @param world     what to bounce off; NULL: nothing (free flight).
/// @param points    the trajectory buffer: Start, then Step, Bounce, Rest, Hit points, then End
///                  (projectile.h gives each method's points). May be NULL when capacity is 0.
/// @param capacity  points the buffer holds. 0: no trajectory is asked for (never too small).
/// @param out       the result; written on OK and on BUFFER_TOO_SMALL.
/// @return OK; BUFFER_TOO_SMALL (capacity > 0 and the trajectory needs more: `out` and the
///         first `capacity` points are written; call again with out->trajectory_needed);
///         NULL_POINTER (settings, out, or points with capacity > 0); INVALID_SETTING (method,
///         engine); NON_FINITE_INPUT, INVALID_STEP, INVALID_RESTITUTION, INVALID_FRICTION,
///         INVALID_RADIUS, NEGATIVE_TIME, OUT_OF_RANGE, TOO_MANY_STEPS, TOO_MANY_EVENTS or
///         NON_FINITE_RESULT (`out` untouched; the buffer's contents are then unspecified).
FS_API fs_status fs_predict_projectile(fs_dvec3 position, fs_vec3 velocity, float time,
                                       const fs_projectile_settings* settings, const fs_world* world,
                                       fs_trajectory_point* points, size_t capacity,
                                       fs_projectile_result* out) FS_NOEXCEPT;

/* ---- Aim ------------------------------------------------------------------------------------ */

/// What fixes the launch velocity besides meeting the target (fs_aim_shot::constraint).
enum {
    /// `|velocity| = speed`: a gun or a throw of fixed strength (low and high arc).
    FS_AIM_SPEED = 0,
    /// The velocity's part across gravity has length `speed` (a fixed lateral speed); with zero
    /// gravity, "vertical" is +Y.
    FS_AIM_HORIZONTAL_SPEED = 1,
    /// The arc's apex is `apex_height` above the launch point; the hit is at or after the apex.
    FS_AIM_APEX_ABOVE_START = 2,
    /// The arc's apex is `apex_height` above the hit point; the hit is at or after the apex.
    FS_AIM_APEX_ABOVE_TARGET = 3,
};

/// The most firing solutions any constraint has: a buffer of this size never loses one.
#define FS_MAX_FIRING_SOLUTIONS 4

/// The shooter and the shot's constraint; fs_aim_shot_default() gives the C++ defaults. The
/// projectile flies in free space (no world, no drag). 56 bytes, alignment 8: from 0,
/// constraint 24, speed 28, apex_height 32, gravity 36, max_time 48, reserved 52.
typedef struct fs_aim_shot {
    fs_dvec3 from;       ///< launch point [Units: m].
    int32_t constraint;  ///< FS_AIM_* (default FS_AIM_SPEED).
    /// FS_AIM_SPEED, FS_AIM_HORIZONTAL_SPEED: the launch speed [Units: m/s] [Limit: finite]; 0
    /// drops the projectile, negative reaches nothing (no solutions, not an error). Default 0.
    float speed;
    /// The apex constraints: the apex's height along -gravity [Units: m] [Limit: finite]; below 0
    /// nothing is reachable. Default 0.
    float apex_height;
    fs_vec3 gravity;  ///< [Units: m/s^2], world axes (default {0, -9.81, 0}).
    float max_time;   ///< latest flight time reported [Units: s] [Limit: >= 0, finite] (default 60).
    float reserved;   ///< padding: ignored.
} fs_aim_shot;

/// A target moving as `position + velocity t + acceleration t^2 / 2`. 48 bytes, alignment 8:
/// position 0, velocity 24, acceleration 36.
typedef struct fs_aim_target {
    fs_dvec3 position;     ///< at t = 0 [Units: m].
    fs_vec3 velocity;      ///< [Units: m/s].
    fs_vec3 acceleration;  ///< [Units: m/s^2].
} fs_aim_target;

/// One way to hit the target. 48 bytes, alignment 8: velocity 0, time 12, hit 16, elevation
/// 40, reserved 44.
typedef struct fs_firing_solution {
    fs_vec3 velocity;  ///< launch velocity [Units: m/s]; for FS_AIM_SPEED, of length `speed`.
    float time;        ///< flight time to the hit [Units: s] [Limit: (0, max_time]].
    fs_dvec3 hit;      ///< where projectile and target meet at `time` [Units: m].
    float elevation;   ///< launch angle above the plane across gravity [Units: rad] [Limit: -pi/2 .. pi/2].
    float reserved;    ///< padding: written as 0.
} fs_firing_solution;

/// The defaults of foresight::AimShot (see fs_aim_shot).
FS_API fs_aim_shot fs_aim_shot_default(void) FS_NOEXCEPT;

/// Every firing solution with a flight time in (0, max_time], earliest first (the low arc or the
/// straight-line intercept first, the high arc last). Allocates nothing.
/// @param shot       launch point, constraint, gravity and time limit.
/// @param target     the target's motion.
/// @param solutions  receives the solutions; with fewer than FS_MAX_FIRING_SOLUTIONS entries,
///                   the earliest. May be NULL when capacity is 0.
/// @param capacity   entries in `solutions`.
/// @param count      receives the number written (0: unreachable, which is not an error).
/// @return OK, NULL_POINTER (shot, target, count, or solutions with capacity > 0),
///         INVALID_SETTING (constraint), NON_FINITE_INPUT, NEGATIVE_TIME (max_time < 0),
///         ZERO_VECTOR (an apex constraint with zero gravity) or NON_FINITE_RESULT; `solutions`
///         and `count` are written only on OK.
FS_API fs_status fs_aim_projectile(const fs_aim_shot* shot, const fs_aim_target* target, fs_firing_solution* solutions,
                                   size_t capacity, size_t* count) FS_NOEXCEPT;

/* ---- Dead reckoning (network replication) ------------------------------------------------- */

/// The DIS (IEEE 1278.1) dead-reckoning models (fs_dr_state::algorithm); dead_reckoning.h
/// documents each. F/R: fixed or rotating orientation; P/V: constant velocity or acceleration;
/// W/B: velocity and acceleration in world or body axes.
enum {
    FS_DR_STATIC = 1,  ///< does not move or turn.
    FS_DR_FPW = 2,     ///< fixed orientation, constant world velocity: `p + v t`.
    FS_DR_RPW = 3,     ///< rotating, constant world velocity.
    FS_DR_RVW = 4,     ///< rotating, constant world acceleration: `p + v t + a t^2 / 2`.
    FS_DR_FVW = 5,     ///< fixed orientation, constant world acceleration.
    FS_DR_FPB = 6,     ///< fixed orientation, constant body velocity.
    FS_DR_RPB = 7,     ///< rotating, constant body velocity (turns with the body).
    FS_DR_RVB = 8,     ///< rotating, constant body acceleration.
    FS_DR_FVB = 9,     ///< fixed orientation, constant body acceleration.
};

/// The state an entity last reported (foresight::DeadReckoningState). 80 bytes, alignment 8:
/// position 0, velocity 24, acceleration 36, orientation 48, angular_velocity 64, algorithm 76.
typedef struct fs_dr_state {
    fs_dvec3 position;         ///< [Units: m], world axes.
    fs_vec3 velocity;          ///< [Units: m/s]; world axes (FS_DR_*W) or body axes (FS_DR_*B).
    fs_vec3 acceleration;      ///< [Units: m/s^2]; axes as `velocity`; used by RVW, FVW, RVB, FVB.
    fs_quat orientation;       ///< body-to-world; non-zero (normalised here).
    fs_vec3 angular_velocity;  ///< [Units: rad/s], body axes; used by RPW, RVW, RPB, RVB.
    int32_t algorithm;         ///< FS_DR_* (1 to 9); another value gives INVALID_ALGORITHM.
} fs_dr_state;

/// An extrapolated state (foresight::DeadReckoningResult). 56 bytes, alignment 8: position 0,
/// velocity 24, orientation 36, reserved 52.
typedef struct fs_dr_result {
    fs_dvec3 position;    ///< [Units: m], world axes.
    fs_vec3 velocity;     ///< [Units: m/s], in the input velocity's axes (world *W, body *B).
    fs_quat orientation;  ///< body-to-world, unit.
    float reserved;       ///< padding: written as 0.
} fs_dr_result;

/// The DIS name of an algorithm: "STATIC", "FPW", ... "FVB"; "?" for another value. Never NULL,
/// static.
FS_API const char* fs_dr_algorithm_name(int32_t algorithm) FS_NOEXCEPT;

/// Extrapolates `state` by `time` with its algorithm (foresight::predictDeadReckoning).
/// @param state  the last update (every field checked, used or not).
/// @param time   [Units: s] [Limit: >= 0, finite], since the update's timestamp.
/// @param out    receives the extrapolated state; written only on OK.
/// @return OK, NULL_POINTER, INVALID_ALGORITHM, NON_FINITE_INPUT, ZERO_QUATERNION,
///         NEGATIVE_TIME or NON_FINITE_RESULT.
FS_API fs_status fs_dr_predict(const fs_dr_state* state, float time, fs_dr_result* out) FS_NOEXCEPT;

/// Extrapolates `count` entities to one time (foresight::predictDeadReckoningBatch): entity i's
/// result is fs_dr_predict(&states[i], (float)max(time - timestamps[i], 0)) bit for bit. An
/// entity that is refused (or has a NaN timestamp) gets its state as given (age 0, velocity and
/// orientation copied) and is counted. Allocates nothing.
/// @param states      `count` updates (may be NULL when count is 0).
/// @param timestamps  `count` timestamps [Units: s] (may be NULL when count is 0).
/// @param count       entities.
/// @param time        [Units: s] the time to extrapolate to.
/// @param out         `count` results (may be NULL when count is 0).
/// @param refused     receives the number of entities refused (may be NULL).
/// @return OK (also when entities are refused) or NULL_POINTER (nothing written).
FS_API fs_status fs_dr_predict_batch(const fs_dr_state* states, const double* timestamps, size_t count, double time,
                                     fs_dr_result* out, size_t* refused) FS_NOEXCEPT;

/// How a receiver shows a remote entity (fs_dr_receiver_settings::mode).
enum {
    FS_DR_MODE_EXTRAPOLATE = 0,  ///< the newest update extrapolated to now, with smoothing.
    FS_DR_MODE_INTERPOLATE = 1,  ///< interpolation_delay in the past, between buffered updates.
};

/// How a receiver hides corrections in FS_DR_MODE_EXTRAPOLATE (fs_dr_receiver_settings::smoothing).
enum {
    FS_DR_SMOOTH_SNAP = 0,                 ///< jump to the new update's extrapolation.
    FS_DR_SMOOTH_LINEAR_BLEND = 1,         ///< blend old to new over blend_time.
    FS_DR_SMOOTH_PROJECTIVE_VELOCITY = 2,  ///< projective velocity blending (default).
    FS_DR_SMOOTH_EXPONENTIAL_DECAY = 3,    ///< the offset decays with half-life decay_half_life.
};

/// What fs_dr_receiver_receive did with an update (foresight::UpdateOutcome).
enum {
    FS_DR_ACCEPTED = 0,       ///< applied, smoothed.
    FS_DR_SNAPPED = 1,        ///< applied with a snap (first update, Snap, teleport, sender restart).
    FS_DR_BUFFERED = 2,       ///< Interpolate mode: stored.
    FS_DR_OUT_OF_ORDER = 3,   ///< dropped: older than what is shown.
    FS_DR_DUPLICATE = 4,      ///< dropped: same timestamp as one already received.
    FS_DR_INVALID = 5,        ///< dropped: NaN/infinite fields, zero quaternion, unknown algorithm.
    FS_DR_TOO_FAR_AHEAD = 6,  ///< dropped: stamped more than max_future_skew after its receive time.
};

/// A receiver's settings (foresight::ReceiverSettings; replication.h documents each).
/// fs_dr_receiver_settings_default() gives the C++ defaults. 36 bytes, alignment 4: mode 0,
/// smoothing 4, blend_time 8, decay_half_life 12, teleport_distance 16, extrapolation_limit 20,
/// interpolation_delay 24, max_future_skew 28, restart_after 32.
typedef struct fs_dr_receiver_settings {
    int32_t mode;               ///< FS_DR_MODE_* (default EXTRAPOLATE).
    int32_t smoothing;          ///< FS_DR_SMOOTH_* (default PROJECTIVE_VELOCITY).
    float blend_time;           ///< [Units: s] [Limit: > 0, finite] (default 0.2).
    float decay_half_life;      ///< [Units: s] [Limit: > 0, finite] (default 0.1).
    float teleport_distance;    ///< [Units: m] [Limit: > 0; infinity disables] (default 10).
    float extrapolation_limit;  ///< [Units: s] [Limit: >= 0; infinity disables] (default 0.25).
    float interpolation_delay;  ///< [Units: s] [Limit: > 0, finite] (default 0.1).
    float max_future_skew;      ///< [Units: s] [Limit: >= 0; infinity disables] (default 1).
    float restart_after;        ///< [Units: s] [Limit: > 0; infinity disables] (default 10).
} fs_dr_receiver_settings;

/// The pose a receiver shows (foresight::ReceivedPose). 56 bytes, alignment 8: position 0,
/// velocity 24, orientation 36, held 52.
typedef struct fs_dr_pose {
    fs_dvec3 position;    ///< [Units: m], world axes.
    fs_vec3 velocity;     ///< [Units: m/s], world axes (converted for body-axis models).
    fs_quat orientation;  ///< body-to-world, unit.
    int32_t held;         ///< 1: extrapolation_limit stopped the extrapolation; else 0.
} fs_dr_pose;

/// A receiver's counters (foresight::ReceiverCounters). 80 bytes, alignment 8, ten uint64_t in
/// this order.
typedef struct fs_dr_receiver_counters {
    uint64_t accepted;        ///< updates applied or buffered.
    uint64_t snaps;           ///< updates that snapped.
    uint64_t teleports;       ///< snaps caused by teleport_distance.
    uint64_t out_of_order;    ///< FS_DR_OUT_OF_ORDER updates.
    uint64_t duplicates;      ///< FS_DR_DUPLICATE updates.
    uint64_t invalid;         ///< FS_DR_INVALID updates.
    uint64_t held;            ///< samples that returned a held pose.
    uint64_t future_updates;  ///< updates stamped after their receive time (within max_future_skew).
    uint64_t too_far_ahead;   ///< FS_DR_TOO_FAR_AHEAD updates.
    uint64_t clock_restarts;  ///< older updates taken as a sender restart.
} fs_dr_receiver_counters;

/// A receiver of one remote entity (foresight::DeadReckoningReceiver): extrapolates or
/// interpolates its updates and blends corrections. Opaque: made by fs_dr_receiver_create,
/// freed by fs_dr_receiver_destroy. Fixed size: only creating it allocates.
typedef struct fs_dr_receiver fs_dr_receiver;

/// The defaults of foresight::ReceiverSettings (see fs_dr_receiver_settings).
FS_API fs_dr_receiver_settings fs_dr_receiver_settings_default(void) FS_NOEXCEPT;

/// Makes a receiver after checking `settings`.
/// @param settings  the settings (required).
/// @param out       receives the receiver (written only on OK); free it with fs_dr_receiver_destroy.
/// @return OK, NULL_POINTER, INVALID_SETTING (an enumeration or a range) or OUT_OF_MEMORY.
FS_API fs_status fs_dr_receiver_create(const fs_dr_receiver_settings* settings, fs_dr_receiver** out) FS_NOEXCEPT;

/// Frees a receiver. NULL is allowed (does nothing).
FS_API void fs_dr_receiver_destroy(fs_dr_receiver* receiver) FS_NOEXCEPT;

/// Takes an update stamped `timestamp` (sender clock) arriving at `receive_time`; bad or stale
/// updates are dropped and counted (the outcome says which).
/// @param timestamp     [Units: s] the sender's time of the state.
/// @param receive_time  [Units: s] the receiver's time now; a correction starts here.
/// @param outcome       receives an FS_DR_ACCEPTED ... FS_DR_TOO_FAR_AHEAD value (may be NULL).
/// @return OK (whatever the outcome) or NULL_POINTER (receiver, state).
FS_API fs_status fs_dr_receiver_receive(fs_dr_receiver* receiver, double timestamp, const fs_dr_state* state,
                                        double receive_time, int32_t* outcome) FS_NOEXCEPT;

/// The pose to show at `time` [Units: s] (times may go backwards).
/// @return OK, NULL_POINTER, NO_UPDATE (nothing accepted yet), NON_FINITE_INPUT (time) or
///         NON_FINITE_RESULT (only with an infinite extrapolation_limit); `out` written only on OK.
FS_API fs_status fs_dr_receiver_sample(fs_dr_receiver* receiver, double time, fs_dr_pose* out) FS_NOEXCEPT;

/// The counters since creation or the last reset.
/// @return OK or NULL_POINTER.
FS_API fs_status fs_dr_receiver_get_counters(const fs_dr_receiver* receiver, fs_dr_receiver_counters* out) FS_NOEXCEPT;

/// Forgets every update and counter (the settings stay). NULL is allowed (does nothing).
FS_API void fs_dr_receiver_reset(fs_dr_receiver* receiver) FS_NOEXCEPT;

#ifdef __cplusplus
}  // extern "C"
#endif

#endif  // FORESIGHT_C_H
