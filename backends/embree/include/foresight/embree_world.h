#pragma once
/// @file embree_world.h
/// A CollisionWorld for large static triangle meshes, backed by an Embree BVH (optional target
/// `foresight::embree`, CMake option FORESIGHT_WITH_EMBREE).
///
/// Every hit reported is exact: its fraction, position and normal are those of the core's
/// ClosestHitCaster (the built-in world's own shape tests) run on the reported shape. Casts with
/// a radius > 0, and every cast before commit(), find exactly StaticWorld's hit (the same
/// shapes in the same order). Rays (radius 0) after commit() may differ from StaticWorld in the
/// graze exception below, and only there.
///
/// Method. The mesh triangles are Embree native triangles over the meshes' own vertices rounded
/// to float once (shared vertices stay shared), in one scene built with RTC_SCENE_FLAG_ROBUST
/// (Embree's watertight float test) and high build quality.
/// - Radius 0, fast path: one plain rtcIntersect1 (no filter) along the segment, started rho
///   before it and ended rho after it; the float closest triangle then goes through the exact
///   test. If that hits within the segment farther than rho / sine from the triangle's edges,
///   it is the mesh's result (compared with the primitives as StaticWorld orders them). The
///   exact test reads one record per triangle, built by commit() in primitive order: the
///   triangle and its double-precision unit normal (64 bytes, one cache line, in float builds;
///   huge pages where the kernel offers them), and skips the inside-the-triangle check where
///   the edge-distance test already proves it (the proof is in embree_world.cpp); the hit,
///   fraction and normal are the exact test's, bit for bit. castSegments runs this path for
///   many rays at once.
///   Otherwise (the exact test misses, or hits near an edge: about 0.3% of casts on a terrain)
///   the slow path traces the ray again with a filter that runs the exact test on every
///   triangle the float test reports, and tests exactly every triangle within 4 rho / sine of
///   each doubtful point (a "local check"); if its fixed-size lists overflow, the exhaustive
///   search below runs instead.
///   rho = 1e-6 m + 2^-20 x (the largest coordinate of the mesh or of the segment's start, plus
///   the segment's length): a bound on how far the float test (vertices, start and direction
///   rounded to float) can move a crossing; sine = the sine of the angle between the segment
///   and the triangle's plane, taken as 1e-3 below that.
/// - Radius > 0 (a swept sphere), and radius 0 in the slow path's overflow: one rtcPointQuery,
///   a sphere centred at the segment's start whose radius is the segment's length plus a
///   padding (the cast radius + the surface tolerance + 1e-4 m + 1e-6 of the coordinates'
///   magnitude, and the start's rounding to float); every triangle whose box, grown by that
///   padding, meets the segment goes through the exact test, and once a hit is found at
///   distance d the sphere shrinks to d + padding. A triangle the swept sphere can touch always
///   lies inside that sphere and the padded box, so a sphere never passes through a gap
///   narrower than its diameter, and grazes are never lost.
///
/// The graze exception (radius 0 only). Embree's float test decides which triangles are
/// candidates; where it can disagree with the exact test, a triangle T that StaticWorld hits at
/// point p may be missed:
/// - p within rho / sine of an edge of T that no triangle the float test reports shares (an
///   open edge, an outer corner, a vertex aimed at exactly): the ray then reports the next
///   exact hit behind p, or none;
/// - p within 2 rho / sine (along the segment) of another triangle's exact hit (coincident or
///   crossing surfaces, a near-tie): the farther of the two may be reported, whose fraction
///   exceeds StaticWorld's by at most 2 rho / (sine x length);
/// - p within rho / sine of the segment's start or end with the segment grazing T's plane
///   (sine below 1): the hit may be missed.
/// A reported hit is never closer than StaticWorld's, and never a hit where StaticWorld has
/// none (it is an exact hit of a shape StaticWorld also tests). On a closed mesh (every edge shared by two triangles
/// over the same vertices), a ray crossing the surface through an edge or a vertex still hits:
/// the float test is watertight there, and the exact tests of the triangles around the float
/// hit (the local check) find the exact one. In the test scene of tests/embree_test.cpp, 187 of
/// 10 000 random rays (a quarter of them aimed exactly at edges and vertices) differ.
/// Cost: a long segment with radius > 0 over a dense mesh gathers every triangle within the
/// query sphere until the first hit shrinks it (about 30 us for a 5 m cast and 190 us for a
/// 50 m cast over a 1 m-grid terrain of 500k triangles, against well under 1 us for rays);
/// acceptable for prediction-sized segments, and the known limit of this version (a
/// capsule-shaped query would fix it).
///
/// The built-in primitives (planes, spheres, boxes, loose triangles) are kept in an internal
/// StaticWorld and tested first, exactly as StaticWorld orders its shapes.
///
/// Casts never allocate and are safe from many threads once commit() has been called (each
/// cast uses its own Embree ray or query context). Memory: the triangles as added (3 RVec3
/// each), the float vertices and indices (kept for the next commit), the confirmation records
/// (64 bytes per triangle in float builds, 96 in double builds), the shared edges (1 byte per
/// triangle, EmbreeWorldSettings::meshAdjacency) and Embree's scene. The
/// loaders catch every exception (an error result); addMesh and add can only throw
/// std::bad_alloc, as StaticWorld::add.

