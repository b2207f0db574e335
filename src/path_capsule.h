#pragma once
// Many steps of a known path cleared with one world query (private; projectile.cpp and
// engine_projectile.cpp).
//
// A predictor that casts one chord per step between the points p[0], p[1], ..., p[n] of a path
// it already knows (free flight) can ask the world once instead: every chord lies within
// `bend` of the long chord p[0] -> p[n] (the distance to a segment is convex, so its largest
// value along a chord is at one of the chord's ends), so every cast of a sphere of radius `reach`
// along them stays inside the capsule of radius reach + bend around the long chord. When
// CollisionWorld::mayTouch says nothing touches that capsule, or CollisionWorld::firstTouch says
// how far along it nothing does, those casts would have hit nothing: the predictor skips them
// and computes exactly what it would have computed with them.
//
// In contact with one plane (rolling, sliding), the steps' casts and probes are answered by a
// world that holds that plane alone (PlaneWorld), and CollisionWorld::isOnlyPlane promises that
// the real world would have answered the same within the capsule around their path.

#include <foresight/static_world.h>
#include <foresight/world.h>

#include "internal.h"

#include <cstddef>
#include <span>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {

// How far the points stray from the segment from their first to their last.
inline double pathBend(std::span<const DVec3> points) {
    const DVec3 a = points.front(), chord = points.back() - a;
    const double chordSquared = glm::dot(chord, chord);
    double bend = 0.0;
    for (std::size_t j = 1; j + 1 < points.size(); ++j) {
        const DVec3 offset = points[j] - a;
        const double t = chordSquared > 0.0 ? std::clamp(glm::dot(offset, chord) / chordSquared, 0.0, 1.0) : 0.0;
        bend = std::max(bend, glm::length(offset - chord * t));
    }
    return bend;
}

// Margin for the casts' own rounding: the world sees each chord from its rounded origin (Real)
// with a float displacement, a little longer than the chord (the exact method's overshoot), and
// the capsule itself is rounded the same way: 1 mm, and 8 units in the last place of Real at the
// path's ends besides (the rounding of coordinates far from the origin).
inline double pathMargin(std::span<const DVec3> points) {
    return 1e-3 + realUlps(points.front(), 8.0) + realUlps(points.back(), 8.0);
}

// The capsule that holds every cast of a sphere of radius `reach` along the chords between
// consecutive `points` (at least two) that stray at most `bend` from the segment from the first
// to the last.
inline SegmentCast pathCapsule(std::span<const DVec3> points, double reach, double bend) {
    SegmentCast capsule;
    capsule.origin = toR(points.front());
    capsule.displacement = toF(points.back() - toD(capsule.origin));
    capsule.radius = static_cast<float>((reach + bend + pathMargin(points)) * (1.0 + 1e-5));
    return capsule;
}

// The same, with the bend measured point by point (any path).
inline SegmentCast pathCapsule(std::span<const DVec3> points, double reach) {
    return pathCapsule(points, reach, pathBend(points));
}

// How far points of the parabola p0 + v s + g s^2 / 2 for s in [0, duration] stray from the chord
// between its ends: p(s) lies |g| s (duration - s) / 2 from the chord's point at the same share
// of the duration, at most |g| duration^2 / 8 (pathBend's answer for those points without its
// square roots; the points' own rounding is far inside pathMargin).
inline double parabolaBend(const DVec3& gravity, double duration) {
    return glm::length(gravity) * duration * duration * 0.125;
}

// After CollisionWorld::firstTouch answered `fraction` for pathCapsule(points, ...): how many
// chords from the first point on lie wholly in the part of the capsule before the touch (both
// ends of a chord project onto the long chord before it, with pathMargin to spare).
inline std::size_t clearChords(std::span<const DVec3> points, float fraction) {
    const DVec3 a = points.front(), chord = points.back() - a;
    const double length = glm::length(chord);
    const double limit = static_cast<double>(fraction) * length - pathMargin(points);
    if (!(length > 0.0) || !(limit > 0.0)) return 0;
    std::size_t clear = 0;
    while (clear + 1 < points.size() && glm::dot(points[clear + 1] - a, chord) / length < limit) ++clear;
    return clear;
}

// The world that a contact coast steps against: one one-sided plane with a material, answered by
// the same shape test as StaticWorld's.
class PlaneWorld final : public CollisionWorld {
public:
    PlaneWorld() = default;
    PlaneWorld(const Plane& plane, const SurfaceMaterial& material) : mPlane(plane), mMaterial(material) {}
    bool castSegment(const SegmentCast& cast, CastHit& hit) const override {
        ClosestHitCaster caster(cast);
        caster.test(mPlane, mMaterial);
        return caster.result(hit);
    }
    bool mayTouch(const SegmentCast& capsule) const override { return foresight::mayTouch(capsule, mPlane); }
    bool findNear(const NearQuery& query, NearCollector& collector) const override {
        NearTester tester(query, collector);
        tester.test(mPlane, mMaterial);
        return true;
    }

    /// The plane.
    const Plane& plane() const { return mPlane; }

private:
    Plane mPlane;
    SurfaceMaterial mMaterial;
};

}  // namespace detail
FORESIGHT_NAMESPACE_END
