// The C API (include/foresight/foresight_c.h) on the C++ one: conversions only. Every function
// is noexcept (an exception would end the program rather than cross into C); the only calls that
// can throw (std::vector growing in StaticWorld::add) are caught here.

#include <foresight/aim.h>
#include <foresight/character.h>
#include <foresight/dead_reckoning.h>
#include <foresight/foresight_c.h>
#include <foresight/projectile.h>
#include <foresight/replication.h>
#include <foresight/static_world.h>
#include <foresight/vehicle.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <new>
#include <span>

using namespace foresight;

// ---- The layout promised by the header (docs/c-api.md): bindings hard-code these. ----------
static_assert(sizeof(float) == 4 && sizeof(double) == 8 && std::numeric_limits<float>::is_iec559 &&
              std::numeric_limits<double>::is_iec559);
static_assert(sizeof(fs_status) == 4);
static_assert(sizeof(fs_vec3) == 12 && alignof(fs_vec3) == 4);
static_assert(sizeof(fs_dvec3) == 24 && alignof(fs_dvec3) == 8);
static_assert(sizeof(fs_quat) == 16 && alignof(fs_quat) == 4);
static_assert(offsetof(fs_quat, w) == 12);
static_assert(sizeof(fs_point_state) == 40 && alignof(fs_point_state) == 8);
static_assert(offsetof(fs_point_state, velocity) == 24 && offsetof(fs_point_state, reserved) == 36);
static_assert(sizeof(fs_vehicle_state) == 64 && alignof(fs_vehicle_state) == 8);
static_assert(offsetof(fs_vehicle_state, velocity) == 24 && offsetof(fs_vehicle_state, orientation) == 36 &&
              offsetof(fs_vehicle_state, angular_velocity) == 52);
static_assert(sizeof(fs_vehicle_settings) == 16 && alignof(fs_vehicle_settings) == 4);
static_assert(offsetof(fs_vehicle_settings, forward) == 4);
static_assert(sizeof(fs_material) == 8 && offsetof(fs_material, friction) == 4);
static_assert(sizeof(fs_plane) == 24 && alignof(fs_plane) == 8);
static_assert(offsetof(fs_plane, reserved) == 12 && offsetof(fs_plane, distance) == 16);
static_assert(sizeof(fs_sphere) == 32 && alignof(fs_sphere) == 8);
static_assert(offsetof(fs_sphere, radius) == 24 && offsetof(fs_sphere, reserved) == 28);
static_assert(sizeof(fs_box) == 56 && alignof(fs_box) == 8);
static_assert(offsetof(fs_box, half_extents) == 24 && offsetof(fs_box, orientation) == 36 &&
              offsetof(fs_box, rounding) == 52);
static_assert(sizeof(fs_triangle) == 72 && offsetof(fs_triangle, b) == 24 && offsetof(fs_triangle, c) == 48);
static_assert(sizeof(fs_projectile_settings) == 48 && alignof(fs_projectile_settings) == 4);
static_assert(offsetof(fs_projectile_settings, gravity) == 4 && offsetof(fs_projectile_settings, step) == 16 &&
              offsetof(fs_projectile_settings, restitution) == 20 && offsetof(fs_projectile_settings, friction) == 24 &&
              offsetof(fs_projectile_settings, radius) == 28 && offsetof(fs_projectile_settings, max_bounces) == 32 &&
              offsetof(fs_projectile_settings, max_steps) == 36 && offsetof(fs_projectile_settings, max_events) == 40 &&
              offsetof(fs_projectile_settings, engine) == 44);
static_assert(sizeof(fs_trajectory_point) == 56 && alignof(fs_trajectory_point) == 8);
static_assert(offsetof(fs_trajectory_point, event) == 4 && offsetof(fs_trajectory_point, position) == 8 &&
              offsetof(fs_trajectory_point, velocity) == 32 && offsetof(fs_trajectory_point, normal) == 44);
static_assert(sizeof(fs_projectile_result) == 80 && alignof(fs_projectile_result) == 8);
static_assert(offsetof(fs_projectile_result, velocity) == 24 && offsetof(fs_projectile_result, time) == 36 &&
              offsetof(fs_projectile_result, bounces) == 40 && offsetof(fs_projectile_result, at_rest) == 44 &&
              offsetof(fs_projectile_result, stopped_at_hit) == 48 &&
              offsetof(fs_projectile_result, hit_normal) == 52 &&
              offsetof(fs_projectile_result, trajectory_size) == 64 &&
              offsetof(fs_projectile_result, trajectory_needed) == 72);
