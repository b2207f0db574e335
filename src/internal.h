#pragma once
// Private helpers shared by the implementation files (not installed).

#include <foresight/config.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {

// Internal computations run in double whatever Real is: the predictors' cost is dominated by
// the world queries, and double keeps the exact methods exact to far below float resolution.
using DVec3 = glm::dvec3;
using DQuat = glm::dquat;

inline bool isFinite(float x) { return std::isfinite(x); }
inline bool isFinite(double x) { return std::isfinite(x); }
template <int N, class T>
inline bool isFinite(const glm::vec<N, T, glm::defaultp>& v) {
    for (int i = 0; i < N; ++i)
        if (!std::isfinite(v[i])) return false;
    return true;
}
inline bool isFinite(const Quat& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

inline DVec3 toD(const Vec3& v) { return DVec3(v); }
#ifdef FORESIGHT_DOUBLE_PRECISION
inline DVec3 toD(const RVec3& v) { return v; }
#endif
inline RVec3 toR(const DVec3& v) { return RVec3(v); }
inline Vec3 toF(const DVec3& v) { return Vec3(v); }

inline DQuat toD(const Quat& q) {
    DQuat r;
    r.w = q.w;
    r.x = q.x;
    r.y = q.y;
    r.z = q.z;
    return r;
}
inline Quat toF(const DQuat& q) {
    Quat r;
    r.w = static_cast<float>(q.w);
    r.x = static_cast<float>(q.x);
    r.y = static_cast<float>(q.y);
    r.z = static_cast<float>(q.z);
    return r;
}

// Signed distance from `o` (in the box's frame) to the box [-h, h] grown by `radius`, and the
// outward unit normal of the closest feature (a face's axis where `o` is inside).
inline double boxSignedDistance(const DVec3& o, const DVec3& h, double radius, DVec3& outward) {
    const DVec3 qd = glm::abs(o) - h;
    const DVec3 outsidePart = glm::max(qd, DVec3(0.0));
    const double outsideLength = glm::length(outsidePart);
    if (outsideLength > 0.0) {
        outward = outsidePart * glm::sign(o) / outsideLength;
        return outsideLength - radius;
    }
    const int axis = (qd.x >= qd.y && qd.x >= qd.z) ? 0 : (qd.y >= qd.z ? 1 : 2);
    outward = DVec3(0.0);
    outward[axis] = o[axis] < 0.0 ? -1.0 : 1.0;
    return qd[axis] - radius;
}

// The largest absolute coordinate of p, at least 1: the scale of p's rounding errors.
inline double coordinateMagnitude(const DVec3& p) {
    return std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

// Units in the last place of Real at p's magnitude, times `ulps`.
inline double realUlps(const DVec3& p, double ulps) {
    return ulps * coordinateMagnitude(p) * static_cast<double>(std::numeric_limits<Real>::epsilon());
}

// The value a person meant by a float: the shortest decimal (at most 9 fractional digits)
// that rounds to it, as a double (0.02f is 0.0199999995529651641845703125; this returns 0.02).
// Used for time steps and times, so that step k lands at k * 0.02 s and not at 0.099999994 s, while staying deterministic.
double decimalValue(float x);

// The rotation of angle |w| t about w / |w| in double, exact for small angles (no NaN at 0).
DQuat rotationFromAngularVelocityD(const DVec3& angularVelocity, double time);

// Series-guarded coefficients of the rotation integrals (the vehicle's closed-form arc, the
// dead-reckoning body-axis integrals).

// sin(x) / x, exact near 0.
inline double sinc(double x) {
    if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;  // next term x^4/120 < 1e-18
    return std::sin(x) / x;
}

// (x - sin x) / x^3, exact near 0 (the direct form cancels catastrophically there).
inline double xMinusSinOverCube(double x) {
    if (std::abs(x) < 0.5) {
        const double x2 = x * x;
        // Taylor series; the first omitted term, x^10 / 13!, is below 1.5e-13 * 2^-10 here.
        return 1.0 / 6.0 - x2 * (1.0 / 120.0 - x2 * (1.0 / 5040.0 - x2 * (1.0 / 362880.0 - x2 / 39916800.0)));
    }
    return (x - std::sin(x)) / (x * x * x);
}

}  // namespace detail
FORESIGHT_NAMESPACE_END
