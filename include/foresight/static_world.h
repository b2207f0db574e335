#pragma once
/// @file static_world.h
/// The built-in collision world: infinite planes, spheres, oriented boxes and triangles,
/// all static. Casts are exact (analytic ray and swept-sphere tests), brute force over the
/// shapes (meant for tens to a few thousands of shapes; large meshes belong to a BVH backend).

#include <foresight/world.h>

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

FORESIGHT_NAMESPACE_BEGIN

/// A surface's own material. Only ProjectileMethod::Engine uses it: it combines these values
/// with the projectile's by the engine's rule (EngineProfile::restitutionCombine,
/// frictionCombine), as the engine combines two colliders' materials; the other methods use the
/// projectile's values. Casts report it in CastHit::restitution and CastHit::friction.
struct SurfaceMaterial {
    float restitution = -1.0f;  ///< [Limit: 0 .. 1, or negative: none (the projectile's value acts alone)]
    float friction = -1.0f;     ///< [Limit: >= 0, or negative: none]
};

/// A one-sided infinite plane: the points x with `dot(normal, x) = distance`. The front side
/// is where the normal points; behind it is solid (a floor, a wall of an arena).
struct Plane {
    Vec3 normal{0, 1, 0};  ///< [Limit: non-zero]; normalised when added (distance with it).
    Real distance = 0;     ///< `dot(normal, x)` on the plane; with a unit normal, the plane's
                           ///< signed distance from the origin [Units: m].
};

/// A solid sphere.
struct Sphere {
    RVec3 center{0};      ///< [Units: m]
    float radius = 1.0f;  ///< [Units: m] [Limit: > 0]
};

/// A solid box, rotated by `orientation` about its centre.
struct OrientedBox {
    RVec3 center{0};                           ///< [Units: m]
    Vec3 halfExtents{0.5f};                    ///< half sizes along the box's local axes [Units: m] [Limit: > 0]
    Quat orientation = glm::identity<Quat>();  ///< local-to-world; normalised when added.
    /// Radius of the rounded edges and corners: the box is the points within `rounding` of the
    /// box shrunk by it (faces stay where they are). Jolt's BoxShape is such a box, with its
    /// convex radius (0.05 m unless set) [Units: m] [Limit: 0 .. the smallest half extent].
    float rounding = 0.0f;
};

/// A two-sided triangle.
struct Triangle {
    RVec3 a{0}, b{0}, c{0};  ///< vertices [Units: m]; must span a non-zero area.
};

/// Checks a shape as StaticWorld::add would: Ok, NonFiniteInput, ZeroVector, InvalidRadius,
/// ZeroQuaternion or DegenerateShape.
Status validatePlane(const Plane& plane);
/// See validatePlane.
Status validateSphere(const Sphere& sphere);
/// See validatePlane.
Status validateBox(const OrientedBox& box);
/// See validatePlane. A triangle is degenerate when its area is below 1e-12 m^2 or relative
/// to its edge lengths (a sliver that cannot give a stable normal).
Status validateTriangle(const Triangle& triangle);
/// Checks a material as StaticWorld::add would: Ok, NonFiniteInput (NaN or infinite), or
/// InvalidRestitution (above 1).
Status validateMaterial(const SurfaceMaterial& material);

namespace detail {
/// Internal to ClosestHitCaster: a cast prepared for the shape tests (double precision).
struct PreparedRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, 1.0};  ///< unit
    double length = 0.0;                  ///< 0: the cast hits nothing
    double tolerance = 0.0;               ///< how far behind a one-sided surface a start is "on" it
    double radius = 0.0;
};
/// Internal to CapsuleTester and PlaneRegionTester: a capsule prepared for the conservative
/// tests (double precision, its radius grown for rounding).
struct PreparedCapsule {
    glm::dvec3 a{0.0}, b{0.0};    ///< the segment
    double radius = 0.0;          ///< grown for rounding
    glm::dvec3 lo{0.0}, hi{0.0};  ///< the segment's bounds grown by the radius
    bool valid = false;           ///< false: not finite
};
/// Internal to ClosestHitCaster: the closest hit so far, as a distance along the ray.
struct ClosestCandidate {
    double distance = std::numeric_limits<double>::infinity();
    glm::dvec3 normal{0.0, 1.0, 0.0};
    SurfaceMaterial material;  // of the shape that gave the closest hit
    void offer(double d, const glm::dvec3& n) {
        if (d < distance) {
            distance = d;
            normal = n;
        }
    }
};
}  // namespace detail

