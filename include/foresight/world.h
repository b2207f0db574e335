#pragma once
/// @file world.h
/// The collision world interface: the predictor asks it for the first hit along a segment.
/// Plug in your engine's own ray or sphere cast by deriving from CollisionWorld or by wrapping
/// a function (CallbackWorld); StaticWorld (static_world.h) is the built-in implementation.

#include <foresight/status.h>

#include <limits>
#include <type_traits>

FORESIGHT_NAMESPACE_BEGIN

/// A segment (or swept sphere) cast: from `origin` to `origin + displacement`.
struct SegmentCast {
    RVec3 origin{0};       ///< start of the segment, the sphere's centre [Units: m].
    Vec3 displacement{0};  ///< end minus start [Units: m]; may be zero (then nothing is hit).
    float radius = 0.0f;   ///< swept sphere radius [Units: m] [Limit: >= 0]; 0 casts a point.
};

/// The first hit of a SegmentCast.
struct CastHit {
    float fraction = 1.0f;  ///< where along the segment [Limit: 0 .. 1]: origin + fraction * displacement.
    RVec3 position{0};      ///< the cast's origin point (sphere centre) at the hit [Units: m].
                            ///< The surface contact is `position - normal * radius`.
    Vec3 normal{0, 1, 0};   ///< unit surface normal at the hit, facing against the motion.
    /// The surface's own coefficient of restitution, or negative when the world has none (then
    /// the projectile's value is the contact's). Used by ProjectileMethod::Engine, which combines
    /// it with the projectile's by the engine's rule [Limit: < 0, or 0 .. 1].
    float restitution = -1.0f;
    /// The surface's own friction coefficient, or negative when the world has none [Limit: < 0, or >= 0].
    float friction = -1.0f;
};

/// A region of a plane, for CollisionWorld::isOnlyPlane: the points within `capsule.radius` of
/// the segment from `capsule.origin` to `capsule.origin + capsule.displacement`, and the plane
/// through `point` with unit normal `normal` (towards the free side) that should be the only
/// surface there, with the material `restitution`, `friction` (as CastHit reports them).
struct PlaneRegion {
    SegmentCast capsule;        ///< the region [Units: m].
    RVec3 point{0};             ///< a point of the plane [Units: m].
    Vec3 normal{0, 1, 0};       ///< the plane's unit normal, pointing to the free side.
    float restitution = -1.0f;  ///< the material the plane's hits report (negative: none).
    float friction = -1.0f;     ///< see restitution.
};

/// The side of a plane that CollisionWorld::firstTouchInFront looks at: the surfaces that lie
/// wholly behind the plane through `point` with unit normal `normal` (none of their points more
/// than `tolerance` in front of it) may be left out of the query.
struct InFrontOf {
    RVec3 point{0};           ///< a point of the plane [Units: m].
    Vec3 normal{0, 1, 0};     ///< the plane's unit normal, towards the side looked at [Limit: unit length].
    float tolerance = 1e-5f;  ///< how far in front a surface left out may reach [Units: m] [Limit: >= 0].
};

/// A sphere for CollisionWorld::findNear: the surfaces within `radius` of `center`.
struct NearQuery {
    RVec3 center{0};      ///< the sphere's centre [Units: m].
    float radius = 0.0f;  ///< how far from the centre surfaces count [Units: m] [Limit: >= 0].
};

/// One surface near a NearQuery's centre: the contact a sphere at the centre would have with it,
/// as an engine's narrow phase measures it (closest points).
struct NearSurface {
    RVec3 point{0};  ///< the surface's point closest to the centre [Units: m].
    /// Unit contact normal: from `point` towards the centre, or the surface's own normal on the
    /// centre's side where the centre lies on the surface (or within the tolerance behind it).
    Vec3 normal{0, 1, 0};
    /// The centre's signed distance from the surface along `normal` [Units: m]: >= 0 in front of
    /// it, down to minus the world's surface tolerance behind a one-sided surface.
    float distance = 0.0f;
    float restitution = -1.0f;  ///< the surface's own restitution, as CastHit::restitution.
    float friction = -1.0f;     ///< the surface's own friction, as CastHit::friction.
};

/// Receives the surfaces of a CollisionWorld::findNear query, one call per shape (per triangle
/// of a mesh), in no particular order. Implementations must not assume the calls stop early.
class NearCollector {
public:
    virtual ~NearCollector() = default;
    /// One surface within the query's radius.
    virtual void add(const NearSurface& surface) = 0;
};

struct Plane;
struct Sphere;
struct OrientedBox;
struct Triangle;
struct SurfaceMaterial;

