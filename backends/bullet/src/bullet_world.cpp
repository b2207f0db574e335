#include <foresight/bullet_world.h>

#include "bullet_convert.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

FORESIGHT_NAMESPACE_BEGIN

namespace {

using bullet_detail::toBt;
using bullet_detail::toD;

// What a hit reported by Bullet means under CollisionWorld's rules. The cast Bullet runs starts
// `skin` before the real origin (so that a start on a surface, or just behind it, still sees
// it); `castLength` is the real segment's length.
struct HitFilter {
    glm::dvec3 direction{0.0};  // unit, of the real segment
    double skin = 0.0;
    double castLength = 0.0;
    bool sphere = false;  // a swept sphere: meshes are thick solids, one-sided as convex shapes

    // Offers a hit at `extendedFraction` of the extended cast with Bullet's world normal;
    // keeps it in `best*` when it is an entering hit closer than the current one.
    bool accept(const btCollisionObject* object, const glm::dvec3& bulletNormal, double extendedFraction,
                double& bestDistance, glm::dvec3& bestNormal) const {
        const btCollisionShape* shape = object->getCollisionShape();
        glm::dvec3 normal = bulletNormal;
        bool twoSided = false;
        if (shape->getShapeType() == STATIC_PLANE_PROXYTYPE) {
            // One-sided: Bullet's ray test also reports the back face (normal facing the ray).
            const auto* plane = static_cast<const btStaticPlaneShape*>(shape);
            normal = toD(object->getWorldTransform().getBasis() * plane->getPlaneNormal());
        } else if (shape->isConcave()) {
            twoSided = !sphere;  // Bullet's normal faces the side the ray comes from
        }
        const double length = glm::length(normal);
        if (!(length > 0.0)) return false;
        normal /= length;
        if (!(glm::dot(normal, direction) < 0.0)) return false;  // not entering
        const double distance = extendedFraction * (castLength + skin) - skin;
        // A two-sided triangle crossed within the skin lies behind the real start (which is
        // past it, moving away): StaticWorld ignores it, so does this.
        if (twoSided && distance < 0.0) return false;
        const double clamped = std::max(0.0, distance);
        if (clamped >= bestDistance) return false;
        bestDistance = clamped;
        bestNormal = normal;
        return true;
    }
};

struct RayCallback final : btCollisionWorld::RayResultCallback {
    const HitFilter* filter = nullptr;
    double bestDistance = std::numeric_limits<double>::infinity();
    glm::dvec3 bestNormal{0.0, 1.0, 0.0};

    btScalar addSingleResult(btCollisionWorld::LocalRayResult& result, bool normalInWorldSpace) override {
        btVector3 normal = result.m_hitNormalLocal;
        if (!normalInWorldSpace) normal = result.m_collisionObject->getWorldTransform().getBasis() * normal;
        if (filter->accept(result.m_collisionObject, toD(normal), static_cast<double>(result.m_hitFraction),
                           bestDistance, bestNormal)) {
            m_collisionObject = result.m_collisionObject;
            // Bullet skips objects whose hit is beyond this; rejected hits leave it unchanged.
            m_closestHitFraction = result.m_hitFraction;
        }
        return m_closestHitFraction;
    }
};

struct SweepCallback final : btCollisionWorld::ConvexResultCallback {
    const HitFilter* filter = nullptr;
    double bestDistance = std::numeric_limits<double>::infinity();
    glm::dvec3 bestNormal{0.0, 1.0, 0.0};
    const btCollisionObject* hitObject = nullptr;

