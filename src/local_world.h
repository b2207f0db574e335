#pragma once
// A small copy of a world's shapes around one place (CollisionWorld::gatherShapes), answering the
// many small queries of a few steps there without the world. Internal to the library.

#include "internal.h"

#include <foresight/static_world.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {

/// The shapes a world gathered for a region (a capsule), in the world's tie-breaking order, and a
/// CollisionWorld over them. A swept-sphere castSegment (radius > 0) or a findNear whose whole
/// volume lies inside the region is answered from the copies, with the shape tests StaticWorld
/// runs in the same order (so the world's own answer, by CollisionWorld::gatherShapes' promise);
/// every other query goes to the world. Each query tests only the shapes whose bounding box
/// meets its own. Fixed capacity, no allocation.
class LocalWorld final : public CollisionWorld, private ShapeCollector {
public:
    static constexpr std::size_t kMaxTriangles = 128;
    static constexpr std::size_t kMaxBoxes = 16;
    static constexpr std::size_t kMaxSpheres = 16;
    static constexpr std::size_t kMaxPlanes = 8;

    /// Gathers `world`'s shapes within `region`; false (and every query then goes to `world`)
    /// when the world cannot gather or there are more shapes than room.
    bool gather(const CollisionWorld& world, const SegmentCast& region) {
        mWorld = &world;
        mShapeCount = mTriangleCount = mBoxCount = mSphereCount = mPlaneCount = 0;
        mTolerance = 0.0;
        mA = DVec3(region.origin);
        mB = mA + DVec3(region.displacement);
        mRadius = static_cast<double>(region.radius);
        mValid = world.gatherShapes(region, *this);
        return mValid;
    }

    /// Whether a sphere of `radius` around every point of the segment a..b lies inside the region
    /// (with the margins of the world's surface tolerance and of rounding).
    bool holds(const DVec3& a, const DVec3& b, double radius) const {
        if (!mValid) return false;
        const double reach = reachOf(radius, std::max(magnitude(a, b), magnitude(mA, mA)));
        if (!(reach < mRadius)) return false;
        // The distance to the region's segment is convex along a..b: the ends decide.
        return distanceToAxis(a) + reach <= mRadius && distanceToAxis(b) + reach <= mRadius;
    }

    bool castSegment(const SegmentCast& cast, CastHit& hit) const override {
        const DVec3 a(cast.origin), d(cast.displacement);
        if (!(cast.radius > 0.0f) || !holds(a, a + d, static_cast<double>(cast.radius)))
            return mWorld->castSegment(cast, hit);
        ClosestHitCaster caster(cast, static_cast<float>(mTolerance));
        if (!caster.valid()) return false;
        Bounds query;
        const double pad = reachOf(static_cast<double>(cast.radius), magnitude(a, a + d));
        query.lo = glm::min(a, a + d) - pad;
        query.hi = glm::max(a, a + d) + pad;
        testShapes(query, caster);
        return caster.result(hit);
    }

    bool findNear(const NearQuery& query, NearCollector& collector) const override {
        const DVec3 c(query.center);
        if (!holds(c, c, static_cast<double>(query.radius))) return mWorld->findNear(query, collector);
        NearTester tester(query, collector, static_cast<float>(mTolerance));
        if (!tester.valid()) return true;
        Bounds bounds;
        const double pad = reachOf(static_cast<double>(query.radius), magnitude(c, c));
        bounds.lo = c - pad;
        bounds.hi = c + pad;
        testShapes(bounds, tester);
        return true;
    }

    /// The boxes gathered, in the world's order (none when the world could not gather).
    std::span<const OrientedBox> boxes() const {
        return mValid ? std::span<const OrientedBox>(mBoxes.data(), mBoxCount) : std::span<const OrientedBox>();
    }
    /// The material of boxes()[i].
    const SurfaceMaterial& boxMaterial(std::size_t i) const { return mBoxMaterials[i]; }

    // The region queries serve long stretches of flight or rolling, beyond a gathered region:
    // the world answers them.
    bool mayTouch(const SegmentCast& capsule) const override { return mWorld->mayTouch(capsule); }
    bool firstTouch(const SegmentCast& capsule, float& fraction) const override {
        return mWorld->firstTouch(capsule, fraction);
    }
    bool firstTouchInFront(const SegmentCast& capsule, const InFrontOf& front, float& fraction) const override {
        return mWorld->firstTouchInFront(capsule, front, fraction);
    }
    bool isOnlyPlane(const PlaneRegion& region) const override { return mWorld->isOnlyPlane(region); }
    float regionQueryCost(float radius) const override { return mWorld->regionQueryCost(radius); }
    bool gatherShapes(const SegmentCast& region, ShapeCollector& collector) const override {
        return mWorld->gatherShapes(region, collector);
    }

private:
    enum class Kind : std::uint8_t { Plane, Sphere, Box, Triangle };
    struct Bounds {
        DVec3 lo, hi;
    };
    struct Entry {
        Kind kind;
        std::uint8_t index;
        Bounds bounds;  // the shape's bounding box (unused for planes) [m]
    };