/// Receives copies of a world's shapes from CollisionWorld::gatherShapes (the shapes and the
/// material type are declared in static_world.h).
class ShapeCollector {
public:
    virtual ~ShapeCollector() = default;
    /// The world's surface tolerance, as StaticWorldSettings::surfaceTolerance [Units: m]; called
    /// once, before the shapes.
    virtual void begin(float surfaceTolerance) = 0;
    /// One shape and its material. Returns false when the collector has no room for it: the
    /// gathering then stops, and fails.
    virtual bool add(const Plane& plane, const SurfaceMaterial& material) = 0;
    /// See add(const Plane&, const SurfaceMaterial&).
    virtual bool add(const Sphere& sphere, const SurfaceMaterial& material) = 0;
    /// See add(const Plane&, const SurfaceMaterial&).
    virtual bool add(const OrientedBox& box, const SurfaceMaterial& material) = 0;
    /// See add(const Plane&, const SurfaceMaterial&).
    virtual bool add(const Triangle& triangle, const SurfaceMaterial& material) = 0;
};

/// What a world must answer. Rules every implementation should follow (the built-in one does):
/// - Report the closest hit with a surface the segment enters (`dot(displacement, normal) < 0`).
/// - A segment that starts on a one-sided surface (within a small tolerance) and moves into it
///   hits at fraction 0, like Unity's Linecast; a segment that starts deep inside a solid, or
///   moves away from a surface, does not hit it.
/// - A zero-length segment hits nothing.
/// Implementations must be thread-safe for concurrent const calls if predictions run in parallel.
class CollisionWorld {
public:
    virtual ~CollisionWorld() = default;

    /// Finds the first hit along `cast`. Returns false (and leaves `hit` undefined) if none.
    virtual bool castSegment(const SegmentCast& cast, CastHit& hit) const = 0;

    /// Whether any surface may lie within `capsule.radius` of the segment from `capsule.origin`
    /// to `capsule.origin + capsule.displacement` (a capsule; every surface counts, from either
    /// side and whatever the segment's direction). False is a promise: a castSegment whose
    /// swept sphere stays inside the capsule hits nothing. True may be a false alarm; it only
    /// costs speed. The default answers true (the world cannot tell:
    /// callers then cast step by step), so a world that implements only castSegment stays
    /// correct.
    virtual bool mayTouch(const SegmentCast& capsule) const {
        (void)capsule;
        return true;
    }

    /// How far along `capsule` nothing may touch it: mayTouch's question, answered with a place.
    /// False is mayTouch's promise (nothing within the whole capsule). True sets `fraction`
    /// [Limit: 0 .. 1] so that no surface comes within `capsule.radius` of the segment's points
    /// `origin + t * displacement` for t < fraction: the capsule cut at `fraction` is clear, and a
    /// castSegment whose swept sphere stays inside that part hits nothing. A fraction earlier than
    /// the real first touch only costs speed. ProjectileMethod::Exact and ProjectileMethod::Engine
    /// ask it to clear many steps of free flight, up to the first possible contact, with one query
    /// instead of one cast per step. The default answers from mayTouch (fraction 0 when it says
    /// true), so a world that implements only mayTouch, or only castSegment, stays correct.
    virtual bool firstTouch(const SegmentCast& capsule, float& fraction) const {
        fraction = 0.0f;
        return mayTouch(capsule);
    }

    /// firstTouch's question about the surfaces in front of a plane: the same answer and the same
    /// promise, except that the surfaces wholly behind `front` (see InFrontOf) need not count. A
    /// caller whose swept sphere stays more than its radius plus `front.tolerance` in front of
    /// that plane cannot meet those surfaces anyway. ProjectileMethod::Exact asks it after a bounce,
    /// with the plane of the surface the body left: the hop over a floor is then cleared by one
    /// query, where firstTouch would find the floor at once and clear nothing. The default
    /// leaves nothing out (firstTouch), which is always correct; StaticWorld and EmbreeWorld
    /// leave out the shapes (and EmbreeWorld the boxes of its tree) wholly behind the plane.
    virtual bool firstTouchInFront(const SegmentCast& capsule, const InFrontOf& front, float& fraction) const {
        (void)front;
        return firstTouch(capsule, fraction);
    }

    /// Whether, inside `region.capsule`, the world is the plane of `region` and nothing else: every
    /// surface that reaches into the capsule lies in that plane and has the region's material, and
    /// together they cover the plane's whole cross-section with the capsule. True is a promise: a
    /// castSegment whose swept sphere stays inside the capsule and starts clear of the plane (its
    /// centre at least its radius in front of it) gets the answer that a world holding only that
    /// one-sided plane (with StaticWorldSettings' default surface tolerance) would give, up to the
    /// rounding of the shapes' own coordinates. (A sphere that starts sunk into a floor of
    /// triangles meets the edges they share; the plane has none.) False may be a false alarm;
    /// it only costs speed. ProjectileMethod::Engine asks it to take many steps of a sphere
    /// rolling or sliding on a floor with one query instead of several casts per step. The
    /// default answers false (the world cannot tell: callers then cast step by step).
    virtual bool isOnlyPlane(const PlaneRegion& region) const {
        (void)region;
        return false;
    }

