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
/// FS_STATUS_INVALID_ALGORITHM). Nothing throws, nothing aborts. Only the fs_world_create*
/// functions, fs_world_add_*, fs_world_load_mesh, fs_world_commit, fs_dr_receiver_create and
/// (the first time on a thread for a trajectory size) the danger functions allocate. Every
/// function is safe to call from several threads at once, except that a world must not be
/// changed (add, destroy) while another thread uses it, and a receiver is used by one thread at
/// a time.

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
    /// C API only: a callback world's cast function (fs_world_create_callback) returned a hit
    /// that is not one: a fraction outside [0, 1] or not finite, a position that is not finite,
    /// a normal that is zero or not finite, a restitution above 1 or NaN, or a NaN friction.
    /// The prediction is abandoned: nothing is written.
    FS_STATUS_INVALID_CALLBACK_HIT = 1003,
    /// C API only: the Embree backend refused: a mesh file could not be read or is not a valid
    /// mesh (fs_world_load_mesh), or the BVH could not be built (fs_world_commit). The error
    /// text those functions write says why, naming the file.
    FS_STATUS_BACKEND_FAILED = 1004,
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
///         ZERO_VECTOR, INVALID_RESTITUTION (material above 1), INVALID_SETTING (a callback
///         world, which holds no shapes) or OUT_OF_MEMORY.
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

/// What fs_world_add_mesh or fs_world_load_mesh did with a mesh. 24 bytes, alignment 8:
/// triangles 0, degenerate_triangles 8, first_degenerate_triangle 16.
typedef struct fs_mesh_report {
    uint64_t triangles;                  ///< triangles added.
    uint64_t degenerate_triangles;       ///< triangles skipped (no area, or a sliver).
    uint64_t first_degenerate_triangle;  ///< 0-based index in the mesh of the first skipped one.
} fs_mesh_report;

/// Adds an indexed triangle mesh (three indices per triangle, two-sided triangles). In a world
/// from fs_world_create every triangle is tested by brute force (up to a few thousand); in an
/// Embree world they go into its BVH (millions; call fs_world_commit afterwards). The whole
/// mesh is refused (nothing added) for a non-finite vertex (NON_FINITE_INPUT), an index count
/// that is not a multiple of 3, an index out of range or no usable triangle (DEGENERATE_SHAPE);
/// degenerate triangles are skipped and counted. Mesh triangles have no material of their own.
/// @param report  receives the counts (may be NULL); written on OK.
/// @return OK, NULL_POINTER (world, vertices or indices with a count above 0), NON_FINITE_INPUT,
///         DEGENERATE_SHAPE, INVALID_SETTING (a callback world) or OUT_OF_MEMORY.
FS_API fs_status fs_world_add_mesh(fs_world* world, const fs_dvec3* vertices, size_t vertex_count,
                                   const uint32_t* indices, size_t index_count, fs_mesh_report* report) FS_NOEXCEPT;

/// 1 when this library was built with the Embree backend (fs_world_create_embree works), else 0.
FS_API int32_t fs_embree_available(void) FS_NOEXCEPT;

/// A world for large levels (foresight::EmbreeWorld): triangle meshes in an Embree BVH plus the
/// built-in shapes. Add shapes (fs_world_add_*) and meshes (fs_world_add_mesh,
/// fs_world_load_mesh), then call fs_world_commit once before predicting (and again after adding
/// more). Free it with fs_world_destroy.
/// @return the world; NULL when the library has no Embree backend or memory runs out.
FS_API fs_world* fs_world_create_embree(void) FS_NOEXCEPT;

/// Loads a mesh file into an Embree world: Wavefront OBJ (`.obj`) or glTF 2.0 (`.gltf` with its
/// buffers, or `.glb`), chosen by the extension (any case). Files are checked strictly (a damaged
/// number or index is refused, never read as 0; glTF buffers must lie inside the file's folder;
/// at most 2^24 vertices and triangles): foresight's embree_world.h has the rules.
/// @param path            the file, UTF-8.
/// @param report          receives the counts (may be NULL); written on OK.
/// @param error           receives a one-line reason on BACKEND_FAILED, NUL-terminated and cut
///                        to `error_capacity` bytes (may be NULL when error_capacity is 0).
/// @return OK, NULL_POINTER, INVALID_SETTING (not an Embree world, or an extension that is none
///         of the three) or BACKEND_FAILED.
FS_API fs_status fs_world_load_mesh(fs_world* world, const char* path, fs_mesh_report* report, char* error,
                                    size_t error_capacity) FS_NOEXCEPT;

