#include <foresight/danger.h>

#include "internal.h"

#include <array>
#include <cstddef>

FORESIGHT_NAMESPACE_BEGIN
using namespace detail;

namespace {

// ---------------------------------------------------------------------------------------------
// Small helpers

// The largest float not above x: reported times never move later than the double they round
// (a first contact or danger start must not be reported late).
float floorToFloat(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}

template <std::size_t N>
void sortSmall(std::array<double, N>& values, std::size_t count) {
    for (std::size_t i = 1; i < count; ++i) {
        const double value = values[i];
        std::size_t j = i;
        for (; j > 0 && values[j - 1] > value; --j) values[j] = values[j - 1];
        values[j] = value;
    }
}

// Real roots of A x^2 + B x + C strictly inside (low, high), appended to `roots`.
template <std::size_t N>
void quadraticRootsInside(double a, double b, double c, double low, double high, std::array<double, N>& roots,
                          std::size_t& count) {
    auto add = [&](double x) {
        if (x > low && x < high && count < N) roots[count++] = x;
    };
    if (a == 0.0) {
        if (b != 0.0) add(-c / b);
        return;
    }
    const double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return;
    // The stable pair: no cancellation between -b and the square root.
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    if (q != 0.0) {
        add(q / a);
        add(c / q);
    } else {
        add(0.0);  // b = 0 and discriminant = 0: the double root at 0
    }
}

// Bisection of a continuous g with g(low) and g(high) of opposite signs (or zero) to double
// precision; returns a point of the final bracket where g <= 0 is on the side `towardNonPositive`.
template <class G>
double bisect(G&& g, double low, double high, bool lowIsNegative) {
    for (int i = 0; i < 200; ++i) {
        const double middle = 0.5 * (low + high);
        if (!(middle > low && middle < high)) break;
        if ((g(middle) < 0.0) == lowIsNegative)
            low = middle;
        else
            high = middle;
    }
    return lowIsNegative ? low : high;
}

// ---------------------------------------------------------------------------------------------
// Projectile segments: p(s) = p0 + v0 s + a s^2 / 2, s in [0, duration].

struct Segment {
    DVec3 p0;
    DVec3 v0;
    DVec3 a;
    double t0 = 0;
    double duration = 0;

    DVec3 at(double s) const { return p0 + v0 * s + a * (0.5 * s * s); }
};

Segment segmentBetween(const TrajectoryPoint& first, const TrajectoryPoint& second) {
    Segment segment;
    segment.p0 = DVec3(toD(first.position));
    segment.v0 = toD(first.velocity);
    segment.t0 = static_cast<double>(first.time);
    segment.duration = static_cast<double>(second.time) - segment.t0;
    const double d = segment.duration;
    // The constant acceleration that joins the two points (gravity in free flight).
    segment.a = d > 0.0 ? (DVec3(toD(second.position)) - segment.p0 - segment.v0 * d) * (2.0 / (d * d)) : DVec3(0.0);
    return segment;
}

// The squared distance from `point` along a segment and its critical points: f(s) = |q + v s +
// a s^2/2|^2, f'(s)/2 = c0 + c1 s + c2 s^2 + c3 s^3.
struct SegmentDistance {
    DVec3 q, v, a;
    double c0, c1, c2, c3;

    SegmentDistance(const Segment& segment, const DVec3& point) : q(segment.p0 - point), v(segment.v0), a(segment.a) {
        c0 = glm::dot(q, v);
        c1 = glm::dot(v, v) + glm::dot(q, a);
        c2 = 1.5 * glm::dot(v, a);
        c3 = 0.5 * glm::dot(a, a);
    }
    double squared(double s) const {
        const DVec3 d = q + v * s + a * (0.5 * s * s);
        return glm::dot(d, d);
    }
    double halfDerivative(double s) const { return c0 + s * (c1 + s * (c2 + s * c3)); }

