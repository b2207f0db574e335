#pragma once
/// @file obj_mesh.h
/// Wavefront OBJ meshes (tinyobjloader) as foresight triangles, for `world.meshes[]`.

#include <foresight/static_world.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace foresight_cli {

/// Triangles of an OBJ file and what was dropped on the way.
struct ObjMesh {
    std::vector<foresight::Triangle> triangles;  ///< valid triangles (validateTriangle is Ok).
    std::size_t degenerateTriangles = 0;         ///< triangles skipped as degenerate.
    std::size_t firstDegenerateFace = 0;         ///< 1-based face number of the first skipped one.
    std::vector<std::string> warnings;           ///< the loader's own warnings, one line each.
};

/// Loads the faces of `file` (polygons are fan-triangulated: exact for convex polygons; lines,
/// points, normals, texture coordinates and materials are ignored). Refuses (returns false
/// with `reason`) an unreadable or malformed file, a non-finite vertex, a face index out of
/// range and a file without any usable triangle.
bool loadObjMesh(const std::filesystem::path& file, ObjMesh& mesh, std::string& reason);

}  // namespace foresight_cli
