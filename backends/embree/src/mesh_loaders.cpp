// File loaders of EmbreeWorld: Wavefront OBJ (tinyobjloader) and glTF 2.0 (tinygltf).
#include <foresight/embree_world.h>

#include <foresight/obj_check.h>

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <exception>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

FORESIGHT_NAMESPACE_BEGIN

namespace {

std::string oneLine(const std::string& text, const char* fallback) {
    std::string joined;
    std::istringstream stream(text);
    std::string line;
    while (std::getline(stream, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '.')) line.pop_back();
        if (line.empty()) continue;
        if (!joined.empty()) joined += "; ";
        joined += line;
    }
    return joined.empty() ? std::string(fallback) : joined;
}

MeshLoadResult failure(const std::filesystem::path& path, const std::string& message) {
    MeshLoadResult result;
    result.error = path.string() + ": " + message;
    return result;
}

std::string mebibytes(std::uintmax_t bytes) { return std::to_string(bytes >> 20) + " MiB"; }

// Reads a regular file of at most maxBytes (never a device, pipe or directory: /dev/zero would
// read until memory runs out, a named pipe would block).
bool readFile(const std::filesystem::path& path, std::uintmax_t maxBytes, std::string& text, std::string& reason) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        reason = std::filesystem::exists(path, ec) ? "not a regular file" : "No such file or directory";
        return false;
    }
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) {
        reason = "cannot be read (" + ec.message() + ")";
        return false;
    }
    if (size > maxBytes) {
        reason = "larger than " + mebibytes(maxBytes) + " (the limit for this file)";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        reason = "cannot be opened";
        return false;
    }
    text.resize(static_cast<std::size_t>(size));
    in.read(text.data(), static_cast<std::streamsize>(size));
    if (in.bad() || static_cast<std::uintmax_t>(in.gcount()) != size || in.peek() != std::char_traits<char>::eof()) {
        reason = "changed while it was read, or read error";
        return false;
    }
    return true;
}

MeshLoadResult addLoaded(EmbreeWorld& world, const std::filesystem::path& path, const std::vector<RVec3>& vertices,
                         const std::vector<std::uint32_t>& indices) {
    MeshLoadResult result;
    const Status status = world.addMesh(vertices, indices, &result.report);
    if (status != Status::Ok) return MeshLoadResult{false, path.string() + ": " + result.report.error, result.report};
    result.ok = true;
    return result;
}

MeshLoadResult loadObjImpl(EmbreeWorld& world, const std::filesystem::path& path) {
    std::string text, reason;
    if (!readFile(path, kMaxObjBytes, text, reason)) return failure(path, reason);
    // tinyobjloader reads numbers and indices leniently: the lines it reads are checked first.
    if (!checkObjText(text, reason)) return failure(path, "malformed OBJ: " + reason);
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, std::string(), config))
        return failure(path, "malformed OBJ: " + oneLine(reader.Error(), "parse error"));
    const auto& coordinates = reader.GetAttrib().vertices;
    if (coordinates.size() % 3 != 0)
        return failure(path, "malformed OBJ: vertex data is not a multiple of 3 coordinates");
    std::vector<RVec3> vertices(coordinates.size() / 3);
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            const double value = static_cast<double>(coordinates[3 * i + static_cast<std::size_t>(k)]);
            if (!std::isfinite(value)) return failure(path, "vertex " + std::to_string(i + 1) + " is not finite");
            vertices[i][k] = static_cast<Real>(value);
        }
    }
    std::vector<std::uint32_t> indices;
    std::size_t faceNumber = 0;
    for (const auto& shape : reader.GetShapes()) {
        const auto& corners = shape.mesh.indices;
        std::size_t offset = 0;
        for (const unsigned char count : shape.mesh.num_face_vertices) {
            ++faceNumber;
            if (offset + count > corners.size())
                return failure(path, "malformed OBJ: face " + std::to_string(faceNumber));
            for (std::size_t k = 0; k < count; ++k) {
                const int index = corners[offset + k].vertex_index;
                if (index < 0 || static_cast<std::size_t>(index) >= vertices.size())
                    return failure(path, "face " + std::to_string(faceNumber) +
                                             " refers to a vertex out of range (the file has " +
                                             std::to_string(vertices.size()) + " vertices)");
            }
            for (std::size_t k = 1; k + 1 < count; ++k) {
                indices.push_back(static_cast<std::uint32_t>(corners[offset].vertex_index));
                indices.push_back(static_cast<std::uint32_t>(corners[offset + k].vertex_index));
                indices.push_back(static_cast<std::uint32_t>(corners[offset + k + 1].vertex_index));
            }
            offset += count;
        }
    }
    if (indices.empty()) return failure(path, "no triangles (no faces)");
    return addLoaded(world, path, vertices, indices);
}