    // Every point of [low, high] where f may have an extremum, and the ends, sorted: the ends,
    // the roots of f'' (where f' may turn) and the roots of f' (isolated between those).
    std::size_t breakpoints(double low, double high, std::array<double, 8>& out) const {
        std::array<double, 8> turns{};
        std::size_t turnCount = 0;
        turns[turnCount++] = low;
        quadraticRootsInside(3.0 * c3, 2.0 * c2, c1, low, high, turns, turnCount);
        turns[turnCount++] = high;
        sortSmall(turns, turnCount);
        std::size_t count = 0;
        for (std::size_t i = 0; i < turnCount; ++i) {
            out[count++] = turns[i];
            if (i + 1 == turnCount) break;
            // f' is monotone on [turns[i], turns[i+1]]: at most one root, found by bisection.
            const double x0 = turns[i], x1 = turns[i + 1];
            const double g0 = halfDerivative(x0), g1 = halfDerivative(x1);
            if ((g0 < 0.0 && g1 > 0.0) || (g0 > 0.0 && g1 < 0.0)) {
                auto g = [this](double s) { return halfDerivative(s); };
                out[count++] = bisect(g, x0, x1, g0 < 0.0);
            }
        }
        return count;  // sorted: the roots lie between the turns that bracket them
    }
};

Status checkTrajectory(std::span<const TrajectoryPoint> trajectory) {
    if (trajectory.empty()) return Status::InvalidStep;
    for (std::size_t i = 0; i < trajectory.size(); ++i) {
        const TrajectoryPoint& point = trajectory[i];
        if (!isFinite(point.time) || !isFinite(point.position) || !isFinite(point.velocity))
            return Status::NonFiniteInput;
        if (i > 0 && point.time < trajectory[i - 1].time) return Status::InvalidStep;
    }
    return Status::Ok;
}

DVec3 positionAt(std::span<const TrajectoryPoint> trajectory, double time) {
    // The last point at or before `time` (after a jump of equal times: its later point).
    const auto after =
        std::upper_bound(trajectory.begin(), trajectory.end(), time,
                         [](double t, const TrajectoryPoint& point) { return t < static_cast<double>(point.time); });
    if (after == trajectory.begin()) return DVec3(toD(trajectory.front().position));
    if (after == trajectory.end()) return DVec3(toD(trajectory.back().position));
    const Segment segment = segmentBetween(*(after - 1), *after);
    return segment.at(std::clamp(time - segment.t0, 0.0, segment.duration));
}

// Earliest time in [from, until] within `distance` of `point` (trajectory already checked).
bool earliestWithin(std::span<const TrajectoryPoint> trajectory, const DVec3& point, double distance, double from,
                    double until, double& found) {
    if (!(from <= until)) return false;
    const double limit = distance * distance;
    const double lastTime = static_cast<double>(trajectory.back().time);
    auto within = [&](const DVec3& p) {
        const DVec3 d = p - point;
        return glm::dot(d, d) <= limit;
    };
    if (within(positionAt(trajectory, from))) {
        found = from;
        return true;
    }
    for (std::size_t i = 0; i + 1 < trajectory.size(); ++i) {
        const Segment segment = segmentBetween(trajectory[i], trajectory[i + 1]);
        if (!(segment.duration > 0.0)) continue;
        const double low = std::max(0.0, from - segment.t0);
        const double high = std::min(segment.duration, until - segment.t0);
        if (!(low <= high)) continue;
        const SegmentDistance f(segment, point);
        std::array<double, 8> pieces{};
        const std::size_t count = f.breakpoints(low, high, pieces);
        // f is monotone between breakpoints: the first piece that reaches the limit holds the
        // answer, at its start or at its single crossing.
        for (std::size_t k = 0; k < count; ++k) {
            if (f.squared(pieces[k]) <= limit) {
                double s = pieces[k];
                if (k > 0) {
                    auto g = [&](double x) { return f.squared(x) - limit; };
                    s = bisect(g, pieces[k - 1], pieces[k], false);
                }
                found = segment.t0 + s;
                return true;
            }
        }
    }
    if (until >= lastTime && within(DVec3(toD(trajectory.back().position)))) {
        found = std::max(from, lastTime);
        return true;
    }
    return false;
}

// Closest approach over [from, until] (trajectory checked; from <= until).
void closestOnPath(std::span<const TrajectoryPoint> trajectory, const DVec3& point, double from, double until,
                   double& bestSquared, double& bestTime) {
    bestSquared = std::numeric_limits<double>::infinity();
    bestTime = from;
    auto consider = [&](double squared, double time) {
        if (squared < bestSquared) {
            bestSquared = squared;
            bestTime = time;
        }
    };
    auto squaredAt = [&](double time) {
        const DVec3 d = positionAt(trajectory, time) - point;
        return glm::dot(d, d);
    };
    // The window's ends (also outside the points' times, where the projectile stands still),
    // then every segment's candidates in time order.
    consider(squaredAt(from), from);
    for (std::size_t i = 0; i + 1 < trajectory.size(); ++i) {
        const Segment segment = segmentBetween(trajectory[i], trajectory[i + 1]);
        if (!(segment.duration > 0.0)) continue;
        const double low = std::max(0.0, from - segment.t0);
        const double high = std::min(segment.duration, until - segment.t0);
        if (!(low <= high)) continue;
        const SegmentDistance f(segment, point);
        std::array<double, 8> candidates{};
        const std::size_t count = f.breakpoints(low, high, candidates);
        for (std::size_t k = 0; k < count; ++k) consider(f.squared(candidates[k]), segment.t0 + candidates[k]);
    }
    consider(squaredAt(until), until);
}

// ---------------------------------------------------------------------------------------------
// Vehicle against character

// sin(x) / x and (x - sin x) / x^3, exact near 0: the closed form of vehicle.cpp, in double.
double sinc(double x) {
    if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;
    return std::sin(x) / x;
}
double xMinusSinOverCube(double x) {
    if (std::abs(x) < 0.5) {
        const double x2 = x * x;
        return 1.0 / 6.0 - x2 * (1.0 / 120.0 - x2 * (1.0 / 5040.0 - x2 * (1.0 / 362880.0 - x2 / 39916800.0)));
    }
    return (x - std::sin(x)) / (x * x * x);
}

struct Motion {
    // vehicle
    DVec3 position;
    DQuat orientation;
    DVec3 angularVelocity;
    double angularSpeed = 0;
    DVec3 forward;     // unit, local axes
    double speed = 0;  // signed
    bool body = true;
    DVec3 halfExtents;
    DVec3 boxCenter;
    double boundingRadius = 0;  // |boxCenter| + |halfExtents|: farthest box point from `position`
    // character
    DVec3 characterPosition;
    DVec3 characterVelocity;
    DVec3 characterAcceleration;
    DVec3 halfAxis;
    double radius = 0;