/// Builds an Embree world's BVH over its meshes; needed before predicting, after the last add.
/// Other worlds have nothing to build: OK. Not thread-safe with predictions in the same world.
/// @param error  as fs_world_load_mesh's.
/// @return OK, NULL_POINTER or BACKEND_FAILED (the world then answers by brute force: correct,
///         slow).
FS_API fs_status fs_world_commit(fs_world* world, char* error, size_t error_capacity) FS_NOEXCEPT;

/// A cast that a callback world answers: a segment, or a sphere swept along it, from `origin`
/// to `origin + displacement`. 40 bytes, alignment 8: origin at 0, displacement at 24, radius
/// at 36.
typedef struct fs_segment_cast {
    fs_dvec3 origin;       ///< start, the sphere's centre [Units: m].
    fs_vec3 displacement;  ///< end minus start [Units: m]; never zero-length in a call.
    float radius;          ///< swept sphere radius [Units: m]; 0 casts a point (a ray).
} fs_segment_cast;

/// The first hit of an fs_segment_cast, filled by a callback world's function. Before the call
/// it holds: fraction 1, position the segment's end, normal {0, 1, 0}, restitution and friction
/// -1 (the surface has no material of its own); a function that has no material leaves them.
/// 48 bytes, alignment 8: fraction at 0, restitution at 4, position at 8, normal at 32,
/// friction at 44.
typedef struct fs_cast_hit {
    float fraction;     ///< where along the segment [Limit: 0 .. 1]: origin + fraction * displacement.
    float restitution;  ///< the surface's own restitution [Limit: 0 .. 1, or negative: none].
    fs_dvec3 position;  ///< the sphere's centre (the ray's point) at the hit [Units: m] [Limit: finite].
    fs_vec3 normal;     ///< surface normal facing against the motion [Limit: non-zero, finite];
                        ///< normalised by the library.
    float friction;     ///< the surface's own friction coefficient [Limit: >= 0, or negative: none].
} fs_cast_hit;

/// A game's own ray or sphere cast, e.g. its physics engine's (Unity's Physics.SphereCast,
/// Godot's PhysicsDirectSpaceState, PhysX, Jolt). Return non-zero and fill `hit` on a hit, zero
/// when the cast hits nothing. The rules (world.h, CollisionWorld): report the closest surface
/// the segment enters (moving against its normal); a segment that starts on a surface and moves
/// into it hits at fraction 0; a segment that starts deep inside a solid, or moves away from a
/// surface, does not hit it. It is called on the thread that predicts, many times per
/// prediction (about one call per step; an Exact prediction with more than 64 bounces and
/// contact changes into a buffer with room for them runs twice), must answer the same cast the
/// same way, and must not throw, longjmp or unwind across the call.
typedef int32_t (*fs_cast_function)(void* context, const fs_segment_cast* cast, fs_cast_hit* hit);

/// A world whose casts are answered by `cast(context, ...)` (foresight::CallbackWorld): how a
/// game lets its own physics engine answer. Nothing is copied: `context` must stay valid while
/// the world is used. Shapes cannot be added to it (fs_world_add_* return INVALID_SETTING).
/// Every hit is checked: a prediction that receives an invalid one returns
/// FS_STATUS_INVALID_CALLBACK_HIT. Free it with fs_world_destroy.
/// @return the world; NULL when `cast` is NULL or memory runs out.
FS_API fs_world* fs_world_create_callback(fs_cast_function cast, void* context) FS_NOEXCEPT;

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
///         NON_FINITE_RESULT, or INVALID_CALLBACK_HIT (a callback world's function returned an
///         invalid hit) (`out` untouched; the buffer's contents are then unspecified).
FS_API fs_status fs_predict_projectile(fs_dvec3 position, fs_vec3 velocity, float time,
                                       const fs_projectile_settings* settings, const fs_world* world,
                                       fs_trajectory_point* points, size_t capacity,
                                       fs_projectile_result* out) FS_NOEXCEPT;

