#pragma once
/// @file character.h
/// Short-horizon extrapolation of a point (a character, a target): constant velocity
/// `p + v t` and constant acceleration `p + v t + a t^2 / 2`. No collisions.

#include <foresight/status.h>

FORESIGHT_NAMESPACE_BEGIN

/// Position and velocity of a moving point, in world axes.
struct PointState {
    RVec3 position{0};  ///< [Units: m]
    Vec3 velocity{0};   ///< [Units: m/s]
};

/// Constant-velocity prediction: position `p + v t`, velocity unchanged.
/// @param start   the current state; every component must be finite.
/// @param time    prediction horizon [Units: s] [Limit: >= 0, finite].
/// @param out     receives the predicted state; left untouched unless Ok is returned.
/// @return Ok, NonFiniteInput, NegativeTime or NonFiniteResult.
Status predictLinear(const PointState& start, float time, PointState& out);

/// Constant-acceleration prediction: position `p + v t + a t^2 / 2`, velocity `v + a t`.
/// @param start         the current state; every component must be finite.
/// @param acceleration  constant acceleration in world axes [Units: m/s^2].
/// @param time          prediction horizon [Units: s] [Limit: >= 0, finite].
/// @param out           receives the predicted state; left untouched unless Ok is returned.
/// @return Ok, NonFiniteInput, NegativeTime or NonFiniteResult.
Status predictAccelerated(const PointState& start, Vec3 acceleration, float time, PointState& out);

FORESIGHT_NAMESPACE_END
