#pragma once
/// @file fuzz_json.h
/// For the harnesses of the CLI's JSON inputs: the bytes parsed as `foresight predict` and the
/// other verbs parse a file (parseJsonText), and the directory mesh file names are resolved
/// against, holding a small OBJ (mesh.obj) and glTF (mesh.gltf) so that `world.meshes` loads
/// real meshes too.

#include "fuzz_common.h"

#include "json_input.h"
#include "json_output.h"

#include <string>

namespace foresight_fuzz {

/// The base directory of the JSON inputs (made once): mesh.obj, a 10 m square of two
/// triangles, and mesh.gltf, one triangle 1 m up.
inline const std::filesystem::path& meshDirectory() {
    static const std::filesystem::path directory = [] {
        writeScratchFile("mesh.obj", "v -5 0 -5\nv 5 0 -5\nv 5 0 5\nv -5 0 5\nf 1 2 3 4\n");
        writeScratchFile(
            "mesh.gltf",
            R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0,"translation":[0,1,0]}],)"
            R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":4}]}],"buffers":[{"byteLength":44,)"
            R"("uri":"data:application/octet-stream;base64,AACgwAAAAAAAAKDAAACgQAAAAAAAAKDAAAAAAAAAAAAAAKBAAAABAAIAAAA="}],)"
            R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],)"
            R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[-5,0,-5],"max":[5,0,5]},)"
            R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}]})");
        return scratchDirectory();
    }();
    return directory;
}

/// Parses the bytes as the CLI parses a file; false when it refuses them.
inline bool parseInput(const std::uint8_t* data, std::size_t size, foresight_cli::Json& document,
                       foresight_cli::Diagnostics& diagnostics) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    return foresight_cli::parseJsonText(text, "fuzz.json", document, diagnostics);
}

/// Serialises an output document as the CLI prints it (every number must be representable).
inline void formatOutput(const foresight_cli::Json& document) {
    const std::string text = foresight_cli::formatJson(document);
    FORESIGHT_FUZZ_CHECK(!text.empty());
}

}  // namespace foresight_fuzz
