#pragma once
/// @file embree_world.h
/// A CollisionWorld for large static triangle meshes, backed by an Embree BVH (optional target
/// `foresight::embree`, CMake option FORESIGHT_WITH_EMBREE).
///
/// Hits are exactly those of StaticWorld holding the same shapes (same fraction, position and
/// normal): Embree only finds candidate triangles, and every candidate goes through the core's
/// ClosestHitCaster, the built-in world's own shape tests.
///
/// Method. Each mesh triangle is an Embree user-geometry primitive whose float bounds are the
/// triangle's exact (double) bounds grown by a padding (1e-6 m + 2^-21 of the mesh's largest
/// coordinate) and rounded outwards, in one scene built with RTC_SCENE_FLAG_ROBUST and high
/// build quality. Every primitive Embree reports is checked against the segment's bounding box
/// grown by the cast radius + the surface tolerance + 1e-4 m (in double) and, if it overlaps,
/// tested with ClosestHitCaster; the closest wins, and among triangles at exactly the same
/// distance the one added first, as in StaticWorld.
/// - Radius 0: rtcIntersect1 along the segment (direction = the float displacement, tnear 0,
///   tfar 1, so the traced ray is the segment itself); the intersect callback offers each
///   primitive and lowers tfar to the closest hit so far. The bounds padding covers the shape
///   tests' edge margin and the rounding of the origin to float (double builds); an origin too
///   far out for that (more than about twice the mesh's extent from the world origin in a
///   double build) takes the radius > 0 path instead.
/// - Radius > 0 (a swept sphere): one rtcPointQuery, a sphere centred at the segment's start
///   whose radius is the segment's length plus the padding above (and the origin's rounding);
///   once a hit is found at distance d the sphere shrinks to d + padding. A triangle the
///   swept sphere can touch always lies inside that sphere and the padded box, so a sphere
///   never passes through a gap narrower than its diameter, and grazes are never lost.
/// Cost: a long segment with radius > 0 over a dense mesh gathers every triangle within the
/// query sphere until the first hit shrinks it (about 30 us for a 5 m cast and 190 us for a
/// 50 m cast over a 1 m-grid terrain of 500k triangles, against 4-5 us for rays); acceptable
/// for prediction-sized segments, and the known limit of this version (a capsule-shaped
/// query would fix it).
///
/// The built-in primitives (planes, spheres, boxes, loose triangles) are kept in an internal
/// StaticWorld and tested first, exactly as StaticWorld orders its shapes.
///
/// Casts never allocate and are safe from many threads once commit() has been called (each
/// cast uses its own Embree query context). The loaders catch every exception (an error
/// result); addMesh and add can only throw std::bad_alloc, as StaticWorld::add.

#include <foresight/static_world.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

FORESIGHT_NAMESPACE_BEGIN

/// What addMesh or a loader did with a mesh.
struct MeshReport {
    std::size_t triangles = 0;               ///< triangles added.
    std::size_t degenerateTriangles = 0;     ///< triangles skipped (validateTriangle: DegenerateShape).
    std::size_t firstDegenerateTriangle = 0; ///< 0-based index (in the mesh) of the first skipped one.
    std::string error;                       ///< why the mesh was refused; empty on success.
};

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

    /// Adds an indexed triangle mesh (three indices per triangle). Refuses the whole mesh
    /// (nothing added) with NonFiniteInput for a non-finite vertex, and with DegenerateShape
    /// when the index count is not a multiple of 3, an index is out of range, or no triangle is
    /// usable; `report->error` then says which. Degenerate triangles are skipped and counted.
    Status addMesh(std::span<const RVec3> vertices, std::span<const std::uint32_t> indices,
                   MeshReport* report = nullptr);

    /// Loads the faces of a Wavefront OBJ file (polygons fan-triangulated) with addMesh.
    MeshLoadResult loadObj(const std::filesystem::path& path);
    /// Loads a glTF 2.0 file (.gltf with its buffers, or binary .glb): every primitive with
    /// TRIANGLES mode of every mesh reached from the default scene (all scenes if none is set),
    /// with the node transforms applied.
    MeshLoadResult loadGltf(const std::filesystem::path& path);

    /// Builds the BVH over the mesh triangles. Returns false (and casts fall back to brute
    /// force) if Embree failed; `error` then says why.
    bool commit(std::string* error = nullptr);

    /// Number of mesh triangles (in the BVH).
    std::size_t meshTriangleCount() const;
    /// The mesh triangles, in the order they were added (degenerate ones skipped), e.g. to
    /// build the same world in another engine. Valid until the next add or move.
    std::span<const Triangle> meshTriangles() const;
    /// The internal world holding the primitives.
    const StaticWorld& primitives() const { return mPrimitives; }

    bool castSegment(const SegmentCast& cast, CastHit& hit) const override;

private:
    struct Impl;
    EmbreeWorldSettings mSettings;
    StaticWorld mPrimitives;
    std::unique_ptr<Impl> mImpl;
};

FORESIGHT_NAMESPACE_END
