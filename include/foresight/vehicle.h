#pragma once
/// @file vehicle.h
/// Vehicle prediction: the position and orientation of a body that turns at a constant angular
/// velocity and whose velocity follows its forward axis (a car, a tank, a boat).
///
/// Two methods:
/// - predictVehicleIterative: the reference article's loop. N equal steps; each moves with the
///   current velocity, turns by the angular velocity, then puts the velocity on the new forward
///   axis with the same speed. The first step moves with the given velocity. First-order: the
///   error shrinks as 1/N (the article's 4 steps are about 2 m off for 10 m/s, 0.5 rad/s, 2 s).
/// - predictVehicleExact: the closed form of the same motion with the velocity on the forward
///   axis from the start: the displacement is the orientation applied to
///   `(t I + (1 - cos wt)/w [k]x + (t - sin(wt)/w) [k]x^2) * forward * speed`
///   (k the unit rotation axis, [k]x its cross-product matrix), with series for small `w t`.
///
/// Speed is `|velocity|`, negated when the vehicle moves backwards (`dot(velocity, forward) < 0`
/// at the start): a reversing vehicle keeps reversing.

#include <foresight/orientation.h>

FORESIGHT_NAMESPACE_BEGIN

/// The kinematic state of a vehicle.
struct VehicleState {
    RVec3 position{0};                         ///< [Units: m], world axes.
    Vec3 velocity{0};                          ///< [Units: m/s], world axes.
    Quat orientation = glm::identity<Quat>();  ///< local-to-world, unit.
    Vec3 angularVelocity{0};                   ///< [Units: rad/s], in the axes of VehicleSettings::frame.
};

/// The largest iteration count predictVehicleIterative accepts (caps the work of one call).
inline constexpr int kMaxVehicleIterations = 1 << 20;

/// How to interpret a VehicleState.
struct VehicleSettings {
    AngularFrame frame = AngularFrame::Body;  ///< axes of the angular velocity.
    Vec3 forward{0.0f, 0.0f, 1.0f};           ///< local forward axis (unit, non-zero; article: +Z).
};

/// The signed speed of a vehicle: `|velocity|`, negative when it moves backwards relative to
/// `forwardWorld` (the forward axis in world axes).
float signedVehicleSpeed(Vec3 velocity, Vec3 forwardWorld);

/// The article's iterated linear + rotational loop.
/// @param start       current state (finite, non-zero orientation).
/// @param time        [Units: s] [Limit: >= 0, finite].
/// @param iterations  [Limit: 1 .. kMaxVehicleIterations]; the article uses 4.
/// @param out         receives the state after `time`; velocity is on the final forward axis.
/// @return Ok, NonFiniteInput, NegativeTime, InvalidIterations, ZeroQuaternion, ZeroVector or
///         NonFiniteResult.
Status predictVehicleIterative(const VehicleState& start, float time, int iterations, const VehicleSettings& settings,
                               VehicleState& out);

/// The exact arc of the article's model (constant angular velocity, velocity on the forward
/// axis with constant signed speed). Costs about as much as two loop iterations.
/// @return Ok, NonFiniteInput, NegativeTime, ZeroQuaternion, ZeroVector or NonFiniteResult.
Status predictVehicleExact(const VehicleState& start, float time, const VehicleSettings& settings, VehicleState& out);

FORESIGHT_NAMESPACE_END
