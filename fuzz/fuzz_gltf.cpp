// glTF 2.0 text files (`world.meshes[]` *.gltf) through EmbreeWorld::loadGltf
// (backends/embree/src/mesh_loaders.cpp, tinygltf), then the BVH build and a cast.
#include "fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path =
        foresight_fuzz::writeScratchFile("input.gltf", std::string_view(reinterpret_cast<const char*>(data), size));
    foresight::EmbreeWorld world;
    foresight_fuzz::useLoaded(world, world.loadGltf(path));
    return 0;
}