/* ---- Engine profiles: a game's own engine settings ------------------------------------------ */

/// Where the damping factor goes in an engine step (fs_engine_profile::order).
enum {
    FS_DAMPING_ORDER_GRAVITY_THEN_DAMPING = 0,  ///< `v = (v + g dt) d` (Jolt, PhysX, Rapier).
    FS_DAMPING_ORDER_DAMPING_THEN_GRAVITY = 1,  ///< `v = v d + g dt` (Bullet, Godot 3, Box2D).
};

/// The damping factor `d` per step for a coefficient `c` (fs_engine_profile::damping).
enum {
    FS_DAMPING_LAW_NONE = 0,            ///< `d = 1`.
    FS_DAMPING_LAW_LINEAR_CLAMPED = 1,  ///< `d = max(0, 1 - c dt)` (Jolt, PhysX, Godot 3).
    FS_DAMPING_LAW_RATIONAL = 2,        ///< `d = 1 / (1 + c dt)` (Rapier, Box2D).
    FS_DAMPING_LAW_POWER = 3,           ///< `d = (1 - min(c, 1))^dt` (Bullet).
};

/// How two materials' coefficients combine (restitution_combine, friction_combine).
enum {
    FS_COMBINE_AVERAGE = 0,         ///< `(a + b) / 2`.
    FS_COMBINE_MIN = 1,             ///< `min(a, b)`.
    FS_COMBINE_MAX = 2,             ///< `max(a, b)`.
    FS_COMBINE_MULTIPLY = 3,        ///< `a b`.
    FS_COMBINE_GEOMETRIC_MEAN = 4,  ///< `sqrt(a b)`.
    FS_COMBINE_SUM_CLAMPED = 5,     ///< `clamp(a + b, 0, 1)`.
};

/// Which velocity a bounce reflects (fs_engine_profile::restitution_base).
enum {
    FS_RESTITUTION_BASE_STEP_START = 0,     ///< the velocity at the start of the step (Jolt, Rapier, Bullet).
    FS_RESTITUTION_BASE_AFTER_GRAVITY = 1,  ///< after that step's gravity and damping (PhysX, Godot 3, Box2D).
};

/// What a body's first step does (fs_engine_profile::first_step).
enum {
    FS_FIRST_STEP_NORMAL = 0,        ///< like every other step.
    FS_FIRST_STEP_NO_GRAVITY = 1,    ///< `p += v dt` only (Godot 3 GodotPhysics).
    FS_FIRST_STEP_DAMPING_ONLY = 2,  ///< `v = v d; p += v dt` (Godot 3 with Bullet).
};

/// When a contact starts to act (fs_engine_profile::contact).
enum {
    FS_CONTACT_SPECULATIVE = 0,  ///< within contact_distance at a step's start (most engines).
    FS_CONTACT_PENETRATION = 1,  ///< once overlapping at a step's start (Godot 3 GodotPhysics).
};

