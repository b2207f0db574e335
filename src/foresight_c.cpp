// The C API (include/foresight/foresight_c.h) on the C++ one: conversions only. Every function
// is noexcept (an exception would end the program rather than cross into C); the only calls that
// can throw (std::vector growing in StaticWorld::add) are caught here.

#include <foresight/aim.h>
#include <foresight/character.h>
#include <foresight/danger.h>
#include <foresight/dead_reckoning.h>
#include <foresight/foresight_c.h>
#include <foresight/projectile.h>
#include <foresight/replication.h>
#include <foresight/static_world.h>
#include <foresight/throw_planner.h>
#include <foresight/vehicle.h>

#if FORESIGHT_C_WITH_EMBREE
#include <foresight/embree_world.h>
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <cstddef>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <vector>

#ifndef FORESIGHT_C_WITH_EMBREE
#define FORESIGHT_C_WITH_EMBREE 0  // 1 when CMake links the Embree backend (EmbreeWorld) in
#endif

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

static_assert(sizeof(fs_projectile_danger) == 12 && offsetof(fs_projectile_danger, contact_radius) == 8);
static_assert(sizeof(fs_danger_zone) == 32 && alignof(fs_danger_zone) == 8);
static_assert(offsetof(fs_danger_zone, radius) == 24 && offsetof(fs_danger_zone, time) == 28);
static_assert(sizeof(fs_danger_start) == 8 && offsetof(fs_danger_start, time) == 4);
static_assert(sizeof(fs_closest_approach) == 8 && offsetof(fs_closest_approach, time) == 4);
static_assert(sizeof(fs_vehicle_body) == 104 && alignof(fs_vehicle_body) == 8);
static_assert(offsetof(fs_vehicle_body, settings) == 64 && offsetof(fs_vehicle_body, half_extents) == 80 &&
              offsetof(fs_vehicle_body, box_center) == 92);
static_assert(sizeof(fs_character_body) == 64 && alignof(fs_character_body) == 8);
static_assert(offsetof(fs_character_body, velocity) == 24 && offsetof(fs_character_body, acceleration) == 36 &&
              offsetof(fs_character_body, radius) == 48 && offsetof(fs_character_body, half_axis) == 52);
static_assert(sizeof(fs_approach_settings) == 8 && offsetof(fs_approach_settings, max_evaluations) == 4);
static_assert(sizeof(fs_vehicle_contact) == 16 && offsetof(fs_vehicle_contact, time) == 4 &&
              offsetof(fs_vehicle_contact, separation) == 8 && offsetof(fs_vehicle_contact, evaluations) == 12);
static_assert(sizeof(fs_throw_plan_budget) == 56 && alignof(fs_throw_plan_budget) == 8);
static_assert(offsetof(fs_throw_plan_budget, elevation_samples) == 4 &&
              offsetof(fs_throw_plan_budget, speed_samples) == 8 && offsetof(fs_throw_plan_budget, refinements) == 12 &&
              offsetof(fs_throw_plan_budget, refinement_predictions) == 16 &&
              offsetof(fs_throw_plan_budget, max_predictions) == 20 &&
              offsetof(fs_throw_plan_budget, max_total_steps) == 24 &&
              offsetof(fs_throw_plan_budget, grid_step) == 32 &&
              offsetof(fs_throw_plan_budget, seed_landing_fractions) == 36);
static_assert(sizeof(fs_throw_plan_request) == 176 && alignof(fs_throw_plan_request) == 8);
static_assert(offsetof(fs_throw_plan_request, target) == 24 &&
              offsetof(fs_throw_plan_request, acceptance_radius) == 48 &&
              offsetof(fs_throw_plan_request, fuse_time) == 52 && offsetof(fs_throw_plan_request, max_speed) == 56 &&
              offsetof(fs_throw_plan_request, min_speed) == 60 && offsetof(fs_throw_plan_request, settings) == 64 &&
              offsetof(fs_throw_plan_request, max_plans) == 112 &&
              offsetof(fs_throw_plan_request, distinct_angle) == 116 && offsetof(fs_throw_plan_request, budget) == 120);
static_assert(sizeof(fs_throw_plan) == 88 && alignof(fs_throw_plan) == 8);
static_assert(offsetof(fs_throw_plan, distance) == 12 && offsetof(fs_throw_plan, final_position) == 16 &&
              offsetof(fs_throw_plan, bounces) == 40 && offsetof(fs_throw_plan, at_rest) == 44 &&
              offsetof(fs_throw_plan, first_impact_time) == 48 && offsetof(fs_throw_plan, first_impact_normal) == 52 &&
              offsetof(fs_throw_plan, first_impact_position) == 64);
static_assert(sizeof(fs_throw_plan_result) == 32 && alignof(fs_throw_plan_result) == 8);
static_assert(offsetof(fs_throw_plan_result, predictions) == 8 &&
              offsetof(fs_throw_plan_result, closest_distance) == 12 &&
              offsetof(fs_throw_plan_result, closest_velocity) == 16 && offsetof(fs_throw_plan_result, reserved) == 28);
