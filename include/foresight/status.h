#pragma once
/// @file status.h
/// Every function that can refuse its input returns a Status: foresight never throws and never
/// produces NaN from bad data; the refusal is reported also in release builds.

#include <foresight/config.h>

FORESIGHT_NAMESPACE_BEGIN

/// Result of a prediction or a world edit. `Status::Ok` is zero.
enum class Status : std::uint8_t {
    Ok = 0,              ///< Success.
    NonFiniteInput,      ///< A position, vector, quaternion or scalar is NaN or infinite.
    NegativeTime,        ///< A prediction time is below zero.
    InvalidStep,         ///< A time step is zero, negative or not finite.
    InvalidIterations,   ///< An iteration count is below 1 or above kMaxVehicleIterations.
    InvalidRestitution,  ///< Restitution is outside [0, 1].
    InvalidFriction,     ///< Friction is negative.
    InvalidRadius,       ///< A radius is negative (casts) or not positive (shapes).
    ZeroQuaternion,      ///< A quaternion has zero length and cannot be normalised.
    ZeroVector,          ///< A vector that must have a direction (normal, forward axis) is zero.
    DegenerateShape,     ///< A triangle with no area, a box with a non-positive half extent.
    TooManySteps,        ///< The prediction would take more steps than the settings' cap.
    TooManyEvents,       ///< The prediction hit its cap on bounces and contact changes.
    NonFiniteResult,     ///< The inputs are valid but so large that the result overflows.
    InvalidAlgorithm,    ///< A dead-reckoning algorithm outside the DIS enumeration (1 to 9).
    InvalidSpeed,        ///< A projectile speed (or speed cap) is zero, negative or not finite.
    InvalidFuse,         ///< A fuse time is zero, negative or not finite.
    InvalidSetting,      ///< A settings field is outside its documented range.
    TimeWentBackwards,   ///< A time is earlier than the one given to the previous call.
    NoUpdate,            ///< A receiver was asked for a pose before it accepted any update.
    OutOfRange,          ///< Beyond the precision envelope: a position farther than kMaxCoordinate
                         ///< on an axis or a speed above kMaxSpeed (config.h).
};

/// A short English description of `status`, e.g. "time must be >= 0". Never null.
const char* statusMessage(Status status);

FORESIGHT_NAMESPACE_END
