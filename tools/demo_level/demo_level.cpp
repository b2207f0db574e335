#include "demo_level.h"

#ifdef FORESIGHT_LEVEL_WITH_GLTF
#include <tiny_gltf.h>
#endif

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <sstream>
#include <utility>

namespace foresight_level {

namespace {

using glm::dvec3;

/// Builds a LevelMesh part by part. Faces are given as vertex loops of convex planar polygons
/// in either order; each is wound so that its normal points the way asked (outward for a solid)
/// and fan-triangulated from its first corner.
class MeshBuilder {
public:
    /// `snapToGrid`: round every vertex to a multiple of 1/256 m (exact in float; see the header).
    MeshBuilder(LevelMesh& mesh, bool snapToGrid) : mMesh(mesh), mSnap(snapToGrid) {}

    void beginPart(std::string name) { mPart = LevelMesh::Part{std::move(name), triangleCount(), 0}; }
    void endPart() {
        mPart.triangleCount = triangleCount() - mPart.firstTriangle;
        mMesh.parts.push_back(std::move(mPart));
    }

    std::uint32_t vertex(const dvec3& position) {
        mMesh.vertices.push_back(mSnap ? snap(position) : position);
        return static_cast<std::uint32_t>(mMesh.vertices.size() - 1);
    }

    /// One convex planar polygon, wound so that its normal has a positive component along `wanted`.
    void face(std::vector<std::uint32_t> loop, const dvec3& wanted) {
        const auto& v = mMesh.vertices;
        // Newell's normal: robust for any convex loop, whichever corners are nearly collinear.
        dvec3 normal(0.0);
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const dvec3& a = v[loop[i]];
            const dvec3& b = v[loop[(i + 1) % loop.size()]];
            normal += dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        }
        if (glm::dot(normal, wanted) < 0.0) std::reverse(loop.begin(), loop.end());
        for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
            mMesh.indices.insert(mMesh.indices.end(), {loop[0], loop[i], loop[i + 1]});
        }
    }

    /// A closed convex solid: its corners (own vertices) and its faces as loops of corner
    /// numbers; every face is wound outwards (away from the corners' centroid).
    void convexSolid(const std::vector<dvec3>& corners, const std::vector<std::vector<int>>& faces) {
        const auto base = static_cast<std::uint32_t>(mMesh.vertices.size());
        dvec3 centroid(0.0);
        for (const dvec3& c : corners) {
            vertex(c);
            centroid += mMesh.vertices.back();
        }
        centroid /= static_cast<double>(corners.size());
        for (const auto& loop : faces) {
            std::vector<std::uint32_t> indices;
            dvec3 faceCentroid(0.0);
            for (const int corner : loop) {
                indices.push_back(base + static_cast<std::uint32_t>(corner));
                faceCentroid += mMesh.vertices[indices.back()];
            }
            faceCentroid /= static_cast<double>(loop.size());
            face(std::move(indices), faceCentroid - centroid);
        }
    }

    /// A box with edges along `axisX`, `axisY`, `axisZ` (half extents as vectors) about `center`.
    void orientedBox(const dvec3& center, const dvec3& axisX, const dvec3& axisY, const dvec3& axisZ) {
        std::vector<dvec3> corners;
        for (int i = 0; i < 8; ++i) {
            corners.push_back(center + ((i & 1) ? axisX : -axisX) + ((i & 2) ? axisY : -axisY) +
                              ((i & 4) ? axisZ : -axisZ));
        }
        convexSolid(corners, kBoxFaces);
    }

    /// An axis-aligned box from `lo` to `hi`.
    void box(const dvec3& lo, const dvec3& hi) {
        const dvec3 half = 0.5 * (hi - lo);
        orientedBox(0.5 * (lo + hi), dvec3(half.x, 0, 0), dvec3(0, half.y, 0), dvec3(0, 0, half.z));
    }