    // The pose of predictVehicleExact at time t (same closed form, kept in double).
    void pose(double t, DVec3& outPosition, DQuat& outOrientation) const {
        const double x = angularSpeed * t;
        const double s = sinc(0.5 * x);
        const double c1 = 0.5 * t * t * s * s;
        const double c2 = t * t * t * xMinusSinOverCube(x);
        const DVec3 f = body ? forward : orientation * forward;
        const DVec3 wxf = glm::cross(angularVelocity, f);
        DVec3 displacement = (t * f + c1 * wxf + c2 * glm::cross(angularVelocity, wxf)) * speed;
        if (body) displacement = orientation * displacement;
        outPosition = position + displacement;
        const DQuat rotation = rotationFromAngularVelocityD(angularVelocity, t);
        outOrientation = glm::normalize(body ? orientation * rotation : rotation * orientation);
    }

    DVec3 characterAt(double t) const {
        return characterPosition + characterVelocity * t + characterAcceleration * (0.5 * t * t);
    }
    DVec3 characterVelocityAt(double t) const { return characterVelocity + characterAcceleration * t; }

    // Exact separation: distance from the box to the capsule's segment, minus the radius.
    double separation(double t) const {
        DVec3 vehiclePosition;
        DQuat q;
        pose(t, vehiclePosition, q);
        const DVec3 center = vehiclePosition + q * boxCenter;
        const DQuat toLocal = glm::conjugate(q);
        const DVec3 c = characterAt(t);
        const DVec3 a = toLocal * (c - halfAxis - center);
        const DVec3 d = toLocal * (halfAxis * 2.0);
        return std::sqrt(boxSegmentSquared(a, d)) - radius;
    }