/// How an engine steps a sphere and answers its contacts (foresight::EngineProfile, which
/// engine_profile.h and docs/engines.md explain field by field): start from
/// fs_engine_profile_default(FS_ENGINE_*) and set what the game changes, typically `timestep`
/// (Unity's Time.fixedDeltaTime, Godot's physics_ticks_per_second) and `linear_damping` (Unity's
/// Rigidbody.drag, Godot's linear_damp). Enumerations are the FS_* constants above, flags 0 or 1.
/// 100 bytes, alignment 4, every field 4 bytes in this order: engine 0, timestep 4, substeps 8,
/// order 12, damping 16, linear_damping 20, added_linear_damping 24, angular_damping 28,
/// first_step 32, restitution_threshold 36, restitution_base 40, restitution_combine 44,
/// friction_combine 48, contact 52, contact_distance 56, penetration_slop 60,
/// position_correction 64, correction_is_velocity 68, split_impulse_correction 72,
/// friction_warm_start 76, max_linear_speed 80, max_step_distance 84, planar 88, rotates 92,
/// triangle_mesh 96.
typedef struct fs_engine_profile {
    int32_t engine;                  ///< FS_ENGINE_*: which engine the values describe.
    float timestep;                  ///< fixed step [Units: s] [Limit: 1e-5 .. 1].
    uint32_t substeps;               ///< equal sub-steps per step [Limit: 1 .. 64].
    int32_t order;                   ///< FS_DAMPING_ORDER_*.
    int32_t damping;                 ///< FS_DAMPING_LAW_*.
    float linear_damping;            ///< the body's linear damping [Units: 1/s] [Limit: >= 0].
    float added_linear_damping;      ///< a project default added to it [Units: 1/s] [Limit: >= 0].
    float angular_damping;           ///< [Units: 1/s] [Limit: >= 0].
    int32_t first_step;              ///< FS_FIRST_STEP_*.
    float restitution_threshold;     ///< no bounce at or below this approach speed [Units: m/s] [Limit: >= 0].
    int32_t restitution_base;        ///< FS_RESTITUTION_BASE_*.
    int32_t restitution_combine;     ///< FS_COMBINE_* for a surface's own restitution.
    int32_t friction_combine;        ///< FS_COMBINE_* for a surface's own friction.
    int32_t contact;                 ///< FS_CONTACT_*.
    float contact_distance;          ///< speculative contact distance [Units: m] [Limit: >= 0].
    float penetration_slop;          ///< penetration left alone [Units: m] [Limit: >= 0].
    float position_correction;       ///< fraction of the penetration removed per step [Limit: 0 .. 1].
    int32_t correction_is_velocity;  ///< 1: the correction is a velocity kept by the body (Bullet, Godot 3).
    float split_impulse_correction;  ///< Bullet's split impulse fraction [Limit: 0 .. 1].
    float friction_warm_start;       ///< warm-started fraction of friction [Limit: 0 .. 1].
    float max_linear_speed;          ///< speed cap [Units: m/s] [Limit: > 0].
    float max_step_distance;         ///< distance cap per step [Units: m] [Limit: > 0].
    int32_t planar;                  ///< 1: motion in the x-y plane only (Box2D).
    int32_t rotates;                 ///< 1: a rolling solid sphere; 0: rotation locked.
    int32_t triangle_mesh;           ///< 1: the world's surfaces are an engine triangle mesh (Bullet).
} fs_engine_profile;

/// The named profile of `engine` (FS_ENGINE_*) with that engine's own defaults
/// (foresight::engineProfile); FS_ENGINE_CUSTOM's for a value outside the enumeration.
FS_API fs_engine_profile fs_engine_profile_default(int32_t engine) FS_NOEXCEPT;

/// Bullet as ammo.js 0.0.10 carries it (Bullet 2.83; foresight::ammoJsProfile): FS_ENGINE_BULLET's
/// profile with restitution_threshold 0, friction_warm_start 0.85, split_impulse_correction 0.8.
FS_API fs_engine_profile fs_engine_profile_ammo_js(void) FS_NOEXCEPT;

/// Checks a profile (foresight::validateEngineProfile).
/// @return OK, NULL_POINTER, NON_FINITE_INPUT, INVALID_STEP (timestep) or INVALID_SETTING.
FS_API fs_status fs_validate_engine_profile(const fs_engine_profile* profile) FS_NOEXCEPT;

/// fs_trajectory_capacity for the Engine method with `profile` instead of settings->engine.
FS_API size_t fs_trajectory_capacity_with_profile(float time, const fs_projectile_settings* settings,
                                                  const fs_engine_profile* profile) FS_NOEXCEPT;

/// fs_predict_projectile with `profile` as the engine of the Engine method (settings->engine is
/// then ignored; other methods ignore the profile, which must still be valid).
/// @return as fs_predict_projectile, NULL_POINTER (profile), and the refusals of
///         fs_validate_engine_profile.
FS_API fs_status fs_predict_projectile_with_profile(fs_dvec3 position, fs_vec3 velocity, float time,
                                                    const fs_projectile_settings* settings,
                                                    const fs_engine_profile* profile, const fs_world* world,
                                                    fs_trajectory_point* points, size_t capacity,
                                                    fs_projectile_result* out) FS_NOEXCEPT;

/// How a game shows a body between its fixed physics steps (fs_rendered_position).
enum {
    FS_RENDER_NONE = 0,         ///< the last completed step.
    FS_RENDER_INTERPOLATE = 1,  ///< between the last two steps, one step behind (Unity, Godot 4 interpolation).
    FS_RENDER_EXTRAPOLATE = 2,  ///< the last step moved on with its velocity (Unity's extrapolation).
};