    /// A vertical prism over a regular polygon of `sides` corners (circumradius `radius`).
    void prism(double x, double z, double radius, int sides, double bottom, double top) {
        std::vector<dvec3> corners;
        const double pi = 3.14159265358979323846;
        for (const double y : {bottom, top}) {
            for (int k = 0; k < sides; ++k) {
                const double angle = 2.0 * pi * k / sides;
                corners.emplace_back(x + radius * std::cos(angle), y, z + radius * std::sin(angle));
            }
        }
        std::vector<std::vector<int>> faces;
        std::vector<int> bottomLoop, topLoop;
        for (int k = 0; k < sides; ++k) {
            const int next = (k + 1) % sides;
            faces.push_back({k, next, sides + next, sides + k});
            bottomLoop.push_back(k);
            topLoop.push_back(sides + k);
        }
        faces.push_back(bottomLoop);
        faces.push_back(topLoop);
        convexSolid(corners, faces);
    }

private:
    static dvec3 snap(const dvec3& p) {
        return dvec3(std::round(p.x * 256.0) / 256.0, std::round(p.y * 256.0) / 256.0, std::round(p.z * 256.0) / 256.0);
    }
    std::uint32_t triangleCount() const { return static_cast<std::uint32_t>(mMesh.indices.size() / 3); }

    // Corner i of a box is -/+ along x, y, z by its bits 0, 1, 2; each face is a loop.
    static inline const std::vector<std::vector<int>> kBoxFaces = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                                   {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};

    LevelMesh& mMesh;
    bool mSnap;
    LevelMesh::Part mPart;
};

// ---------------------------------------------------------------------------------------------
// Writers

/// Checks what both writers rely on; fills `parts` (one part "mesh" for a mesh without parts).
bool checkMesh(const LevelMesh& mesh, const std::filesystem::path& path, std::vector<LevelMesh::Part>& parts,
               std::string& error) {
    const std::string name = path.string();
    if (mesh.indices.size() % 3 != 0) {
        error = name + ": the mesh's index count (" + std::to_string(mesh.indices.size()) + ") is not a multiple of 3";
        return false;
    }
    if (mesh.vertices.size() > std::numeric_limits<std::uint32_t>::max()) {
        error = name + ": the mesh has too many vertices";
        return false;
    }
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        if (mesh.indices[i] >= mesh.vertices.size()) {
            error = name + ": index " + std::to_string(i) + " of the mesh is out of range";
            return false;
        }
    }
    for (const dvec3& v : mesh.vertices) {
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
            error = name + ": the mesh has a non-finite vertex";
            return false;
        }
    }
    parts = mesh.parts;
    if (parts.empty()) {
        parts.push_back(LevelMesh::Part{"mesh", 0, static_cast<std::uint32_t>(mesh.triangleCount())});
        return true;
    }
    std::size_t next = 0;
    for (const auto& part : parts) {
        if (part.firstTriangle != next) {
            error = name + ": the mesh's part \"" + part.name + "\" does not start where the previous one ends";
            return false;
        }
        next += part.triangleCount;
    }
    if (next != mesh.triangleCount()) {
        error = name + ": the mesh's parts do not cover its " + std::to_string(mesh.triangleCount()) + " triangles";
        return false;
    }
    return true;
}

bool writeBytes(const std::filesystem::path& path, const std::string& bytes, std::string& error) {
    errno = 0;
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (file == nullptr) {
        error = path.string() + ": cannot write: " + std::strerror(errno != 0 ? errno : EACCES);
        return false;
    }
    errno = 0;
    const std::size_t written = std::fwrite(bytes.data(), 1, bytes.size(), file);
    int reason = written == bytes.size() ? 0 : (errno != 0 ? errno : EIO);
    if (std::fclose(file) != 0 && reason == 0) reason = errno != 0 ? errno : EIO;
    if (reason != 0) {
        error = path.string() + ": cannot write: " + std::strerror(reason);
        return false;
    }
    return true;
}

std::string lowerExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension;
}

[[maybe_unused]] void appendLittleEndian(std::vector<unsigned char>& bytes, std::uint32_t value) {
    for (int shift = 0; shift < 32; shift += 8) bytes.push_back(static_cast<unsigned char>((value >> shift) & 0xffu));
}

}  // namespace

