#include <foresight/orientation.h>

#include "internal.h"

FORESIGHT_NAMESPACE_BEGIN
using namespace detail;

namespace detail {
DQuat rotationFromAngularVelocityD(const DVec3& angularVelocity, double time) {
    // q = (cos(|w| t / 2), sin(|w| t / 2) * w / |w|). Written with sinc so that a zero or tiny
    // angular velocity gives the identity (the article normalises a zero vector: NaN).
    const double rate = glm::length(angularVelocity);
    const double half = 0.5 * rate * time;
    double sincHalf;  // sin(half) / half
    if (std::abs(half) < 1e-4)
        sincHalf = 1.0 - half * half / 6.0;  // next term half^4/120 < 1e-18: below double eps
    else
        sincHalf = std::sin(half) / half;
    DQuat q;
    q.w = std::cos(half);
    const DVec3 xyz = angularVelocity * (0.5 * time * sincHalf);
    q.x = xyz.x;
    q.y = xyz.y;
    q.z = xyz.z;
    return q;
}
}  // namespace detail

Quat rotationFromAngularVelocity(Vec3 angularVelocity, float time) {
    return toF(rotationFromAngularVelocityD(toD(angularVelocity), time));
}

Quat composeRotation(Quat orientation, Quat rotation, AngularFrame frame) {
    const DQuat q = toD(orientation);
    const DQuat r = toD(rotation);
    return toF(glm::normalize(frame == AngularFrame::Body ? q * r : r * q));
}

Status normalizeQuaternion(Quat q, Quat& out) {
    if (!isFinite(q)) return Status::NonFiniteInput;
    const DQuat d = toD(q);
    const double length = std::sqrt(d.w * d.w + d.x * d.x + d.y * d.y + d.z * d.z);
    if (!(length > 0.0) || !std::isfinite(length)) return Status::ZeroQuaternion;
    out = toF(d * (1.0 / length));
    return Status::Ok;
}

Status predictOrientation(Quat orientation, Vec3 angularVelocity, AngularFrame frame, float time, Quat& out) {
    if (!isFinite(angularVelocity) || !isFinite(time)) return Status::NonFiniteInput;
    Quat q;
    if (Status s = normalizeQuaternion(orientation, q); s != Status::Ok) return s;
    if (time < 0.0f) return Status::NegativeTime;
    const DQuat r = rotationFromAngularVelocityD(toD(angularVelocity), time);
    const DQuat qd = toD(q);
    out = toF(glm::normalize(frame == AngularFrame::Body ? qd * r : r * qd));
    return Status::Ok;
}

FORESIGHT_NAMESPACE_END
