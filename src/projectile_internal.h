#pragma once
// Private entry to the projectile predictor for the throw planner (throw_planner.cpp): a
// prediction that gives up as soon as it surely ends too far from a point to matter.

#include <foresight/projectile.h>

#include "internal.h"

#include <span>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {

// A prediction whose end matters only if it lies within `keepBelow` of `target` [m].
struct DistanceCutoff {
    DVec3 target{0.0};
    double keepBelow = std::numeric_limits<double>::infinity();
};

// predictProjectile, with a cutoff for the Exact method (ignored by the others, and when null):
// at grid steps at least kCutoffInterval apart the run stops, with `abandoned` set and `out`
// untouched, once its position p at time t with velocity v satisfies
//   |p - target| - (|v| T + |g| T^2 / 2) > keepBelow + kCutoffMargin,
// T being the time left (the prediction's `time` less t). The bracket bounds the distance still
// to cover: an exact flight's speed grows by at most |g| per second (gravity; sliding adds at
// most gravity along the surface, less friction) and an impact never adds speed (restitution
// <= 1, friction only takes), so the end then lies farther than keepBelow from target. The
// margin covers the end's rounding to Real and the placements at impacts, which move the body
// without speed: a few ulps each, or up to 0.1 mm out of a surface it lies behind by rounding
// (keepInFront), so a hundred such pushes all towards the target to use it up.
inline constexpr double kCutoffInterval = 0.1;  // [s]
inline constexpr double kCutoffMargin = 0.01;   // [m]
Status predictProjectileWithCutoff(RVec3 position, Vec3 velocity, float time, const ProjectileSettings& settings,
                                   const CollisionWorld* world, std::span<TrajectoryPoint> trajectory,
                                   ProjectileResult& out, const DistanceCutoff* cutoff, bool& abandoned);

}  // namespace detail
FORESIGHT_NAMESPACE_END