LevelMesh makeDemoLevel() {
    LevelMesh mesh;
    MeshBuilder builder(mesh, true);

    // Floor: 1 m tiles over x, z in [-18, 18], shared corners, facing +Y.
    builder.beginPart("floor");
    constexpr int kFloorHalf = 18;
    constexpr int kFloorCorners = 2 * kFloorHalf + 1;
    const auto floorBase = static_cast<std::uint32_t>(mesh.vertices.size());
    for (int iz = 0; iz < kFloorCorners; ++iz) {
        for (int ix = 0; ix < kFloorCorners; ++ix) builder.vertex(dvec3(ix - kFloorHalf, 0, iz - kFloorHalf));
    }
    for (int iz = 0; iz + 1 < kFloorCorners; ++iz) {
        for (int ix = 0; ix + 1 < kFloorCorners; ++ix) {
            const auto corner = [&](int dx, int dz) {
                return floorBase + static_cast<std::uint32_t>((iz + dz) * kFloorCorners + ix + dx);
            };
            builder.face({corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)}, dvec3(0, 1, 0));
        }
    }
    builder.endPart();

    // Perimeter walls, 0.5 m thick and 4 m high, outside the inner courtyard [-15, 15]^2.
    constexpr double kInner = 15.0, kOuter = 15.5, kWallHeight = 4.0;
    builder.beginPart("wall_north");
    builder.box(dvec3(-kOuter, 0, kInner), dvec3(kOuter, kWallHeight, kOuter));
    builder.endPart();
    builder.beginPart("wall_south");  // a doorway x in [-1, 1], 2.5 m high, with a lintel
    builder.box(dvec3(-kOuter, 0, -kOuter), dvec3(-1, kWallHeight, -kInner));
    builder.box(dvec3(1, 0, -kOuter), dvec3(kOuter, kWallHeight, -kInner));
    builder.box(dvec3(-1, 2.5, -kOuter), dvec3(1, kWallHeight, -kInner));
    builder.endPart();
    builder.beginPart("wall_east");
    builder.box(dvec3(kInner, 0, -kInner), dvec3(kOuter, kWallHeight, kInner));
    builder.endPart();
    builder.beginPart("wall_west");
    builder.box(dvec3(-kOuter, 0, -kInner), dvec3(-kInner, kWallHeight, kInner));
    builder.endPart();

    // A raised platform in the north-west corner, reached by stairs and a ramp.
    constexpr double kRise = 0.1875, kRun = 0.3125, kPlatformHeight = 10 * kRise;
    builder.beginPart("platform");
    builder.box(dvec3(-15, 0, 9), dvec3(-7, kPlatformHeight, 15));
    builder.endPart();
    builder.beginPart("stairs");
    for (int i = 0; i < 9; ++i) {
        const double front = 9.0 - kRun * (9 - i);
        builder.box(dvec3(-12, 0, front), dvec3(-9, kRise * (i + 1), front + kRun));
    }
    builder.endPart();
    builder.beginPart("ramp");
    builder.convexSolid({dvec3(-1, 0, 11), dvec3(-1, 0, 14), dvec3(-7, 0, 11), dvec3(-7, 0, 14),
                         dvec3(-7, kPlatformHeight, 11), dvec3(-7, kPlatformHeight, 14)},
                        {{0, 1, 3, 2}, {0, 4, 5, 1}, {2, 3, 5, 4}, {0, 2, 4}, {1, 3, 5}});
    builder.endPart();

    // A colonnade along the east side.
    builder.beginPart("pillars");
    for (const double z : {-9.0, -3.0, 3.0, 9.0}) builder.prism(9.0, z, 0.375, 12, 0.0, 3.5);
    builder.endPart();

    // Crates; the turned ones use the exact rotation cos = 4/5, sin = 3/5 (corners stay on the grid).
    builder.beginPart("crates");
    const dvec3 up(0, 0.625, 0);
    builder.box(dvec3(-10.625, 0, -10.625), dvec3(-9.375, 1.25, -9.375));
    builder.box(dvec3(-9.25, 0, -10.625), dvec3(-8.0, 1.25, -9.375));
    builder.orientedBox(dvec3(-10, 1.5625, -10), dvec3(0.25, 0, 0.1875), dvec3(0, 0.3125, 0), dvec3(-0.1875, 0, 0.25));
    builder.orientedBox(dvec3(-11, 0.625, -6), dvec3(0.5, 0, 0.375), up, dvec3(-0.375, 0, 0.5));
    builder.box(dvec3(11.875, 0, -13.125), dvec3(13.125, 1.25, -11.875));
    builder.endPart();
    return mesh;
}