    btScalar addSingleResult(btCollisionWorld::LocalConvexResult& result, bool normalInWorldSpace) override {
        btVector3 normal = result.m_hitNormalLocal;
        if (!normalInWorldSpace) normal = result.m_hitCollisionObject->getWorldTransform().getBasis() * normal;
        if (filter->accept(result.m_hitCollisionObject, toD(normal), static_cast<double>(result.m_hitFraction),
                           bestDistance, bestNormal)) {
            hitObject = result.m_hitCollisionObject;
            m_closestHitFraction = result.m_hitFraction;
        }
        return m_closestHitFraction;
    }
};

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

template <class T>
glm::vec<3, T, glm::defaultp> toVec(const btVector3& v) {
    return glm::vec<3, T, glm::defaultp>(static_cast<T>(v.x()), static_cast<T>(v.y()), static_cast<T>(v.z()));
}

// Bullet's filter rule (RayResultCallback::needsCollision) for the queries' group and mask.
bool passesFilter(const BulletWorldSettings& settings, const btBroadphaseProxy& proxy) {
    return (proxy.m_collisionFilterGroup & settings.collisionFilterMask) != 0 &&
           (settings.collisionFilterGroup & proxy.m_collisionFilterMask) != 0;
}

// Bullet's primitive shapes as foresight's: a sphere (getRadius() includes the local scaling),
// the outer box (margin and scaling included) with sharp edges (a box with the default margin
// is rounded by it in Bullet's own tests), a static plane in world coordinates.
Sphere sphereOf(const btSphereShape& s, const btTransform& transform) {
    return Sphere{toVec<Real>(transform.getOrigin()), static_cast<float>(s.getRadius())};
}
OrientedBox boxOf(const btBoxShape& b, const btTransform& transform) {
    const btQuaternion r = transform.getRotation();
    OrientedBox box;
    box.center = toVec<Real>(transform.getOrigin());
    box.halfExtents = toVec<float>(b.getHalfExtentsWithMargin());
    box.orientation.w = static_cast<float>(r.w());
    box.orientation.x = static_cast<float>(r.x());
    box.orientation.y = static_cast<float>(r.y());
    box.orientation.z = static_cast<float>(r.z());
    return box;
}
Plane planeOf(const btStaticPlaneShape& p, const btTransform& transform) {
    const btVector3 normal = transform.getBasis() * p.getPlaneNormal();
    const btScalar distance = p.getPlaneConstant() + normal.dot(transform.getOrigin());
    return Plane{toVec<float>(normal), static_cast<Real>(distance)};
}

// Visits the objects whose bounds the cast's swept bounds overlap (Bullet's broadphase), as
// btCollisionWorld::rayTest and convexSweepTest do, and tests each: Bullet's primitive shapes
// (planes, spheres, boxes) with foresight's exact tests (ClosestHitCaster), every other shape
// with Bullet's own narrowphase (rayTestSingle / objectQuerySingle) and the callbacks above.
struct BroadphaseVisitor final : btBroadphaseRayCallback {
    const BulletWorldSettings* settings = nullptr;
    ClosestHitCaster* caster = nullptr;
    // Bullet's narrowphase, for the other shapes.
    btTransform from, to;
    const btConvexShape* sphere = nullptr;   // null: a ray
    btTransform exactFrom;                   // the real origin (rays against meshes)
    RayCallback* rayCallback = nullptr;      // convex and other shapes: cast from `from`
    RayCallback* meshRayCallback = nullptr;  // concave shapes: cast from `exactFrom`
    SweepCallback* sweepCallback = nullptr;

    bool process(const btBroadphaseProxy* proxy) override {
        if (!passesFilter(*settings, *proxy)) return true;
        const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
        const btCollisionShape* shape = object->getCollisionShape();
        const btTransform& transform = object->getWorldTransform();
        switch (shape->getShapeType()) {
            case SPHERE_SHAPE_PROXYTYPE:
                caster->test(sphereOf(*static_cast<const btSphereShape*>(shape), transform));
                return true;
            case BOX_SHAPE_PROXYTYPE:
                caster->test(boxOf(*static_cast<const btBoxShape*>(shape), transform));
                return true;
            case STATIC_PLANE_PROXYTYPE:
                caster->test(planeOf(*static_cast<const btStaticPlaneShape*>(shape), transform));
                return true;
            default:
                break;
        }
        if (sphere == nullptr && shape->isConcave())
            // Two-sided triangles: a start on a triangle's plane ignores it (as in StaticWorld),
            // which Bullet's ray-triangle test does when the ray starts exactly there; with the
            // skin, float rounding of the fraction would decide instead.
            btCollisionWorld::rayTestSingle(exactFrom, to, const_cast<btCollisionObject*>(object), shape, transform,
                                            *meshRayCallback);
        else if (sphere == nullptr)
            btCollisionWorld::rayTestSingle(from, to, const_cast<btCollisionObject*>(object), shape, transform,
                                            *rayCallback);
        else
            btCollisionWorld::objectQuerySingle(sphere, from, to, const_cast<btCollisionObject*>(object), shape,
                                                transform, *sweepCallback, btScalar(0));
        return true;
    }
};

// The shapes of the objects whose bounds meet an axis-aligned box (Bullet's broadphase, with
// the casts' filter rule), as foresight's: spheres, boxes and planes as BroadphaseVisitor
// read them, a concave shape's triangles inside the box one by one (in world coordinates),
// and `other` for any other shape. `Visit` returns false to stop.
template <class Visit>
struct ShapeVisitor final : btBroadphaseAabbCallback {
    const BulletWorldSettings* settings = nullptr;
    btVector3 lo, hi;  // the box, world coordinates
    Visit* visit = nullptr;
    bool stopped = false;

