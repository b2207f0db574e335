// Binary glTF (`world.meshes[]` *.glb) through EmbreeWorld::loadGltf
// (backends/embree/src/mesh_loaders.cpp, tinygltf), then the BVH build and a cast. The loader
// takes a file as GLB when it starts with "glTF"; the seeds (corpus/glb/) all do.
#include "fuzz_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path =
        foresight_fuzz::writeScratchFile("input.glb", std::string_view(reinterpret_cast<const char*>(data), size));
    foresight::EmbreeWorld world;
    foresight_fuzz::useLoaded(world, world.loadGltf(path));
    return 0;
}