static_assert(std::tuple_size_v<decltype(ThrowPlanBudget::seedLandingFractions)> == 5);
static_assert(sizeof(fs_engine_profile) == 100 && alignof(fs_engine_profile) == 4);
static_assert(
    offsetof(fs_engine_profile, timestep) == 4 && offsetof(fs_engine_profile, substeps) == 8 &&
    offsetof(fs_engine_profile, order) == 12 && offsetof(fs_engine_profile, damping) == 16 &&
    offsetof(fs_engine_profile, linear_damping) == 20 && offsetof(fs_engine_profile, added_linear_damping) == 24 &&
    offsetof(fs_engine_profile, angular_damping) == 28 && offsetof(fs_engine_profile, first_step) == 32 &&
    offsetof(fs_engine_profile, restitution_threshold) == 36 && offsetof(fs_engine_profile, restitution_base) == 40 &&
    offsetof(fs_engine_profile, restitution_combine) == 44 && offsetof(fs_engine_profile, friction_combine) == 48 &&
    offsetof(fs_engine_profile, contact) == 52 && offsetof(fs_engine_profile, contact_distance) == 56 &&
    offsetof(fs_engine_profile, penetration_slop) == 60 && offsetof(fs_engine_profile, position_correction) == 64 &&
    offsetof(fs_engine_profile, correction_is_velocity) == 68 &&
    offsetof(fs_engine_profile, split_impulse_correction) == 72 &&
    offsetof(fs_engine_profile, friction_warm_start) == 76 && offsetof(fs_engine_profile, max_linear_speed) == 80 &&
    offsetof(fs_engine_profile, max_step_distance) == 84 && offsetof(fs_engine_profile, planar) == 88 &&
    offsetof(fs_engine_profile, rotates) == 92 && offsetof(fs_engine_profile, triangle_mesh) == 96);
static_assert(FS_DAMPING_ORDER_DAMPING_THEN_GRAVITY == static_cast<int>(DampingOrder::DampingThenGravity) &&
              FS_DAMPING_LAW_POWER == static_cast<int>(DampingLaw::Power) &&
              FS_DAMPING_LAW_RATIONAL == static_cast<int>(DampingLaw::Rational) &&
              FS_DAMPING_LAW_LINEAR_CLAMPED == static_cast<int>(DampingLaw::LinearClamped) &&
              FS_COMBINE_AVERAGE == static_cast<int>(CombineRule::Average) &&
              FS_COMBINE_MIN == static_cast<int>(CombineRule::Min) &&
              FS_COMBINE_MAX == static_cast<int>(CombineRule::Max) &&
              FS_COMBINE_MULTIPLY == static_cast<int>(CombineRule::Multiply) &&
              FS_COMBINE_GEOMETRIC_MEAN == static_cast<int>(CombineRule::GeometricMean) &&
              FS_COMBINE_SUM_CLAMPED == static_cast<int>(CombineRule::SumClamped) &&
              FS_RESTITUTION_BASE_AFTER_GRAVITY == static_cast<int>(RestitutionBase::AfterGravity) &&
              FS_FIRST_STEP_NO_GRAVITY == static_cast<int>(FirstStepRule::NoGravity) &&
              FS_FIRST_STEP_DAMPING_ONLY == static_cast<int>(FirstStepRule::DampingOnly) &&
              FS_CONTACT_PENETRATION == static_cast<int>(ContactMethod::Penetration) &&
              FS_RENDER_NONE == static_cast<int>(RenderSmoothing::None) &&
              FS_RENDER_INTERPOLATE == static_cast<int>(RenderSmoothing::Interpolate) &&
              FS_RENDER_EXTRAPOLATE == static_cast<int>(RenderSmoothing::Extrapolate));

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

static_assert(sizeof(fs_segment_cast) == 40 && alignof(fs_segment_cast) == 8);
static_assert(offsetof(fs_segment_cast, displacement) == 24 && offsetof(fs_segment_cast, radius) == 36);
static_assert(sizeof(fs_cast_hit) == 48 && alignof(fs_cast_hit) == 8);
static_assert(offsetof(fs_cast_hit, restitution) == 4 && offsetof(fs_cast_hit, position) == 8 &&
              offsetof(fs_cast_hit, normal) == 32 && offsetof(fs_cast_hit, friction) == 44);

// The handle: a StaticWorld, or (cast != nullptr) a callback world, whose casts go to the
// caller's function through a CheckedCallbackWorld made for each prediction.
static_assert(sizeof(fs_mesh_report) == 24 && offsetof(fs_mesh_report, degenerate_triangles) == 8 &&
              offsetof(fs_mesh_report, first_degenerate_triangle) == 16);

// The handle: a StaticWorld; or (cast != nullptr) a callback world, whose casts go to the
// caller's function through a CheckedCallbackWorld made for each prediction; or (embree) an
// EmbreeWorld.
struct fs_world {
    StaticWorld world;
    fs_cast_function cast = nullptr;
    void* context = nullptr;
#if FORESIGHT_C_WITH_EMBREE
    std::unique_ptr<EmbreeWorld> embree;
#endif
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
        return static_cast<Real>(x);  // the identity (a cast for the float branch's type check)
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

// A callback world's casts for one prediction: each hit the caller's function returns is checked
// (a hostile or buggy callback must not make the prediction read NaN or loop on nonsense). The
// first invalid hit is remembered; from then on every cast misses, so the prediction ends
// quickly, and the caller returns FS_STATUS_INVALID_CALLBACK_HIT instead of its result.
class CheckedCallbackWorld final : public CollisionWorld {
public:
    CheckedCallbackWorld(fs_cast_function cast, void* context) : mCast(cast), mContext(context) {}