    // Squared distance from the box [-h, h] to the segment a + u d, u in [0, 1] (local axes).
    // g(u) is convex and quadratic between the u where the segment crosses a slab plane: its
    // minimum is at a crossing, an end, or a piece's vertex.
    double boxSegmentSquared(const DVec3& a, const DVec3& d) const {
        auto g = [&](double u) {
            double sum = 0;
            for (int i = 0; i < 3; ++i) {
                const double x = a[i] + u * d[i];
                const double outside = x - std::clamp(x, -halfExtents[i], halfExtents[i]);
                sum += outside * outside;
            }
            return sum;
        };
        if (d == DVec3(0.0)) return g(0.0);
        std::array<double, 8> cuts{};
        std::size_t count = 0;
        cuts[count++] = 0.0;
        cuts[count++] = 1.0;
        for (int i = 0; i < 3; ++i) {
            if (d[i] == 0.0) continue;
            for (const double bound : {-halfExtents[i], halfExtents[i]}) {
                const double u = (bound - a[i]) / d[i];
                if (u > 0.0 && u < 1.0) cuts[count++] = u;
            }
        }
        sortSmall(cuts, count);
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < count; ++k) {
            best = std::min(best, g(cuts[k]));
            if (k + 1 == count) break;
            const double u0 = cuts[k], u1 = cuts[k + 1];
            // On this piece each axis is below, inside or above its slab: sum the outside ones.
            const double middle = 0.5 * (u0 + u1);
            double alpha = 0, beta = 0;
            for (int i = 0; i < 3; ++i) {
                const double x = a[i] + middle * d[i];
                if (x < -halfExtents[i] || x > halfExtents[i]) {
                    const double plane = x < 0.0 ? -halfExtents[i] : halfExtents[i];
                    alpha += d[i] * d[i];
                    beta += 2.0 * d[i] * (a[i] - plane);
                }
            }
            if (alpha > 0.0) best = std::min(best, g(std::clamp(-beta / (2.0 * alpha), u0, u1)));
        }
        return best;
    }

    // A bound on |dD/dt| over [t0, t1] (the header's proof sketch).
    double speedBound(double t0, double t1) const {
        const double character0 = glm::length(characterVelocityAt(t0));
        const double character1 = glm::length(characterVelocityAt(t1));
        double relative = 0;
        if (angularSpeed == 0.0) {
            const DVec3 vehicleVelocity = (orientation * forward) * speed;  // constant
            relative = std::max(glm::length(vehicleVelocity - characterVelocityAt(t0)),
                                glm::length(vehicleVelocity - characterVelocityAt(t1)));
        } else {
            relative = std::abs(speed) + std::max(character0, character1);
            // Tighter on short intervals: both velocities change no faster than |speed| |w| and
            // |acceleration| from their values at the middle.
            const double middle = 0.5 * (t0 + t1);
            DVec3 unused;
            DQuat q;
            pose(middle, unused, q);
            const DVec3 vehicleVelocity = (q * forward) * speed;
            const double change =
                (std::abs(speed) * angularSpeed + glm::length(characterAcceleration)) * (0.5 * (t1 - t0));
            relative = std::min(relative, glm::length(vehicleVelocity - characterVelocityAt(middle)) + change);
        }
        return relative + angularSpeed * boundingRadius;
    }
};

bool validCharacter(const CharacterBody& character) {
    return isFinite(character.position) && isFinite(character.velocity) && isFinite(character.acceleration) &&
           isFinite(character.radius) && isFinite(character.halfAxis);
}