#include <foresight/static_world.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

FORESIGHT_NAMESPACE_BEGIN

/// Largest glTF or GLB file loadGltf reads, together with every buffer file it names [bytes]:
/// 2 GiB.
inline constexpr std::uintmax_t kMaxGltfBytes = std::uintmax_t(2) << 30;
/// Most vertices one loadGltf call adds, counting each node's instance of a mesh: 2^24.
inline constexpr std::size_t kMaxLoadedVertices = std::size_t(1) << 24;
/// Most triangles one loadGltf call adds, counting each node's instance of a mesh: 2^24.
inline constexpr std::size_t kMaxLoadedTriangles = std::size_t(1) << 24;

/// Result of EmbreeWorld::loadObj / loadGltf.
struct MeshLoadResult {
    bool ok = false;    ///< true when the file's triangles were added.
    std::string error;  ///< on failure: one line naming the file, e.g. "level.glb: truncated GLB".
    MeshReport report;  ///< counts (also filled on success).
};

/// Settings of an EmbreeWorld.
struct EmbreeWorldSettings {
    /// As StaticWorldSettings::surfaceTolerance [Units: m] [Limit: >= 0].
    float surfaceTolerance = 1e-5f;
    /// Whether commit() finds the mesh edges shared by exactly two triangles, one on either side
    /// (1 byte per triangle; linear in the mesh, single-threaded: 0.05 s for a 1M-triangle
    /// terrain here, beside Embree's 0.4 to 0.6 s), so that isOnlyPlane need not pair them
    /// again on every call (13% of an exact projectile's time on the demo level's tiled floor).
    /// It changes no answer, except that a region refused only because it holds more edges than
    /// PlaneRegionTester keeps, or because the distances of an edge's two copies rounded to
    /// either side of the radius, may get the plane.
    bool meshAdjacency = true;
};

/// Triangle meshes in an Embree BVH plus StaticWorld's primitives. Add shapes and meshes, call
/// commit() once, then cast. Adding after commit() needs another commit() (which rebuilds the
/// BVH). Before commit() the mesh triangles are tested by brute force (correct, slow).
class EmbreeWorld final : public CollisionWorld {
public:
    EmbreeWorld();
    explicit EmbreeWorld(const EmbreeWorldSettings& settings);
    ~EmbreeWorld() override;
    EmbreeWorld(EmbreeWorld&&) noexcept;
    EmbreeWorld& operator=(EmbreeWorld&&) noexcept;
    EmbreeWorld(const EmbreeWorld&) = delete;
    EmbreeWorld& operator=(const EmbreeWorld&) = delete;

    /// Adds a primitive (as StaticWorld::add; not part of the BVH).
    Status add(const Plane& plane);
    /// See add(const Plane&).
    Status add(const Sphere& sphere);
    /// See add(const Plane&).
    Status add(const OrientedBox& box);
    /// See add(const Plane&).
    Status add(const Triangle& triangle);
    /// Adds every shape of `world` as a primitive, with its material (as `world` holds them,
    /// already validated).
    void addPrimitives(const StaticWorld& world);
    /// Adds a primitive with its own material (as StaticWorld::add(shape, material)).
    Status add(const Plane& plane, const SurfaceMaterial& material);
    /// See add(const Plane&, const SurfaceMaterial&).
    Status add(const Sphere& sphere, const SurfaceMaterial& material);
    /// See add(const Plane&, const SurfaceMaterial&).
    Status add(const OrientedBox& box, const SurfaceMaterial& material);
    /// See add(const Plane&, const SurfaceMaterial&).
    Status add(const Triangle& triangle, const SurfaceMaterial& material);

    /// Adds an indexed triangle mesh (three indices per triangle) to the BVH, with checkMesh's
    /// rules (static_world.h): the whole mesh is refused (nothing added) with NonFiniteInput or
    /// DegenerateShape, `report->error` saying why; degenerate triangles are skipped and counted.
    /// Also DegenerateShape past 2^32 - 2 triangles or vertices in all.
    Status addMesh(std::span<const RVec3> vertices, std::span<const std::uint32_t> indices,
                   MeshReport* report = nullptr);

    /// Loads the faces of a Wavefront OBJ file (polygons fan-triangulated) with addMesh. The
    /// file must be a regular file of at most kMaxObjBytes whose vertex and face lines pass
    /// checkObjText (obj_check.h): a damaged number or index is refused, never read as 0.
    MeshLoadResult loadObj(const std::filesystem::path& path);
    /// Loads a glTF 2.0 file (.gltf with its buffers, or binary .glb): every primitive with
    /// TRIANGLES mode of every mesh reached from the default scene (all scenes if none is set),
    /// with the node transforms applied. Refused rather than guessed: GLB versions other than 2,
    /// a scene, node, mesh, accessor or buffer view that does not exist, an accessor reaching past
    /// its view or buffer, a byteStride outside 4..252 or smaller than an element, node graphs
    /// that are not trees, rotations that are not unit quaternions, more than
    /// kMaxLoadedVertices / kMaxLoadedTriangles. Buffer files must be regular files inside the
    /// glTF's folder (no absolute or `..` paths leading out of it), kMaxGltfBytes in all.
    MeshLoadResult loadGltf(const std::filesystem::path& path);

