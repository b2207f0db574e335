#include <foresight/status.h>

#include "internal.h"

#include <cmath>

FORESIGHT_NAMESPACE_BEGIN

const char* versionString() { return FORESIGHT_VERSION_STRING; }

const char* statusMessage(Status status) {
    switch (status) {
        case Status::Ok:
            return "ok";
        case Status::NonFiniteInput:
            return "expected finite numbers";
        case Status::NegativeTime:
            return "time must be >= 0";
        case Status::InvalidStep:
            return "step must be > 0";
        case Status::InvalidIterations:
            return "iterations must be between 1 and 1048576";
        case Status::InvalidRestitution:
            return "restitution must be in [0, 1]";
        case Status::InvalidFriction:
            return "friction must be >= 0";
        case Status::InvalidRadius:
            return "radius out of range (casts: >= 0, shapes: > 0)";
        case Status::ZeroQuaternion:
            return "quaternion has zero length";
        case Status::ZeroVector:
            return "vector must not be zero";
        case Status::DegenerateShape:
            return "degenerate shape (zero area or extent)";
        case Status::TooManySteps:
            return "too many steps (time / step is over the work cap)";
        case Status::TooManyEvents:
            return "too many bounces and contact changes (over the work cap)";
        case Status::NonFiniteResult:
            return "result is not finite (inputs too large)";
        case Status::InvalidAlgorithm:
            return "unknown dead-reckoning algorithm";
        case Status::InvalidSpeed:
            return "speed must be > 0 and finite";
        case Status::InvalidFuse:
            return "fuse time must be > 0 and finite";
        case Status::InvalidSetting:
            return "a settings value is outside its documented range";
        case Status::TimeWentBackwards:
            return "time is earlier than the previous call's";
        case Status::NoUpdate:
            return "no update has been accepted yet";
        case Status::OutOfRange:
            return kDoublePrecision
                       ? "beyond the precision envelope (positions within 1e8 m of the origin, speeds up to 1e6 m/s)"
                       : "beyond the precision envelope (positions within 1e5 m of the origin, speeds up to 1e6 m/s; "
                         "build with FORESIGHT_DOUBLE_PRECISION for 1e8 m)";
    }
    return "unknown status";
}

namespace detail {
double decimalValue(float x) {
    // The first decimal with at most 9 fractional digits that rounds back to x: a few
    // multiplications, not a text round trip (this runs on every prediction).
    if (!std::isfinite(x)) return x;
    const double value = x;
    double scale = 1.0;
    for (int digits = 0; digits <= 9; ++digits, scale *= 10.0) {
        const double candidate = std::nearbyint(value * scale) / scale;
        if (static_cast<float>(candidate) == x) return candidate;
    }
    return value;
}
}  // namespace detail

FORESIGHT_NAMESPACE_END
