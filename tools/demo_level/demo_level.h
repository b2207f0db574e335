#pragma once
/// @file demo_level.h
/// The demo level: a small but real-looking level mesh made by the project (no downloaded
/// assets), and writers for Wavefront OBJ and glTF 2.0. Target `foresight_demo_level` (GLM and,
/// for the glTF writer, TinyGLTF); independent of the core library's precision (glm::dvec3).
/// `foresight level` writes the files; the build writes them to `${PROJECT_BINARY_DIR}/data/`
/// (target `foresight_demo_level_files`) for the tests.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace foresight_level {

/// An indexed triangle mesh in metres, +Y up (the library's axes). Triangles wind
/// counter-clockwise seen from outside a solid (outward normals).
struct LevelMesh {
    /// A named piece of the mesh: the triangles [firstTriangle, firstTriangle + triangleCount).
    struct Part {
        std::string name;                 ///< e.g. "floor", "wall_north", "stairs".
        std::uint32_t firstTriangle = 0;  ///< index of the part's first triangle.
        std::uint32_t triangleCount = 0;  ///< number of triangles of the part.
    };
    std::vector<glm::dvec3> vertices;    ///< [Units: m]
    std::vector<std::uint32_t> indices;  ///< 3 per triangle
    std::vector<Part> parts;             ///< named pieces ("floor", "wall_north", "stairs", ...), in order
    /// Number of triangles (indices / 3).
    std::size_t triangleCount() const { return indices.size() / 3; }
};

/// The demo level: a walled courtyard, centred on x = z = 0, floor at y = 0. North is +Z, east
/// is +X. Every coordinate is a multiple of 1/256 m (exactly representable in float, so the OBJ
/// and the glTF files hold identical triangles). Parts, in this order:
/// - `floor`: a single-sided surface facing +Y, x and z in [-18, 18] in 1 m tiles (1296 tiles,
///   2592 triangles): the 30 m x 30 m courtyard, the ground under its walls and a 2.5 m apron
///   outside them.
/// - `wall_north`, `wall_south`, `wall_east`, `wall_west`: boxes 0.5 m thick and 4 m high
///   around the inner courtyard x, z in [-15, 15]: outer bounds x, z in [-15.5, 15.5].
///   North: z in [15, 15.5], x in [-15.5, 15.5]; south: z in [-15.5, -15], the same x, with a
///   doorway x in [-1, 1], y in [0, 2.5] (two boxes and a lintel above the doorway); east:
///   x in [15, 15.5], z in [-15, 15]; west: x in [-15.5, -15], z in [-15, 15].
/// - `platform`: a box x in [-15, -7], z in [9, 15], y in [0, 1.875] (north-west corner).
/// - `stairs`: 9 steps up to the platform from the south, x in [-12, -9]; step i (0..8) is a
///   box from the floor, z in [6.1875 + 0.3125 i, 6.5 + 0.3125 i], top y = 0.1875 (i + 1)
///   (rise 0.1875 m, run 0.3125 m; the tenth riser is the platform's edge at z = 9).
/// - `ramp`: a wedge from the floor at x = -1 up to the platform's top at x = -7
///   (17.35 degrees, 1.875 m over 6 m), z in [11, 14].
/// - `pillars`: four 12-sided prisms (circumradius 0.375 m, 3.5 m high) centred at x = 9,
///   z = -9, -3, 3, 9.
/// - `crates`: 1.25 m crates in the south-west: axis-aligned ones centred at (-10, -10) and
///   (-8.625, -10), a 0.625 m crate turned by atan(3/4) on top of the first, a 1.25 m crate
///   turned by atan(3/4) centred at (-11, -6), and an axis-aligned one at (12.5, -12.5).
/// Every part but the floor is made of closed convex solids (each with its own vertices,
/// triangles wound outwards). Bounds: x, z in [-18, 18], y in [0, 4]. The middle of the
/// courtyard (|x| < 6, -6 < z < 9) is open floor. About 3000 triangles; deterministic.
LevelMesh makeDemoLevel();

/// A closed box room seen from inside (normals facing in), floor at y = 0, centred on x = z = 0:
/// x in [-size.x / 2, size.x / 2], y in [0, size.y], z in [-size.z / 2, size.z / 2], 12
/// triangles on 8 shared vertices. Parts: "floor", "ceiling", "wall_north" (+Z), "wall_south",
/// "wall_east" (+X), "wall_west". [Units: m] [Limit: every component finite and > 0; otherwise
/// the mesh is empty]
LevelMesh makeClosedRoom(const glm::dvec3& size);

/// Writes `mesh` as Wavefront OBJ: every vertex with `%.17g` (doubles round-trip), then per part
/// `o NAME` and its faces (1-based). Writers; return false with `error` naming the file on
/// failure (an unwritable file, or a mesh whose indices are out of range, whose index count is
/// not a multiple of 3 or whose parts do not cover its triangles in order; a mesh without parts
/// is written as one part "mesh").
bool writeObj(const LevelMesh& mesh, const std::filesystem::path& path, std::string& error);

/// .gltf (JSON with the buffer embedded as a base64 data URI) or .glb (binary), by extension
/// (any other extension is an error). One buffer: FLOAT VEC3 positions (glTF's POSITION must be
/// float: coordinates are rounded to float, exact for the demo level) with min/max, then
/// UNSIGNED_INT indices; one mesh and one node per part, named after it, with one TRIANGLES
/// primitive (its own index accessor into the shared positions); one scene, no transforms.
/// Errors as writeObj.
bool writeGltf(const LevelMesh& mesh, const std::filesystem::path& path, std::string& error);

}  // namespace foresight_level
