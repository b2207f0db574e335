#pragma once
/// @file unreal.h
/// Conversions between Unreal Engine's coordinates and foresight's, for any type shaped like
/// Unreal's FVector (members X, Y, Z) and FQuat (members X, Y, Z, W). No Unreal header is
/// needed: the functions are templates, so the same code takes FVector (double in Unreal 5,
/// float in Unreal 4), FVector3f or a type of your own.
///
/// Unreal: centimetres, +Z up, +X forward, +Y right (left-handed). foresight: metres, +Y up,
/// +Z forward, +X right. The axes map as Unreal X -> foresight Z, Y -> X, Z -> Y: a cyclic
/// permutation, which is a rotation, so handedness, cross products and the sense of rotations
/// carry over unchanged (a positive yaw about Unreal's +Z, which turns +X towards +Y, becomes a
/// positive rotation about foresight's +Y, which turns +Z towards +X). Only lengths are scaled:
/// 1 Unreal unit = 1 cm = 0.01 m. Directions, normals, angular velocities [rad/s] and rotations
/// are only permuted; time is in seconds in both.
///
/// A vehicle facing Unreal's +X faces foresight's +Z, VehicleSettings' default forward axis.
/// Unreal's physics reports angular velocity in world axes (e.g.
/// `GetPhysicsAngularVelocityInRadians`): predict with `VehicleSettings::frame =
/// AngularFrame::World`, or turn it into the body's axes first.
///
/// Example (in an Unreal module that links foresight):
/// @code
///   using namespace foresight;
///   ProjectileSettings settings;
///   settings.gravity = unreal::toAcceleration(FVector(0, 0, GetWorld()->GetGravityZ()));
///   ProjectileResult result;
///   predictProjectile(unreal::toPosition(Hand), unreal::toVelocity(ThrowVelocity), 3.0f, settings,
///                     &world, trajectory, result);
///   const FVector Landing = unreal::fromPosition<FVector>(result.position);
/// @endcode

#include <foresight/config.h>

#include <concepts>

FORESIGHT_NAMESPACE_BEGIN

/// Unreal Engine coordinates (Z up, X forward, centimetres) to and from foresight's.
namespace unreal {

/// Metres per Unreal unit (1 uu = 1 cm).
inline constexpr double kMetresPerUnit = 0.01;
/// Unreal units per metre.
inline constexpr double kUnitsPerMetre = 100.0;
/// Unreal's default gravity, along its -Z [Units: cm/s^2] (UPhysicsSettings::DefaultGravityZ).
inline constexpr double kDefaultGravityZ = -980.0;

/// A type shaped like FVector: members X, Y, Z convertible to double.
template <typename V>
concept VectorLike = requires(const V& v) {
    {static_cast<double>(v.X)};
    {static_cast<double>(v.Y)};
    {static_cast<double>(v.Z)};
};

/// A type shaped like FQuat: members X, Y, Z, W convertible to double (W: the scalar part).
template <typename Q>
concept QuatLike = requires(const Q& q) {
    {static_cast<double>(q.X)};
    {static_cast<double>(q.Y)};
    {static_cast<double>(q.Z)};
    {static_cast<double>(q.W)};
};

namespace detail {
/// foresight's (x, y, z) from Unreal's (X, Y, Z) times `scale`: x = Y, y = Z, z = X.
template <typename Out, VectorLike V>
Out permuteIn(const V& v, double scale) {
    using S = typename Out::value_type;
    return Out(static_cast<S>(static_cast<double>(v.Y) * scale), static_cast<S>(static_cast<double>(v.Z) * scale),
               static_cast<S>(static_cast<double>(v.X) * scale));
}
/// Unreal's (X, Y, Z) from foresight's (x, y, z) times `scale`: X = z, Y = x, Z = y.
template <typename V, typename In>
V permuteOut(const In& v, double scale) {
    using S = decltype(V{}.X);
    return V(static_cast<S>(static_cast<double>(v.z) * scale), static_cast<S>(static_cast<double>(v.x) * scale),
             static_cast<S>(static_cast<double>(v.y) * scale));
}
}  // namespace detail

/// A position [Units: Unreal cm, Unreal axes] as foresight's [Units: m, foresight axes].
template <VectorLike V>
RVec3 toPosition(const V& position) {
    return detail::permuteIn<RVec3>(position, kMetresPerUnit);
}

/// A velocity [Units: cm/s, Unreal axes] as foresight's [Units: m/s].
template <VectorLike V>
Vec3 toVelocity(const V& velocity) {
    return detail::permuteIn<Vec3>(velocity, kMetresPerUnit);
}

/// An acceleration, e.g. gravity [Units: cm/s^2, Unreal axes] as foresight's [Units: m/s^2].
template <VectorLike V>
Vec3 toAcceleration(const V& acceleration) {
    return detail::permuteIn<Vec3>(acceleration, kMetresPerUnit);
}

/// A length-free vector (a direction, a normal, an axis, an angular velocity [rad/s]) in
/// foresight's axes: permuted, not scaled.
template <VectorLike V>
Vec3 toDirection(const V& direction) {
    return detail::permuteIn<Vec3>(direction, 1.0);
}

/// A rotation (Unreal's FQuat, local-to-world) as foresight's Quat: the same rotation in
/// foresight's axes (the scalar part stays, the vector part is permuted like a direction).
template <QuatLike Q>
Quat toRotation(const Q& rotation) {
    Quat q;
    q.w = static_cast<float>(static_cast<double>(rotation.W));
    q.x = static_cast<float>(static_cast<double>(rotation.Y));
    q.y = static_cast<float>(static_cast<double>(rotation.Z));
    q.z = static_cast<float>(static_cast<double>(rotation.X));
    return q;
}

/// A foresight position [Units: m] as Unreal's [Units: cm]; V must be constructible from
/// (X, Y, Z), as FVector is.
template <VectorLike V>
V fromPosition(const RVec3& position) {
    return detail::permuteOut<V>(position, kUnitsPerMetre);
}

/// A foresight velocity [Units: m/s] as Unreal's [Units: cm/s].
template <VectorLike V>
V fromVelocity(const Vec3& velocity) {
    return detail::permuteOut<V>(velocity, kUnitsPerMetre);
}

/// A foresight acceleration [Units: m/s^2] as Unreal's [Units: cm/s^2].
template <VectorLike V>
V fromAcceleration(const Vec3& acceleration) {
    return detail::permuteOut<V>(acceleration, kUnitsPerMetre);
}

/// A foresight direction, normal or angular velocity [rad/s] in Unreal's axes (not scaled).
template <VectorLike V>
V fromDirection(const Vec3& direction) {
    return detail::permuteOut<V>(direction, 1.0);
}

/// A foresight rotation as Unreal's; Q must be constructible from (X, Y, Z, W), as FQuat is.
template <QuatLike Q>
Q fromRotation(const Quat& rotation) {
    using S = decltype(Q{}.X);
    return Q(static_cast<S>(rotation.z), static_cast<S>(rotation.x), static_cast<S>(rotation.y),
             static_cast<S>(rotation.w));
}

/// Gravity along Unreal's Z (World->GetGravityZ(), [Units: cm/s^2], negative: down) as a
/// foresight acceleration [Units: m/s^2]: (0, gravityZ / 100, 0).
inline Vec3 gravityFromZ(double gravityZ = kDefaultGravityZ) {
    return Vec3(0.0f, static_cast<float>(gravityZ * kMetresPerUnit), 0.0f);
}

}  // namespace unreal

FORESIGHT_NAMESPACE_END