    // Every shape whose bounds meet `bounds` (every plane), in order, through `tester.test(shape,
    // material)` (a ClosestHitCaster or a NearTester).
    template <class Tester>
    void testShapes(const Bounds& bounds, Tester& tester) const {
        for (std::size_t i = 0; i < mShapeCount; ++i) {
            const Entry& e = mShapes[i];
            if (e.kind == Kind::Plane)
                tester.test(mPlanes[e.index], mPlaneMaterials[e.index]);
            else if (!meets(e.bounds, bounds))
                continue;
            else if (e.kind == Kind::Sphere)
                tester.test(mSpheres[e.index], mSphereMaterials[e.index]);
            else if (e.kind == Kind::Box)
                tester.test(mBoxes[e.index], mBoxMaterials[e.index]);
            else
                tester.test(mTriangles[e.index], mTriangleMaterials[e.index]);
        }
    }
    static bool meets(const Bounds& a, const Bounds& b) {
        return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y && a.lo.z <= b.hi.z &&
               b.lo.z <= a.hi.z;
    }
    // A query's reach around its segment: its radius, the surface tolerance, and margins for the
    // rounding of coordinates of `magnitude` [m].
    double reachOf(double radius, double magnitude) const { return radius + mTolerance + 1e-4 + 1e-6 * magnitude; }
    static double magnitude(const DVec3& a, const DVec3& b) {
        return std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z), std::abs(b.x), std::abs(b.y), std::abs(b.z)});
    }
    double distanceToAxis(const DVec3& p) const {
        const DVec3 ab = mB - mA;
        const double ll = glm::dot(ab, ab);
        const double t = ll > 0.0 ? std::clamp(glm::dot(p - mA, ab) / ll, 0.0, 1.0) : 0.0;
        return glm::length(p - (mA + ab * t));
    }
    bool push(Kind kind, std::size_t index, const Bounds& bounds) {
        if (mShapeCount == mShapes.size()) return false;
        mShapes[mShapeCount++] = Entry{kind, static_cast<std::uint8_t>(index), bounds};
        return true;
    }

    // ShapeCollector
    void begin(float surfaceTolerance) override { mTolerance = std::max(0.0, static_cast<double>(surfaceTolerance)); }
    bool add(const Plane& plane, const SurfaceMaterial& material) override {
        if (mPlaneCount == kMaxPlanes) return false;
        mPlanes[mPlaneCount] = plane;
        mPlaneMaterials[mPlaneCount] = material;
        return push(Kind::Plane, mPlaneCount++, Bounds{});
    }
    bool add(const Sphere& sphere, const SurfaceMaterial& material) override {
        if (mSphereCount == kMaxSpheres) return false;
        mSpheres[mSphereCount] = sphere;
        mSphereMaterials[mSphereCount] = material;
        const DVec3 c(sphere.center);
        const double r = static_cast<double>(sphere.radius) * (1.0 + 1e-6);
        return push(Kind::Sphere, mSphereCount++, grown(Bounds{c - r, c + r}));
    }
    bool add(const OrientedBox& box, const SurfaceMaterial& material) override {
        if (mBoxCount == kMaxBoxes) return false;
        mBoxes[mBoxCount] = box;
        mBoxMaterials[mBoxCount] = material;
        // The rotated box's extent along each world axis (the rounding as a sphere around it).
        const glm::dmat3 m = glm::mat3_cast(glm::normalize(DQuat(box.orientation)));
        const DVec3 h(box.halfExtents);
        DVec3 extent(0.0);
        for (int axis = 0; axis < 3; ++axis) extent += glm::abs(m[axis]) * h[axis];
        extent += static_cast<double>(box.rounding);
        const DVec3 c(box.center);
        return push(Kind::Box, mBoxCount++, grown(Bounds{c - extent, c + extent}));
    }
    bool add(const Triangle& triangle, const SurfaceMaterial& material) override {
        if (mTriangleCount == kMaxTriangles) return false;
        mTriangles[mTriangleCount] = triangle;
        mTriangleMaterials[mTriangleCount] = material;
        const DVec3 a(triangle.a), b(triangle.b), c(triangle.c);
        return push(Kind::Triangle, mTriangleCount++,
                    grown(Bounds{glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c))}));
    }
    // A bounding box grown by a relative margin for the rounding of whatever computed it.
    static Bounds grown(Bounds b) {
        const double margin = 1e-9 * (1.0 + magnitude(b.lo, b.hi));
        b.lo -= margin;
        b.hi += margin;
        return b;
    }

    const CollisionWorld* mWorld = nullptr;
    bool mValid = false;
    DVec3 mA{0.0}, mB{0.0};  // the region's segment [m]
    double mRadius = 0.0;    // the region's radius [m]
    double mTolerance = 0.0;
    // Left uninitialised (the first counts are used): a prediction need not clear 17 KB.
    std::array<Entry, kMaxTriangles + kMaxBoxes + kMaxSpheres + kMaxPlanes> mShapes;
    std::size_t mShapeCount = 0;
    std::array<Triangle, kMaxTriangles> mTriangles;
    std::array<SurfaceMaterial, kMaxTriangles> mTriangleMaterials;
    std::array<OrientedBox, kMaxBoxes> mBoxes;
    std::array<SurfaceMaterial, kMaxBoxes> mBoxMaterials;
    std::array<Sphere, kMaxSpheres> mSpheres;
    std::array<SurfaceMaterial, kMaxSpheres> mSphereMaterials;
    std::array<Plane, kMaxPlanes> mPlanes;
    std::array<SurfaceMaterial, kMaxPlanes> mPlaneMaterials;
    std::size_t mTriangleCount = 0, mBoxCount = 0, mSphereCount = 0, mPlaneCount = 0;
};

}  // namespace detail
FORESIGHT_NAMESPACE_END