    struct Triangles final : btTriangleCallback {
        ShapeVisitor* owner = nullptr;
        btTransform transform;
        void processTriangle(btVector3* t, int, int) override {
            if (owner->stopped) return;
            const Triangle triangle{toVec<Real>(transform * t[0]), toVec<Real>(transform * t[1]),
                                    toVec<Real>(transform * t[2])};
            if (!(*owner->visit)(triangle)) owner->stopped = true;
        }
    };

    bool process(const btBroadphaseProxy* proxy) override {
        if (stopped) return false;
        if (!passesFilter(*settings, *proxy)) return true;
        const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
        const btCollisionShape* shape = object->getCollisionShape();
        const btTransform& transform = object->getWorldTransform();
        bool go = true;
        switch (shape->getShapeType()) {
            case SPHERE_SHAPE_PROXYTYPE:
                go = (*visit)(sphereOf(*static_cast<const btSphereShape*>(shape), transform));
                break;
            case BOX_SHAPE_PROXYTYPE:
                go = (*visit)(boxOf(*static_cast<const btBoxShape*>(shape), transform));
                break;
            case STATIC_PLANE_PROXYTYPE:
                go = (*visit)(planeOf(*static_cast<const btStaticPlaneShape*>(shape), transform));
                break;
            default:
                if (shape->isConcave()) {
                    // The box in the shape's frame: the bounds of its corners taken there.
                    const btTransform inverse = transform.inverse();
                    btVector3 localLo(BT_LARGE_FLOAT, BT_LARGE_FLOAT, BT_LARGE_FLOAT), localHi = -localLo;
                    for (int corner = 0; corner < 8; ++corner) {
                        const btVector3 c((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(),
                                          (corner & 4) ? hi.z() : lo.z());
                        const btVector3 l = inverse * c;
                        localLo.setMin(l);
                        localHi.setMax(l);
                    }
                    Triangles triangles;
                    triangles.owner = this;
                    triangles.transform = transform;
                    static_cast<const btConcaveShape*>(shape)->processAllTriangles(&triangles, localLo, localHi);
                } else {
                    go = (*visit)(shape);  // another shape: the visitor decides
                }
                break;
        }
        if (!go) stopped = true;
        return !stopped;
    }
};

// The bounds of a capsule, grown by its radius and a margin for the rounding to btScalar.
template <class Visit>
bool visitNear(const btCollisionWorld& world, const BulletWorldSettings& settings, const SegmentCast& capsule,
               Visit visit) {
    const glm::dvec3 a(static_cast<double>(capsule.origin.x), static_cast<double>(capsule.origin.y),
                       static_cast<double>(capsule.origin.z));
    const glm::dvec3 b = a + glm::dvec3(capsule.displacement);
    const double magnitude =
        std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z), std::abs(b.x), std::abs(b.y), std::abs(b.z), 1.0});
    const double grow = std::max(0.0, static_cast<double>(capsule.radius)) + 1e-4 +
                        8.0 * magnitude * static_cast<double>(std::numeric_limits<btScalar>::epsilon());
    if (!std::isfinite(magnitude + grow) || magnitude > 1e15) return false;
    ShapeVisitor<Visit> visitor;
    visitor.settings = &settings;
    visitor.lo = toBt(glm::min(a, b) - grow);
    visitor.hi = toBt(glm::max(a, b) + grow);
    visitor.visit = &visit;
    btBroadphaseInterface* broadphase = const_cast<btBroadphaseInterface*>(world.getBroadphase());
    broadphase->aabbTest(visitor.lo, visitor.hi, visitor);
    return true;
}

}  // namespace

