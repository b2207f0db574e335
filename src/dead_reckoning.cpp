#include <foresight/dead_reckoning.h>

#include <foresight/orientation.h>

#include "internal.h"

FORESIGHT_NAMESPACE_BEGIN
using namespace detail;

namespace {

constexpr const char* kAlgorithmNames[kDeadReckoningAlgorithmCount] = {"STATIC", "FPW", "RPW", "RVW", "FVW",
                                                                       "FPB",    "RPB", "RVB", "FVB"};

bool isAlgorithm(DeadReckoningAlgorithm algorithm) {
    const int value = static_cast<int>(algorithm);
    return value >= 1 && value <= kDeadReckoningAlgorithmCount;
}

// (x^2/2 - x sin x - cos x + 1) / x^4, the w w^T coefficient of R2 divided by t^4.
double secondIntegralAxialCoefficient(double x) {
    const double x2 = x * x;
    if (std::abs(x) < 1.0) {
        // Taylor series sum over m >= 2 of (-1)^m (2m - 1)/(2m)! x^(2m - 4); the direct form
        // loses all digits as x -> 0 (four terms of size 1 cancel down to x^4/8). The first
        // omitted term, 21/22! x^18, is below 1.9e-20: under double rounding of the 1/8 here.
        return 1.0 / 8.0 -
               x2 * (1.0 / 144.0 -
                     x2 * (1.0 / 5760.0 -
                           x2 * (1.0 / 403200.0 -
                                 x2 * (1.0 / 43545600.0 -
                                       x2 * (1.0 / 6706022400.0 -
                                             x2 * (1.0 / 1394852659200.0 -
                                                   x2 * (1.0 / 376610217984000.0 - x2 / 128047474114560000.0)))))));
    }
    // For |x| >= 1 the numerator is >= 0.118 while its terms are O(x^2): a few ulps at most.
    return (0.5 * x2 - x * std::sin(x) - std::cos(x) + 1.0) / (x2 * x2);
}

// The body-axis displacement R1 v + R2 a for angular velocity w over time t, where
//   R1 = integral_0^t exp([w]x s) ds,  R2 = integral_0^t s exp([w]x s) ds,
// [w]x the cross-product matrix (w x .). With exp([w]x s) = cos(|w|s) I + sin(|w|s)/|w| [w]x
// + (1 - cos(|w|s))/|w|^2 w w^T, integrating term by term gives (x = |w| t)
//   R1 = t sinc(x) I + t^2 (1 - cos x)/x^2 [w]x + t^3 (x - sin x)/x^3 w w^T
//   R2 = t^2 (x sin x + cos x - 1)/x^2 I + t^3 (sin x - x cos x)/x^3 [w]x
//        + t^4 (x^2/2 - x sin x - cos x + 1)/x^4 w w^T,
// the forms of IEEE 1278.1 with every |w|^-k folded into a bounded function of x. The
// functions of x are built from sinc and (x - sin x)/x^3 (exact near 0):
//   (1 - cos x)/x^2 = sinc(x/2)^2 / 2,
//   (x sin x + cos x - 1)/x^2 = sinc(x) - sinc(x/2)^2 / 2          (-> 1/2),
//   (sin x - x cos x)/x^3 = sinc(x/2)^2 / 2 - (x - sin x)/x^3      (-> 1/3),
// neither difference cancels badly (1 - 1/2, 1/2 - 1/6 at 0).
DVec3 bodyDisplacement(const DVec3& w, double t, const DVec3& v, const DVec3& a) {
    const double x = glm::length(w) * t;
    const double sincX = sinc(x);
    const double halfSinc = sinc(0.5 * x);
    const double oneMinusCos = 0.5 * halfSinc * halfSinc;  // (1 - cos x)/x^2
    const double xMinusSin = xMinusSinOverCube(x);         // (x - sin x)/x^3
    const double t2 = t * t;
    const double t3 = t2 * t;
    const DVec3 r1v = t * sincX * v + t2 * oneMinusCos * glm::cross(w, v) + t3 * xMinusSin * glm::dot(w, v) * w;
    const DVec3 r2a = t2 * (sincX - oneMinusCos) * a + t3 * (oneMinusCos - xMinusSin) * glm::cross(w, a) +
                      t2 * t2 * secondIntegralAxialCoefficient(x) * glm::dot(w, a) * w;
    return r1v + r2a;
}

}  // namespace

