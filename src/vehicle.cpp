#include <foresight/vehicle.h>

#include "internal.h"

FORESIGHT_NAMESPACE_BEGIN
using namespace detail;

namespace {

struct PreparedVehicle {
    DVec3 position;
    DVec3 velocity;
    DQuat orientation;
    DVec3 angularVelocity;
    DVec3 forward;  // unit, local axes
    double speed;   // signed: negative when reversing
};

Status prepare(const VehicleState& start, float time, const VehicleSettings& settings, PreparedVehicle& out) {
    if (!isFinite(start.position) || !isFinite(start.velocity) || !isFinite(start.angularVelocity) ||
        !isFinite(settings.forward) || !isFinite(time))
        return Status::NonFiniteInput;
    Quat q;
    if (Status s = normalizeQuaternion(start.orientation, q); s != Status::Ok) return s;
    if (time < 0.0f) return Status::NegativeTime;
    const DVec3 forward = toD(settings.forward);
    const double forwardLength = glm::length(forward);
    if (!(forwardLength > 0.0)) return Status::ZeroVector;
    out.position = toD(start.position);
    out.velocity = toD(start.velocity);
    out.orientation = toD(q);
    out.angularVelocity = toD(start.angularVelocity);
    out.forward = forward / forwardLength;
    out.speed = signedVehicleSpeed(start.velocity, toF(out.orientation * out.forward));
    return Status::Ok;
}

Status finish(const DVec3& position, const DVec3& velocity, const DQuat& orientation, const VehicleState& start,
              VehicleState& out) {
    VehicleState result;
    result.position = toR(position);
    result.velocity = toF(velocity);
    result.orientation = toF(glm::normalize(orientation));
    result.angularVelocity = start.angularVelocity;
    if (!isFinite(result.position) || !isFinite(result.velocity) || !isFinite(result.orientation))
        return Status::NonFiniteResult;
    out = result;
    return Status::Ok;
}

DQuat compose(const DQuat& q, const DQuat& r, AngularFrame frame) {
    return glm::normalize(frame == AngularFrame::Body ? q * r : r * q);
}

}  // namespace

float signedVehicleSpeed(Vec3 velocity, Vec3 forwardWorld) {
    const double speed = glm::length(toD(velocity));
    return static_cast<float>(glm::dot(toD(velocity), toD(forwardWorld)) < 0.0 ? -speed : speed);
}

Status predictVehicleIterative(const VehicleState& start, float time, int iterations, const VehicleSettings& settings,
                               VehicleState& out) {
    if (iterations < 1 || iterations > kMaxVehicleIterations) return Status::InvalidIterations;
    PreparedVehicle v;
    if (Status s = prepare(start, time, settings, v); s != Status::Ok) return s;
    const double dt = static_cast<double>(time) / iterations;
    const DQuat stepRotation = rotationFromAngularVelocityD(v.angularVelocity, dt);
    for (int i = 0; i < iterations; ++i) {
        // Move with the current velocity, turn, then put the velocity on the new forward axis.
        v.position += v.velocity * dt;
        v.orientation = compose(v.orientation, stepRotation, settings.frame);
        v.velocity = (v.orientation * v.forward) * v.speed;
    }
    return finish(v.position, v.velocity, v.orientation, start, out);
}

Status predictVehicleExact(const VehicleState& start, float time, const VehicleSettings& settings, VehicleState& out) {
    PreparedVehicle v;
    if (Status s = prepare(start, time, settings, v); s != Status::Ok) return s;
    const double t = time;
    const DVec3& w = v.angularVelocity;
    const double x = glm::length(w) * t;  // total turn angle
    // Integral of the rotation exp(s [w]x) over s in [0, t], applied to a unit vector f:
    //   t f + (1 - cos x)/|w|^2 (w x f) + (t - sin(x)/|w|)/|w|^2 (w x (w x f)),
    // with the coefficients written as t^2 sinc(x/2)^2 / 2 and t^3 (x - sin x)/x^3 so that
    // they need no division by |w| and stay exact as |w| -> 0.
    const double s = sinc(0.5 * x);
    const double c1 = 0.5 * t * t * s * s;
    const double c2 = t * t * t * xMinusSinOverCube(x);
    // Body frame: the motion is the local forward axis turned by w in local axes, then rotated
    // into the world. World frame: the world forward axis turned by w in world axes.
    const bool body = settings.frame == AngularFrame::Body;
    const DVec3 f = body ? v.forward : v.orientation * v.forward;
    const DVec3 wxf = glm::cross(w, f);
    DVec3 displacement = (t * f + c1 * wxf + c2 * glm::cross(w, wxf)) * v.speed;
    if (body) displacement = v.orientation * displacement;
    const DQuat orientation = compose(v.orientation, rotationFromAngularVelocityD(w, t), settings.frame);
    const DVec3 velocity = (orientation * v.forward) * v.speed;
    return finish(v.position + displacement, velocity, orientation, start, out);
}

FORESIGHT_NAMESPACE_END