Status prepareMotion(const VehicleBody& vehicle, const CharacterBody& character, Motion& motion) {
    const VehicleState& state = vehicle.state;
    if (!isFinite(state.position) || !isFinite(state.velocity) || !isFinite(state.angularVelocity) ||
        !isFinite(vehicle.settings.forward) || !isFinite(vehicle.halfExtents) || !isFinite(vehicle.boxCenter) ||
        !validCharacter(character))
        return Status::NonFiniteInput;
    Quat q;
    if (const Status s = normalizeQuaternion(state.orientation, q); s != Status::Ok) return s;
    const DVec3 forward = toD(vehicle.settings.forward);
    const double forwardLength = glm::length(forward);
    if (!(forwardLength > 0.0)) return Status::ZeroVector;
    if (!(vehicle.halfExtents.x > 0.0f && vehicle.halfExtents.y > 0.0f && vehicle.halfExtents.z > 0.0f))
        return Status::DegenerateShape;
    if (character.radius < 0.0f) return Status::InvalidRadius;
    motion.position = DVec3(toD(state.position));
    motion.orientation = toD(q);
    motion.angularVelocity = toD(state.angularVelocity);
    motion.angularSpeed = glm::length(motion.angularVelocity);
    motion.forward = forward / forwardLength;
    motion.speed = static_cast<double>(signedVehicleSpeed(state.velocity, toF(motion.orientation * motion.forward)));
    motion.body = vehicle.settings.frame == AngularFrame::Body;
    motion.halfExtents = toD(vehicle.halfExtents);
    motion.boxCenter = toD(vehicle.boxCenter);
    motion.boundingRadius = glm::length(motion.boxCenter) + glm::length(motion.halfExtents);
    motion.characterPosition = DVec3(toD(character.position));
    motion.characterVelocity = toD(character.velocity);
    motion.characterAcceleration = toD(character.acceleration);
    motion.halfAxis = toD(character.halfAxis);
    motion.radius = static_cast<double>(character.radius);
    return Status::Ok;
}

