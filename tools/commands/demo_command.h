#pragma once
/// @file demo_command.h
/// `foresight demo`: the reference article's three scenarios (a running character, a bouncing
/// grenade, a turning car) and a grenade thrown across the demo level (demo_level.h), each
/// predicted the article's way ("faithful") and exactly; one answer of each AI use (a firing
/// solution, a planned throw, danger: tools/README.md), computed when it runs.
/// `foresight level` (level_command.h) writes the demo level's files.

#include "json_output.h"
#include "picture_options.h"

#include <string>

namespace foresight_cli {

/// The file name the demo scenario gives its level mesh (`world.meshes[0].file`), relative to
/// the scenario file.
inline constexpr const char* kDemoLevelFile = "demo_level.obj";

/// The demo's input, in the scenario format (`foresight demo --scenario FILE` writes it;
/// tests/data/demo_scenario.json is a copy). Its world includes the demo level as the mesh
/// kDemoLevelFile. Its last four predictions come from the AI answers (aim_target, aim_shot,
/// planned_throw, pedestrian), computed here. An empty object if that fails (never expected).
Json demoScenario();

/// Runs the demo: prints the comparison table to standard output, and writes the full result
/// (`jsonFile`) and the input scenario (`scenarioFile`) when those are not empty ("-": standard
/// output, which then holds only that JSON). A scenario file gets the level mesh written beside
/// it (kDemoLevelFile); with "-" a note on standard error says where it must go. The demo
/// itself builds the level in memory (makeDemoLevel), without files. Returns the exit status.
/// Pictures: `pictures.htmlFile` defaults to kDemoHtmlFile in the current directory when the
/// viewer is built (and `writeHtml` is true); the table then ends with where it is.
int demoCommand(const std::string& jsonFile, const std::string& scenarioFile, const PictureOptions& pictures,
                bool writeHtml = true);

/// Where `foresight demo` writes its viewer page unless told otherwise.
inline constexpr const char* kDemoHtmlFile = "foresight-demo.html";

}  // namespace foresight_cli