const char* deadReckoningAlgorithmName(DeadReckoningAlgorithm algorithm) {
    return isAlgorithm(algorithm) ? kAlgorithmNames[static_cast<int>(algorithm) - 1] : "?";
}

bool findDeadReckoningAlgorithm(std::string_view name, DeadReckoningAlgorithm& out) {
    for (int i = 0; i < kDeadReckoningAlgorithmCount; ++i) {
        if (name == kAlgorithmNames[i]) {
            out = static_cast<DeadReckoningAlgorithm>(i + 1);
            return true;
        }
    }
    return false;
}

bool deadReckoningRotates(DeadReckoningAlgorithm algorithm) {
    using A = DeadReckoningAlgorithm;
    return algorithm == A::Rpw || algorithm == A::Rvw || algorithm == A::Rpb || algorithm == A::Rvb;
}

bool deadReckoningUsesAcceleration(DeadReckoningAlgorithm algorithm) {
    using A = DeadReckoningAlgorithm;
    return algorithm == A::Rvw || algorithm == A::Fvw || algorithm == A::Rvb || algorithm == A::Fvb;
}

bool deadReckoningInBodyAxes(DeadReckoningAlgorithm algorithm) {
    using A = DeadReckoningAlgorithm;
    return algorithm == A::Fpb || algorithm == A::Rpb || algorithm == A::Rvb || algorithm == A::Fvb;
}

Status validateDeadReckoningState(const DeadReckoningState& state) {
    if (!isAlgorithm(state.algorithm)) return Status::InvalidAlgorithm;
    if (!isFinite(state.position) || !isFinite(state.velocity) || !isFinite(state.acceleration) ||
        !isFinite(state.angularVelocity))
        return Status::NonFiniteInput;
    Quat unit;
    return normalizeQuaternion(state.orientation, unit);
}

Status predictDeadReckoning(const DeadReckoningState& state, float time, DeadReckoningResult& out) {
    if (Status s = validateDeadReckoningState(state); s != Status::Ok) return s;
    if (!isFinite(time)) return Status::NonFiniteInput;
    if (time < 0.0f) return Status::NegativeTime;

    const double t = time;
    const DVec3 p = toD(state.position);
    const DVec3 v = toD(state.velocity);
    const DVec3 a = deadReckoningUsesAcceleration(state.algorithm) ? toD(state.acceleration) : DVec3(0.0);
    // Zero for the fixed-orientation models: R1 = t I, R2 = t^2/2 I exactly (the series at 0).
    const DVec3 w = deadReckoningRotates(state.algorithm) ? toD(state.angularVelocity) : DVec3(0.0);
    const DQuat q = glm::normalize(toD(state.orientation));

    DVec3 position = p;
    DVec3 velocity = v;
    DQuat orientation = q;
    if (state.algorithm != DeadReckoningAlgorithm::Static) {
        if (deadReckoningInBodyAxes(state.algorithm)) {
            position = p + q * bodyDisplacement(w, t, v, a);
        } else {
            position = p + (v * t + a * (0.5 * t * t));
        }
        velocity = v + a * t;
        orientation = glm::normalize(q * rotationFromAngularVelocityD(w, t));
    }

    DeadReckoningResult result;
    result.position = toR(position);
    result.velocity = toF(velocity);
    result.orientation = toF(orientation);
    if (!isFinite(result.position) || !isFinite(result.velocity) || !isFinite(result.orientation))
        return Status::NonFiniteResult;
    out = result;
    return Status::Ok;
}

FORESIGHT_NAMESPACE_END