    /// Builds the BVH over the mesh triangles, and the region queries' tree (Embree's BVH builder
    /// over the triangles' boxes). Returns false (and casts fall back to brute force) if Embree
    /// failed; `error` then says why. A region tree Embree cannot build is not an error: the
    /// region queries then test every triangle. A mesh with a coordinate beyond 1e15 m [Units: m]
    /// gets no region tree, and its casts test every triangle (Embree's float rays and box
    /// binning are not valid that far out).
    bool commit(std::string* error = nullptr);

    /// Number of mesh triangles (in the BVH).
    std::size_t meshTriangleCount() const;
    /// The mesh triangles, in the order they were added (degenerate ones skipped), e.g. to
    /// build the same world in another engine. Valid until the next add or move.
    std::span<const Triangle> meshTriangles() const;
    /// The internal world holding the primitives.
    const StaticWorld& primitives() const { return mPrimitives; }

    bool castSegment(const SegmentCast& cast, CastHit& hit) const override;
    /// Many casts at once (throw planning, a frame's projectiles): for each i below
    /// n = min(casts.size(), hits.size(), found.size()), the answer castSegment(casts[i], hits[i])
    /// gives, bit for bit: found[i] = 1 and hits[i] filled on a hit, found[i] = 0 (and hits[i]
    /// unspecified, as castSegment leaves it) otherwise. Casts, hits and units as castSegment
    /// (metres; fractions of each cast's displacement). Entries from n on are not touched.
    /// Rays (radius 0) after commit() go through the fast path in groups of 16: each ray is
    /// traced and its exact confirmation's data is requested from memory at once, then the
    /// group's hits are confirmed, so that those memory reads overlap instead of each stalling
    /// its cast. Swept spheres (radius > 0), casts before commit(), and rays in doubt are
    /// answered one by one, as castSegment answers them. No allocation; thread-safe as
    /// castSegment (the spans must not overlap between concurrent calls).
    /// @return the number of hits among the first n casts.
    std::size_t castSegments(std::span<const SegmentCast> casts, std::span<CastHit> hits,
                             std::span<std::uint8_t> found) const;
    /// The primitives as StaticWorld answers, then a walk of the region tree (built by commit():
    /// Embree's BVH builder over the mesh triangles' boxes, four children per node) into the
    /// boxes the capsule enters, whose triangles go through CapsuleTester::mayTouch; it stops at
    /// the first. No alarm that StaticWorld's mayTouch would not raise.
    bool mayTouch(const SegmentCast& capsule) const override;
    /// The primitives as StaticWorld answers, then a walk of the region tree, nearest boxes
    /// first, whose triangles go through CapsuleTester::firstTouch; boxes entered no earlier than
    /// the earliest touch found are skipped. The answer is StaticWorld's for the same shapes, bit
    /// for bit. regionQueryCost keeps its default (1): on the demo level the exact method asks
    /// it rather than casting every chord, and is faster for it (docs/results.md, Speed).
    bool firstTouch(const SegmentCast& capsule, float& fraction) const override;

    /// firstTouch, leaving out the shapes and the tree's boxes that BehindTester finds behind
    /// `front` (static_world.h).
    bool firstTouchInFront(const SegmentCast& capsule, const InFrontOf& front, float& fraction) const override;
    /// The primitives, then the mesh triangles of the region tree's boxes that the region's
    /// capsule enters, through PlaneRegionTester; it stops at the first that rules the region out.
    bool isOnlyPlane(const PlaneRegion& region) const override;
    /// The primitives as StaticWorld answers, then the mesh triangles that one Embree point query
    /// (the query's sphere, grown by the float rounding of its centre) finds, through NearTester.
    /// False beyond Embree's float range (then nothing of the mesh is reported).
    bool findNear(const NearQuery& query, NearCollector& collector) const override;
    /// The primitives as StaticWorld gathers them, then the mesh triangles of the region tree's
    /// boxes that the region enters and that CapsuleTester::mayTouch accepts, in the order added:
    /// the order castSegment breaks ties in. False when more than 512 mesh triangles qualify or
    /// when the collector is full.
    bool gatherShapes(const SegmentCast& region, ShapeCollector& collector) const override;

private:
    // firstTouch and firstTouchInFront (front and behind, its tester, null: nothing left out).
    bool touchFirst(const SegmentCast& capsule, const InFrontOf* front, const BehindTester* behind,
                    float& fraction) const;
    /// castSegment without its radius-0 fast path (swept spheres, casts in doubt, before commit()).
    bool castSlow(const SegmentCast& cast, CastHit& hit) const;

    struct Impl;
    EmbreeWorldSettings mSettings;
    StaticWorld mPrimitives;
    std::unique_ptr<Impl> mImpl;
};

FORESIGHT_NAMESPACE_END