    /// Roughly how many castSegment calls with this `radius` [Units: m] one mayTouch, firstTouch
    /// or isOnlyPlane query costs in this world [Limit: >= 0]. ProjectileMethod::Exact clears
    /// many steps with one such query only where a query is worth at most two casts (one clears
    /// about six steps of free flight on average, and costs a cast or more when it clears none).
    /// The default, 1, suits a world that tests every shape for every query (StaticWorld) or
    /// finds the candidates of casts and of region queries by the same search; a world whose
    /// point casts take a much faster path than its region queries (BulletWorld's ray tests)
    /// says so. Only speed depends on it: the answers are the same either way.
    virtual float regionQueryCost(float radius) const {
        (void)radius;
        return 1.0f;
    }

    /// Copies into `collector` every shape that may come within `region.radius` of the segment
    /// from `region.origin` to `region.origin + region.displacement` (at least the shapes that
    /// mayTouch would find there; a few more do no harm), in the order in which this world's
    /// castSegment prefers one of two equally close hits (the first wins). Returns true when it
    /// copied them all: then a StaticWorld holding exactly these shapes in this order, with this
    /// surface tolerance, answers a swept-sphere castSegment (radius > 0) bit for bit as this
    /// world does, and findNear with the same surfaces (in its own order), for every query that
    /// stays inside the region. Returns false when the world cannot (the default) or the
    /// collector ran out of room. ProjectileMethod::Engine gathers the shapes around a sphere
    /// once and asks them, instead of the world, the several small queries of each of the next
    /// steps it takes one by one. The Bullet 3.24 and Godot 3 with Bullet profiles also read the
    /// gathered boxes to compute a first contact as Bullet's float arithmetic does (docs/engines.md);
    /// where the world cannot gather, that contact is the profile's own (its normal then differs
    /// from Bullet's by Bullet's rounding, up to about 1e-4 rad on a 30 m box).
    virtual bool gatherShapes(const SegmentCast& region, ShapeCollector& collector) const {
        (void)region;
        (void)collector;
        return false;
    }

    /// Every surface within `query.radius` of `query.center`, each passed to `collector` with its
    /// closest point: what a physics engine's narrow phase finds around a sphere, whatever way it
    /// moves. Surfaces follow the cast rules: a one-sided surface counts from its front side (and
    /// up to the surface tolerance behind it); a solid whose inside holds the centre deeper than
    /// that does not count. Returns false when the world cannot answer (the default: it then calls
    /// nothing), true when it has reported every such surface it can measure (a world may leave
    /// out shapes it has no closest-point test for: its casts still meet them).
    /// ProjectileMethod::Engine asks it in each step it takes one by one while the sphere touches
    /// a surface, so that a sphere pressed into one face also meets the faces beside it (casts,
    /// which ignore a surface they start inside, may miss one in a narrow corner).
    virtual bool findNear(const NearQuery& query, NearCollector& collector) const {
        (void)query;
        (void)collector;
        return false;
    }
};

/// Signature of a user ray cast: return true and fill `hit` on a hit.
using CastSegmentFunction = bool (*)(void* context, const SegmentCast& cast, CastHit& hit);

/// A CollisionWorld that forwards to a function pointer and a context (no allocation).
/// Use `CallbackWorld::wrap(lambda)` to forward to any callable that outlives the world.
class CallbackWorld final : public CollisionWorld {
public:
    /// Forwards every query to `function(context, cast, hit)`. `function` must not be null.
    CallbackWorld(CastSegmentFunction function, void* context) : mFunction(function), mContext(context) {}

    /// Wraps a callable `bool(const SegmentCast&, CastHit&)`; the callable is referenced, not
    /// copied, so it must outlive the returned world.
    template <class Callable>
    static CallbackWorld wrap(Callable& callable) {
        static_assert(std::is_invocable_r_v<bool, Callable&, const SegmentCast&, CastHit&>,
                      "callable must be bool(const SegmentCast&, CastHit&)");
        return CallbackWorld([](void* context, const SegmentCast& cast,
                                CastHit& hit) -> bool { return (*static_cast<Callable*>(context))(cast, hit); },
                             static_cast<void*>(&callable));
    }

    bool castSegment(const SegmentCast& cast, CastHit& hit) const override { return mFunction(mContext, cast, hit); }

    /// Infinite: the function answers casts only, and the region queries' defaults ("maybe",
    /// at once) clear nothing, so asking them is never worth a cast (ProjectileMethod::Exact
    /// and ProjectileMethod::Engine then cast step by step without trying them).
    float regionQueryCost(float radius) const override {
        (void)radius;
        return std::numeric_limits<float>::infinity();
    }

private:
    CastSegmentFunction mFunction;
    void* mContext;
};

/// A world with nothing in it.
class EmptyWorld final : public CollisionWorld {
public:
    bool castSegment(const SegmentCast&, CastHit&) const override { return false; }
};

FORESIGHT_NAMESPACE_END