// Images are not needed: never decode them.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;
}

using DMat4 = glm::dmat4;

// A node's rotation must be a unit quaternion (glTF); a slightly denormalised one is normalised.
bool validRotation(const tinygltf::Node& node) {
    if (node.rotation.size() != 4) return node.rotation.empty();
    double squared = 0.0;
    for (const double c : node.rotation) {
        if (!std::isfinite(c)) return false;
        squared += c * c;
    }
    return std::abs(std::sqrt(squared) - 1.0) <= 1e-2;
}

DMat4 nodeTransform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        DMat4 m(1.0);
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[static_cast<std::size_t>(4 * c + r)];
        return m;
    }
    DMat4 m(1.0);
    if (node.translation.size() == 3)
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4) {
        glm::dquat q;
        q.x = node.rotation[0];
        q.y = node.rotation[1];
        q.z = node.rotation[2];
        q.w = node.rotation[3];
        m = m * glm::mat4_cast(glm::normalize(q));
    }
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

// An accessor's element `i`, component `k`, as a double; false when out of the buffer.
struct AccessorView {
    const unsigned char* data = nullptr;
    std::size_t count = 0, stride = 0, componentSize = 0;
    int componentType = 0;
};

bool viewAccessor(const tinygltf::Model& model, int index, int type, AccessorView& view, std::string& reason) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
        reason = "accessor " + std::to_string(index) + " does not exist";
        return false;
    }
    const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
    if (accessor.type != type) {
        reason = "accessor " + std::to_string(index) + " has the wrong type";
        return false;
    }
    if (accessor.sparse.isSparse) {
        reason = "accessor " + std::to_string(index) + " is sparse (not supported)";
        return false;
    }
    if (accessor.bufferView < 0 || static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size()) {
        reason = "accessor " + std::to_string(index) + " has no valid buffer view";
        return false;
    }
    const tinygltf::BufferView& bufferView = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    if (bufferView.buffer < 0 || static_cast<std::size_t>(bufferView.buffer) >= model.buffers.size()) {
        reason = "buffer view " + std::to_string(accessor.bufferView) + " has no valid buffer";
        return false;
    }
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<std::size_t>(bufferView.buffer)].data;
    const int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
    if (componentSize <= 0 || components <= 0) {
        reason = "accessor " + std::to_string(index) + " has an invalid component type";
        return false;
    }
    const std::size_t elementSize = static_cast<std::size_t>(componentSize) * static_cast<std::size_t>(components);
    // byteStride: 0 (tightly packed) or 4 to 252, a multiple of 4, and no smaller than an element.
    if (bufferView.byteStride > 0 &&
        (bufferView.byteStride < elementSize || bufferView.byteStride > 252 || bufferView.byteStride % 4 != 0)) {
        reason = "buffer view " + std::to_string(accessor.bufferView) + " has byteStride " +
                 std::to_string(bufferView.byteStride) + ", invalid for accessor " + std::to_string(index) +
                 " (elements of " + std::to_string(elementSize) + " bytes; glTF allows 4 to 252, multiples of 4)";
        return false;
    }
    const std::size_t stride = bufferView.byteStride > 0 ? bufferView.byteStride : elementSize;
    // Every sum below is checked before it is formed: offsets near 2^64 must not wrap.
    const std::size_t size = buffer.size();
    const bool viewFits = bufferView.byteOffset <= size && bufferView.byteLength <= size - bufferView.byteOffset;
    const std::size_t viewLength = viewFits ? bufferView.byteLength : 0;
    bool fits = viewFits && accessor.byteOffset <= viewLength;
    if (fits && accessor.count > 0) {
        const std::size_t room = viewLength - accessor.byteOffset;  // bytes from the first element on
        fits = elementSize <= room && accessor.count - 1 <= (room - elementSize) / stride;
    }
    if (!fits) {
        reason = "accessor " + std::to_string(index) +
                 " reaches past the end of its buffer view or buffer (truncated file?)";
        return false;
    }
    const std::size_t begin = bufferView.byteOffset + accessor.byteOffset;
    view.data = buffer.data() + begin;
    view.count = accessor.count;
    view.stride = stride;
    view.componentSize = static_cast<std::size_t>(componentSize);
    view.componentType = accessor.componentType;
    return true;
}