/// Where a game draws a fixed-step trajectory (Engine or Stepped: Start, then one point per
/// step) at `render_time` [Units: s] (foresight::renderedPosition, projectile.h).
/// @param step  the trajectory's step [Units: s] [Limit: > 0, finite]: the profile's timestep
///              (Engine) or settings.step (Stepped).
/// @return OK, NULL_POINTER (trajectory with a count above 0, or out), INVALID_STEP (no points,
///         or a step that is not positive and finite), NON_FINITE_INPUT (render_time) or
///         INVALID_SETTING (smoothing); `out` is written only on OK.
FS_API fs_status fs_rendered_position(const fs_trajectory_point* trajectory, size_t count, float step,
                                      float render_time, int32_t smoothing, fs_dvec3* out) FS_NOEXCEPT;

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

/* ---- Danger: where and when a grenade is dangerous -------------------------------------- */

/* These functions read a trajectory that fs_predict_projectile wrote (points[0 .. trajectory_size))
 * and model it as danger.h explains: between two points, the parabola that joins them. The
 * trajectory is passed as a pointer and a count: at least one point, times finite and
 * non-decreasing, events FS_EVENT_*. Each call converts it to the C++ layout in a buffer of the
 * calling thread that keeps its size: the first call with N points on a thread allocates it,
 * later calls with at most N points allocate nothing (OUT_OF_MEMORY if that allocation fails).
 * Common refusals: NULL_POINTER (the trajectory with a count above 0, or an output),
 * INVALID_STEP (no points, or times that decrease), NON_FINITE_INPUT, INVALID_SETTING (an
 * event outside FS_EVENT_*). */

/// A predicted grenade as a danger (foresight::ProjectileDanger without its trajectory). 12
/// bytes, alignment 4: fuse_time 0, blast_radius 4, contact_radius 8.
typedef struct fs_projectile_danger {
    float fuse_time;     ///< when it explodes [Units: s] [Limit: >= 0].
    float blast_radius;  ///< radius of the blast around its centre [Units: m] [Limit: >= 0].
    /// Before the fuse, a point this close to the projectile is unsafe (include the projectile's
    /// own radius); 0: nothing is dangerous before the fuse [Units: m] [Limit: >= 0].
    float contact_radius;
} fs_projectile_danger;

/// Where and when a projectile explodes. 32 bytes, alignment 8: center 0, radius 24, time 28.
typedef struct fs_danger_zone {
    fs_dvec3 center;  ///< the projectile's position at the fuse time [Units: m].
    float radius;     ///< the blast radius [Units: m].
    float time;       ///< the fuse time; dangerous from then on [Units: s].
} fs_danger_zone;

/// When something starts (danger at a point, a path coming close). 8 bytes, alignment 4: ever 0,
/// time 4.
typedef struct fs_danger_start {
    int32_t ever;  ///< 1: it happens, at `time`; 0: never (then `time` is 0).
    float time;    ///< the earliest time [Units: s].
} fs_danger_start;

/// A closest approach. 8 bytes, alignment 4: distance 0, time 4.
typedef struct fs_closest_approach {
    /// The smallest distance [Units: m]; for vehicles the separation (negative when overlapping,
    /// down to minus the character's radius).
    float distance;
    float time;  ///< when it happens [Units: s] (danger.h says which time of equal minima).
} fs_closest_approach;

/// The projectile's position at `time` [Units: s] (before the first point: the first point;
/// after the last: the last) (foresight::positionOnTrajectory).
/// @return OK, the common refusals, NON_FINITE_RESULT; `out` is written only on OK.
FS_API fs_status fs_position_on_trajectory(const fs_trajectory_point* trajectory, size_t count, float time,
                                           fs_dvec3* out) FS_NOEXCEPT;

/// The danger zone: the position at the fuse time, the blast radius, the fuse time
/// (foresight::computeDangerZone).
/// @return OK, the common refusals, INVALID_FUSE (fuse_time < 0), INVALID_RADIUS (a negative
///         radius), NON_FINITE_RESULT.
FS_API fs_status fs_compute_danger_zone(const fs_trajectory_point* trajectory, size_t count,
                                        const fs_projectile_danger* danger, fs_danger_zone* out) FS_NOEXCEPT;

