#pragma once
/// @file bullet_world.h
/// foresight::bullet: predictions against a game's existing Bullet Physics world.
///
/// A game already on Bullet plugs in with one line and passes the world to the predictors:
/// @code
///   foresight::BulletWorld world(myDynamicsWorld);   // any btCollisionWorld
///   foresight::predictProjectile(position, velocity, 3.0f, settings, &world, points, result);
/// @endcode
/// BulletScene builds a static Bullet world from foresight's own shapes (tests, ground truth).
/// Link the CMake target foresight::bullet (built when FORESIGHT_WITH_BULLET is ON).
///
/// Axes and units are foresight's (metres, +Y up); Bullet's world is used as it is, without any
/// conversion, so it must use the same ones.

#include <foresight/static_world.h>
#include <foresight/world.h>

#include <btBulletCollisionCommon.h>

#include <memory>
#include <span>
#include <vector>

FORESIGHT_NAMESPACE_BEGIN

/// Settings of a BulletWorld.
struct BulletWorldSettings {
    /// Bullet collision filter group of the casts (btBroadphaseProxy bits); every bit by
    /// default, so that the casts see every object whose mask accepts any group.
    int collisionFilterGroup = btBroadphaseProxy::AllFilter;
    /// Bullet collision filter mask of the casts: which object groups they see (every one by
    /// default).
    int collisionFilterMask = btBroadphaseProxy::AllFilter;
    /// A cast that starts this close behind a one-sided surface (a plane, a convex solid, a
    /// mesh seen by a sphere) and moves into it hits at fraction 0, as in StaticWorld
    /// [Units: m] [Limit: >= 0]. Measured along the cast (the cast is started this far back);
    /// 4 ulps of btScalar at the origin's coordinates are added.
    float surfaceTolerance = 1e-5f;
};

/// A CollisionWorld that asks a btCollisionWorld (or btDiscreteDynamicsWorld) for the hits.
///
/// - radius 0: btCollisionWorld::rayTest. radius > 0: convexSweepTest with a btSphereShape of
///   that radius (its collision margin is the radius itself, so the sphere is exact).
/// - The contract of CollisionWorld is kept: zero-length and non-finite casts hit nothing
///   (Bullet is not called); only hits that enter a surface count (`dot(displacement, normal)
///   < 0`); btStaticPlaneShape is one-sided (Bullet's own ray test hits it from behind too;
///   those hits are dropped); triangle meshes are two-sided for rays, as StaticWorld's
///   triangles; a start on a one-sided surface moving in hits at fraction 0 (see
///   BulletWorldSettings::surfaceTolerance). A ray that starts deep inside a convex solid is
///   Bullet's to answer (it usually reports no hit).
/// - Accuracy is Bullet's: ray hits on planes, boxes and meshes are exact to btScalar rounding;
///   on spheres and other implicit convex shapes they come from Bullet's GJK ray cast (about
///   1e-4 m). Sphere sweeps (btContinuousConvexCollision, conservative advancement) stop up to
///   about 1 mm short of the contact along the normal, so the reported centre is that far off
///   the surface instead of touching it: the projectile then bounces up to that early (see
///   tests/bullet_test.cpp for the measured deviations). Box collision margins round a box's
///   edges unless the box was given setMargin(0) (BulletScene does).
/// - No allocation per cast once Bullet's broadphase has grown its ray-test stack (the first
///   casts may allocate through btAlignedAlloc; the callbacks and the sphere are stack objects).
/// - Thread safety: btCollisionWorld::rayTest and convexSweepTest do not modify the world, but
///   btDbvtBroadphase (the usual broadphase) walks its tree with a stack it owns, shared by every
///   thread unless Bullet was built with BT_THREADSAFE (then one stack per thread, up to
///   BT_MAX_THREAD_COUNT). Debian's and most distributions' libbullet are not: run predictions on
///   one BulletWorld from one thread at a time, or build Bullet with BT_THREADSAFE. The world
///   must not be stepped or edited while a prediction runs.
class BulletWorld final : public CollisionWorld {
public:
    /// Wraps `world`, which must outlive this object (it is referenced, not copied).
    explicit BulletWorld(const btCollisionWorld& world, const BulletWorldSettings& settings = {})
        : mWorld(&world), mSettings(settings) {}

    bool castSegment(const SegmentCast& cast, CastHit& hit) const override;

    /// The wrapped Bullet world.
    const btCollisionWorld& bulletWorld() const { return *mWorld; }
    /// The settings given at construction.
    const BulletWorldSettings& settings() const { return mSettings; }

private:
    const btCollisionWorld* mWorld;
    BulletWorldSettings mSettings;
};

/// A static Bullet world (btCollisionWorld with a btDbvtBroadphase) built from foresight's
/// shapes, which owns everything Bullet needs. For tests and ground-truth comparisons against
/// StaticWorld; a game passes its own world to BulletWorld instead.
///
/// Shapes map to: Plane -> btStaticPlaneShape; Sphere -> btSphereShape; OrientedBox ->
/// btBoxShape with its collision margin set to 0 (Bullet's default 0.04 m margin would round
/// the box's edges and corners by 4 cm); triangles -> btBvhTriangleMeshShape (margin 0) over a
/// btTriangleMesh. Positions are converted to btScalar (float in the default Bullet build).
class BulletScene {
public:
    BulletScene();
    ~BulletScene();
    BulletScene(const BulletScene&) = delete;
    BulletScene& operator=(const BulletScene&) = delete;

    /// Adds a shape after validating it as StaticWorld::add does (same Status values);
    /// nothing is added unless Ok is returned.
    Status add(const Plane& plane);
    /// See add(const Plane&).
    Status add(const Sphere& sphere);
    /// See add(const Plane&).
    Status add(const OrientedBox& box);
    /// One triangle (a mesh of one). See add(const Plane&).
    Status add(const Triangle& triangle);
    /// A triangle mesh as one btBvhTriangleMeshShape; every triangle is validated first
    /// (DegenerateShape, NonFiniteInput) and nothing is added unless all are valid. An empty
    /// span adds nothing and returns Ok.
    Status addMesh(std::span<const Triangle> triangles);
    /// Every shape of `world` (its triangles as one mesh). Returns the first refusal.
    Status add(const StaticWorld& world);

    /// Number of collision objects (a mesh counts once).
    std::size_t objectCount() const { return mObjects.size(); }

    /// The Bullet world, to wrap in a BulletWorld or to inspect.
    const btCollisionWorld& world() const { return *mWorld; }
    /// See world() const.
    btCollisionWorld& world() { return *mWorld; }

private:
    void addObject(std::unique_ptr<btCollisionShape> shape, const btTransform& transform);

    std::unique_ptr<btDefaultCollisionConfiguration> mConfiguration;
    std::unique_ptr<btCollisionDispatcher> mDispatcher;
    std::unique_ptr<btDbvtBroadphase> mBroadphase;
    std::unique_ptr<btCollisionWorld> mWorld;
    std::vector<std::unique_ptr<btTriangleMesh>> mMeshes;
    std::vector<std::unique_ptr<btCollisionShape>> mShapes;
    std::vector<std::unique_ptr<btCollisionObject>> mObjects;
};

FORESIGHT_NAMESPACE_END
