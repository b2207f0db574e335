#pragma once
/// @file orientation.h
/// Orientation predicted from a constant angular velocity, as an axis-angle quaternion.

#include <foresight/status.h>

FORESIGHT_NAMESPACE_BEGIN

/// The axes an angular velocity is expressed in.
enum class AngularFrame : std::uint8_t {
    /// The object's own (local) axes: `q' = q * r`, as the reference article composes it.
    Body,
    /// World axes: `q' = r * q`.
    World,
};

/// The rotation made by turning at `angularVelocity` [rad/s] for `time` [s]: an angle of
/// `|w| t` about the axis `w / |w|`. A zero (or underflowing) angular velocity gives the
/// identity, never NaN. Exact for small angles too (uses the half-angle sinc series).
/// Inputs must be finite; this is the unchecked building block of predictOrientation.
Quat rotationFromAngularVelocity(Vec3 angularVelocity, float time);

/// Applies `rotation` to `orientation` in the given frame: `orientation * rotation` (Body) or
/// `rotation * orientation` (World). The result is renormalised.
Quat composeRotation(Quat orientation, Quat rotation, AngularFrame frame);

/// Predicted orientation after `time` of constant angular velocity.
/// @param orientation      current orientation, local-to-world; normalised here, must be non-zero.
/// @param angularVelocity  [Units: rad/s], in the axes named by `frame`.
/// @param frame            Body (article, `q * r`) or World (`r * q`).
/// @param time             [Units: s] [Limit: >= 0, finite].
/// @param out              receives the unit quaternion; untouched unless Ok.
/// @return Ok, NonFiniteInput, ZeroQuaternion or NegativeTime.
Status predictOrientation(Quat orientation, Vec3 angularVelocity, AngularFrame frame, float time, Quat& out);

/// Normalises `q` into `out`; refuses a zero or non-finite quaternion (ZeroQuaternion,
/// NonFiniteInput). Public so that tools validate exactly as the predictors do.
Status normalizeQuaternion(Quat q, Quat& out);

FORESIGHT_NAMESPACE_END