bool BulletWorld::mayTouch(const SegmentCast& capsule) const {
    // Bullet's own sphere sweep against a mesh stops up to about 1 mm before the surface (see
    // castSegment): its triangles are tested against a capsule 2 mm wider.
    SegmentCast wider = capsule;
    wider.radius = std::max(0.0f, capsule.radius) + 2e-3f;
    bool touched = false;
    const bool visited = visitNear(*mWorld, mSettings, wider, [&](const auto& shape) {
        using Shape = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<Shape, const btCollisionShape*>)
            touched = true;  // a shape foresight does not test: maybe
        else if constexpr (std::is_same_v<Shape, Triangle>)
            touched = foresight::mayTouch(wider, shape);
        else
            touched = foresight::mayTouch(capsule, shape);
        return !touched;
    });
    return touched || !visited;  // beyond btScalar's range: maybe
}

bool BulletWorld::firstTouch(const SegmentCast& capsule, float& fraction) const {
    // As mayTouch: the triangles of concave shapes 2 mm closer.
    SegmentCast wider = capsule;
    wider.radius = std::max(0.0f, capsule.radius) + 2e-3f;
    bool touched = false;
    fraction = 1.0f;
    const bool visited = visitNear(*mWorld, mSettings, wider, [&](const auto& shape) {
        using Shape = std::decay_t<decltype(shape)>;
        float f = 0.0f;
        bool touches = true;  // a shape foresight does not test: maybe, at once
        if constexpr (std::is_same_v<Shape, Triangle>)
            touches = foresight::firstTouch(wider, shape, f);
        else if constexpr (!std::is_same_v<Shape, const btCollisionShape*>)
            touches = foresight::firstTouch(capsule, shape, f);
        if (touches) {
            touched = true;
            fraction = std::min(fraction, f);
        }
        return fraction > 0.0f;
    });
    if (!visited) {  // beyond btScalar's range: maybe, at once
        fraction = 0.0f;
        return true;
    }
    if (!touched) fraction = 0.0f;
    return touched;
}

bool BulletWorld::isOnlyPlane(const PlaneRegion& region) const {
    if (mSettings.surfaceTolerance != StaticWorldSettings{}.surfaceTolerance) return false;
    PlaneRegionTester tester(region);
    bool other = false;
    // Meshes are answered by Bullet's own sweep (1 mm and a few degrees off the exact hit): no
    // promise where one reaches in; nor where any other shape foresight does not test does.
    SegmentCast wider = region.capsule;
    wider.radius = std::max(0.0f, wider.radius) + 2e-3f;
    const bool visited = visitNear(*mWorld, mSettings, wider, [&](const auto& shape) {
        using Shape = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<Shape, const btCollisionShape*>)
            other = true;
        else if constexpr (std::is_same_v<Shape, Triangle>)
            other = other || foresight::mayTouch(wider, shape);
        else
            tester.test(shape);
        return !other && !tester.failed();
    });
    return visited && !other && tester.result();
}

bool BulletWorld::findNear(const NearQuery& query, NearCollector& collector) const {
    NearTester tester(query, collector, mSettings.surfaceTolerance);
    if (!tester.valid()) return true;
    SegmentCast sphere;
    sphere.origin = query.center;
    sphere.radius = query.radius;
    return visitNear(*mWorld, mSettings, sphere, [&](const auto& shape) {
        using Shape = std::decay_t<decltype(shape)>;
        if constexpr (!std::is_same_v<Shape, const btCollisionShape*>) tester.test(shape);
        return true;
    });
}