class StaticWorld;

/// The exact shape tests of StaticWorld, offered one shape at a time, keeping the closest hit.
/// For worlds that find their candidate shapes themselves (a BVH over a mesh, a grid): they get
/// the same hits, normals and surface rules as the built-in world. No allocation.
/// @code
///   ClosestHitCaster caster(cast);
///   for (const Triangle& t : candidates) caster.test(t);
///   CastHit hit;
///   if (caster.result(hit)) { ... }
/// @endcode
class ClosestHitCaster {
public:
    /// Prepares `cast`. `surfaceTolerance` is StaticWorldSettings::surfaceTolerance [Units: m].
    explicit ClosestHitCaster(const SegmentCast& cast, float surfaceTolerance = 1e-5f);

    /// False when the cast can hit nothing (zero length, non-finite): tests then do nothing.
    bool valid() const { return mRay.length > 0.0; }

    /// Tests one shape (validated as StaticWorld::add would; unvalidated shapes give
    /// unspecified hits but never undefined behaviour). `material` is the shape's own, which
    /// result() reports when this shape gives the closest hit (default: none).
    void test(const Plane& plane, const SurfaceMaterial& material = {});
    /// See test(const Plane&, const SurfaceMaterial&).
    void test(const Sphere& sphere, const SurfaceMaterial& material = {});
    /// See test(const Plane&, const SurfaceMaterial&).
    void test(const OrientedBox& box, const SurfaceMaterial& material = {});
    /// See test(const Plane&, const SurfaceMaterial&).
    void test(const Triangle& triangle, const SurfaceMaterial& material = {});

    /// The closest hit so far as a fraction of the segment; infinity when none. Shapes whose
    /// bounds start beyond it cannot change the result (an early-out for BVH traversals).
    double closestFraction() const;

    /// The closest hit; false if none.
    bool result(CastHit& hit) const;

private:
    friend class StaticWorld;  // runs its loops over the shapes without the per-shape checks
    detail::PreparedRay mRay;
    detail::ClosestCandidate mBest;
    glm::dvec3 mDisplacement{0.0};
};

/// Conservative capsule tests, for CollisionWorld::mayTouch of worlds that find their candidate
/// shapes themselves: false only when the shape is certainly farther than `capsule.radius` from
/// the segment (with a margin for rounding); true may be a false alarm. Unvalidated shapes give
/// unspecified answers but never undefined behaviour. No allocation.
bool mayTouch(const SegmentCast& capsule, const Plane& plane);
/// See mayTouch(const SegmentCast&, const Plane&). Exact: the segment's distance to the centre.
bool mayTouch(const SegmentCast& capsule, const Sphere& sphere);
/// See mayTouch(const SegmentCast&, const Plane&). The segment's bounds in the box's frame.
bool mayTouch(const SegmentCast& capsule, const OrientedBox& box);
/// See mayTouch(const SegmentCast&, const Plane&). The bounds, then the triangle's plane.
bool mayTouch(const SegmentCast& capsule, const Triangle& triangle);

