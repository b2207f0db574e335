#include "level_command.h"

#include "demo_level.h"
#include "text_file.h"

#include <glm/vec3.hpp>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <utility>

namespace foresight_cli {

int levelCommand(const LevelOptions& options) {
    if (options.objFile.empty() && options.gltfFile.empty() && options.glbFile.empty()) {
        std::cerr << "foresight level: nothing to write: give --obj FILE, --gltf FILE or --glb FILE\n";
        return 2;
    }
    const bool room = options.room || !options.roomSize.empty();
    glm::dvec3 size(10.0, 4.0, 10.0);
    if (!options.roomSize.empty()) {
        for (int axis = 0; axis < 3; ++axis) {
            const double value = options.roomSize.size() == 3 ? options.roomSize[static_cast<std::size_t>(axis)] : 0.0;
            if (!std::isfinite(value) || !(value > 0.0)) {
                std::cerr << "--room-size: expected 3 finite sizes > 0 (metres)\n";
                return 2;
            }
            size[axis] = value;
        }
    }
    const foresight_level::LevelMesh mesh =
        room ? foresight_level::makeClosedRoom(size) : foresight_level::makeDemoLevel();
    const auto extensionIs = [](const std::string& file, const char* wanted) {
        std::string extension = std::filesystem::path(file).extension().string();
        for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return extension == wanted;
    };
    for (const auto& [file, extension] : {std::pair{options.gltfFile, ".gltf"}, std::pair{options.glbFile, ".glb"}}) {
        if (!file.empty() && !extensionIs(file, extension)) {
            std::cerr << file << ": expected a file name ending in " << extension << '\n';
            return 2;
        }
    }
    // Everything is written before anything is printed: on failure standard output stays empty.
    std::string report;
    std::string error;
    const std::string what = room ? "closed room" : "demo level";
    const auto line = [&](const std::string& file) {
        report += file + ": " + std::to_string(mesh.triangleCount()) + " triangles, " +
                  std::to_string(mesh.vertices.size()) + " vertices, " + std::to_string(mesh.parts.size()) +
                  " parts (" + what + ")\n";
    };
    if (!options.objFile.empty()) {
        if (!foresight_level::writeObj(mesh, options.objFile, error)) {
            std::cerr << error << '\n';
            return 2;
        }
        line(options.objFile);
    }
    for (const std::string& file : {options.gltfFile, options.glbFile}) {
        if (file.empty()) continue;
        if (!foresight_level::writeGltf(mesh, file, error)) {
            std::cerr << error << '\n';
            return 2;
        }
        line(file);
    }
    std::string reason;
    if (!writeTextFile("-", report, reason)) {
        std::cerr << "foresight level: cannot write to standard output: " << reason << '\n';
        return 1;
    }
    return 0;
}

}  // namespace foresight_cli
