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

    double bestDistance = std::numeric_limits<double>::infinity();
    glm::dvec3 bestNormal(0.0, 1.0, 0.0);
    if (radius <= 0.0) {
        RayCallback callback;
        callback.filter = &filter;
        callback.m_collisionFilterGroup = mSettings.collisionFilterGroup;
        callback.m_collisionFilterMask = mSettings.collisionFilterMask;
        mWorld->rayTest(from, to, callback);
        bestDistance = callback.bestDistance;
        bestNormal = callback.bestNormal;
    } else {
        // A stack object: no allocation. Its margin is its radius (the sphere is all margin).
        btSphereShape sphere(static_cast<btScalar>(radius));
        SweepCallback callback;
        callback.filter = &filter;
        callback.m_collisionFilterGroup = mSettings.collisionFilterGroup;
        callback.m_collisionFilterMask = mSettings.collisionFilterMask;
        btTransform fromTransform, toTransform;
        fromTransform.setIdentity();
        fromTransform.setOrigin(from);
        toTransform.setIdentity();
        toTransform.setOrigin(to);
        mWorld->convexSweepTest(&sphere, fromTransform, toTransform, callback, btScalar(0));
        bestDistance = callback.bestDistance;
        bestNormal = callback.bestNormal;
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