/// Conservative first-touch tests, for CollisionWorld::firstTouch of worlds that find their
/// candidate shapes themselves: false only when the shape is certainly farther than
/// `capsule.radius` from the whole segment; true sets `fraction` [Limit: 0 .. 1] no later than the
/// first point of the segment within that distance of the shape (with a margin for rounding).
/// Planes and spheres are exact; boxes use the box grown by the radius, triangles their bounds
/// grown by the radius and the slab of their plane. Unvalidated shapes give unspecified answers
/// but never undefined behaviour. No allocation.
bool firstTouch(const SegmentCast& capsule, const Plane& plane, float& fraction);
/// See firstTouch(const SegmentCast&, const Plane&, float&).
bool firstTouch(const SegmentCast& capsule, const Sphere& sphere, float& fraction);
/// See firstTouch(const SegmentCast&, const Plane&, float&).
bool firstTouch(const SegmentCast& capsule, const OrientedBox& box, float& fraction);
/// See firstTouch(const SegmentCast&, const Plane&, float&).
bool firstTouch(const SegmentCast& capsule, const Triangle& triangle, float& fraction);

/// The conservative triangle tests above with the capsule prepared once, for worlds that walk
/// their own tree of candidate triangles (EmbreeWorld's region queries): the answers of
/// mayTouch(capsule, triangle) and firstTouch(capsule, triangle, fraction) bit for bit, without
/// preparing the capsule for each triangle. The tests grow the radius by 1e-4 m and 1e-6 of the
/// segment's largest coordinate magnitude (rounding): a tree may skip a box of triangles when the
/// segment stays farther than the radius so grown (and its own rounding) from the box, for the
/// firstTouch test refuses every triangle inside it. No allocation.
/// @code
///   const CapsuleTester tester(capsule);
///   float fraction = 0.0f;
///   for (const Triangle& t : candidates) if (tester.firstTouch(t, fraction)) { /* ... */ }
/// @endcode
class CapsuleTester {
public:
    /// Prepares `capsule` in double precision, its radius grown by the tests' rounding margin.
    explicit CapsuleTester(const SegmentCast& capsule);

    /// False when the capsule is not finite: then every shape may touch it at once (the tests
    /// answer true, fraction 0).
    bool valid() const { return mCapsule.valid; }

    /// mayTouch(capsule, triangle), with the capsule prepared once.
    bool mayTouch(const Triangle& triangle) const;

    /// firstTouch(capsule, triangle, fraction), with the capsule prepared once.
    bool firstTouch(const Triangle& triangle, float& fraction) const;

private:
    detail::PreparedCapsule mCapsule;
};

/// Which shapes lie wholly behind the plane of an InFrontOf: those CollisionWorld::firstTouchInFront
/// may leave out (no point of them more than `front.tolerance` in front of the plane). An
/// infinite plane is behind only when it is parallel (its normal equal to the front's, or its
/// opposite, in float). No allocation.
class BehindTester {
public:
    /// Prepares `front` in double precision (its normal normalised).
    explicit BehindTester(const InFrontOf& front);

    /// False when `front` is not finite or its normal is zero: then no shape is behind.
    bool valid() const { return mValid; }

    /// Whether the shape lies wholly behind the plane.
    bool behind(const Plane& plane) const;
    /// See behind(const Plane&).
    bool behind(const Sphere& sphere) const;
    /// See behind(const Plane&).
    bool behind(const OrientedBox& box) const;
    /// See behind(const Plane&).
    bool behind(const Triangle& triangle) const;
    /// Whether the axis-aligned box [lo, hi] lies wholly behind the plane (for a tree of bounds).
    bool behind(const glm::dvec3& lo, const glm::dvec3& hi) const;

private:
    glm::dvec3 mNormal{0.0};
    Vec3 mFloatNormal{0.0f};
    double mLevel = 0.0;  // dot(normal, point) + tolerance
    bool mValid = false;
};

