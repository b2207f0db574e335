#include <foresight/bullet_world.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

FORESIGHT_NAMESPACE_BEGIN

namespace {

btVector3 toBt(const glm::dvec3& v) {
    return btVector3(static_cast<btScalar>(v.x), static_cast<btScalar>(v.y), static_cast<btScalar>(v.z));
}

glm::dvec3 toD(const btVector3& v) {
    return glm::dvec3(static_cast<double>(v.x()), static_cast<double>(v.y()), static_cast<double>(v.z()));
}

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
    bool accept(const btCollisionObject* object, const glm::dvec3& bulletNormal,
                double extendedFraction, double& bestDistance, glm::dvec3& bestNormal) const {
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

// Visits the objects whose bounds the cast's swept bounds overlap (Bullet's broadphase), as
// btCollisionWorld::rayTest and convexSweepTest do, and tests each: Bullet's primitive shapes
// (planes, spheres, boxes) with foresight's exact tests (ClosestHitCaster), every other shape
// with Bullet's own narrowphase (rayTestSingle / objectQuerySingle) and the callbacks above.
struct BroadphaseVisitor final : btBroadphaseRayCallback {
    const BulletWorldSettings* settings = nullptr;
    ClosestHitCaster* caster = nullptr;
    // Bullet's narrowphase, for the other shapes.
    btTransform from, to;
    const btConvexShape* sphere = nullptr;  // null: a ray
    btTransform exactFrom;               // the real origin (rays against meshes)
    RayCallback* rayCallback = nullptr;  // convex and other shapes: cast from `from`
    RayCallback* meshRayCallback = nullptr;  // concave shapes: cast from `exactFrom`
    SweepCallback* sweepCallback = nullptr;

    bool process(const btBroadphaseProxy* proxy) override {
        // Bullet's filter rule (RayResultCallback::needsCollision).
        if ((proxy->m_collisionFilterGroup & settings->collisionFilterMask) == 0 ||
            (settings->collisionFilterGroup & proxy->m_collisionFilterMask) == 0)
            return true;
        const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
        const btCollisionShape* shape = object->getCollisionShape();
        const btTransform& transform = object->getWorldTransform();
        switch (shape->getShapeType()) {
        case SPHERE_SHAPE_PROXYTYPE: {
            // getRadius() includes the shape's local scaling.
            const auto* s = static_cast<const btSphereShape*>(shape);
            caster->test(Sphere{toVec<Real>(transform.getOrigin()), static_cast<float>(s->getRadius())});
            return true;
        }
        case BOX_SHAPE_PROXYTYPE: {
            // The outer box (margin and scaling included), with sharp edges: a box with the
            // default margin is rounded by it in Bullet's own tests.
            const auto* b = static_cast<const btBoxShape*>(shape);
            const btQuaternion r = transform.getRotation();
            OrientedBox box;
            box.center = toVec<Real>(transform.getOrigin());
            box.halfExtents = toVec<float>(b->getHalfExtentsWithMargin());
            box.orientation.w = static_cast<float>(r.w());
            box.orientation.x = static_cast<float>(r.x());
            box.orientation.y = static_cast<float>(r.y());
            box.orientation.z = static_cast<float>(r.z());
            caster->test(box);
            return true;
        }
        case STATIC_PLANE_PROXYTYPE: {
            const auto* p = static_cast<const btStaticPlaneShape*>(shape);
            const btVector3 normal = transform.getBasis() * p->getPlaneNormal();
            const btScalar distance = p->getPlaneConstant() + normal.dot(transform.getOrigin());
            caster->test(Plane{toVec<float>(normal), static_cast<Real>(distance)});
            return true;
        }
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

}  // namespace

bool BulletWorld::castSegment(const SegmentCast& cast, CastHit& hit) const {
    const glm::dvec3 origin(static_cast<double>(cast.origin.x), static_cast<double>(cast.origin.y),
                            static_cast<double>(cast.origin.z));
    const glm::dvec3 displacement(static_cast<double>(cast.displacement.x),
                                  static_cast<double>(cast.displacement.y),
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
        visitor.m_rayDirectionInverse[i] = direction[i] == btScalar(0) ? btScalar(BT_LARGE_FLOAT) : btScalar(1) / direction[i];
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
    hit.position = RVec3(static_cast<Real>(position.x), static_cast<Real>(position.y),
                         static_cast<Real>(position.z));
    hit.normal = Vec3(static_cast<float>(bestNormal.x), static_cast<float>(bestNormal.y),
                      static_cast<float>(bestNormal.z));
    return true;
}

FORESIGHT_NAMESPACE_END