    bool castSegment(const SegmentCast& cast, CastHit& hit) const override {
        if (mInvalid) return false;
        const fs_segment_cast c{fs_dvec3{static_cast<double>(cast.origin.x), static_cast<double>(cast.origin.y),
                                         static_cast<double>(cast.origin.z)},
                                fs_vec3{cast.displacement.x, cast.displacement.y, cast.displacement.z}, cast.radius};
        fs_cast_hit h{1.0f, -1.0f,
                      fs_dvec3{c.origin.x + static_cast<double>(c.displacement.x),
                               c.origin.y + static_cast<double>(c.displacement.y),
                               c.origin.z + static_cast<double>(c.displacement.z)},
                      fs_vec3{0.0f, 1.0f, 0.0f}, -1.0f};
        if (mCast(mContext, &c, &h) == 0) return false;
        const double nx = h.normal.x, ny = h.normal.y, nz = h.normal.z;
        const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
        const RVec3 position = toCpp(h.position);  // beyond float's range: infinite, refused below
        const bool valid = std::isfinite(h.fraction) && h.fraction >= 0.0f && h.fraction <= 1.0f &&
                           std::isfinite(position.x) && std::isfinite(position.y) && std::isfinite(position.z) &&
                           std::isfinite(length) && length > 0.0 && !std::isnan(h.restitution) &&
                           h.restitution <= 1.0f && !std::isnan(h.friction);
        if (!valid) {
            mInvalid = true;
            return false;
        }
        hit.fraction = h.fraction;
        hit.position = position;
        // A unit normal (to float rounding) is kept as it is, so that a callback forwarding to a
        // foresight world gives that world's results bit for bit.
        hit.normal = std::abs(length - 1.0) <= 1e-6
                         ? Vec3(h.normal.x, h.normal.y, h.normal.z)
                         : Vec3(static_cast<float>(nx / length), static_cast<float>(ny / length),
                                static_cast<float>(nz / length));
        hit.restitution = h.restitution < 0.0f ? -1.0f : h.restitution;
        hit.friction = h.friction < 0.0f ? -1.0f : h.friction;
        return true;
    }

