#include "obj_mesh.h"

#include "text_file.h"

#include <foresight/obj_check.h>

#include <tiny_obj_loader.h>

#include <cmath>
#include <sstream>

namespace foresight_cli {

namespace {

std::vector<std::string> nonEmptyLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream stream(text);
    std::string line;
    while (std::getline(stream, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '.')) line.pop_back();
        if (!line.empty()) lines.push_back(line);
    }
    return lines;
}

std::string oneLine(const std::string& text) {
    std::string joined;
    for (const auto& line : nonEmptyLines(text)) {
        if (!joined.empty()) joined += "; ";
        joined += line;
    }
    return joined.empty() ? std::string("malformed OBJ") : joined;
}

}  // namespace

bool loadObjMesh(const std::filesystem::path& file, ObjMesh& mesh, std::string& reason) {
    mesh = ObjMesh{};
    std::string text;
    if (!readRegularFile(file, foresight::kMaxObjBytes, text, reason)) return false;
    // tinyobjloader reads numbers and indices leniently ("nan", "1,5", "3.7" and "v 1 0" become
    // numbers): the lines it reads are checked strictly first.
    if (!foresight::checkObjText(text, reason)) {
        reason = "malformed OBJ: " + reason;
        return false;
    }

    // Triangulated here rather than by tinyobjloader, whose triangulation skips faces with
    // out-of-range indices silently: every index is checked below instead.
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // Materials are not needed: ParseFromString ignores `mtllib` (no other file is opened).
    if (!reader.ParseFromString(text, std::string(), config)) {
        reason = "malformed OBJ: " + oneLine(reader.Error());
        return false;
    }
    mesh.warnings = nonEmptyLines(reader.Warning());

    const auto& vertices = reader.GetAttrib().vertices;
    if (vertices.size() % 3 != 0) {
        reason = "malformed OBJ: vertex data is not a multiple of 3 coordinates";
        return false;
    }
    const std::size_t vertexCount = vertices.size() / 3;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        if (!std::isfinite(static_cast<double>(vertices[i]))) {
            reason = "vertex " + std::to_string(i / 3 + 1) + " is not finite";
            return false;
        }
    }
    auto vertex = [&](std::size_t index) {
        return foresight::RVec3(static_cast<foresight::Real>(vertices[3 * index + 0]),
                                static_cast<foresight::Real>(vertices[3 * index + 1]),
                                static_cast<foresight::Real>(vertices[3 * index + 2]));
    };

    std::size_t faceNumber = 0;
    for (const auto& shape : reader.GetShapes()) {
        const auto& indices = shape.mesh.indices;
        std::size_t offset = 0;
        for (const unsigned char corners : shape.mesh.num_face_vertices) {
            ++faceNumber;
            if (offset + corners > indices.size()) {
                reason = "malformed OBJ: face " + std::to_string(faceNumber) + " has more than 255 vertices";
                return false;
            }
            for (std::size_t k = 0; k < corners; ++k) {
                const int index = indices[offset + k].vertex_index;
                if (index < 0 || static_cast<std::size_t>(index) >= vertexCount) {
                    reason = "face " + std::to_string(faceNumber) + " refers to " +
                             (index < 0 ? std::string("a vertex before the first one (relative index)")
                                        : "vertex " + std::to_string(index + 1)) +
                             ", out of range (the file has " + std::to_string(vertexCount) + " vertices)";
                    return false;
                }
            }
            // A fan from the first corner.
            for (std::size_t k = 1; k + 1 < corners; ++k) {
                const foresight::Triangle triangle{
                    vertex(static_cast<std::size_t>(indices[offset].vertex_index)),
                    vertex(static_cast<std::size_t>(indices[offset + k].vertex_index)),
                    vertex(static_cast<std::size_t>(indices[offset + k + 1].vertex_index))};
                const foresight::Status status = foresight::validateTriangle(triangle);
                if (status == foresight::Status::Ok) {
                    mesh.triangles.push_back(triangle);
                } else if (status == foresight::Status::DegenerateShape) {
                    if (mesh.degenerateTriangles++ == 0) mesh.firstDegenerateFace = faceNumber;
                } else {
                    reason = "face " + std::to_string(faceNumber) + ": " + foresight::statusMessage(status);
                    return false;
                }
            }
            offset += corners;
        }
        if (offset != indices.size()) {
            reason = "malformed OBJ: a face in shape \"" + shape.name + "\" has more than 255 vertices";
            return false;
        }
    }
    if (mesh.triangles.empty()) {
        reason = mesh.degenerateTriangles > 0
                     ? "no usable triangles (" + std::to_string(mesh.degenerateTriangles) + " degenerate ones skipped)"
                     : std::string("no triangles (no faces)");
        return false;
    }
    return true;
}

}  // namespace foresight_cli