/// The test behind CollisionWorld::isOnlyPlane, offered one shape at a time, for worlds that find
/// their candidate shapes themselves (as ClosestHitCaster is for casts). A shape that reaches
/// into the region must lie in the plane with the region's material: an infinite plane covers
/// the region at once, a box when the region's cross-section lies inside its face (and the box
/// is deeper than the region reaches), triangles when every one of their edges that crosses the
/// cross-section is shared with a triangle on its other side (so no hole or border lies there).
/// Spheres and other surfaces fail it. No allocation; at most kMaxEdges edges near the region
/// (then it fails: the caller takes smaller steps).
/// @code
///   PlaneRegionTester tester(region);
///   for (const Triangle& t : candidates) if (!tester.failed()) tester.test(t);
///   const bool only = tester.result();
/// @endcode
class PlaneRegionTester {
public:
    /// Edges crossing the region kept at most (3 per triangle).
    static constexpr int kMaxEdges = 192;

    /// Prepares `region` (its normal is normalised; a zero or non-finite one fails).
    explicit PlaneRegionTester(const PlaneRegion& region);

    /// Offers one shape with its own material (negative values: none).
    void test(const Plane& plane, const SurfaceMaterial& material = {});
    /// See test(const Plane&, const SurfaceMaterial&).
    void test(const Sphere& sphere, const SurfaceMaterial& material = {});
    /// See test(const Plane&, const SurfaceMaterial&).
    void test(const OrientedBox& box, const SurfaceMaterial& material = {});
    /// See test(const Plane&, const SurfaceMaterial&). For a triangle of a mesh whose adjacency
    /// the caller knows, bit k of `sharedEdges` (edge 0: a to b, 1: b to c, 2: c to a) promises
    /// that exactly one other triangle has that edge (the same two vertices), that its third
    /// vertex lies on the other side of the edge (in this triangle's plane), and that it is
    /// offered too whenever the edge comes within the region's capsule (as every world that
    /// offers each triangle that may touch the capsule does). result() needs such an edge only to
    /// find its pair, so it is not kept: the same answer without the edge's distance test and its
    /// sort. 0 (the default) promises nothing.
    void test(const Triangle& triangle, const SurfaceMaterial& material = {}, std::uint8_t sharedEdges = 0);

    /// True once a shape has ruled the region out: the rest need not be offered.
    bool failed() const { return mFailed; }

    /// Whether a group of mesh triangles may be left unoffered without changing result(): true
    /// only when no shape has failed the region, a triangle offered already holds the
    /// cross-section's anchor, and every triangle with its vertices inside the box [lo, hi],
    /// its unit normal within `spread` of `normal` or of `-normal` (each component; at most
    /// 1e-14), no material of its own and all three edges shared (sharedEdges 7) would pass
    /// test() keeping nothing. A world's tree asks it for a node whose triangles are all like
    /// that (a flat floor's tiles) instead of offering them one by one. Conservative: false
    /// where rounding could make a triangle's own test fail [Units: m for lo, hi].
    bool passesFlatGroup(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& normal, double spread) const;

    /// Whether the shapes offered make the region the plane alone, covered.
    bool result() const;

private:
    struct Edge {
        glm::dvec3 from, to;  // ordered: from < to
        int side;             // the side of the edge its triangle lies on
    };
    bool sameMaterial(const SurfaceMaterial& material) const;
    void addEdge(const glm::dvec3& u, const glm::dvec3& v, const glm::dvec3& w);

    SegmentCast mCapsule;               // the region, as given
    detail::PreparedCapsule mPrepared;  // the same, prepared for the triangle and edge tests
    glm::dvec3 mNormal{0.0, 1.0, 0.0};
    double mDistance = 0.0;   // dot(normal, x) on the plane
    double mTolerance = 0.0;  // how far from the plane a vertex still lies in it [m]
    glm::dvec3 mAnchor{0.0};  // a point of the cross-section: the start's projection
    SurfaceMaterial mMaterial;
    bool mFailed = false;
    bool mCovered = false;                       // a plane or a box covers the cross-section
    bool mAnchored = false;                      // a triangle holds the anchor
    mutable std::array<Edge, kMaxEdges> mEdges;  // the first mEdgeCount are used (not cleared: 10 KB)
    int mEdgeCount = 0;
};

