#pragma once
// Private helpers of the engine-matched projectile method (engine_profile.cpp,
// engine_projectile.cpp).

#include <algorithm>
#include <cmath>
#include <foresight/engine_profile.h>
#include <foresight/projectile.h>

#include "internal.h"

#include <span>

#include <cstdint>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {

/// Largest EngineProfile::substeps accepted.
inline constexpr std::uint32_t kMaxEngineSubsteps = 64;

// The damping factor of `law` for coefficient c over dt.
double dampingFactor(DampingLaw law, double c, double dt);

// One free-flight step of a profile (after its first step), written as the linear recurrence
//   v' = d v + b g dt,   p' = p + a v dt + cg g dt^2
// which covers every order, law and sub-step count (see engineRecurrence).
struct EngineRecurrence {
    double dt = 0;         // the step [s], at its decimal value
    double d = 1;          // damping factor per step
    double oneMinusD = 0;  // 1 - d, computed without cancellation
    double a = 1, b = 1, cg = 1;
};

EngineRecurrence engineRecurrence(const EngineProfile& profile);

// G_k = sum_{j<k} d^j and H_k = sum_{j<k} G_j, accurate for d near 1 and for d = 0.
void geometricSums(double d, double oneMinusD, std::uint64_t k, double& g, double& h);

// Records trajectory points into the caller's storage; counts what did not fit.
struct TrajectoryRecorder {
    std::span<TrajectoryPoint> storage;
    std::size_t size = 0;
    std::size_t needed = 0;
    double reach = 0.0;  // the largest |coordinate| of any point added [m] (the precision envelope)

    void add(double time, TrajectoryEvent event, const DVec3& position, const DVec3& velocity,
             const DVec3& normal = DVec3(0.0)) {
        ++needed;
        reach = std::max({reach, std::abs(position.x), std::abs(position.y), std::abs(position.z)});
        if (size >= storage.size()) return;
        TrajectoryPoint& point = storage[size++];
        point.time = static_cast<float>(time);
        point.event = event;
        point.position = toR(position);
        point.velocity = toF(velocity);
        point.normal = toF(normal);
    }
};

// ProjectileMethod::Engine: `steps` steps of settings.engine from (p, v) in `world`.
Status runEngineProjectile(const DVec3& position, const DVec3& velocity, std::uint64_t steps,
                           const ProjectileSettings& settings, const CollisionWorld& world,
                           TrajectoryRecorder& recorder, ProjectileResult& result);

}  // namespace detail
FORESIGHT_NAMESPACE_END