    /// Whether a cast returned an invalid hit.
    bool invalid() const { return mInvalid; }

private:
    fs_cast_function mCast;
    void* mContext;
    mutable bool mInvalid = false;
};

// Adds a shape; a failed allocation empties the world (StaticWorld may have grown one of its
// two vectors and not the other) and is reported.
template <class Shape>
fs_status addShape(fs_world* world, const Shape& shape, const fs_material* material) noexcept {
    if (world->cast != nullptr) return FS_STATUS_INVALID_SETTING;  // a callback world holds no shapes
#if FORESIGHT_C_WITH_EMBREE
    if (world->embree) {
        try {
            return toC(world->embree->add(shape, toCpp(material)));
        } catch (...) {
            world->embree.reset(new (std::nothrow) EmbreeWorld);
            return FS_STATUS_OUT_OF_MEMORY;
        }
    }
#endif
    try {
        return toC(world->world.add(shape, toCpp(material)));
    } catch (...) {
        world->world.clear();
        return FS_STATUS_OUT_OF_MEMORY;
    }
}

// A world handle as the C++ world a prediction uses: a StaticWorld, or a checked callback world
// made in `callback` for this call; nullptr for no world.
const CollisionWorld* worldFor(const fs_world* world, std::optional<CheckedCallbackWorld>& callback) {
    if (world == nullptr) return nullptr;
    if (world->cast != nullptr) return &callback.emplace(world->cast, world->context);
#if FORESIGHT_C_WITH_EMBREE
    if (world->embree) return world->embree.get();
#endif
    return &world->world;
}

#if FORESIGHT_C_WITH_EMBREE
// Writes `text` into the caller's error buffer, cut to fit and NUL-terminated.
void copyError(char* error, size_t capacity, const std::string& text) {
    if (error == nullptr || capacity == 0) return;
    const std::size_t n = std::min(text.size(), capacity - 1);
    std::memcpy(error, text.data(), n);
    error[n] = '\0';
}
#endif

// The calling thread's trajectory in C++ layout (see "Danger" in foresight_c.h): it keeps the
// largest size it was given.
thread_local std::vector<TrajectoryPoint> tTrajectory;

// Converts a C trajectory into tTrajectory; OK, NULL_POINTER, INVALID_SETTING (an event) or
// OUT_OF_MEMORY. An empty trajectory converts to an empty span (which the C++ refuses).
fs_status toCpp(const fs_trajectory_point* points, size_t count, std::span<const TrajectoryPoint>& out) noexcept {
    if (points == nullptr && count > 0) return FS_STATUS_NULL_POINTER;
    try {
        if (tTrajectory.size() < count) tTrajectory.resize(count);
    } catch (...) {
        return FS_STATUS_OUT_OF_MEMORY;
    }
    for (std::size_t i = 0; i < count; ++i) {
        const fs_trajectory_point& p = points[i];
        if (p.event < FS_EVENT_START || p.event > FS_EVENT_END) return FS_STATUS_INVALID_SETTING;
        TrajectoryPoint& q = tTrajectory[i];
        q.time = p.time;
        q.event = static_cast<TrajectoryEvent>(p.event);
        q.position = toCpp(p.position);
        q.velocity = toCpp(p.velocity);
        q.normal = toCpp(p.normal);
    }
    out = std::span<const TrajectoryPoint>(tTrajectory.data(), count);
    return FS_STATUS_OK;
}

ProjectileDanger toCpp(std::span<const TrajectoryPoint> trajectory, const fs_projectile_danger& d) {
    ProjectileDanger r;
    r.trajectory = trajectory;
    r.fuseTime = d.fuse_time;
    r.blastRadius = d.blast_radius;
    r.contactRadius = d.contact_radius;
    return r;
}

// False for a frame outside the enumeration.
bool toCpp(const fs_vehicle_body& b, VehicleBody& out) {
    out.state = toCpp(b.state);
    if (!toCpp(b.settings, out.settings)) return false;
    out.halfExtents = toCpp(b.half_extents);
    out.boxCenter = toCpp(b.box_center);
    return true;
}

CharacterBody toCpp(const fs_character_body& c) {
    CharacterBody r;
    r.position = toCpp(c.position);
    r.velocity = toCpp(c.velocity);
    r.acceleration = toCpp(c.acceleration);
    r.radius = c.radius;
    r.halfAxis = toCpp(c.half_axis);
    return r;
}

ApproachSettings toCpp(const fs_approach_settings& s) {
    ApproachSettings r;
    r.tolerance = s.tolerance;
    r.maxEvaluations = s.max_evaluations;
    return r;
}

// False for an enumeration outside its values.
bool toCpp(const fs_throw_plan_request& q, ThrowPlanRequest& out) {
    out.start = toCpp(q.start);
    out.target = toCpp(q.target);
    out.acceptanceRadius = q.acceptance_radius;
    out.fuseTime = q.fuse_time;
    out.maxSpeed = q.max_speed;
    out.minSpeed = q.min_speed;
    if (!toCpp(q.settings, out.settings)) return false;
    out.maxPlans = q.max_plans;
    out.distinctAngle = q.distinct_angle;
    const fs_throw_plan_budget& b = q.budget;
    out.budget.azimuthSamples = b.azimuth_samples;
    out.budget.elevationSamples = b.elevation_samples;
    out.budget.speedSamples = b.speed_samples;
    out.budget.refinements = b.refinements;
    out.budget.refinementPredictions = b.refinement_predictions;
    out.budget.maxPredictions = b.max_predictions;
    out.budget.maxTotalSteps = b.max_total_steps;
    out.budget.gridStep = b.grid_step;
    std::copy(std::begin(b.seed_landing_fractions), std::end(b.seed_landing_fractions),
              out.budget.seedLandingFractions.begin());
    return true;
}

// False for an enumeration or flag outside its values.
bool toCpp(const fs_engine_profile& p, EngineProfile& out) {
    const auto within = [](int32_t value, int32_t last) { return value >= 0 && value <= last; };
    if (!within(p.engine, FS_ENGINE_BOX2D) || !within(p.order, FS_DAMPING_ORDER_DAMPING_THEN_GRAVITY) ||
        !within(p.damping, FS_DAMPING_LAW_POWER) || !within(p.first_step, FS_FIRST_STEP_DAMPING_ONLY) ||
        !within(p.restitution_base, FS_RESTITUTION_BASE_AFTER_GRAVITY) ||
        !within(p.restitution_combine, FS_COMBINE_SUM_CLAMPED) || !within(p.friction_combine, FS_COMBINE_SUM_CLAMPED) ||
        !within(p.contact, FS_CONTACT_PENETRATION) || !within(p.correction_is_velocity, 1) || !within(p.planar, 1) ||
        !within(p.rotates, 1) || !within(p.triangle_mesh, 1))
        return false;
    out.engine = static_cast<PhysicsEngine>(p.engine);
    out.timestep = p.timestep;
    out.substeps = p.substeps;
    out.order = static_cast<DampingOrder>(p.order);
    out.damping = static_cast<DampingLaw>(p.damping);
    out.linearDamping = p.linear_damping;
    out.addedLinearDamping = p.added_linear_damping;
    out.angularDamping = p.angular_damping;
    out.firstStep = static_cast<FirstStepRule>(p.first_step);
    out.restitutionThreshold = p.restitution_threshold;
    out.restitutionBase = static_cast<RestitutionBase>(p.restitution_base);
    out.restitutionCombine = static_cast<CombineRule>(p.restitution_combine);
    out.frictionCombine = static_cast<CombineRule>(p.friction_combine);
    out.contact = static_cast<ContactMethod>(p.contact);
    out.contactDistance = p.contact_distance;
    out.penetrationSlop = p.penetration_slop;
    out.positionCorrection = p.position_correction;
    out.correctionIsVelocity = p.correction_is_velocity != 0;
    out.splitImpulseCorrection = p.split_impulse_correction;
    out.frictionWarmStart = p.friction_warm_start;
    out.maxLinearSpeed = p.max_linear_speed;
    out.maxStepDistance = p.max_step_distance;
    out.planar = p.planar != 0;
    out.rotates = p.rotates != 0;
    out.triangleMesh = p.triangle_mesh != 0;
    return true;
}

fs_engine_profile toC(const EngineProfile& p) {
    fs_engine_profile r;
    r.engine = static_cast<int32_t>(p.engine);
    r.timestep = p.timestep;
    r.substeps = p.substeps;
    r.order = static_cast<int32_t>(p.order);
    r.damping = static_cast<int32_t>(p.damping);
    r.linear_damping = p.linearDamping;
    r.added_linear_damping = p.addedLinearDamping;
    r.angular_damping = p.angularDamping;
    r.first_step = static_cast<int32_t>(p.firstStep);
    r.restitution_threshold = p.restitutionThreshold;
    r.restitution_base = static_cast<int32_t>(p.restitutionBase);
    r.restitution_combine = static_cast<int32_t>(p.restitutionCombine);
    r.friction_combine = static_cast<int32_t>(p.frictionCombine);
    r.contact = static_cast<int32_t>(p.contact);
    r.contact_distance = p.contactDistance;
    r.penetration_slop = p.penetrationSlop;
    r.position_correction = p.positionCorrection;
    r.correction_is_velocity = p.correctionIsVelocity ? 1 : 0;
    r.split_impulse_correction = p.splitImpulseCorrection;
    r.friction_warm_start = p.frictionWarmStart;
    r.max_linear_speed = p.maxLinearSpeed;
    r.max_step_distance = p.maxStepDistance;
    r.planar = p.planar ? 1 : 0;
    r.rotates = p.rotates ? 1 : 0;
    r.triangle_mesh = p.triangleMesh ? 1 : 0;
    return r;
}

// fs_predict_projectile's work once the settings are in C++ form.
fs_status predictInto(fs_dvec3 position, fs_vec3 velocity, float time, const ProjectileSettings& cppSettings,
                      const fs_world* world, fs_trajectory_point* points, size_t capacity,
                      fs_projectile_result* out) noexcept {
    // The trajectory is predicted in C++ layout into the caller's buffer, then converted in
    // place, last point first: an fs_trajectory_point is at least as large as a TrajectoryPoint,
    // so C point i covers only C++ points i and later (already converted, or read just before).
    // No allocation. Only the points a prediction usually needs are made C++ points first
    // (trajectoryCapacity: all of a Stepped or Engine trajectory, an Exact one with up to 64
    // events), so that a large buffer costs nothing per call; a prediction that needs more, when
    // the buffer has the room, runs again on the whole buffer (deterministic: the same result).
    static_assert(sizeof(TrajectoryPoint) <= sizeof(fs_trajectory_point));
    static_assert(alignof(TrajectoryPoint) <= alignof(fs_trajectory_point));
    std::optional<CheckedCallbackWorld> callbackWorld;
    const CollisionWorld* cppWorld = worldFor(world, callbackWorld);
    auto* first = reinterpret_cast<TrajectoryPoint*>(static_cast<void*>(points));
    std::size_t prepared = 0;
    const auto prepare = [&](std::size_t count) {
        if (count > prepared) std::uninitialized_default_construct_n(first + prepared, count - prepared);
        prepared = std::max(prepared, count);
        return capacity > 0 ? std::span<TrajectoryPoint>(first, prepared) : std::span<TrajectoryPoint>();
    };
    const bool usual = std::isfinite(time) && time >= 0.0f && validateProjectileSettings(cppSettings) == Status::Ok;
    std::span<TrajectoryPoint> trajectory =
        prepare(std::min(capacity, usual ? trajectoryCapacity(time, cppSettings) : std::size_t{16}));
    ProjectileResult result;
    Status s = predictProjectile(toCpp(position), toCpp(velocity), time, cppSettings, cppWorld, trajectory, result);
    if (s == Status::Ok && result.trajectoryNeeded > prepared && capacity > prepared &&
        !(callbackWorld && callbackWorld->invalid())) {
        trajectory = prepare(capacity);
        s = predictProjectile(toCpp(position), toCpp(velocity), time, cppSettings, cppWorld, trajectory, result);
    }
    if (callbackWorld && callbackWorld->invalid()) return FS_STATUS_INVALID_CALLBACK_HIT;
    if (s != Status::Ok) return toC(s);
    // In blocks, last first: a block's C++ points are read before its C points are written, so
    // the processor does not have to order each load after the stores just before it (converting
    // point by point cost 3 us for the article's 140-point grenade, a fifth of the prediction).
    constexpr std::size_t kBlock = 32;
    for (std::size_t end = result.trajectorySize; end > 0;) {
        const std::size_t begin = end > kBlock ? end - kBlock : 0;
        std::array<fs_trajectory_point, kBlock> block;
        for (std::size_t i = begin; i < end; ++i) block[i - begin] = toC(trajectory[i]);
        for (std::size_t i = begin; i < end; ++i)
            ::new (static_cast<void*>(points + i)) fs_trajectory_point(block[i - begin]);
        end = begin;
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
        case FS_STATUS_BACKEND_FAILED:
            return "the Embree backend failed: a mesh file could not be loaded, or the BVH could not be built";
        case FS_STATUS_INVALID_CALLBACK_HIT:
            return "the world's cast callback returned an invalid hit (fraction outside 0..1, a non-finite position, "
                   "a zero or non-finite normal, or an invalid material)";
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

fs_world* fs_world_create_callback(fs_cast_function cast, void* context) noexcept {
    if (cast == nullptr) return nullptr;
    fs_world* world = new (std::nothrow) fs_world;
    if (world == nullptr) return nullptr;
    world->cast = cast;
    world->context = context;
    return world;
}

void fs_world_destroy(fs_world* world) noexcept { delete world; }

fs_status fs_world_add_mesh(fs_world* world, const fs_dvec3* vertices, size_t vertex_count, const uint32_t* indices,
                            size_t index_count, fs_mesh_report* report) noexcept {
    if (world == nullptr || (vertices == nullptr && vertex_count > 0) || (indices == nullptr && index_count > 0))
        return FS_STATUS_NULL_POINTER;
    if (world->cast != nullptr) return FS_STATUS_INVALID_SETTING;
    fs_mesh_report counts{0, 0, 0};
    try {
        std::vector<RVec3> points(vertex_count);
        for (std::size_t i = 0; i < vertex_count; ++i) points[i] = toCpp(vertices[i]);
        const std::span<const std::uint32_t> indexSpan(indices, index_count);
        MeshReport meshReport;
#if FORESIGHT_C_WITH_EMBREE
        const Status s = world->embree ? world->embree->addMesh(points, indexSpan, &meshReport)
                                       : world->world.addMesh(points, indexSpan, &meshReport);
#else
        const Status s = world->world.addMesh(points, indexSpan, &meshReport);
#endif
        if (s != Status::Ok) return toC(s);
        counts =
            fs_mesh_report{meshReport.triangles, meshReport.degenerateTriangles, meshReport.firstDegenerateTriangle};
        if (report != nullptr) *report = counts;
        return FS_STATUS_OK;
    } catch (...) {
        // A StaticWorld that ran out of memory midway is emptied, as fs_world_add_* do.
#if FORESIGHT_C_WITH_EMBREE
        if (world->embree) {
            world->embree.reset(new (std::nothrow) EmbreeWorld);
            return FS_STATUS_OUT_OF_MEMORY;
        }
#endif
        world->world.clear();
        return FS_STATUS_OUT_OF_MEMORY;
    }
}

int32_t fs_embree_available(void) noexcept { return FORESIGHT_C_WITH_EMBREE ? 1 : 0; }

fs_world* fs_world_create_embree(void) noexcept {
#if FORESIGHT_C_WITH_EMBREE
    fs_world* world = new (std::nothrow) fs_world;
    if (world == nullptr) return nullptr;
    world->embree.reset(new (std::nothrow) EmbreeWorld);
    if (!world->embree) {
        delete world;
        return nullptr;
    }
    return world;
#else
    return nullptr;
#endif
}

fs_status fs_world_load_mesh(fs_world* world, const char* path, fs_mesh_report* report, char* error,
                             size_t error_capacity) noexcept {
    if (world == nullptr || path == nullptr || (error == nullptr && error_capacity > 0)) return FS_STATUS_NULL_POINTER;
#if FORESIGHT_C_WITH_EMBREE
    if (!world->embree) return FS_STATUS_INVALID_SETTING;
    try {
        std::string extension;
        if (const char* dot = std::strrchr(path, '.'); dot != nullptr)
            for (const char* c = dot; *c != '\0'; ++c)
                extension += static_cast<char>(std::tolower(static_cast<unsigned char>(*c)));
        MeshLoadResult loaded;
        if (extension == ".obj") {
            loaded = world->embree->loadObj(std::filesystem::u8path(path));
        } else if (extension == ".gltf" || extension == ".glb") {
            loaded = world->embree->loadGltf(std::filesystem::u8path(path));
        } else {
            return FS_STATUS_INVALID_SETTING;
        }
        if (!loaded.ok) {
            copyError(error, error_capacity, loaded.error);
            return FS_STATUS_BACKEND_FAILED;
        }
        if (report != nullptr)
            *report = fs_mesh_report{loaded.report.triangles, loaded.report.degenerateTriangles,
                                     loaded.report.firstDegenerateTriangle};
        return FS_STATUS_OK;
    } catch (const std::bad_alloc&) {
        return FS_STATUS_OUT_OF_MEMORY;
    } catch (const std::exception& e) {
        copyError(error, error_capacity, std::string(path) + ": " + e.what());
        return FS_STATUS_BACKEND_FAILED;
    } catch (...) {
        copyError(error, error_capacity, std::string(path) + ": could not be loaded");
        return FS_STATUS_BACKEND_FAILED;
    }
#else
    (void)report;
    return FS_STATUS_INVALID_SETTING;  // no Embree world exists in this build
#endif
}

fs_status fs_world_commit(fs_world* world, char* error, size_t error_capacity) noexcept {
    if (world == nullptr || (error == nullptr && error_capacity > 0)) return FS_STATUS_NULL_POINTER;
#if FORESIGHT_C_WITH_EMBREE
    if (world->embree) {
        try {
            std::string why;
            if (!world->embree->commit(&why)) {
                copyError(error, error_capacity, why);
                return FS_STATUS_BACKEND_FAILED;
            }
        } catch (...) {
            copyError(error, error_capacity, "the Embree BVH could not be built (out of memory)");
            return FS_STATUS_BACKEND_FAILED;
        }
    }
#endif
    return FS_STATUS_OK;
}

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
    return predictInto(position, velocity, time, cppSettings, world, points, capacity, out);
}

fs_status fs_predict_projectile_with_profile(fs_dvec3 position, fs_vec3 velocity, float time,
                                             const fs_projectile_settings* settings, const fs_engine_profile* profile,
                                             const fs_world* world, fs_trajectory_point* points, size_t capacity,
                                             fs_projectile_result* out) noexcept {
    if (settings == nullptr || profile == nullptr || out == nullptr || (points == nullptr && capacity > 0))
        return FS_STATUS_NULL_POINTER;
    ProjectileSettings cppSettings;
    if (!toCpp(*settings, cppSettings) || !toCpp(*profile, cppSettings.engine)) return FS_STATUS_INVALID_SETTING;
    // The profile is checked whatever the method (validateProjectileSettings checks it only for
    // the Engine method).
    if (const Status s = validateEngineProfile(cppSettings.engine); s != Status::Ok) return toC(s);
    return predictInto(position, velocity, time, cppSettings, world, points, capacity, out);
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

fs_status fs_position_on_trajectory(const fs_trajectory_point* trajectory, size_t count, float time,
                                    fs_dvec3* out) noexcept {
    if (out == nullptr) return FS_STATUS_NULL_POINTER;
    std::span<const TrajectoryPoint> points;
    if (const fs_status c = toCpp(trajectory, count, points); c != FS_STATUS_OK) return c;
    RVec3 position;
    const Status s = positionOnTrajectory(points, time, position);
    if (s == Status::Ok) *out = toCPosition(position);
    return toC(s);
}

fs_status fs_compute_danger_zone(const fs_trajectory_point* trajectory, size_t count,
                                 const fs_projectile_danger* danger, fs_danger_zone* out) noexcept {
    if (danger == nullptr || out == nullptr) return FS_STATUS_NULL_POINTER;
    std::span<const TrajectoryPoint> points;
    if (const fs_status c = toCpp(trajectory, count, points); c != FS_STATUS_OK) return c;
    DangerZone zone;
    const Status s = computeDangerZone(toCpp(points, *danger), zone);
    if (s == Status::Ok) *out = fs_danger_zone{toCPosition(zone.center), zone.radius, zone.time};
    return toC(s);
}

fs_status fs_is_point_safe(const fs_trajectory_point* trajectory, size_t count, const fs_projectile_danger* danger,
                           fs_dvec3 point, float time, int32_t* safe) noexcept {
    if (danger == nullptr || safe == nullptr) return FS_STATUS_NULL_POINTER;
    std::span<const TrajectoryPoint> points;
    if (const fs_status c = toCpp(trajectory, count, points); c != FS_STATUS_OK) return c;
    bool isSafe = false;
    const Status s = isPointSafe(toCpp(points, *danger), toCpp(point), time, isSafe);
    if (s == Status::Ok) *safe = isSafe ? 1 : 0;
    return toC(s);
}

fs_status fs_find_danger_start(const fs_trajectory_point* trajectory, size_t count, const fs_projectile_danger* danger,
                               fs_dvec3 point, fs_danger_start* out) noexcept {
    if (danger == nullptr || out == nullptr) return FS_STATUS_NULL_POINTER;
    std::span<const TrajectoryPoint> points;
    if (const fs_status c = toCpp(trajectory, count, points); c != FS_STATUS_OK) return c;
    DangerStart start;
    const Status s = findDangerStart(toCpp(points, *danger), toCpp(point), start);
    if (s == Status::Ok) *out = fs_danger_start{start.ever ? 1 : 0, start.time};
    return toC(s);
}

fs_status fs_find_path_approach(const fs_trajectory_point* trajectory, size_t count, fs_dvec3 point, float distance,
                                float from_time, float until_time, fs_danger_start* out) noexcept {
    if (out == nullptr) return FS_STATUS_NULL_POINTER;
    std::span<const TrajectoryPoint> points;
    if (const fs_status c = toCpp(trajectory, count, points); c != FS_STATUS_OK) return c;
    DangerStart start;
    const Status s = findPathApproach(points, toCpp(point), distance, from_time, until_time, start);
    if (s == Status::Ok) *out = fs_danger_start{start.ever ? 1 : 0, start.time};
    return toC(s);
}

fs_status fs_find_closest_path_approach(const fs_trajectory_point* trajectory, size_t count, fs_dvec3 point,
                                        float from_time, float until_time, fs_closest_approach* out) noexcept {
    if (out == nullptr) return FS_STATUS_NULL_POINTER;
    std::span<const TrajectoryPoint> points;
    if (const fs_status c = toCpp(trajectory, count, points); c != FS_STATUS_OK) return c;
    ClosestApproach approach;
    const Status s = findClosestPathApproach(points, toCpp(point), from_time, until_time, approach);
    if (s == Status::Ok) *out = fs_closest_approach{approach.distance, approach.time};
    return toC(s);
}

fs_vehicle_body fs_vehicle_body_default(void) noexcept {
    const VehicleBody d;
    const VehicleSettings& vs = d.settings;
    return fs_vehicle_body{toC(d.state), fs_vehicle_settings{static_cast<int32_t>(vs.frame), toC(vs.forward)},
                           toC(d.halfExtents), toC(d.boxCenter)};
}

fs_character_body fs_character_body_default(void) noexcept {
    const CharacterBody d;
    return fs_character_body{toCPosition(d.position), toC(d.velocity), toC(d.acceleration), d.radius, toC(d.halfAxis)};
}

fs_approach_settings fs_approach_settings_default(void) noexcept {
    const ApproachSettings d;
    return fs_approach_settings{d.tolerance, d.maxEvaluations};
}

fs_status fs_compute_vehicle_separation(const fs_vehicle_body* vehicle, const fs_character_body* character, float time,
                                        float* separation) noexcept {
    if (vehicle == nullptr || character == nullptr || separation == nullptr) return FS_STATUS_NULL_POINTER;
    VehicleBody body;
    if (!toCpp(*vehicle, body)) return FS_STATUS_INVALID_SETTING;
    float result = 0.0f;
    const Status s = computeVehicleSeparation(body, toCpp(*character), time, result);
    if (s == Status::Ok) *separation = result;
    return toC(s);
}

fs_status fs_find_vehicle_contact(const fs_vehicle_body* vehicle, const fs_character_body* character, float horizon,
                                  const fs_approach_settings* settings, fs_vehicle_contact* out) noexcept {
    if (vehicle == nullptr || character == nullptr || settings == nullptr || out == nullptr)
        return FS_STATUS_NULL_POINTER;
    VehicleBody body;
    if (!toCpp(*vehicle, body)) return FS_STATUS_INVALID_SETTING;
    VehicleContact contact;
    const Status s = findVehicleContact(body, toCpp(*character), horizon, toCpp(*settings), contact);
    if (s == Status::Ok)
        *out = fs_vehicle_contact{contact.contact ? 1 : 0, contact.time, contact.separation, contact.evaluations};
    return toC(s);
}

fs_status fs_find_closest_vehicle_approach(const fs_vehicle_body* vehicle, const fs_character_body* character,
                                           float horizon, const fs_approach_settings* settings,
                                           fs_closest_approach* out) noexcept {
    if (vehicle == nullptr || character == nullptr || settings == nullptr || out == nullptr)
        return FS_STATUS_NULL_POINTER;
    VehicleBody body;
    if (!toCpp(*vehicle, body)) return FS_STATUS_INVALID_SETTING;
    ClosestApproach approach;
    const Status s = findClosestVehicleApproach(body, toCpp(*character), horizon, toCpp(*settings), approach);
    if (s == Status::Ok) *out = fs_closest_approach{approach.distance, approach.time};
    return toC(s);
}

fs_throw_plan_request fs_throw_plan_request_default(void) noexcept {
    const ThrowPlanRequest d;
    fs_throw_plan_request r;
    r.start = toCPosition(d.start);
    r.target = toCPosition(d.target);
    r.acceptance_radius = d.acceptanceRadius;
    r.fuse_time = d.fuseTime;
    r.max_speed = d.maxSpeed;
    r.min_speed = d.minSpeed;
    r.settings = fs_projectile_settings_default();
    r.max_plans = d.maxPlans;
    r.distinct_angle = d.distinctAngle;
    const ThrowPlanBudget& b = d.budget;
    r.budget.azimuth_samples = b.azimuthSamples;
    r.budget.elevation_samples = b.elevationSamples;
    r.budget.speed_samples = b.speedSamples;
    r.budget.refinements = b.refinements;
    r.budget.refinement_predictions = b.refinementPredictions;
    r.budget.max_predictions = b.maxPredictions;
    r.budget.max_total_steps = b.maxTotalSteps;
    r.budget.grid_step = b.gridStep;
    std::copy(b.seedLandingFractions.begin(), b.seedLandingFractions.end(),
              std::begin(r.budget.seed_landing_fractions));
    return r;
}

size_t fs_throw_plan_scratch_size(const fs_throw_plan_request* request) noexcept {
    if (request == nullptr) return 0;
    ThrowPlanRequest cppRequest;
    if (!toCpp(*request, cppRequest)) return 0;
    return throwPlanScratchSize(cppRequest);
}

fs_status fs_plan_throw(const fs_throw_plan_request* request, const fs_world* world, fs_throw_plan* plans,
                        size_t capacity, fs_trajectory_point* scratch, size_t scratch_capacity,
                        fs_throw_plan_result* out) noexcept {
    if (request == nullptr || out == nullptr || (plans == nullptr && capacity > 0) ||
        (scratch == nullptr && scratch_capacity > 0))
        return FS_STATUS_NULL_POINTER;
    ThrowPlanRequest cppRequest;
    if (!toCpp(*request, cppRequest)) return FS_STATUS_INVALID_SETTING;
    // The plans are made in C++ layout on the stack, at most maxPlans of them up to a bound,
    // then converted. The scratch is the caller's buffer reused as C++ points (it is only
    // scratch: its contents are unspecified afterwards), as in fs_predict_projectile.
    constexpr std::size_t kMaxPlansAtOnce = 64;
    std::array<ThrowPlan, kMaxPlansAtOnce> found;
    const std::size_t wanted = std::min({capacity, found.size(), static_cast<std::size_t>(cppRequest.maxPlans)});
    std::span<TrajectoryPoint> cppScratch;
    if (scratch_capacity > 0) {
        auto* first = reinterpret_cast<TrajectoryPoint*>(static_cast<void*>(scratch));
        std::uninitialized_default_construct_n(first, scratch_capacity);
        cppScratch = std::span<TrajectoryPoint>(first, scratch_capacity);
    }
    std::optional<CheckedCallbackWorld> callbackWorld;
    const CollisionWorld* cppWorld = worldFor(world, callbackWorld);
    ThrowPlanResult result;
    const Status s = planThrow(cppRequest, cppWorld, std::span<ThrowPlan>(found.data(), wanted), cppScratch, result);
    if (callbackWorld && callbackWorld->invalid()) return FS_STATUS_INVALID_CALLBACK_HIT;
    if (s != Status::Ok) return toC(s);
    for (std::size_t i = 0; i < result.planCount; ++i) {
        const ThrowPlan& p = found[i];
        plans[i] = fs_throw_plan{
            toC(p.launchVelocity), p.distance,        toCPosition(p.finalPosition), p.bounces,
            p.atRest ? 1 : 0,      p.firstImpactTime, toC(p.firstImpactNormal),     toCPosition(p.firstImpactPosition)};
    }
    out->plan_count = result.planCount;
    out->predictions = result.predictions;
    out->closest_distance = result.closestDistance;
    out->closest_velocity = toC(result.closestVelocity);
    out->reserved = 0.0f;
    return FS_STATUS_OK;
}

fs_engine_profile fs_engine_profile_default(int32_t engine) noexcept {
    if (engine < FS_ENGINE_CUSTOM || engine > FS_ENGINE_BOX2D) engine = FS_ENGINE_CUSTOM;
    return toC(engineProfile(static_cast<PhysicsEngine>(engine)));
}

fs_engine_profile fs_engine_profile_ammo_js(void) noexcept { return toC(ammoJsProfile()); }

fs_status fs_validate_engine_profile(const fs_engine_profile* profile) noexcept {
    if (profile == nullptr) return FS_STATUS_NULL_POINTER;
    EngineProfile cppProfile;
    if (!toCpp(*profile, cppProfile)) return FS_STATUS_INVALID_SETTING;
    return toC(validateEngineProfile(cppProfile));
}

size_t fs_trajectory_capacity_with_profile(float time, const fs_projectile_settings* settings,
                                           const fs_engine_profile* profile) noexcept {
    if (settings == nullptr || profile == nullptr || !std::isfinite(time) || time < 0.0f) return 0;
    ProjectileSettings cppSettings;
    if (!toCpp(*settings, cppSettings) || !toCpp(*profile, cppSettings.engine)) return 0;
    if (validateEngineProfile(cppSettings.engine) != Status::Ok ||
        validateProjectileSettings(cppSettings) != Status::Ok)
        return 0;
    return trajectoryCapacity(time, cppSettings);
}

fs_status fs_rendered_position(const fs_trajectory_point* trajectory, size_t count, float step, float render_time,
                               int32_t smoothing, fs_dvec3* out) noexcept {
    if (out == nullptr) return FS_STATUS_NULL_POINTER;
    if (smoothing < FS_RENDER_NONE || smoothing > FS_RENDER_EXTRAPOLATE) return FS_STATUS_INVALID_SETTING;
    if (!std::isfinite(step) || step <= 0.0f) return FS_STATUS_INVALID_STEP;
    if (!std::isfinite(render_time)) return FS_STATUS_NON_FINITE_INPUT;
    if (count == 0) return FS_STATUS_INVALID_STEP;
    std::span<const TrajectoryPoint> points;
    if (const fs_status c = toCpp(trajectory, count, points); c != FS_STATUS_OK) return c;
    const RVec3 position = renderedPosition(points, step, render_time, static_cast<RenderSmoothing>(smoothing));
    if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z))
        return FS_STATUS_NON_FINITE_RESULT;
    *out = toCPosition(position);
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