static_assert(sizeof(fs_aim_shot) == 56 && alignof(fs_aim_shot) == 8);
static_assert(offsetof(fs_aim_shot, constraint) == 24 && offsetof(fs_aim_shot, speed) == 28 &&
              offsetof(fs_aim_shot, apex_height) == 32 && offsetof(fs_aim_shot, gravity) == 36 &&
              offsetof(fs_aim_shot, max_time) == 48 && offsetof(fs_aim_shot, reserved) == 52);
static_assert(sizeof(fs_aim_target) == 48 && alignof(fs_aim_target) == 8);
static_assert(offsetof(fs_aim_target, velocity) == 24 && offsetof(fs_aim_target, acceleration) == 36);
static_assert(sizeof(fs_firing_solution) == 48 && alignof(fs_firing_solution) == 8);
static_assert(offsetof(fs_firing_solution, time) == 12 && offsetof(fs_firing_solution, hit) == 16 &&
              offsetof(fs_firing_solution, elevation) == 40 && offsetof(fs_firing_solution, reserved) == 44);

// ---- The enumerations mirror the C++ ones value for value. ----------------------------------
static_assert(FS_STATUS_OK == static_cast<int>(Status::Ok));
static_assert(FS_STATUS_NON_FINITE_INPUT == static_cast<int>(Status::NonFiniteInput));
static_assert(FS_STATUS_NEGATIVE_TIME == static_cast<int>(Status::NegativeTime));
static_assert(FS_STATUS_INVALID_STEP == static_cast<int>(Status::InvalidStep));
static_assert(FS_STATUS_INVALID_ITERATIONS == static_cast<int>(Status::InvalidIterations));
static_assert(FS_STATUS_INVALID_RESTITUTION == static_cast<int>(Status::InvalidRestitution));
static_assert(FS_STATUS_INVALID_FRICTION == static_cast<int>(Status::InvalidFriction));
static_assert(FS_STATUS_INVALID_RADIUS == static_cast<int>(Status::InvalidRadius));
static_assert(FS_STATUS_ZERO_QUATERNION == static_cast<int>(Status::ZeroQuaternion));
static_assert(FS_STATUS_ZERO_VECTOR == static_cast<int>(Status::ZeroVector));
static_assert(FS_STATUS_DEGENERATE_SHAPE == static_cast<int>(Status::DegenerateShape));
static_assert(FS_STATUS_TOO_MANY_STEPS == static_cast<int>(Status::TooManySteps));
static_assert(FS_STATUS_TOO_MANY_EVENTS == static_cast<int>(Status::TooManyEvents));
static_assert(FS_STATUS_NON_FINITE_RESULT == static_cast<int>(Status::NonFiniteResult));
static_assert(FS_STATUS_INVALID_ALGORITHM == static_cast<int>(Status::InvalidAlgorithm));
static_assert(FS_STATUS_INVALID_SPEED == static_cast<int>(Status::InvalidSpeed));
static_assert(FS_STATUS_INVALID_FUSE == static_cast<int>(Status::InvalidFuse));
static_assert(FS_STATUS_INVALID_SETTING == static_cast<int>(Status::InvalidSetting));
static_assert(FS_STATUS_TIME_WENT_BACKWARDS == static_cast<int>(Status::TimeWentBackwards));
static_assert(FS_STATUS_NO_UPDATE == static_cast<int>(Status::NoUpdate));
static_assert(FS_STATUS_OUT_OF_RANGE == static_cast<int>(Status::OutOfRange));
static_assert(FS_FRAME_BODY == static_cast<int>(AngularFrame::Body) &&
              FS_FRAME_WORLD == static_cast<int>(AngularFrame::World));
static_assert(FS_METHOD_EXACT == static_cast<int>(ProjectileMethod::Exact) &&
              FS_METHOD_STEPPED == static_cast<int>(ProjectileMethod::Stepped) &&
              FS_METHOD_ENGINE == static_cast<int>(ProjectileMethod::Engine));
static_assert(FS_ENGINE_CUSTOM == static_cast<int>(PhysicsEngine::Custom) &&
              FS_ENGINE_JOLT == static_cast<int>(PhysicsEngine::Jolt) &&
              FS_ENGINE_PHYSX == static_cast<int>(PhysicsEngine::PhysX) &&
              FS_ENGINE_RAPIER == static_cast<int>(PhysicsEngine::Rapier) &&
              FS_ENGINE_BULLET == static_cast<int>(PhysicsEngine::Bullet) &&
              FS_ENGINE_GODOT3 == static_cast<int>(PhysicsEngine::Godot3) &&
              FS_ENGINE_GODOT3_BULLET == static_cast<int>(PhysicsEngine::Godot3Bullet) &&
              FS_ENGINE_BOX2D == static_cast<int>(PhysicsEngine::Box2D));
