// Wavefront OBJ meshes (`world.meshes[]`): the CLI's loader (loadObjMesh, tools/obj_mesh.cpp)
// and, with the Embree backend, EmbreeWorld::loadObj (backends/embree/src/mesh_loaders.cpp),
// both on the same file; then the BVH build and a cast, as a scenario would use the mesh.
#include "fuzz_common.h"

#include "obj_mesh.h"

#include <cmath>

#ifdef FORESIGHT_FUZZ_WITH_EMBREE
#include "fuzz_mesh.h"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path =
        foresight_fuzz::writeScratchFile("input.obj", std::string_view(reinterpret_cast<const char*>(data), size));
    foresight_cli::ObjMesh mesh;
    std::string reason;
    if (foresight_cli::loadObjMesh(path, mesh, reason)) {
        FORESIGHT_FUZZ_CHECK(!mesh.triangles.empty());
        for (const auto& t : mesh.triangles)
            for (const auto& v : {t.a, t.b, t.c})
                FORESIGHT_FUZZ_CHECK(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
    } else {
        FORESIGHT_FUZZ_CHECK(!reason.empty());
    }
#ifdef FORESIGHT_FUZZ_WITH_EMBREE
    foresight::EmbreeWorld world;
    foresight_fuzz::useLoaded(world, world.loadObj(path));
#endif
    return 0;
}
