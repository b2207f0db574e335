#include <foresight/character.h>

#include "internal.h"

FORESIGHT_NAMESPACE_BEGIN
using namespace detail;

namespace {
Status checkStart(const PointState& start, float time) {
    if (!isFinite(start.position) || !isFinite(start.velocity) || !isFinite(time)) return Status::NonFiniteInput;
    if (time < 0.0f) return Status::NegativeTime;
    return Status::Ok;
}
}  // namespace

Status predictLinear(const PointState& start, float time, PointState& out) {
    return predictAccelerated(start, Vec3(0.0f), time, out);
}

Status predictAccelerated(const PointState& start, Vec3 acceleration, float time, PointState& out) {
    if (Status s = checkStart(start, time); s != Status::Ok) return s;
    if (!isFinite(acceleration)) return Status::NonFiniteInput;
    const double t = time;
    const DVec3 a = toD(acceleration);
    const DVec3 v = toD(start.velocity);
    PointState result;
    result.position = toR(toD(start.position) + v * t + a * (0.5 * t * t));
    result.velocity = toF(v + a * t);
    if (!isFinite(result.position) || !isFinite(result.velocity)) return Status::NonFiniteResult;
    out = result;
    return Status::Ok;
}

FORESIGHT_NAMESPACE_END