static_assert(FS_EVENT_START == static_cast<int>(TrajectoryEvent::Start) &&
              FS_EVENT_STEP == static_cast<int>(TrajectoryEvent::Step) &&
              FS_EVENT_BOUNCE == static_cast<int>(TrajectoryEvent::Bounce) &&
              FS_EVENT_REST == static_cast<int>(TrajectoryEvent::Rest) &&
              FS_EVENT_HIT == static_cast<int>(TrajectoryEvent::Hit) &&
              FS_EVENT_END == static_cast<int>(TrajectoryEvent::End));
static_assert(FS_AIM_SPEED == static_cast<int>(AimConstraint::Speed) &&
              FS_AIM_HORIZONTAL_SPEED == static_cast<int>(AimConstraint::HorizontalSpeed) &&
              FS_AIM_APEX_ABOVE_START == static_cast<int>(AimConstraint::ApexAboveStart) &&
              FS_AIM_APEX_ABOVE_TARGET == static_cast<int>(AimConstraint::ApexAboveTarget));
static_assert(FS_MAX_FIRING_SOLUTIONS == kMaxFiringSolutions);
static_assert(sizeof(fs_dr_state) == 80 && alignof(fs_dr_state) == 8);
static_assert(offsetof(fs_dr_state, velocity) == 24 && offsetof(fs_dr_state, acceleration) == 36 &&
              offsetof(fs_dr_state, orientation) == 48 && offsetof(fs_dr_state, angular_velocity) == 64 &&
              offsetof(fs_dr_state, algorithm) == 76);
static_assert(sizeof(fs_dr_result) == 56 && alignof(fs_dr_result) == 8);
static_assert(offsetof(fs_dr_result, velocity) == 24 && offsetof(fs_dr_result, orientation) == 36 &&
              offsetof(fs_dr_result, reserved) == 52);
static_assert(sizeof(fs_dr_receiver_settings) == 36 && alignof(fs_dr_receiver_settings) == 4);
static_assert(offsetof(fs_dr_receiver_settings, smoothing) == 4 && offsetof(fs_dr_receiver_settings, blend_time) == 8 &&
              offsetof(fs_dr_receiver_settings, decay_half_life) == 12 &&
              offsetof(fs_dr_receiver_settings, teleport_distance) == 16 &&
              offsetof(fs_dr_receiver_settings, extrapolation_limit) == 20 &&
              offsetof(fs_dr_receiver_settings, interpolation_delay) == 24 &&
              offsetof(fs_dr_receiver_settings, max_future_skew) == 28 &&
              offsetof(fs_dr_receiver_settings, restart_after) == 32);
static_assert(sizeof(fs_dr_pose) == 56 && alignof(fs_dr_pose) == 8);
static_assert(offsetof(fs_dr_pose, velocity) == 24 && offsetof(fs_dr_pose, orientation) == 36 &&
              offsetof(fs_dr_pose, held) == 52);
static_assert(sizeof(fs_dr_receiver_counters) == 80 && offsetof(fs_dr_receiver_counters, clock_restarts) == 72);
static_assert(FS_DR_STATIC == static_cast<int>(DeadReckoningAlgorithm::Static) &&
              FS_DR_FPW == static_cast<int>(DeadReckoningAlgorithm::Fpw) &&
              FS_DR_RPW == static_cast<int>(DeadReckoningAlgorithm::Rpw) &&
              FS_DR_RVW == static_cast<int>(DeadReckoningAlgorithm::Rvw) &&
              FS_DR_FVW == static_cast<int>(DeadReckoningAlgorithm::Fvw) &&
              FS_DR_FPB == static_cast<int>(DeadReckoningAlgorithm::Fpb) &&
              FS_DR_RPB == static_cast<int>(DeadReckoningAlgorithm::Rpb) &&
              FS_DR_RVB == static_cast<int>(DeadReckoningAlgorithm::Rvb) &&
              FS_DR_FVB == static_cast<int>(DeadReckoningAlgorithm::Fvb));
