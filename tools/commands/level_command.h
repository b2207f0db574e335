#pragma once
/// @file level_command.h
/// `foresight level`: the demo level (demo_level.h), or a closed room, written as files.

#include <string>
#include <vector>

namespace foresight_cli {

/// Options of `foresight level`.
struct LevelOptions {
    std::string objFile;           ///< Wavefront OBJ output, or empty.
    std::string gltfFile;          ///< glTF (.gltf, JSON with the buffer embedded) output, or empty.
    std::string glbFile;           ///< binary glTF (.glb) output, or empty.
    bool room = false;             ///< the closed room instead of the courtyard.
    std::vector<double> roomSize;  ///< the room's size (3 numbers, implies `room`) [Units: m].
};

/// `foresight level`: writes the demo level (or the closed room) to every file given, then
/// prints one line per file (name, triangles) to standard output. Returns 0, or 2 (nothing on
/// standard output) for no output file, a bad room size, a wrong extension or a write error,
/// with a message naming the file.
int levelCommand(const LevelOptions& options);

}  // namespace foresight_cli
