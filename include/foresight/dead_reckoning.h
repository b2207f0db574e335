#pragma once
/// @file dead_reckoning.h
/// Network dead reckoning: the nine IEEE 1278.1 (DIS) models that extrapolate a replicated
/// entity from its last state update.
///
/// Names follow DIS: DRM(F|R, P|V, W|B). F: fixed orientation, R: rotating (the angular
/// velocity is applied). P: constant velocity, V: constant acceleration as well. W: velocity and
/// acceleration in world axes; B: in the entity's body axes.
///
/// Frames, as DIS defines them:
/// - `orientation` is body-to-world (a body vector `b` is `orientation * b` in world axes);
/// - `angularVelocity` is in body axes, so the orientation after `t` is
///   `orientation * exp(angularVelocity t)` (the axis-angle quaternion, exact, no NaN at zero);
/// - `*W`: `velocity`, `acceleration` are in world axes; position `p + v t (+ a t^2 / 2)`;
/// - `*B`: `velocity`, `acceleration` are in body axes at time 0. The body-axis velocity grows
///   as `v + a t` in the rotating body axes, so the world displacement is
///   `orientation * (R1 v + R2 a)` with R1 = integral over [0, t] of exp([w]x s) ds and
///   R2 = integral over [0, t] of s exp([w]x s) ds (the closed forms of IEEE 1278.1; see
///   predictDeadReckoning). F*B models use R1 = t I and R2 = t^2/2 I (no rotation).
///
/// The output velocity is in the same axes as the input's: world axes for `*W`, body axes for
/// `*B` (the body axes of the output orientation, which the input called "time 0"), so an
/// output can be fed back in as the next input: extrapolating `t1` then `t2` is extrapolating
/// `t1 + t2`, for all nine models (each is the flow of an autonomous differential equation).
///
/// Positions are `RVec3`: DIS positions are geocentric (about 6.4e6 m from the origin), where a
/// float resolves only 0.5 m; use the double build (FORESIGHT_DOUBLE_PRECISION) for them.
/// Everything is computed in double internally. No call allocates.

#include <foresight/status.h>

#include <string_view>

FORESIGHT_NAMESPACE_BEGIN

/// The DIS dead-reckoning algorithms; the values are the DIS enumeration (1 to 9).
enum class DeadReckoningAlgorithm : std::uint8_t {
    Static = 1,  ///< DRM 1, STATIC: the entity does not move or turn.
    Fpw = 2,     ///< DRM 2, FPW: fixed orientation, constant world velocity.
    Rpw = 3,     ///< DRM 3, RPW: rotating, constant world velocity.
    Rvw = 4,     ///< DRM 4, RVW: rotating, constant world acceleration.
    Fvw = 5,     ///< DRM 5, FVW: fixed orientation, constant world acceleration.
    Fpb = 6,     ///< DRM 6, FPB: fixed orientation, constant body velocity.
    Rpb = 7,     ///< DRM 7, RPB: rotating, constant body velocity (turns with the body).
    Rvb = 8,     ///< DRM 8, RVB: rotating, constant body acceleration (turns with the body).
    Fvb = 9,     ///< DRM 9, FVB: fixed orientation, constant body acceleration.
};

/// The number of DIS dead-reckoning algorithms (Static to Fvb).
inline constexpr int kDeadReckoningAlgorithmCount = 9;

/// The state an entity last reported (a DIS entity state update), the input of a prediction.
struct DeadReckoningState {
    DeadReckoningAlgorithm algorithm = DeadReckoningAlgorithm::Fpw;  ///< the model to extrapolate with.
    RVec3 position{0};                                               ///< [Units: m], world axes (geocentric in DIS).
    Vec3 velocity{0};                          ///< [Units: m/s]; world axes (`*W`) or body axes at time 0 (`*B`).
    Vec3 acceleration{0};                      ///< [Units: m/s^2]; axes as `velocity`; used by RVW, FVW, RVB, FVB only.
    Quat orientation = glm::identity<Quat>();  ///< body-to-world; normalised here, must be non-zero.
    Vec3 angularVelocity{0};                   ///< [Units: rad/s], body axes; used by RPW, RVW, RPB, RVB only.
};