/// Whether `point` [Units: m] is safe at `time` [Units: s]: outside the blast from the fuse time
/// on (a point at exactly blast_radius is unsafe), farther than contact_radius from the
/// projectile before it (foresight::isPointSafe).
/// @param safe  receives 1 (safe) or 0.
/// @return OK or fs_compute_danger_zone's refusals.
FS_API fs_status fs_is_point_safe(const fs_trajectory_point* trajectory, size_t count,
                                  const fs_projectile_danger* danger, fs_dvec3 point, float time,
                                  int32_t* safe) FS_NOEXCEPT;

/// When danger starts at `point` [Units: m]: the earliest time fs_is_point_safe says 0
/// (foresight::findDangerStart).
/// @return OK or fs_compute_danger_zone's refusals.
FS_API fs_status fs_find_danger_start(const fs_trajectory_point* trajectory, size_t count,
                                      const fs_projectile_danger* danger, fs_dvec3 point,
                                      fs_danger_start* out) FS_NOEXCEPT;

/// The earliest time in [from_time, until_time] [Units: s] at which the projectile comes within
/// `distance` [Units: m] [Limit: >= 0] of `point`, exact per segment (foresight::findPathApproach).
/// @return OK, the common refusals or INVALID_RADIUS (distance < 0).
FS_API fs_status fs_find_path_approach(const fs_trajectory_point* trajectory, size_t count, fs_dvec3 point,
                                       float distance, float from_time, float until_time,
                                       fs_danger_start* out) FS_NOEXCEPT;

/// The closest approach of the projectile to `point` over [from_time, until_time] [Units: s],
/// exact per segment (foresight::findClosestPathApproach).
/// @return OK, the common refusals or NON_FINITE_RESULT.
FS_API fs_status fs_find_closest_path_approach(const fs_trajectory_point* trajectory, size_t count, fs_dvec3 point,
                                               float from_time, float until_time, fs_closest_approach* out) FS_NOEXCEPT;

/* ---- Danger: a vehicle and a character ---------------------------------------------------- */

/// A vehicle as an oriented box on the exact path of fs_predict_vehicle_exact
/// (foresight::VehicleBody); fs_vehicle_body_default() gives the C++ defaults. 104 bytes,
/// alignment 8: state 0, settings 64, half_extents 80, box_center 92.
typedef struct fs_vehicle_body {
    fs_vehicle_state state;        ///< at t = 0.
    fs_vehicle_settings settings;  ///< frame of the angular velocity, forward axis.
    fs_vec3 half_extents;          ///< the box, local axes [Units: m] [Limit: each > 0] (default {0.9, 0.7, 2.2}).
    fs_vec3 box_center;            ///< the box's centre from state.position, local axes [Units: m] (default 0).
} fs_vehicle_body;

/// A character: a sphere, or a capsule of constant direction, moving as `p + v t + a t^2 / 2`
/// (foresight::CharacterBody). 64 bytes, alignment 8: position 0, velocity 24, acceleration 36,
/// radius 48, half_axis 52.
typedef struct fs_character_body {
    fs_dvec3 position;     ///< the centre at t = 0 [Units: m].
    fs_vec3 velocity;      ///< [Units: m/s].
    fs_vec3 acceleration;  ///< [Units: m/s^2]; 0 for constant velocity.
    float radius;          ///< [Units: m] [Limit: >= 0] (default 0.4).
    /// Half of the capsule's inner segment, world axes [Units: m]; zero for a sphere.
    fs_vec3 half_axis;
} fs_character_body;

/// Tolerance and work cap of the vehicle queries (foresight::ApproachSettings). 8 bytes,
/// alignment 4: tolerance 0, max_evaluations 4.
typedef struct fs_approach_settings {
    float tolerance;           ///< distance tolerance [Units: m] [Limit: > 0, finite] (default 1e-3).
    uint32_t max_evaluations;  ///< separations computed per query at most [Limit: >= 1] (default 65536).
} fs_approach_settings;

/// The first contact of a vehicle and a character. 16 bytes, alignment 4: contact 0, time 4,
/// separation 8, evaluations 12.
typedef struct fs_vehicle_contact {
    int32_t contact;       ///< 1: they come within the tolerance before the horizon; else 0.
    float time;            ///< time of first contact [Units: s], valid when contact is 1.
    float separation;      ///< the separation at `time` (at the horizon if none) [Units: m].
    uint32_t evaluations;  ///< separations computed.
} fs_vehicle_contact;