LevelMesh makeClosedRoom(const glm::dvec3& size) {
    LevelMesh mesh;
    for (int axis = 0; axis < 3; ++axis) {
        if (!std::isfinite(size[axis]) || !(size[axis] > 0.0)) return mesh;
    }
    MeshBuilder builder(mesh, false);
    const dvec3 lo(-0.5 * size.x, 0.0, -0.5 * size.z);
    const dvec3 hi(0.5 * size.x, size.y, 0.5 * size.z);
    for (int i = 0; i < 8; ++i)
        builder.vertex(dvec3((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z));
    // Each face with the direction its normal must take (into the room).
    const std::array<std::pair<const char*, std::pair<std::vector<std::uint32_t>, dvec3>>, 6> faces{{
        {"floor", {{0, 1, 5, 4}, dvec3(0, 1, 0)}},
        {"ceiling", {{2, 3, 7, 6}, dvec3(0, -1, 0)}},
        {"wall_north", {{4, 5, 7, 6}, dvec3(0, 0, -1)}},
        {"wall_south", {{0, 1, 3, 2}, dvec3(0, 0, 1)}},
        {"wall_east", {{1, 3, 7, 5}, dvec3(-1, 0, 0)}},
        {"wall_west", {{0, 2, 6, 4}, dvec3(1, 0, 0)}},
    }};
    for (const auto& [name, face] : faces) {
        builder.beginPart(name);
        builder.face(face.first, face.second);
        builder.endPart();
    }
    return mesh;
}

bool writeObj(const LevelMesh& mesh, const std::filesystem::path& path, std::string& error) {
    std::vector<LevelMesh::Part> parts;
    if (!checkMesh(mesh, path, parts, error)) return false;
    std::string text;
    text.reserve(48 * mesh.vertices.size() + 24 * mesh.indices.size() / 3 + 256);
    char line[256];
    std::snprintf(line, sizeof line,
                  "# foresight level mesh: %zu vertices, %zu triangles, %zu parts\n"
                  "# metres, +Y up; a triangle (a, b, c) faces along cross(b - a, c - a)\n",
                  mesh.vertices.size(), mesh.triangleCount(), parts.size());
    text += line;
    for (const dvec3& v : mesh.vertices) {
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v.x, v.y, v.z);
        text += line;
    }
    for (const auto& part : parts) {
        text += "o " + part.name + "\n";
        for (std::size_t t = part.firstTriangle; t < std::size_t(part.firstTriangle) + part.triangleCount; ++t) {
            std::snprintf(line, sizeof line, "f %lu %lu %lu\n", static_cast<unsigned long>(mesh.indices[3 * t]) + 1,
                          static_cast<unsigned long>(mesh.indices[3 * t + 1]) + 1,
                          static_cast<unsigned long>(mesh.indices[3 * t + 2]) + 1);
            text += line;
        }
    }
    return writeBytes(path, text, error);
}

