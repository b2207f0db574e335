#include <foresight/status.h>

#include "internal.h"

#include <charconv>
#include <cstdlib>

FORESIGHT_NAMESPACE_BEGIN

const char* versionString() { return FORESIGHT_VERSION_STRING; }

const char* statusMessage(Status status) {
    switch (status) {
    case Status::Ok: return "ok";
    case Status::NonFiniteInput: return "expected finite numbers";
    case Status::NegativeTime: return "time must be >= 0";
    case Status::InvalidStep: return "step must be > 0";
    case Status::InvalidIterations: return "iterations must be between 1 and 1048576";
    case Status::InvalidRestitution: return "restitution must be in [0, 1]";
    case Status::InvalidFriction: return "friction must be >= 0";
    case Status::InvalidRadius: return "radius out of range (casts: >= 0, shapes: > 0)";
    case Status::ZeroQuaternion: return "quaternion has zero length";
    case Status::ZeroVector: return "vector must not be zero";
    case Status::DegenerateShape: return "degenerate shape (zero area or extent)";
    case Status::TooManySteps: return "too many steps (time / step is over the work cap)";
    case Status::TooManyEvents: return "too many bounces and contact changes (over the work cap)";
    case Status::NonFiniteResult: return "result is not finite (inputs too large)";
    }
    return "unknown status";
}

namespace detail {
double decimalValue(float x) {
    if (!std::isfinite(x)) return x;
    char text[32];
    const auto written = std::to_chars(text, text + sizeof(text) - 1, x);
    if (written.ec != std::errc()) return x;
    *written.ptr = '\0';
    return std::strtod(text, nullptr);
}
}  // namespace detail

FORESIGHT_NAMESPACE_END