/// The extrapolated state.
struct DeadReckoningResult {
    RVec3 position{0};                         ///< [Units: m], world axes.
    Vec3 velocity{0};                          ///< [Units: m/s], in the input velocity's axes
                                               ///< (world for `*W`, body for `*B`).
    Quat orientation = glm::identity<Quat>();  ///< body-to-world, unit.
};

/// The DIS name of `algorithm`: "STATIC", "FPW", "RPW", "RVW", "FVW", "FPB", "RPB", "RVB" or
/// "FVB"; "?" for a value outside the enumeration. Never null.
const char* deadReckoningAlgorithmName(DeadReckoningAlgorithm algorithm);

/// Finds the algorithm called `name` (exactly as deadReckoningAlgorithmName spells it).
/// @return true and sets `out` when found; false (out untouched) otherwise.
bool findDeadReckoningAlgorithm(std::string_view name, DeadReckoningAlgorithm& out);

/// True for the models that apply the angular velocity (RPW, RVW, RPB, RVB).
bool deadReckoningRotates(DeadReckoningAlgorithm algorithm);

/// True for the models that use the acceleration (RVW, FVW, RVB, FVB).
bool deadReckoningUsesAcceleration(DeadReckoningAlgorithm algorithm);

/// True for the body-axis models (FPB, RPB, RVB, FVB): velocity and acceleration in body axes.
bool deadReckoningInBodyAxes(DeadReckoningAlgorithm algorithm);

/// Checks a state as predictDeadReckoning does (every field, whether its model uses it or not,
/// so that a state is valid whatever model is later chosen).
/// @return Ok, InvalidAlgorithm (not one of the nine), NonFiniteInput or ZeroQuaternion.
Status validateDeadReckoningState(const DeadReckoningState& state);

/// Extrapolates `state` by `time` with its algorithm.
///
/// - STATIC: everything as given (the velocity is echoed, as DIS receivers leave it).
/// - FPW, RPW: `p + v t`; FVW, RVW: `p + v t + a t^2 / 2`, velocity `v + a t`.
/// - FPB: `p + q (v t)`; FVB: `p + q (v t + a t^2 / 2)`, velocity `v + a t` (body axes).
/// - RPB: `p + q (R1 v)`; RVB: `p + q (R1 v + R2 a)`, velocity `v + a t` (body axes), with,
///   for w the angular velocity, x = |w| t and [w]x the cross-product matrix (w x .):
///   R1 = sin(x)/|w| I + (1 - cos x)/|w|^2 [w]x + (x - sin x)/|w|^3 w w^T,
///   R2 = (cos x + x sin x - 1)/|w|^2 I + (sin x - x cos x)/|w|^3 [w]x
///        + (x^2/2 - x sin x - cos x + 1)/|w|^4 w w^T.
///   The coefficients are evaluated as t, t^2, t^3, t^4 times functions of x with series near
///   0, so they are exact for any small or zero |w| (R1 -> t I, R2 -> t^2/2 I).
/// - R*: orientation `q * exp(w t)`; F* and STATIC: `q`.
///
/// @param state  the last update; validated with validateDeadReckoningState.
/// @param time   [Units: s] [Limit: >= 0, finite], since the update's timestamp.
/// @param out    receives the extrapolated state; untouched unless Ok.
/// @return Ok, InvalidAlgorithm, NonFiniteInput, ZeroQuaternion, NegativeTime or
///         NonFiniteResult (finite inputs so large that the result overflows).
Status predictDeadReckoning(const DeadReckoningState& state, float time, DeadReckoningResult& out);

FORESIGHT_NAMESPACE_END