static_assert(FS_DR_MODE_EXTRAPOLATE == static_cast<int>(ReceiverMode::Extrapolate) &&
              FS_DR_MODE_INTERPOLATE == static_cast<int>(ReceiverMode::Interpolate));
static_assert(FS_DR_SMOOTH_SNAP == static_cast<int>(Smoothing::Snap) &&
              FS_DR_SMOOTH_LINEAR_BLEND == static_cast<int>(Smoothing::LinearBlend) &&
              FS_DR_SMOOTH_PROJECTIVE_VELOCITY == static_cast<int>(Smoothing::ProjectiveVelocityBlending) &&
              FS_DR_SMOOTH_EXPONENTIAL_DECAY == static_cast<int>(Smoothing::ExponentialDecay));
static_assert(FS_DR_ACCEPTED == static_cast<int>(UpdateOutcome::Accepted) &&
              FS_DR_SNAPPED == static_cast<int>(UpdateOutcome::Snapped) &&
              FS_DR_BUFFERED == static_cast<int>(UpdateOutcome::Buffered) &&
              FS_DR_OUT_OF_ORDER == static_cast<int>(UpdateOutcome::OutOfOrder) &&
              FS_DR_DUPLICATE == static_cast<int>(UpdateOutcome::Duplicate) &&
              FS_DR_INVALID == static_cast<int>(UpdateOutcome::Invalid) &&
              FS_DR_TOO_FAR_AHEAD == static_cast<int>(UpdateOutcome::TooFarAhead));

// The handle is the C++ world itself.
struct fs_world {
    StaticWorld world;
};

// And the C++ receiver.
struct fs_dr_receiver {
    DeadReckoningReceiver receiver;
};

