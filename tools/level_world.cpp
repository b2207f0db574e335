#include "level_world.h"

#ifdef FORESIGHT_CLI_WITH_EMBREE
#include <foresight/embree_world.h>
#endif

#include <memory>
#include <vector>

namespace foresight_cli {

bool addLevelMesh(Scenario& scenario, const foresight_level::LevelMesh& mesh, std::string& error) {
    std::vector<foresight::RVec3> vertices(mesh.vertices.begin(), mesh.vertices.end());
#ifdef FORESIGHT_CLI_WITH_EMBREE
    // An EmbreeWorld keeps its primitives and its meshes apart: the order of the two calls
    // changes nothing.
    auto world = std::make_unique<foresight::EmbreeWorld>();
    foresight::MeshReport report;
    if (world->addMesh(vertices, mesh.indices, &report) != foresight::Status::Ok) {
        error = report.error;
        return false;
    }
    world->addPrimitives(scenario.world);
    if (!world->commit(&error)) return false;
    scenario.meshWorld = std::move(world);
#else
    foresight::MeshReport report;
    if (scenario.world.addMesh(vertices, mesh.indices, &report) != foresight::Status::Ok) {
        error = report.error;
        return false;
    }
#endif
    return true;
}

}  // namespace foresight_cli