bool BulletWorld::castSegment(const SegmentCast& cast, CastHit& hit) const {
    const glm::dvec3 origin(static_cast<double>(cast.origin.x), static_cast<double>(cast.origin.y),
                            static_cast<double>(cast.origin.z));
    const glm::dvec3 displacement(static_cast<double>(cast.displacement.x), static_cast<double>(cast.displacement.y),
                                  static_cast<double>(cast.displacement.z));
    const double length = glm::length(displacement);
    // Zero-length and non-finite casts hit nothing (and are never given to Bullet).
    if (!(length > 0.0) || !std::isfinite(length) || !finite(origin)) return false;
    const double radius = static_cast<double>(cast.radius);
    if (!(radius >= 0.0) || !std::isfinite(radius)) return false;

    HitFilter filter;
    filter.direction = displacement / length;
    filter.castLength = length;
    filter.sphere = radius > 0.0;
    // The tolerance plus 4 ulps of btScalar at the origin's coordinates: Bullet computes in
    // btScalar, so a start on a surface is only known to that.
    const double magnitude = std::max({std::abs(origin.x), std::abs(origin.y), std::abs(origin.z), 1.0});
    filter.skin = static_cast<double>(std::max(0.0f, mSettings.surfaceTolerance)) +
                  4.0 * magnitude * static_cast<double>(std::numeric_limits<btScalar>::epsilon());
    const btVector3 from = toBt(origin - filter.direction * filter.skin);
    const btVector3 to = toBt(origin + displacement);

    ClosestHitCaster caster(cast, mSettings.surfaceTolerance);
    BroadphaseVisitor visitor;
    visitor.settings = &mSettings;
    visitor.caster = &caster;
    visitor.from.setIdentity();
    visitor.from.setOrigin(from);
    visitor.to.setIdentity();
    visitor.to.setOrigin(to);
    visitor.exactFrom.setIdentity();
    visitor.exactFrom.setOrigin(toBt(origin));
    // The broadphase's ray walk (as in btCollisionWorld::rayTest).
    btVector3 direction = to - from;
    direction.normalize();
    for (int i = 0; i < 3; ++i) {
        visitor.m_rayDirectionInverse[i] =
            direction[i] == btScalar(0) ? btScalar(BT_LARGE_FLOAT) : btScalar(1) / direction[i];
        visitor.m_signs[i] = visitor.m_rayDirectionInverse[i] < btScalar(0) ? 1u : 0u;
    }
    visitor.m_lambda_max = direction.dot(to - from);

    // Bullet's collision world is const here, as in its own const rayTest, whose broadphase
    // walk goes through the same non-const pointer.
    btBroadphaseInterface* broadphase = const_cast<btBroadphaseInterface*>(mWorld->getBroadphase());
    RayCallback rayCallback, meshRayCallback;
    HitFilter meshFilter = filter;
    meshFilter.skin = 0.0;
    SweepCallback sweepCallback;
    double bestDistance = std::numeric_limits<double>::infinity();
    glm::dvec3 bestNormal(0.0, 1.0, 0.0);
    if (radius <= 0.0) {
        rayCallback.filter = &filter;
        rayCallback.m_flags = mSettings.rayFlags;
        meshRayCallback.filter = &meshFilter;
        meshRayCallback.m_flags = mSettings.rayFlags;
        visitor.rayCallback = &rayCallback;
        visitor.meshRayCallback = &meshRayCallback;
        broadphase->rayTest(from, to, visitor);
        const bool mesh = meshRayCallback.bestDistance < rayCallback.bestDistance;
        bestDistance = mesh ? meshRayCallback.bestDistance : rayCallback.bestDistance;
        bestNormal = mesh ? meshRayCallback.bestNormal : rayCallback.bestNormal;
    } else {
        // A stack object: no allocation. Its margin is its radius (the sphere is all margin).
        btSphereShape sphere(static_cast<btScalar>(radius));
        sweepCallback.filter = &filter;
        visitor.sphere = &sphere;
        visitor.sweepCallback = &sweepCallback;
        const btVector3 extent(sphere.getRadius(), sphere.getRadius(), sphere.getRadius());
        broadphase->rayTest(from, to, visitor, -extent, extent);
        bestDistance = sweepCallback.bestDistance;
        bestNormal = sweepCallback.bestNormal;
    }
    CastHit exact;
    if (caster.result(exact) && static_cast<double>(exact.fraction) * length <= bestDistance) {
        hit = exact;
        return true;
    }
    if (!(bestDistance <= length)) return false;
    const double fraction = std::clamp(bestDistance / length, 0.0, 1.0);
    hit.fraction = static_cast<float>(fraction);
    const glm::dvec3 position = origin + displacement * fraction;
    hit.position = RVec3(static_cast<Real>(position.x), static_cast<Real>(position.y), static_cast<Real>(position.z));
    hit.normal =
        Vec3(static_cast<float>(bestNormal.x), static_cast<float>(bestNormal.y), static_cast<float>(bestNormal.z));
    return true;
}

FORESIGHT_NAMESPACE_END