template <class T>
T readAt(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));
    return value;
}

struct GltfLoader {
    const tinygltf::Model& model;
    std::vector<RVec3> vertices;
    std::vector<std::uint32_t> indices;
    std::string reason;

    bool primitive(const tinygltf::Primitive& primitive, const DMat4& transform) {
        if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != -1)
            return true;  // lines, points, strips: skipped
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) return true;
        AccessorView pv;
        if (!viewAccessor(model, position->second, TINYGLTF_TYPE_VEC3, pv, reason)) return false;
        if (pv.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
            reason = "POSITION is not float";
            return false;
        }
        const std::size_t base = vertices.size();
        if (pv.count > kMaxLoadedVertices - base) {
            reason = "more than " + std::to_string(kMaxLoadedVertices) +
                     " vertices in all (with every node's instance of its mesh)";
            return false;
        }
        for (std::size_t i = 0; i < pv.count; ++i) {
            const unsigned char* p = pv.data + i * pv.stride;
            const glm::dvec4 local(readAt<float>(p), readAt<float>(p + 4), readAt<float>(p + 8), 1.0);
            if (!std::isfinite(local.x) || !std::isfinite(local.y) || !std::isfinite(local.z)) {
                reason = "vertex " + std::to_string(i) + " of accessor " + std::to_string(position->second) +
                         " is not finite";
                return false;
            }
            const glm::dvec4 world = transform * local;
            if (!std::isfinite(world.x) || !std::isfinite(world.y) || !std::isfinite(world.z)) {
                reason = "a transformed vertex is not finite";
                return false;
            }
            vertices.emplace_back(static_cast<Real>(world.x), static_cast<Real>(world.y), static_cast<Real>(world.z));
        }
        if (primitive.indices < -1) {
            reason =
                "a primitive's indices are accessor " + std::to_string(primitive.indices) + ", which does not exist";
            return false;
        }
        // A mirroring transform flips the winding; triangles are two-sided, so it does not matter.
        if (primitive.indices < 0) {
            if (pv.count % 3 != 0) {
                reason = "a non-indexed primitive's vertex count is not a multiple of 3";
                return false;
            }
            if (pv.count > 3 * kMaxLoadedTriangles - indices.size()) {
                reason = "more than " + std::to_string(kMaxLoadedTriangles) +
                         " triangles in all (with every node's instance of its mesh)";
                return false;
            }
            for (std::size_t i = 0; i < pv.count; ++i) indices.push_back(static_cast<std::uint32_t>(base + i));
            return true;
        }
        AccessorView iv;
        if (!viewAccessor(model, primitive.indices, TINYGLTF_TYPE_SCALAR, iv, reason)) return false;
        if (iv.count % 3 != 0) {
            reason = "an index count is not a multiple of 3";
            return false;
        }
        if (iv.count > 3 * kMaxLoadedTriangles - indices.size()) {
            reason = "more than " + std::to_string(kMaxLoadedTriangles) +
                     " triangles in all (with every node's instance of its mesh)";
            return false;
        }
        for (std::size_t i = 0; i < iv.count; ++i) {
            const unsigned char* p = iv.data + i * iv.stride;
            std::uint64_t index = 0;
            switch (iv.componentType) {
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    index = readAt<std::uint8_t>(p);
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
                    index = readAt<std::uint16_t>(p);
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
                    index = readAt<std::uint32_t>(p);
                    break;
                default:
                    reason = "indices are not unsigned integers";
                    return false;
            }
            if (index >= pv.count) {
                reason = "index " + std::to_string(i) + " refers to vertex " + std::to_string(index) +
                         ", out of range (" + std::to_string(pv.count) + " vertices)";
                return false;
            }
            indices.push_back(static_cast<std::uint32_t>(base + index));
        }
        return true;
    }

    bool node(int index, const DMat4& parent, int depth) {
        if (index < 0 || static_cast<std::size_t>(index) >= model.nodes.size()) {
            reason = "node " + std::to_string(index) + " does not exist";
            return false;
        }
        if (depth > 256) {
            reason = "the node hierarchy is deeper than 256 levels";
            return false;
        }
        const tinygltf::Node& n = model.nodes[static_cast<std::size_t>(index)];
        if (!validRotation(n)) {
            reason = "node " + std::to_string(index) + "'s rotation is not a unit quaternion (x, y, z, w)";
            return false;
        }
        const DMat4 transform = parent * nodeTransform(n);
        if (n.mesh < -1) {
            reason = "node " + std::to_string(index) + "'s mesh " + std::to_string(n.mesh) + " does not exist";
            return false;
        }
        if (n.mesh >= 0) {
            if (static_cast<std::size_t>(n.mesh) >= model.meshes.size()) {
                reason = "mesh " + std::to_string(n.mesh) + " does not exist";
                return false;
            }
            for (const tinygltf::Primitive& p : model.meshes[static_cast<std::size_t>(n.mesh)].primitives)
                if (!primitive(p, transform)) return false;
        }
        for (const int child : n.children)
            if (!node(child, transform, depth + 1)) return false;
        return true;
    }
};