/// The shape tests behind StaticWorld::findNear, offered one shape at a time, for worlds that
/// find their candidate shapes themselves (as ClosestHitCaster is for casts): each shape within
/// the query's radius goes to the collector with its closest point (NearSurface). Planes count
/// from their front, box and sphere surfaces from outside (a centre inside the solid deeper
/// than the tolerance does not count), triangles from both sides. No allocation.
class NearTester {
public:
    /// Prepares `query`; `surfaceTolerance` is StaticWorldSettings::surfaceTolerance [Units: m].
    NearTester(const NearQuery& query, NearCollector& collector, float surfaceTolerance = 1e-5f);

    /// False when the query is not finite or its radius is negative: tests then do nothing.
    bool valid() const { return mValid; }

    /// Tests one shape (validated as StaticWorld::add would) with its own material.
    void test(const Plane& plane, const SurfaceMaterial& material = {});
    /// See test(const Plane&, const SurfaceMaterial&).
    void test(const Sphere& sphere, const SurfaceMaterial& material = {});
    /// See test(const Plane&, const SurfaceMaterial&).
    void test(const OrientedBox& box, const SurfaceMaterial& material = {});
    /// See test(const Plane&, const SurfaceMaterial&).
    void test(const Triangle& triangle, const SurfaceMaterial& material = {});

private:
    void report(const glm::dvec3& point, const glm::dvec3& normal, double distance, const SurfaceMaterial& material);
    NearCollector& mCollector;
    glm::dvec3 mCenter{0.0};
    double mRadius = 0.0;
    double mTolerance = 0.0;
    bool mValid = false;
};

/// What addMesh (StaticWorld's, EmbreeWorld's) or a mesh loader did with a mesh.
struct MeshReport {
    std::size_t triangles = 0;                ///< triangles added.
    std::size_t degenerateTriangles = 0;      ///< triangles skipped (validateTriangle: DegenerateShape).
    std::size_t firstDegenerateTriangle = 0;  ///< 0-based index (in the mesh) of the first skipped one.
    std::string error;                        ///< why the mesh was refused; empty on success.
};

/// Checks an indexed triangle mesh (three indices per triangle) as addMesh does, adding nothing:
/// NonFiniteInput for a non-finite vertex; DegenerateShape when the index count is not a
/// multiple of 3, an index is out of range, or no triangle is usable (`report.error` says which
/// and where). Ok otherwise, with `report.triangles` the usable triangles and the degenerate
/// ones (validateTriangle) counted, the first one named.
Status checkMesh(std::span<const RVec3> vertices, std::span<const std::uint32_t> indices, MeshReport& report);

/// Whether triangle `index` of a mesh that checkMesh accepted with `report` is usable, without
/// testing it again where the report already says (none degenerate, or before the first one).
inline bool usableInCheckedMesh(const Triangle& triangle, std::size_t index, const MeshReport& report) {
    return report.degenerateTriangles == 0 || index < report.firstDegenerateTriangle ||
           (index > report.firstDegenerateTriangle && validateTriangle(triangle) == Status::Ok);
}

/// Settings of a StaticWorld.
struct StaticWorldSettings {
    /// A cast that starts this close behind a one-sided surface and moves into it still hits
    /// it (at fraction 0), so rounding never lets a resting object fall through
    /// [Units: m] [Limit: >= 0]. Grows with the coordinates' magnitude (4 ulps).
    float surfaceTolerance = 1e-5f;
};

/// The built-in static world. Shapes are added once (this allocates); casts never allocate and
/// are safe to run from many threads at once.
class StaticWorld final : public CollisionWorld {
public:
    StaticWorld() = default;
    explicit StaticWorld(const StaticWorldSettings& settings) : mSettings(settings) {}