namespace {

// A double position coordinate as Real. Beyond float's range (float builds) it becomes an
// infinity of the same sign, which the C++ refuses as non-finite: the conversion itself would
// be undefined behaviour for such values.
Real toReal(double x) {
    if constexpr (kDoublePrecision) {
        return x;
    } else {
        constexpr double kMax = std::numeric_limits<float>::max();
        if (x > kMax) return std::numeric_limits<float>::infinity();
        if (x < -kMax) return -std::numeric_limits<float>::infinity();
        return static_cast<Real>(x);  // NaN stays NaN
    }
}

RVec3 toCpp(const fs_dvec3& v) { return RVec3(toReal(v.x), toReal(v.y), toReal(v.z)); }
Vec3 toCpp(const fs_vec3& v) { return Vec3(v.x, v.y, v.z); }
Quat toCpp(const fs_quat& q) {
    Quat r;
    r.x = q.x;
    r.y = q.y;
    r.z = q.z;
    r.w = q.w;
    return r;
}
SurfaceMaterial toCpp(const fs_material* m) {
    SurfaceMaterial r;
    if (m != nullptr) {
        r.restitution = m->restitution;
        r.friction = m->friction;
    }
    return r;
}

// (A function of its own: RVec3 and Vec3 are one type in float builds.)
fs_dvec3 toCPosition(const RVec3& v) {
    return fs_dvec3{static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}
fs_vec3 toC(const Vec3& v) { return fs_vec3{v.x, v.y, v.z}; }
fs_quat toC(const Quat& q) { return fs_quat{q.x, q.y, q.z, q.w}; }

fs_status toC(Status s) { return static_cast<fs_status>(s); }

PointState toCpp(const fs_point_state& s) { return PointState{toCpp(s.position), toCpp(s.velocity)}; }
fs_point_state toC(const PointState& s) { return fs_point_state{toCPosition(s.position), toC(s.velocity), 0.0f}; }

VehicleState toCpp(const fs_vehicle_state& s) {
    VehicleState r;
    r.position = toCpp(s.position);
    r.velocity = toCpp(s.velocity);
    r.orientation = toCpp(s.orientation);
    r.angularVelocity = toCpp(s.angular_velocity);
    return r;
}
fs_vehicle_state toC(const VehicleState& s) {
    return fs_vehicle_state{toCPosition(s.position), toC(s.velocity), toC(s.orientation), toC(s.angularVelocity)};
}

// False for a frame outside the enumeration.
bool toCpp(const fs_vehicle_settings& s, VehicleSettings& out) {
    if (s.frame != FS_FRAME_BODY && s.frame != FS_FRAME_WORLD) return false;
    out.frame = static_cast<AngularFrame>(s.frame);
    out.forward = toCpp(s.forward);
    return true;
}

// False for a method or engine outside their enumerations.
bool toCpp(const fs_projectile_settings& s, ProjectileSettings& out) {
    if (s.method < FS_METHOD_EXACT || s.method > FS_METHOD_ENGINE) return false;
    if (s.engine < FS_ENGINE_CUSTOM || s.engine > FS_ENGINE_BOX2D) return false;
    out.method = static_cast<ProjectileMethod>(s.method);
    out.gravity = toCpp(s.gravity);
    out.step = s.step;
    out.restitution = s.restitution;
    out.friction = s.friction;
    out.radius = s.radius;
    out.maxBounces = s.max_bounces;
    out.maxSteps = s.max_steps;
    out.maxEvents = s.max_events;
    out.engine = engineProfile(static_cast<PhysicsEngine>(s.engine));
    return true;
}

fs_trajectory_point toC(const TrajectoryPoint& p) {
    return fs_trajectory_point{p.time, static_cast<int32_t>(p.event), toCPosition(p.position), toC(p.velocity),
                               toC(p.normal)};
}

// Adds a shape; a failed allocation empties the world (StaticWorld may have grown one of its
// two vectors and not the other) and is reported.
template <class Shape>
fs_status addShape(fs_world* world, const Shape& shape, const fs_material* material) noexcept {
    try {
        return toC(world->world.add(shape, toCpp(material)));
    } catch (...) {
        world->world.clear();
        return FS_STATUS_OUT_OF_MEMORY;
    }
}

// An algorithm outside 1 to 9 becomes 0, which the C++ refuses (InvalidAlgorithm): a plain
// cast to the uint8_t enumeration would wrap 257 to 1.
DeadReckoningState toCpp(const fs_dr_state& s) {
    DeadReckoningState r;
    r.algorithm =
        static_cast<DeadReckoningAlgorithm>(s.algorithm >= FS_DR_STATIC && s.algorithm <= FS_DR_FVB ? s.algorithm : 0);
    r.position = toCpp(s.position);
    r.velocity = toCpp(s.velocity);
    r.acceleration = toCpp(s.acceleration);
    r.orientation = toCpp(s.orientation);
    r.angularVelocity = toCpp(s.angular_velocity);
    return r;
}
fs_dr_result toC(const DeadReckoningResult& r) {
    return fs_dr_result{toCPosition(r.position), toC(r.velocity), toC(r.orientation), 0.0f};
}

// False for a mode or smoothing outside their enumerations.
bool toCpp(const fs_dr_receiver_settings& s, ReceiverSettings& out) {
    if (s.mode < FS_DR_MODE_EXTRAPOLATE || s.mode > FS_DR_MODE_INTERPOLATE) return false;
    if (s.smoothing < FS_DR_SMOOTH_SNAP || s.smoothing > FS_DR_SMOOTH_EXPONENTIAL_DECAY) return false;
    out.mode = static_cast<ReceiverMode>(s.mode);
    out.smoothing = static_cast<Smoothing>(s.smoothing);
    out.blendTime = s.blend_time;
    out.decayHalfLife = s.decay_half_life;
    out.teleportDistance = s.teleport_distance;
    out.extrapolationLimit = s.extrapolation_limit;
    out.interpolationDelay = s.interpolation_delay;
    out.maxFutureSkew = s.max_future_skew;
    out.restartAfter = s.restart_after;
    return true;
}

}  // namespace

extern "C" {

uint32_t fs_abi_version(void) noexcept { return FS_ABI_VERSION; }

const char* fs_status_message(fs_status status) noexcept {
    switch (status) {
        case FS_STATUS_BUFFER_TOO_SMALL:
            return "the trajectory buffer is too small (the result says how many points it needs)";
        case FS_STATUS_NULL_POINTER:
            return "a required pointer is NULL";
        case FS_STATUS_OUT_OF_MEMORY:
            return "out of memory";
        default:
            break;
    }
    if (status < FS_STATUS_OK || status > FS_STATUS_OUT_OF_RANGE) return "unknown status";
    return statusMessage(static_cast<Status>(status));
}

fs_status fs_predict_linear(const fs_point_state* start, float time, fs_point_state* out) noexcept {
    if (start == nullptr || out == nullptr) return FS_STATUS_NULL_POINTER;
    PointState result;
    const Status s = predictLinear(toCpp(*start), time, result);
    if (s == Status::Ok) *out = toC(result);
    return toC(s);
}

fs_status fs_predict_accelerated(const fs_point_state* start, fs_vec3 acceleration, float time,
                                 fs_point_state* out) noexcept {
    if (start == nullptr || out == nullptr) return FS_STATUS_NULL_POINTER;
    PointState result;
    const Status s = predictAccelerated(toCpp(*start), toCpp(acceleration), time, result);
    if (s == Status::Ok) *out = toC(result);
    return toC(s);
}

fs_vehicle_settings fs_vehicle_settings_default(void) noexcept {
    const VehicleSettings d;
    return fs_vehicle_settings{static_cast<int32_t>(d.frame), toC(d.forward)};
}

fs_status fs_predict_vehicle_iterative(const fs_vehicle_state* start, float time, int32_t iterations,
                                       const fs_vehicle_settings* settings, fs_vehicle_state* out) noexcept {
    if (start == nullptr || settings == nullptr || out == nullptr) return FS_STATUS_NULL_POINTER;
    VehicleSettings cppSettings;
    if (!toCpp(*settings, cppSettings)) return FS_STATUS_INVALID_SETTING;
    VehicleState result;
    const Status s = predictVehicleIterative(toCpp(*start), time, iterations, cppSettings, result);
    if (s == Status::Ok) *out = toC(result);
    return toC(s);
}

fs_status fs_predict_vehicle_exact(const fs_vehicle_state* start, float time, const fs_vehicle_settings* settings,
                                   fs_vehicle_state* out) noexcept {
    if (start == nullptr || settings == nullptr || out == nullptr) return FS_STATUS_NULL_POINTER;
    VehicleSettings cppSettings;
    if (!toCpp(*settings, cppSettings)) return FS_STATUS_INVALID_SETTING;
    VehicleState result;
    const Status s = predictVehicleExact(toCpp(*start), time, cppSettings, result);
    if (s == Status::Ok) *out = toC(result);
    return toC(s);
}

fs_world* fs_world_create(void) noexcept { return new (std::nothrow) fs_world; }

void fs_world_destroy(fs_world* world) noexcept { delete world; }

fs_status fs_world_add_plane(fs_world* world, const fs_plane* plane, const fs_material* material) noexcept {
    if (world == nullptr || plane == nullptr) return FS_STATUS_NULL_POINTER;
    return addShape(world, Plane{toCpp(plane->normal), toReal(plane->distance)}, material);
}

fs_status fs_world_add_sphere(fs_world* world, const fs_sphere* sphere, const fs_material* material) noexcept {
    if (world == nullptr || sphere == nullptr) return FS_STATUS_NULL_POINTER;
    return addShape(world, Sphere{toCpp(sphere->center), sphere->radius}, material);
}

fs_status fs_world_add_box(fs_world* world, const fs_box* box, const fs_material* material) noexcept {
    if (world == nullptr || box == nullptr) return FS_STATUS_NULL_POINTER;
    OrientedBox b;
    b.center = toCpp(box->center);
    b.halfExtents = toCpp(box->half_extents);
    b.orientation = toCpp(box->orientation);
    b.rounding = box->rounding;
    return addShape(world, b, material);
}

fs_status fs_world_add_triangle(fs_world* world, const fs_triangle* triangle, const fs_material* material) noexcept {
    if (world == nullptr || triangle == nullptr) return FS_STATUS_NULL_POINTER;
    return addShape(world, Triangle{toCpp(triangle->a), toCpp(triangle->b), toCpp(triangle->c)}, material);
}

fs_projectile_settings fs_projectile_settings_default(void) noexcept {
    const ProjectileSettings d;
    fs_projectile_settings s;
    s.method = static_cast<int32_t>(d.method);
    s.gravity = toC(d.gravity);
    s.step = d.step;
    s.restitution = d.restitution;
    s.friction = d.friction;
    s.radius = d.radius;
    s.max_bounces = d.maxBounces;
    s.max_steps = d.maxSteps;
    s.max_events = d.maxEvents;
    s.engine = static_cast<int32_t>(d.engine.engine);
    return s;
}

size_t fs_trajectory_capacity(float time, const fs_projectile_settings* settings) noexcept {
    if (settings == nullptr || !std::isfinite(time) || time < 0.0f) return 0;
    ProjectileSettings cppSettings;
    if (!toCpp(*settings, cppSettings) || validateProjectileSettings(cppSettings) != Status::Ok) return 0;
    return trajectoryCapacity(time, cppSettings);
}

fs_status fs_predict_projectile(fs_dvec3 position, fs_vec3 velocity, float time, const fs_projectile_settings* settings,
                                const fs_world* world, fs_trajectory_point* points, size_t capacity,
                                fs_projectile_result* out) noexcept {
    if (settings == nullptr || out == nullptr || (points == nullptr && capacity > 0)) return FS_STATUS_NULL_POINTER;
    ProjectileSettings cppSettings;
    if (!toCpp(*settings, cppSettings)) return FS_STATUS_INVALID_SETTING;
    // The trajectory is predicted in C++ layout into the caller's buffer, then converted in
    // place, last point first: an fs_trajectory_point is at least as large as a TrajectoryPoint,
    // so C point i covers only C++ points i and later (already converted, or read just before).
    // No allocation.
    static_assert(sizeof(TrajectoryPoint) <= sizeof(fs_trajectory_point));
    static_assert(alignof(TrajectoryPoint) <= alignof(fs_trajectory_point));
    const CollisionWorld* cppWorld = world != nullptr ? &world->world : nullptr;
    std::span<TrajectoryPoint> trajectory;
    if (capacity > 0) {
        auto* first = reinterpret_cast<TrajectoryPoint*>(static_cast<void*>(points));
        std::uninitialized_default_construct_n(first, capacity);
        trajectory = std::span<TrajectoryPoint>(first, capacity);
    }
    ProjectileResult result;
    const Status s =
        predictProjectile(toCpp(position), toCpp(velocity), time, cppSettings, cppWorld, trajectory, result);
    if (s != Status::Ok) return toC(s);
    for (std::size_t i = result.trajectorySize; i-- > 0;) {
        const fs_trajectory_point p = toC(trajectory[i]);
        ::new (static_cast<void*>(points + i)) fs_trajectory_point(p);
    }
    out->position = toCPosition(result.position);
    out->velocity = toC(result.velocity);
    out->time = result.time;
    out->bounces = result.bounces;
    out->at_rest = result.atRest ? 1 : 0;
    out->stopped_at_hit = result.stoppedAtHit ? 1 : 0;
    out->hit_normal = toC(result.hitNormal);
    out->trajectory_size = result.trajectorySize;
    out->trajectory_needed = result.trajectoryNeeded;
    if (capacity > 0 && result.trajectoryNeeded > result.trajectorySize) return FS_STATUS_BUFFER_TOO_SMALL;
    return FS_STATUS_OK;
}

fs_aim_shot fs_aim_shot_default(void) noexcept {
    const AimShot d;
    fs_aim_shot s;
    s.from = toCPosition(d.from);
    s.constraint = static_cast<int32_t>(d.constraint);
    s.speed = d.speed;
    s.apex_height = d.apexHeight;
    s.gravity = toC(d.gravity);
    s.max_time = d.maxTime;
    s.reserved = 0.0f;
    return s;
}

fs_status fs_aim_projectile(const fs_aim_shot* shot, const fs_aim_target* target, fs_firing_solution* solutions,
                            size_t capacity, size_t* count) noexcept {
    if (shot == nullptr || target == nullptr || count == nullptr || (solutions == nullptr && capacity > 0))
        return FS_STATUS_NULL_POINTER;
    if (shot->constraint < FS_AIM_SPEED || shot->constraint > FS_AIM_APEX_ABOVE_TARGET)
        return FS_STATUS_INVALID_SETTING;
    AimShot cppShot;
    cppShot.from = toCpp(shot->from);
    cppShot.constraint = static_cast<AimConstraint>(shot->constraint);
    cppShot.speed = shot->speed;
    cppShot.apexHeight = shot->apex_height;
    cppShot.gravity = toCpp(shot->gravity);
    cppShot.maxTime = shot->max_time;
    const AimTarget cppTarget{toCpp(target->position), toCpp(target->velocity), toCpp(target->acceleration)};
    // At most kMaxFiringSolutions, on the stack; the earliest `capacity` of them are copied out,
    // as aimProjectile writes the earliest into a shorter span.
    std::array<FiringSolution, kMaxFiringSolutions> found;
    std::size_t n = 0;
    const Status s =
        aimProjectile(cppShot, cppTarget, std::span<FiringSolution>(found.data(), std::min(capacity, found.size())), n);
    if (s != Status::Ok) return toC(s);
    for (std::size_t i = 0; i < n; ++i)
        solutions[i] = fs_firing_solution{toC(found[i].velocity), found[i].time, toCPosition(found[i].hit),
                                          found[i].elevation, 0.0f};
    *count = n;
    return FS_STATUS_OK;
}

const char* fs_dr_algorithm_name(int32_t algorithm) noexcept {
    if (algorithm < FS_DR_STATIC || algorithm > FS_DR_FVB) return "?";
    return deadReckoningAlgorithmName(static_cast<DeadReckoningAlgorithm>(algorithm));
}

fs_status fs_dr_predict(const fs_dr_state* state, float time, fs_dr_result* out) noexcept {
    if (state == nullptr || out == nullptr) return FS_STATUS_NULL_POINTER;
    DeadReckoningResult result;
    const Status s = predictDeadReckoning(toCpp(*state), time, result);
    if (s == Status::Ok) *out = toC(result);
    return toC(s);
}

fs_status fs_dr_predict_batch(const fs_dr_state* states, const double* timestamps, size_t count, double time,
                              fs_dr_result* out, size_t* refused) noexcept {
    if (count > 0 && (states == nullptr || timestamps == nullptr || out == nullptr)) return FS_STATUS_NULL_POINTER;
    // One entity at a time through the C++ batch call (its age and refusal rules), converting on
    // the way: no allocation.
    std::size_t n = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const DeadReckoningState state = toCpp(states[i]);
        DeadReckoningResult result;
        n += predictDeadReckoningBatch(std::span<const DeadReckoningState>(&state, 1),
                                       std::span<const double>(timestamps + i, 1), time,
                                       std::span<DeadReckoningResult>(&result, 1));
        out[i] = toC(result);
    }
    if (refused != nullptr) *refused = n;
    return FS_STATUS_OK;
}

fs_dr_receiver_settings fs_dr_receiver_settings_default(void) noexcept {
    const ReceiverSettings d;
    return fs_dr_receiver_settings{static_cast<int32_t>(d.mode),
                                   static_cast<int32_t>(d.smoothing),
                                   d.blendTime,
                                   d.decayHalfLife,
                                   d.teleportDistance,
                                   d.extrapolationLimit,
                                   d.interpolationDelay,
                                   d.maxFutureSkew,
                                   d.restartAfter};
}

fs_status fs_dr_receiver_create(const fs_dr_receiver_settings* settings, fs_dr_receiver** out) noexcept {
    if (settings == nullptr || out == nullptr) return FS_STATUS_NULL_POINTER;
    ReceiverSettings cppSettings;
    if (!toCpp(*settings, cppSettings)) return FS_STATUS_INVALID_SETTING;
    const Status s = validateReceiverSettings(cppSettings);
    if (s != Status::Ok) return toC(s);
    auto* receiver = new (std::nothrow) fs_dr_receiver{DeadReckoningReceiver(cppSettings)};
    if (receiver == nullptr) return FS_STATUS_OUT_OF_MEMORY;
    *out = receiver;
    return FS_STATUS_OK;
}

void fs_dr_receiver_destroy(fs_dr_receiver* receiver) noexcept { delete receiver; }

fs_status fs_dr_receiver_receive(fs_dr_receiver* receiver, double timestamp, const fs_dr_state* state,
                                 double receive_time, int32_t* outcome) noexcept {
    if (receiver == nullptr || state == nullptr) return FS_STATUS_NULL_POINTER;
    const UpdateOutcome o = receiver->receiver.receive(timestamp, toCpp(*state), receive_time);
    if (outcome != nullptr) *outcome = static_cast<int32_t>(o);
    return FS_STATUS_OK;
}

fs_status fs_dr_receiver_sample(fs_dr_receiver* receiver, double time, fs_dr_pose* out) noexcept {
    if (receiver == nullptr || out == nullptr) return FS_STATUS_NULL_POINTER;
    ReceivedPose pose;
    const Status s = receiver->receiver.sample(time, pose);
    if (s == Status::Ok)
        *out = fs_dr_pose{toCPosition(pose.position), toC(pose.velocity), toC(pose.orientation), pose.held ? 1 : 0};
    return toC(s);
}

fs_status fs_dr_receiver_get_counters(const fs_dr_receiver* receiver, fs_dr_receiver_counters* out) noexcept {
    if (receiver == nullptr || out == nullptr) return FS_STATUS_NULL_POINTER;
    const ReceiverCounters& c = receiver->receiver.counters();
    *out = fs_dr_receiver_counters{c.accepted, c.snaps, c.teleports,     c.outOfOrder,  c.duplicates,
                                   c.invalid,  c.held,  c.futureUpdates, c.tooFarAhead, c.clockRestarts};
    return FS_STATUS_OK;
}

void fs_dr_receiver_reset(fs_dr_receiver* receiver) noexcept {
    if (receiver != nullptr) receiver->receiver.reset();
}

}  // extern "C"
