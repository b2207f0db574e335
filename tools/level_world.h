#pragma once
/// @file level_world.h
/// A generated level mesh (demo_level.h) in a scenario's world, where `foresight predict` puts
/// the triangles of a mesh file: for the demo and `foresight compare`'s built-in scenes.

#include "demo_level.h"
#include "scenario.h"

#include <string>

namespace foresight_cli {

/// Adds `mesh` to `scenario` as scenario.cpp adds `world.meshes[]`: into an EmbreeWorld that also
/// holds the scenario's primitives when the CLI has Embree (Scenario::meshWorld; call it after
/// every primitive is in scenario.world), else as StaticWorld triangles after the scenario's
/// own (degenerate ones skipped, as the OBJ loader does). Returns false with `error` if the
/// mesh is refused.
bool addLevelMesh(Scenario& scenario, const foresight_level::LevelMesh& mesh, std::string& error);

}  // namespace foresight_cli
