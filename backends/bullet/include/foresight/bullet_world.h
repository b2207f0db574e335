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

#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <BulletDynamics/ConstraintSolver/btSequentialImpulseConstraintSolver.h>
#include <BulletDynamics/Dynamics/btDiscreteDynamicsWorld.h>
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
    /// [Units: m] [Limit: >= 0]. Planes, spheres and boxes: StaticWorldSettings::surfaceTolerance.
    /// Shapes Bullet answers for: measured along the cast (Bullet's cast starts this far back,
    /// plus 4 ulps of btScalar at the origin's coordinates).
    float surfaceTolerance = 1e-5f;
    /// btTriangleRaycastCallback::EFlags for Bullet's ray tests (RayResultCallback::m_flags), on
    /// the shapes Bullet answers for. The default asks for Bullet's GJK ray cast against convex
    /// shapes (cylinders, hulls, ...): Bullet's own default, the sub-simplex cast, stops up to
    /// about a centimetre before the surface.
    unsigned int rayFlags = btTriangleRaycastCallback::kF_UseGjkConvexCastRaytest;
};

/// A CollisionWorld that asks a btCollisionWorld (or btDiscreteDynamicsWorld) for the hits.
///
/// - Bullet's broadphase finds the objects along the cast (as btCollisionWorld::rayTest and
///   convexSweepTest do, with the same collision filter rule). Bullet's primitive shapes,
///   btStaticPlaneShape, btSphereShape and btBoxShape, are then tested with foresight's exact
///   tests (ClosestHitCaster, the same as StaticWorld's): Bullet's own convex ray casts are off
///   by millimetres to a centimetre on them (sub-simplex: up to 1.6 cm on boxes, 7 mm on spheres;
///   GJK: 4 mm on spheres and missed hits on margin-free boxes; measured in
///   tests/bullet_test.cpp). Boxes are taken at their outer size (margin included) with sharp
///   edges; local scaling is included for spheres and boxes.
/// - Every other shape (triangle meshes, heightfields, convex hulls, cylinders, capsules,
///   compounds, ...) is Bullet's: rayTestSingle (radius 0) or objectQuerySingle with a
///   btSphereShape of the cast's radius (radius > 0). Ray hits on triangle meshes are exact to
///   btScalar rounding (near a shared edge Bullet may report the neighbouring triangle: its test
///   grows triangles by 1e-4 of their size). Bullet's sphere sweeps (btContinuousConvexCollision,
///   conservative advancement) stop within 1 mm of the contact, so the reported centre is up to
///   1 mm off the surface (and, from GJK in float, up to 0.4 mm into it, measured) and the
///   normal is GJK's (measured up to 5 degrees off near mesh edges): a projectile then bounces
///   up to about 1 mm early.
/// - The contract of CollisionWorld is kept: zero-length and non-finite casts hit nothing
///   (Bullet is not called); only hits that enter a surface count (`dot(displacement, normal)
///   < 0`, the normal facing against the motion); planes, spheres and boxes are one-sided and a
///   start on them (within surfaceTolerance) moving in hits at fraction 0; triangle meshes are
///   two-sided for rays, and a ray starting on a triangle's plane ignores that triangle; for
///   Bullet's other shapes the cast is started surfaceTolerance before the origin so that a
///   start on their surface moving in hits at fraction 0, and hits that leave a surface are
///   dropped. A start deep inside a shape Bullet answers for is Bullet's to answer.
/// - No allocation per cast once Bullet's broadphase has grown its ray-test stack (the first
///   casts may allocate through btAlignedAlloc; the callbacks and the sphere are stack objects).
/// - Thread safety: the casts do not modify the world, but btDbvtBroadphase (the usual
///   broadphase) walks its tree with a stack it owns, shared by every thread unless Bullet was
///   built with BT_THREADSAFE (then one per thread, up to BT_MAX_THREAD_COUNT). Debian's
///   libbullet 3.24 is not (btGetCurrentThreadIndex() is 0 on every thread): there, run
///   predictions on one Bullet world from one thread at a time.
///   The world must not be stepped or edited while a prediction runs.
class BulletWorld final : public CollisionWorld {
public:
    /// Wraps `world`, which must outlive this object (it is referenced, not copied).
    explicit BulletWorld(const btCollisionWorld& world, const BulletWorldSettings& settings = {})
        : mWorld(&world), mSettings(settings) {}