/// The defaults of foresight::VehicleBody (identity orientation, at rest, the default box).
FS_API fs_vehicle_body fs_vehicle_body_default(void) FS_NOEXCEPT;
/// The defaults of foresight::CharacterBody (a sphere of radius 0.4 m at rest at the origin).
FS_API fs_character_body fs_character_body_default(void) FS_NOEXCEPT;
/// The defaults of foresight::ApproachSettings.
FS_API fs_approach_settings fs_approach_settings_default(void) FS_NOEXCEPT;

/// The separation of the vehicle and the character at `time` [Units: s] [Limit: >= 0]: exact,
/// <= 0 when they overlap (foresight::computeVehicleSeparation).
/// @return OK, NULL_POINTER, INVALID_SETTING (the vehicle's frame), NON_FINITE_INPUT,
///         ZERO_QUATERNION, ZERO_VECTOR, DEGENERATE_SHAPE, INVALID_RADIUS, NEGATIVE_TIME or
///         NON_FINITE_RESULT.
FS_API fs_status fs_compute_vehicle_separation(const fs_vehicle_body* vehicle, const fs_character_body* character,
                                               float time, float* separation) FS_NOEXCEPT;

/// The first time in [0, horizon] [Units: s] at which the vehicle and the character touch
/// (foresight::findVehicleContact: never later than the true first overlap).
/// @return as fs_compute_vehicle_separation, INVALID_STEP (settings), TOO_MANY_STEPS
///         (max_evaluations reached).
FS_API fs_status fs_find_vehicle_contact(const fs_vehicle_body* vehicle, const fs_character_body* character,
                                         float horizon, const fs_approach_settings* settings,
                                         fs_vehicle_contact* out) FS_NOEXCEPT;

/// The closest approach in [0, horizon] [Units: s] (foresight::findClosestVehicleApproach).
/// @return as fs_find_vehicle_contact.
FS_API fs_status fs_find_closest_vehicle_approach(const fs_vehicle_body* vehicle, const fs_character_body* character,
                                                  float horizon, const fs_approach_settings* settings,
                                                  fs_closest_approach* out) FS_NOEXCEPT;

/* ---- Throw planning ----------------------------------------------------------------------- */

/// Caps on the work of fs_plan_throw (foresight::ThrowPlanBudget). 56 bytes, alignment 8:
/// azimuth_samples 0, elevation_samples 4, speed_samples 8, refinements 12,
/// refinement_predictions 16, max_predictions 20, max_total_steps 24, grid_step 32,
/// seed_landing_fractions 36.
typedef struct fs_throw_plan_budget {
    uint32_t azimuth_samples;         ///< grid: directions around the up axis (default 16).
    uint32_t elevation_samples;       ///< grid: elevations from -30 to +75 degrees (default 5).
    uint32_t speed_samples;           ///< grid: speeds (default 3).
    uint32_t refinements;             ///< candidates refined at most [Limit: 1 .. 32] (default 6).
    uint32_t refinement_predictions;  ///< predictions per refinement at most (default 24).
    uint32_t max_predictions;         ///< predictions per call at most (default 400).
    uint64_t max_total_steps;         ///< max_predictions x steps per prediction at most (default 2^24).
    float grid_step;  ///< the grid's time step (Exact method) [Units: s] [Limit: >= 0; 0: the request's] (default 0.1).
    /// Seeds: first landing at these fractions of the fuse time [Limit: (0, 1]; others skipped].
    float seed_landing_fractions[5];
} fs_throw_plan_budget;