// glTF nodes form disjoint strict trees: no node is the child of two nodes (or twice of one), none
// is its own child, and a scene's nodes are roots. Checked before the traversal, which then visits
// each node once per scene (a node listed twice as a child would double the work at every level).
bool checkNodeTrees(const tinygltf::Model& model, std::string& reason) {
    const std::size_t count = model.nodes.size();
    std::vector<int> parent(count, -1);
    for (std::size_t i = 0; i < count; ++i) {
        for (const int child : model.nodes[i].children) {
            if (child < 0 || static_cast<std::size_t>(child) >= count) {
                reason = "node " + std::to_string(i) + " has child " + std::to_string(child) + ", which does not exist";
                return false;
            }
            if (static_cast<std::size_t>(child) == i || parent[static_cast<std::size_t>(child)] >= 0) {
                reason = "node " + std::to_string(child) + " is a child twice (of node " + std::to_string(i) +
                         (parent[static_cast<std::size_t>(child)] >= 0
                              ? " and node " + std::to_string(parent[static_cast<std::size_t>(child)])
                              : std::string(", itself")) +
                         "): glTF nodes must form trees";
                return false;
            }
            parent[static_cast<std::size_t>(child)] = static_cast<int>(i);
        }
    }
    for (std::size_t s = 0; s < model.scenes.size(); ++s) {
        std::vector<bool> listed(count, false);
        for (const int root : model.scenes[s].nodes) {
            if (root < 0 || static_cast<std::size_t>(root) >= count) {
                reason =
                    "scene " + std::to_string(s) + " lists node " + std::to_string(root) + ", which does not exist";
                return false;
            }
            if (parent[static_cast<std::size_t>(root)] >= 0 || listed[static_cast<std::size_t>(root)]) {
                reason =
                    "scene " + std::to_string(s) + " lists node " + std::to_string(root) +
                    (listed[static_cast<std::size_t>(root)] ? " twice" : ", which is not a root (it has a parent)");
                return false;
            }
            listed[static_cast<std::size_t>(root)] = true;
        }
    }
    return true;
}

// External files a glTF names (buffers, images): regular files inside the glTF's own folder
// only, within the loader's byte budget. tinygltf's file callbacks.
struct ConfinedFiles {
    std::filesystem::path folder;  // canonical
    std::uintmax_t budget = 0;     // bytes left for all external files
    std::string refusal;           // why the last file was refused
};

bool confinedPath(ConfinedFiles& files, const std::string& name, std::filesystem::path& resolved) {
    std::error_code ec;
    const std::filesystem::path path = std::filesystem::weakly_canonical(std::filesystem::path(name), ec);
    if (ec) return false;
    const auto [folderEnd, pathAt] = std::mismatch(files.folder.begin(), files.folder.end(), path.begin(), path.end());
    (void)pathAt;
    if (folderEnd != files.folder.end()) {
        files.refusal = "\"" + name + "\" is outside the glTF's folder";
        return false;
    }
    resolved = path;
    return true;
}

bool confinedExists(const std::string& name, void* user) {
    auto& files = *static_cast<ConfinedFiles*>(user);
    std::filesystem::path path;
    std::error_code ec;
    return confinedPath(files, name, path) && std::filesystem::is_regular_file(path, ec);
}

std::string noExpansion(const std::string& name, void*) { return name; }