Status checkQuery(float horizon, const ApproachSettings& settings) {
    if (!isFinite(horizon)) return Status::NonFiniteInput;
    if (horizon < 0.0f) return Status::NegativeTime;
    if (!(isFinite(settings.tolerance) && settings.tolerance > 0.0f) || settings.maxEvaluations < 1)
        return Status::InvalidStep;
    return Status::Ok;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Projectiles

Status validateTrajectory(std::span<const TrajectoryPoint> trajectory) { return checkTrajectory(trajectory); }

Status validateProjectileDanger(const ProjectileDanger& danger) {
    if (const Status s = checkTrajectory(danger.trajectory); s != Status::Ok) return s;
    if (!isFinite(danger.fuseTime) || !isFinite(danger.blastRadius) || !isFinite(danger.contactRadius))
        return Status::NonFiniteInput;
    if (danger.fuseTime < 0.0f) return Status::InvalidFuse;
    if (danger.blastRadius < 0.0f || danger.contactRadius < 0.0f) return Status::InvalidRadius;
    return Status::Ok;
}

Status positionOnTrajectory(std::span<const TrajectoryPoint> trajectory, float time, RVec3& out) {
    if (const Status s = checkTrajectory(trajectory); s != Status::Ok) return s;
    if (!isFinite(time)) return Status::NonFiniteInput;
    const RVec3 position = toR(positionAt(trajectory, static_cast<double>(time)));
    if (!isFinite(position)) return Status::NonFiniteResult;
    out = position;
    return Status::Ok;
}

Status computeDangerZone(const ProjectileDanger& danger, DangerZone& out) {
    if (const Status s = validateProjectileDanger(danger); s != Status::Ok) return s;
    DangerZone zone;
    zone.center = toR(positionAt(danger.trajectory, static_cast<double>(danger.fuseTime)));
    if (!isFinite(zone.center)) return Status::NonFiniteResult;
    zone.radius = danger.blastRadius;
    zone.time = danger.fuseTime;
    out = zone;
    return Status::Ok;
}

Status isPointSafe(const ProjectileDanger& danger, RVec3 point, float time, bool& safe) {
    if (const Status s = validateProjectileDanger(danger); s != Status::Ok) return s;
    if (!isFinite(point) || !isFinite(time)) return Status::NonFiniteInput;
    const DVec3 p = DVec3(toD(point));
    if (time >= danger.fuseTime) {
        const DVec3 d = p - positionAt(danger.trajectory, static_cast<double>(danger.fuseTime));
        const double radius = static_cast<double>(danger.blastRadius);
        safe = !(glm::dot(d, d) <= radius * radius);
    } else if (danger.contactRadius > 0.0f && time >= danger.trajectory.front().time) {
        // Before the trajectory's first time the projectile is not there yet (findDangerStart
        // looks from that time on): only [first time, fuse) can be unsafe by contact.
        const DVec3 d = p - positionAt(danger.trajectory, static_cast<double>(time));
        const double radius = static_cast<double>(danger.contactRadius);
        safe = !(glm::dot(d, d) <= radius * radius);
    } else {
        safe = true;
    }
    return Status::Ok;
}

Status findDangerStart(const ProjectileDanger& danger, RVec3 point, DangerStart& out) {
    if (const Status s = validateProjectileDanger(danger); s != Status::Ok) return s;
    if (!isFinite(point)) return Status::NonFiniteInput;
    const DVec3 p = DVec3(toD(point));
    const double fuse = static_cast<double>(danger.fuseTime);
    DangerStart start;
    if (danger.contactRadius > 0.0f) {
        // The projectile itself, from the start of the prediction until (not at) the fuse.
        double found = 0;
        if (earliestWithin(danger.trajectory, p, static_cast<double>(danger.contactRadius),
                           static_cast<double>(danger.trajectory.front().time), fuse, found) &&
            found < fuse) {
            start.ever = true;
            start.time = floorToFloat(found);
        }
    }
    if (!start.ever) {
        const DVec3 d = p - positionAt(danger.trajectory, fuse);
        const double radius = static_cast<double>(danger.blastRadius);
        if (glm::dot(d, d) <= radius * radius) {
            start.ever = true;
            start.time = danger.fuseTime;
        }
    }
    out = start;
    return Status::Ok;
}

Status findPathApproach(std::span<const TrajectoryPoint> trajectory, RVec3 point, float distance, float fromTime,
                        float untilTime, DangerStart& out) {
    if (const Status s = checkTrajectory(trajectory); s != Status::Ok) return s;
    if (!isFinite(point) || !isFinite(distance) || !isFinite(fromTime) || !isFinite(untilTime))
        return Status::NonFiniteInput;
    if (distance < 0.0f) return Status::InvalidRadius;
    DangerStart start;
    double found = 0;
    if (earliestWithin(trajectory, DVec3(toD(point)), static_cast<double>(distance), static_cast<double>(fromTime),
                       static_cast<double>(untilTime), found)) {
        start.ever = true;
        start.time = std::max(fromTime, floorToFloat(found));
    }
    out = start;
    return Status::Ok;
}

Status findClosestPathApproach(std::span<const TrajectoryPoint> trajectory, RVec3 point, float fromTime,
                               float untilTime, ClosestApproach& out) {
    if (const Status s = checkTrajectory(trajectory); s != Status::Ok) return s;
    if (!isFinite(point) || !isFinite(fromTime) || !isFinite(untilTime)) return Status::NonFiniteInput;
    const double from = static_cast<double>(fromTime);
    const double until = std::max(from, static_cast<double>(untilTime));
    double squared = 0, time = 0;
    closestOnPath(trajectory, DVec3(toD(point)), from, until, squared, time);
    ClosestApproach approach;
    approach.distance = static_cast<float>(std::sqrt(squared));
    approach.time = std::clamp(static_cast<float>(time), fromTime, std::max(fromTime, untilTime));
    if (!isFinite(approach.distance)) return Status::NonFiniteResult;
    out = approach;
    return Status::Ok;
}

// ---------------------------------------------------------------------------------------------
// Vehicles

Status validateVehicleCharacter(const VehicleBody& vehicle, const CharacterBody& character) {
    Motion motion;
    return prepareMotion(vehicle, character, motion);
}

Status computeVehicleSeparation(const VehicleBody& vehicle, const CharacterBody& character, float time,
                                float& separation) {
    Motion motion;
    if (const Status s = prepareMotion(vehicle, character, motion); s != Status::Ok) return s;
    if (!isFinite(time)) return Status::NonFiniteInput;
    if (time < 0.0f) return Status::NegativeTime;
    const double value = motion.separation(static_cast<double>(time));
    if (!isFinite(value) || !isFinite(static_cast<float>(value))) return Status::NonFiniteResult;
    separation = static_cast<float>(value);
    return Status::Ok;
}

Status findVehicleContact(const VehicleBody& vehicle, const CharacterBody& character, float horizon,
                          const ApproachSettings& settings, VehicleContact& out) {
    Motion motion;
    if (const Status s = prepareMotion(vehicle, character, motion); s != Status::Ok) return s;
    if (const Status s = checkQuery(horizon, settings); s != Status::Ok) return s;
    const double end = static_cast<double>(horizon);
    const double tolerance = static_cast<double>(settings.tolerance);
    VehicleContact contact;
    double t = 0;
    for (;;) {
        if (contact.evaluations >= settings.maxEvaluations) return Status::TooManySteps;
        const double separation = motion.separation(t);
        ++contact.evaluations;
        if (!isFinite(separation)) return Status::NonFiniteResult;
        contact.separation = static_cast<float>(separation);
        if (separation <= tolerance) {
            contact.contact = true;
            contact.time = floorToFloat(t);
            break;
        }
        if (t >= end) break;
        // The largest step the bound allows: first with the bound over the rest of the horizon,
        // then with bounds over shorter windows (tighter), each used only inside its window.
        double bound = motion.speedBound(t, end);
        if (!isFinite(bound)) return Status::NonFiniteResult;
        if (bound <= 0.0) {  // nothing moves relative to the other: the separation stays
            t = end;
            continue;
        }
        double step = separation / bound;
        for (int refine = 0; refine < 4 && t + step < end; ++refine) {
            const double window = std::min(2.0 * step, end - t);
            const double local = motion.speedBound(t, t + window);
            const double candidate = local > 0.0 ? std::min(separation / local, window) : window;
            if (!(candidate > step)) break;
            step = candidate;
        }
        const double next = t + step;
        t = next >= end ? end : next;
    }
    if (!isFinite(contact.separation)) return Status::NonFiniteResult;
    out = contact;
    return Status::Ok;
}

Status findClosestVehicleApproach(const VehicleBody& vehicle, const CharacterBody& character, float horizon,
                                  const ApproachSettings& settings, ClosestApproach& out) {
    Motion motion;
    if (const Status s = prepareMotion(vehicle, character, motion); s != Status::Ok) return s;
    if (const Status s = checkQuery(horizon, settings); s != Status::Ok) return s;
    const double end = static_cast<double>(horizon);
    const double tolerance = static_cast<double>(settings.tolerance);
    // Two passes, sharing maxEvaluations (the header's contract, with mu the true minimum):
    // 1. branch and bound to 3/4 of the tolerance: the lowest value m found has
    //    mu <= m <= mu + 3 tolerance / 4;
    // 2. conservative advancement from t = 0 that never skips a time where D <= m and stops at
    //    the first time where D <= m + tolerance / 4 (every step is at least tolerance / (4 L),
    //    so it ends). The reported time T has D > m >= mu on [0, T) and D(T) <= mu + tolerance:
    //    no later than the first time of the true minimum, whatever pass 1's samples (equal
    //    minima of a periodic path give the first, whatever the horizon).
    // The split: pass 1's cost on a plateau (D constant for long) grows as 1 / its tolerance,
    // pass 2's near a minimum as 1 / sqrt of its margin; 3/4 keeps pass 1 within a power-of-two
    // depth of a plain search to `tolerance`.
    const double searchTolerance = 0.75 * tolerance;
    // The separation is never below -radius (the segment inside the box): a floor for the bound,
    // which stops the search on an overlap plateau.
    const double floor = -motion.radius;
    std::uint32_t evaluations = 0;
    double bestValue = std::numeric_limits<double>::infinity();
    auto evaluate = [&](double t, double& value) {
        if (evaluations >= settings.maxEvaluations) return Status::TooManySteps;
        value = motion.separation(t);
        ++evaluations;
        if (!isFinite(value)) return Status::NonFiniteResult;
        bestValue = std::min(bestValue, value);
        return Status::Ok;
    };
    struct Interval {
        double a, b, valueA, valueB;
    };
    auto lowerBound = [&](const Interval& interval) {
        const double bound = motion.speedBound(interval.a, interval.b);
        return std::max(floor, 0.5 * (interval.valueA + interval.valueB - bound * (interval.b - interval.a)));
    };
    double start = 0, finish = 0;
    if (const Status s = evaluate(0.0, start); s != Status::Ok) return s;
    if (end > 0.0) {
        if (const Status s = evaluate(end, finish); s != Status::Ok) return s;
        // Depth-first, earlier half first; each level adds at most one pending interval, and
        // intervals narrower than 2 tolerance / bound are always dropped, so the stack is shallow.
        std::array<Interval, 256> stack{};
        std::size_t size = 0;
        stack[size++] = Interval{0.0, end, start, finish};
        while (size > 0) {
            const Interval interval = stack[--size];
            if (!(lowerBound(interval) < bestValue - searchTolerance)) continue;
            const double middle = 0.5 * (interval.a + interval.b);
            if (!(middle > interval.a && middle < interval.b)) continue;
            double value = 0;
            if (const Status s = evaluate(middle, value); s != Status::Ok) return s;
            const Interval left{interval.a, middle, interval.valueA, value};
            const Interval right{middle, interval.b, value, interval.valueB};
            if (size + 2 > stack.size()) return Status::TooManySteps;
            if (lowerBound(right) < bestValue - searchTolerance) stack[size++] = right;
            if (lowerBound(left) < bestValue - searchTolerance) stack[size++] = left;
        }
    }

    // Pass 2. The value m is reached at a time in [0, end] that is never stepped over, so the
    // advancement stops by then; `t >= end` only guards against rounding.
    const double never = bestValue;                      // never stepped over
    const double accept = bestValue + 0.25 * tolerance;  // reported when reached
    double t = 0.0;
    double value = start;
    for (;;) {
        if (value <= accept || t >= end) break;
        double bound = motion.speedBound(t, end);
        if (!isFinite(bound)) return Status::NonFiniteResult;
        if (bound <= 0.0) break;  // nothing moves: D is constant, so D(0) is already minimal
        double step = (value - never) / bound;
        for (int refine = 0; refine < 4 && t + step < end; ++refine) {
            const double window = std::min(2.0 * step, end - t);
            const double local = motion.speedBound(t, t + window);
            const double candidate = local > 0.0 ? std::min((value - never) / local, window) : window;
            if (!(candidate > step)) break;
            step = candidate;
        }
        t = t + step >= end ? end : t + step;
        if (evaluations >= settings.maxEvaluations) return Status::TooManySteps;
        value = motion.separation(t);
        ++evaluations;
        if (!isFinite(value)) return Status::NonFiniteResult;
    }
    ClosestApproach approach;
    approach.distance = static_cast<float>(value);
    approach.time = floorToFloat(t);
    if (!isFinite(approach.distance)) return Status::NonFiniteResult;
    out = approach;
    return Status::Ok;
}

FORESIGHT_NAMESPACE_END