bool writeGltf(const LevelMesh& mesh, const std::filesystem::path& path, std::string& error) {
    const std::string extension = lowerExtension(path);
    if (extension != ".gltf" && extension != ".glb") {
        error = path.string() + ": expected a .gltf or .glb file name";
        return false;
    }
    const bool binary = extension == ".glb";
    std::vector<LevelMesh::Part> parts;
    if (!checkMesh(mesh, path, parts, error)) return false;
    if (mesh.vertices.empty() || mesh.indices.empty()) {
        error = path.string() + ": the mesh has no triangle (glTF accessors cannot be empty)";
        return false;
    }
#ifndef FORESIGHT_LEVEL_WITH_GLTF
    (void)binary;
    error = path.string() + ": cannot write glTF: built without TinyGLTF";
    return false;
#else
    try {
        tinygltf::Model model;
        model.asset.version = "2.0";
        model.asset.generator = "foresight_level";

        // One buffer: positions (float, little-endian), then indices (uint32).
        tinygltf::Buffer buffer;
        std::array<double, 3> lo{}, hi{};
        lo.fill(std::numeric_limits<double>::infinity());
        hi.fill(-std::numeric_limits<double>::infinity());
        for (const dvec3& v : mesh.vertices) {
            for (int axis = 0; axis < 3; ++axis) {
                const float coordinate = static_cast<float>(v[axis]);
                lo[static_cast<std::size_t>(axis)] = std::min(lo[static_cast<std::size_t>(axis)], double(coordinate));
                hi[static_cast<std::size_t>(axis)] = std::max(hi[static_cast<std::size_t>(axis)], double(coordinate));
                appendLittleEndian(buffer.data, std::bit_cast<std::uint32_t>(coordinate));
            }
        }
        const std::size_t positionBytes = buffer.data.size();
        for (const std::uint32_t index : mesh.indices) appendLittleEndian(buffer.data, index);
        model.buffers.push_back(std::move(buffer));

        tinygltf::BufferView positionView;
        positionView.buffer = 0;
        positionView.byteOffset = 0;
        positionView.byteLength = positionBytes;
        positionView.target = TINYGLTF_TARGET_ARRAY_BUFFER;
        model.bufferViews.push_back(positionView);
        tinygltf::BufferView indexView;
        indexView.buffer = 0;
        indexView.byteOffset = positionBytes;
        indexView.byteLength = 4 * mesh.indices.size();
        indexView.target = TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER;
        model.bufferViews.push_back(indexView);

        tinygltf::Accessor positions;
        positions.bufferView = 0;
        positions.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        positions.type = TINYGLTF_TYPE_VEC3;
        positions.count = mesh.vertices.size();
        positions.minValues.assign(lo.begin(), lo.end());
        positions.maxValues.assign(hi.begin(), hi.end());
        model.accessors.push_back(positions);

        tinygltf::Scene scene;
        scene.name = "level";
        for (const auto& part : parts) {
            if (part.triangleCount == 0) continue;  // glTF accessors cannot be empty
            tinygltf::Accessor indices;
            indices.bufferView = 1;
            indices.byteOffset = std::size_t(12) * part.firstTriangle;
            indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
            indices.type = TINYGLTF_TYPE_SCALAR;
            indices.count = std::size_t(3) * part.triangleCount;
            model.accessors.push_back(indices);

            tinygltf::Primitive primitive;
            primitive.attributes["POSITION"] = 0;
            primitive.indices = static_cast<int>(model.accessors.size() - 1);
            primitive.mode = TINYGLTF_MODE_TRIANGLES;
            tinygltf::Mesh gltfMesh;
            gltfMesh.name = part.name;
            gltfMesh.primitives.push_back(primitive);
            model.meshes.push_back(gltfMesh);

            tinygltf::Node node;
            node.name = part.name;
            node.mesh = static_cast<int>(model.meshes.size() - 1);
            model.nodes.push_back(node);
            scene.nodes.push_back(static_cast<int>(model.nodes.size() - 1));
        }
        model.scenes.push_back(scene);
        model.defaultScene = 0;

        std::ostringstream stream;
        tinygltf::TinyGLTF writer;
        if (!writer.WriteGltfSceneToStream(&model, stream, /*prettyPrint=*/true, binary)) {
            error = path.string() + ": the glTF writer failed";
            return false;
        }
        return writeBytes(path, stream.str(), error);
    } catch (const std::exception& exception) {
        error = path.string() + ": cannot write glTF: " + exception.what();
        return false;
    }
#endif
}

}  // namespace foresight_level