bool confinedRead(std::vector<unsigned char>* out, std::string* err, const std::string& name, void* user) {
    auto& files = *static_cast<ConfinedFiles*>(user);
    std::filesystem::path path;
    std::string text, reason;
    if (!confinedPath(files, name, path)) {
        if (err) *err += files.refusal.empty() ? "cannot resolve \"" + name + "\"" : files.refusal;
        return false;
    }
    if (!readFile(path, files.budget, text, reason)) {
        files.refusal = "\"" + name + "\": " + reason;
        if (err) *err += files.refusal;
        return false;
    }
    files.budget -= text.size();
    out->assign(text.begin(), text.end());
    return true;
}

bool noWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not allowed";
    return false;
}

MeshLoadResult loadGltfImpl(EmbreeWorld& world, const std::filesystem::path& path) {
    std::string bytes, reason;
    if (!readFile(path, kMaxGltfBytes, bytes, reason)) return failure(path, reason);
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skipImage, nullptr);
    std::error_code ec;
    const std::filesystem::path folder =
        std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec).parent_path(), ec);
    if (ec) return failure(path, "cannot resolve its folder (" + ec.message() + ")");
    ConfinedFiles files{folder, kMaxGltfBytes - bytes.size(), {}};
    loader.SetFsCallbacks(tinygltf::FsCallbacks{confinedExists, noExpansion, confinedRead, noWrite, &files});
    std::string err, warn;
    const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    if (binary) {
        std::uint32_t version = 0;
        if (bytes.size() >= 8) std::memcpy(&version, bytes.data() + 4, 4);
        if (version != 2) return failure(path, "GLB version " + std::to_string(version) + " (only glTF 2.0 is read)");
    }
    const std::string baseDir = folder.string();
    const bool loaded =
        binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                             static_cast<unsigned>(bytes.size()), baseDir)
               : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned>(bytes.size()),
                                            baseDir);
    if (!loaded) {
        if (!files.refusal.empty()) return failure(path, "a file it names is refused: " + files.refusal);
        return failure(path,
                       std::string(binary ? "malformed GLB: " : "malformed glTF: ") + oneLine(err, "parse error"));
    }
    if (model.defaultScene < -1 ||
        (model.defaultScene >= 0 && static_cast<std::size_t>(model.defaultScene) >= model.scenes.size()))
        return failure(path, "its scene " + std::to_string(model.defaultScene) + " does not exist (" +
                                 std::to_string(model.scenes.size()) + " scenes)");
    if (!checkNodeTrees(model, reason)) return failure(path, reason);
    GltfLoader gltf{model, {}, {}, {}};
    bool ok = true;
    if (model.defaultScene >= 0) {
        for (const int n : model.scenes[static_cast<std::size_t>(model.defaultScene)].nodes)
            if (ok) ok = gltf.node(n, DMat4(1.0), 0);
    } else if (!model.scenes.empty()) {
        for (const auto& scene : model.scenes)
            for (const int n : scene.nodes)
                if (ok) ok = gltf.node(n, DMat4(1.0), 0);
    } else {
        // No scene: every mesh, untransformed.
        for (const auto& mesh : model.meshes)
            for (const auto& p : mesh.primitives)
                if (ok) ok = gltf.primitive(p, DMat4(1.0));
    }
    if (!ok) return failure(path, gltf.reason);
    if (gltf.indices.empty()) return failure(path, "no triangles (no TRIANGLES primitives)");
    return addLoaded(world, path, gltf.vertices, gltf.indices);
}

}  // namespace

MeshLoadResult EmbreeWorld::loadObj(const std::filesystem::path& path) {
    try {
        return loadObjImpl(*this, path);
    } catch (const std::bad_alloc&) {
        return failure(path, "out of memory");
    } catch (const std::exception& e) {
        return failure(path, std::string("malformed OBJ: ") + e.what());
    } catch (...) {
        return failure(path, "malformed OBJ");
    }
}

MeshLoadResult EmbreeWorld::loadGltf(const std::filesystem::path& path) {
    try {
        return loadGltfImpl(*this, path);
    } catch (const std::bad_alloc&) {
        return failure(path, "out of memory");
    } catch (const std::exception& e) {
        return failure(path, std::string("malformed glTF: ") + e.what());
    } catch (...) {
        return failure(path, "malformed glTF");
    }
}

FORESIGHT_NAMESPACE_END