/// What to plan (foresight::ThrowPlanRequest); fs_throw_plan_request_default() gives the C++
/// defaults. 176 bytes, alignment 8: start 0, target 24, acceptance_radius 48, fuse_time 52,
/// max_speed 56, min_speed 60, settings 64, max_plans 112, distinct_angle 116, budget 120.
typedef struct fs_throw_plan_request {
    fs_dvec3 start;                   ///< launch position (the sphere's centre) [Units: m].
    fs_dvec3 target;                  ///< where the grenade should be at the fuse time [Units: m].
    float acceptance_radius;          ///< a plan ends within this of target [Units: m] [Limit: > 0] (default 0.5).
    float fuse_time;                  ///< launch to blast [Units: s] [Limit: > 0] (default 3).
    float max_speed;                  ///< launch speed cap [Units: m/s] [Limit: > 0] (default 20).
    float min_speed;                  ///< lowest launch speed [Units: m/s] [Limit: 0 .. max_speed] (default 0).
    fs_projectile_settings settings;  ///< the forward model (method, gravity, materials, radius, step, caps).
    uint32_t max_plans;               ///< plans wanted [Limit: >= 1] (default 3).
    float distinct_angle;         ///< plans differ by this angle at least [Units: rad] [Limit: 0 .. pi] (default 0.1).
    fs_throw_plan_budget budget;  ///< caps on the work.
} fs_throw_plan_request;

/// One throw that works (foresight::ThrowPlan). 88 bytes, alignment 8: launch_velocity 0,
/// distance 12, final_position 16, bounces 40, at_rest 44, first_impact_time 48,
/// first_impact_normal 52, first_impact_position 64.
typedef struct fs_throw_plan {
    fs_vec3 launch_velocity;         ///< [Units: m/s]; speed within [min_speed, max_speed].
    float distance;                  ///< from the final position to the target [Units: m].
    fs_dvec3 final_position;         ///< where the grenade is at the fuse time [Units: m].
    uint32_t bounces;                ///< bounces until the fuse time.
    int32_t at_rest;                 ///< 1: resting on a surface at the fuse time.
    float first_impact_time;         ///< [Units: s]; < 0 when none (or not recorded: scratch too small).
    fs_vec3 first_impact_normal;     ///< unit normal of the first impact; zero when none.
    fs_dvec3 first_impact_position;  ///< [Units: m]; the start when none.
} fs_throw_plan;

/// What fs_plan_throw did (foresight::ThrowPlanResult). 32 bytes, alignment 8: plan_count 0,
/// predictions 8, closest_distance 12, closest_velocity 16, reserved 28.
typedef struct fs_throw_plan_result {
    uint64_t plan_count;       ///< plans written, closest first.
    uint32_t predictions;      ///< forward predictions run.
    float closest_distance;    ///< closest any tried throw came [Units: m]; FLT_MAX when none finished.
    fs_vec3 closest_velocity;  ///< the launch velocity of that throw [Units: m/s].
    float reserved;            ///< padding: written as 0.
} fs_throw_plan_result;

/// The defaults of foresight::ThrowPlanRequest (its settings: fs_projectile_settings_default()).
FS_API fs_throw_plan_request fs_throw_plan_request_default(void) FS_NOEXCEPT;

/// Scratch points that let fs_plan_throw record every first impact (0 for a refused request).
FS_API size_t fs_throw_plan_scratch_size(const fs_throw_plan_request* request) FS_NOEXCEPT;

/// Plans throws that put a grenade within acceptance_radius of the target when its fuse ends,
/// bank shots included (foresight::planThrow; throw_planner.h explains the search). Allocates
/// nothing. To draw a plan: fs_predict_projectile(request->start, plan.launch_velocity,
/// request->fuse_time, &request->settings, world, ...).
/// @param world             what the grenade bounces off (a static or callback world); NULL: nothing.
/// @param plans             receives up to min(max_plans, capacity) plans, closest first.
/// @param scratch           trajectory scratch of fs_throw_plan_scratch_size() points to record
///                          every first impact; may be smaller (even NULL with 0).
/// @param out               what was done.
/// @return OK (also when nothing was found: plan_count 0), NULL_POINTER, INVALID_SETTING (an
///         enumeration), the refusals of foresight::validateThrowPlanRequest (NON_FINITE_INPUT,
///         INVALID_FUSE, INVALID_RADIUS, INVALID_SPEED, INVALID_ITERATIONS, INVALID_STEP, the
///         settings' refusals, TOO_MANY_STEPS) or INVALID_CALLBACK_HIT; outputs are written only
///         on OK.
FS_API fs_status fs_plan_throw(const fs_throw_plan_request* request, const fs_world* world, fs_throw_plan* plans,
                               size_t capacity, fs_trajectory_point* scratch, size_t scratch_capacity,
                               fs_throw_plan_result* out) FS_NOEXCEPT;

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