    bool castSegment(const SegmentCast& cast, CastHit& hit) const override;
    /// The objects whose bounds meet the capsule's (Bullet's broadphase aabbTest, with the casts'
    /// filter): planes, spheres, boxes and the triangles of concave shapes (meshes, heightfields;
    /// 2 mm closer, as Bullet's own sweep stops up to 1 mm early) through foresight's
    /// conservative tests; any other shape answers "maybe".
    bool mayTouch(const SegmentCast& capsule) const override;
    /// The same objects through foresight's conservative firstTouch tests: the earliest; any
    /// other shape answers "maybe, at once" (fraction 0).
    bool firstTouch(const SegmentCast& capsule, float& fraction) const override;
    /// The same objects: planes, spheres and boxes through PlaneRegionTester. A concave shape's
    /// triangle within reach, any other shape, or a surface tolerance other than the default
    /// answers false: Bullet's own sweeps answer for those, up to 1 mm and a few degrees off
    /// the plane's exact answers.
    bool isOnlyPlane(const PlaneRegion& region) const override;
    /// The same objects (bounds grown by the query's radius): planes, spheres, boxes and the
    /// triangles of concave shapes through NearTester, exactly; other shapes are left out (the
    /// casts still meet them). False beyond btScalar's range.
    bool findNear(const NearQuery& query, NearCollector& collector) const override;
    /// 5 for point casts (Bullet's rayTest walks its tree cheaply; measured on a level of 3 000
    /// triangles, the exact method spent 6 % more clearing with region queries than casting
    /// every chord), 2 for swept spheres (the two came out even).
    float regionQueryCost(float radius) const override { return radius > 0.0f ? 2.0f : 5.0f; }

    /// The wrapped Bullet world.
    const btCollisionWorld& bulletWorld() const { return *mWorld; }
    /// The settings given at construction.
    const BulletWorldSettings& settings() const { return mSettings; }

private:
    const btCollisionWorld* mWorld;
    BulletWorldSettings mSettings;
};

/// A static Bullet world (a btDiscreteDynamicsWorld with a btDbvtBroadphase and a
/// btSequentialImpulseConstraintSolver) built from foresight's shapes, which owns everything
/// Bullet needs. For tests and ground-truth comparisons against StaticWorld (BulletWorld casts)
/// and for rigid-body reference simulations (simulateProjectileRigidBody, bullet_simulation.h);
/// a game passes its own world to BulletWorld instead.
///
/// Shapes map to: Plane -> btStaticPlaneShape; Sphere -> btSphereShape; OrientedBox ->
/// btBoxShape with its collision margin set to 0 (the outer size is kept; Bullet's default
/// 0.04 m margin would round the box's edges and corners by 4 cm in Bullet's own queries);
/// triangles -> btBvhTriangleMeshShape (margin 0, quantized BVH) over a btTriangleMesh. All
/// objects are static (CF_STATIC_OBJECT, filter group StaticFilter). Positions are converted to
/// btScalar (float in the default Bullet build: about 1e-6 m at 10 m from the origin).
///
/// Materials: every static object has restitution 1, friction 1 and rolling and spinning
/// friction 0. Bullet combines the two bodies of a contact as products (btManifoldResult::
/// calculateCombinedRestitution and calculateCombinedFriction, Bullet 2.x and 3.x, the latter
/// clamped to [-10, 10]), so a simulated body's own restitution and friction are the effective
/// ones. Bullet's defaults (restitution 0, friction 0.5) would make every contact dead and halve
/// the friction. The casts of BulletWorld do not read materials.
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
    /// The same world as a dynamics world (for simulations; gravity (0, -kDefaultGravity, 0)). Bodies
    /// added to it are the caller's to remove; objectCount() counts only the static shapes.
    btDiscreteDynamicsWorld& dynamicsWorld() { return *mWorld; }
    /// See dynamicsWorld().
    const btDiscreteDynamicsWorld& dynamicsWorld() const { return *mWorld; }

private:
    void addObject(std::unique_ptr<btCollisionShape> shape, const btTransform& transform);

    std::unique_ptr<btDefaultCollisionConfiguration> mConfiguration;
    std::unique_ptr<btCollisionDispatcher> mDispatcher;
    std::unique_ptr<btDbvtBroadphase> mBroadphase;
    std::unique_ptr<btSequentialImpulseConstraintSolver> mSolver;
    std::unique_ptr<btDiscreteDynamicsWorld> mWorld;
    std::vector<std::unique_ptr<btTriangleMesh>> mMeshes;
    std::vector<std::unique_ptr<btCollisionShape>> mShapes;
    std::vector<std::unique_ptr<btCollisionObject>> mObjects;
};

FORESIGHT_NAMESPACE_END