    /// Adds a shape after validating it; nothing is added unless Ok is returned.
    Status add(const Plane& plane);
    /// See add(const Plane&).
    Status add(const Sphere& sphere);
    /// See add(const Plane&).
    Status add(const OrientedBox& box);
    /// See add(const Plane&). Degenerate triangles are refused with DegenerateShape.
    Status add(const Triangle& triangle);
    /// Adds a shape with its own material (SurfaceMaterial), which casts that hit it report.
    Status add(const Plane& plane, const SurfaceMaterial& material);
    /// See add(const Plane&, const SurfaceMaterial&).
    Status add(const Sphere& sphere, const SurfaceMaterial& material);
    /// See add(const Plane&, const SurfaceMaterial&).
    Status add(const OrientedBox& box, const SurfaceMaterial& material);
    /// See add(const Plane&, const SurfaceMaterial&).
    Status add(const Triangle& triangle, const SurfaceMaterial& material);

    /// Adds the usable triangles of an indexed mesh (checkMesh's rules: a mesh it refuses adds
    /// nothing; degenerate triangles are skipped and counted in `report`), each tested by every
    /// cast like a triangle added alone: for up to a few thousand (EmbreeWorld for more).
    Status addMesh(std::span<const RVec3> vertices, std::span<const std::uint32_t> indices,
                   MeshReport* report = nullptr);

    /// Removes every shape.
    void clear();

    /// Number of shapes of every kind.
    std::size_t shapeCount() const;

    bool castSegment(const SegmentCast& cast, CastHit& hit) const override;

    /// Every shape through the conservative mayTouch tests above (a linear scan).
    bool mayTouch(const SegmentCast& capsule) const override;

    /// Every shape through the conservative firstTouch tests above (a linear scan): the earliest.
    bool firstTouch(const SegmentCast& capsule, float& fraction) const override;

    /// firstTouch, leaving out the shapes that BehindTester finds behind `front`.
    bool firstTouchInFront(const SegmentCast& capsule, const InFrontOf& front, float& fraction) const override;

    /// Every shape through PlaneRegionTester (a linear scan). False unless the world has the
    /// default surface tolerance (the promise is about a plane with that tolerance).
    bool isOnlyPlane(const PlaneRegion& region) const override;

    /// Every shape through NearTester (a linear scan).
    bool findNear(const NearQuery& query, NearCollector& collector) const override;

    /// Every shape whose mayTouch test passes, kind by kind (planes, spheres, boxes, triangles)
    /// in the order added: the order castSegment tests them in (a linear scan).
    bool gatherShapes(const SegmentCast& region, ShapeCollector& collector) const override;

    /// The shapes as added (normalised).
    std::span<const Plane> planes() const { return mPlanes; }
    /// See planes().
    std::span<const Sphere> spheres() const { return mSpheres; }
    /// See planes().
    std::span<const OrientedBox> boxes() const { return mBoxes; }
    /// See planes().
    std::span<const Triangle> triangles() const { return mTriangles; }
    /// The materials of planes() in the same order (none where added without one).
    std::span<const SurfaceMaterial> planeMaterials() const { return mPlaneMaterials; }
    /// See planeMaterials().
    std::span<const SurfaceMaterial> sphereMaterials() const { return mSphereMaterials; }
    /// See planeMaterials().
    std::span<const SurfaceMaterial> boxMaterials() const { return mBoxMaterials; }
    /// See planeMaterials().
    std::span<const SurfaceMaterial> triangleMaterials() const { return mTriangleMaterials; }

private:
    StaticWorldSettings mSettings;
    std::vector<Plane> mPlanes;
    std::vector<Sphere> mSpheres;
    std::vector<OrientedBox> mBoxes;
    std::vector<Triangle> mTriangles;
    std::vector<SurfaceMaterial> mPlaneMaterials, mSphereMaterials, mBoxMaterials, mTriangleMaterials;
};

FORESIGHT_NAMESPACE_END
