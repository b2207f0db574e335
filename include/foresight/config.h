#pragma once
/// @file config.h
/// The one place where foresight's numeric types are chosen.
///
/// Axes and units used everywhere in foresight: metres, seconds, radians; +Y is up and +Z is
/// forward by default (as in the reference article); a vehicle's forward axis is configurable.
///
/// Positions are `RVec3`: float by default, double when the library is built with
/// `FORESIGHT_DOUBLE_PRECISION` (CMake option of the same name; the definition is PUBLIC on the
/// `foresight::foresight` target, so consumers see the same type). Everything else (velocities,
/// accelerations, normals, quaternions, times) stays float, as in Jolt Physics' `RVec3`.
/// The two builds live in different inline namespaces, so mixing them fails at link time
/// instead of corrupting memory.

#include <cstdint>
#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#if defined(GLM_FORCE_QUAT_DATA_XYZW) || defined(GLM_FORCE_QUAT_DATA_WXYZ)
#error "foresight is built with GLM's default quaternion layout; do not force another one"
#endif

/// Library version (semantic versioning).
#define FORESIGHT_VERSION_MAJOR 0
#define FORESIGHT_VERSION_MINOR 1
#define FORESIGHT_VERSION_PATCH 0
/// Library version as a string, e.g. "0.1.0".
#define FORESIGHT_VERSION_STRING "0.1.0"

#ifdef FORESIGHT_DOUBLE_PRECISION
#define FORESIGHT_ABI_NAMESPACE abi_v0_f64
#else
#define FORESIGHT_ABI_NAMESPACE abi_v0_f32
#endif

/// Opens the foresight namespace (with the precision-tagged inline namespace).
#define FORESIGHT_NAMESPACE_BEGIN \
    namespace foresight {         \
    inline namespace FORESIGHT_ABI_NAMESPACE {
/// Closes what FORESIGHT_NAMESPACE_BEGIN opened.
#define FORESIGHT_NAMESPACE_END \
    }                           \
    }

FORESIGHT_NAMESPACE_BEGIN

#ifdef FORESIGHT_DOUBLE_PRECISION
/// Scalar type of world positions [Units: m]: double in this build.
using Real = double;
#else
/// Scalar type of world positions [Units: m]: float in this build.
using Real = float;
#endif

/// A world position [Units: m]. Double when FORESIGHT_DOUBLE_PRECISION is defined.
using RVec3 = glm::vec<3, Real, glm::defaultp>;
/// A direction, velocity [m/s], acceleration [m/s^2], angular velocity [rad/s] or normal.
using Vec3 = glm::vec3;
/// A rotation (unit quaternion). Build it with glm::angleAxis or named components, never with
/// the four-float constructor, whose argument order depends on GLM's configuration.
using Quat = glm::quat;

/// True when positions are double precision in this build.
inline constexpr bool kDoublePrecision = sizeof(Real) == sizeof(double);

/// The precision envelope, distances: predictions whose positions (start, trajectory, end, aim
/// shooter and target) reach beyond this on any axis are refused with Status::OutOfRange
/// [Units: m]. Double-precision builds: 1e8 m. Computation is in double and its rounding grows
/// with the distance from the origin: a bouncing throw ends about 2e-14 |x| from where the same
/// throw ends at the origin (measured: 2e-6 m at 1e8 m, 0.02 m at 1e12 m, tens of meters at
/// 1e16 m). Default (float) builds: 1e5 m, where a float position's step is 8 mm; the positions'
/// own rounding then moves results, and bounces amplify it (measured on a 3 s throw with five
/// bounces and friction: 9 mm at 1 km, 0.15 m at 16 km, 0.6 m at 65 km): keep float worlds
/// within a few km of the origin, or build with FORESIGHT_DOUBLE_PRECISION.
inline constexpr double kMaxCoordinate = kDoublePrecision ? 1.0e8 : 1.0e5;

static_assert(sizeof(Vec3) == 3 * sizeof(float), "GLM must be configured with packed vec3");
static_assert(sizeof(Quat) == 4 * sizeof(float), "GLM must be configured with packed quat");
static_assert(sizeof(RVec3) == 3 * sizeof(Real), "GLM must be configured with packed vec3");

/// The precision envelope, speeds: a start velocity or aim speed faster than this is refused
/// with Status::OutOfRange [Units: m/s] (a rifle bullet flies about 1e3 m/s).
inline constexpr double kMaxSpeed = 1.0e6;

/// The gravity foresight's settings default to, along -Y [Units: m/s^2]: 9.81, the value of the
/// reference article and Unity's default. It is the rounded figure most games use, not standard
/// gravity (9.80665 m/s^2 by definition); set the settings' `gravity` for any other value.
inline constexpr float kDefaultGravity = 9.81f;

/// Version of the library that was compiled (may differ from the headers if mismatched).
const char* versionString();

FORESIGHT_NAMESPACE_END
