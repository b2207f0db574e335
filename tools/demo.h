#pragma once
/// @file demo.h
/// `foresight demo`: the reference article's three scenarios (a running character, a bouncing
/// grenade, a turning car), each predicted the article's way ("faithful") and exactly.

#include "json_output.h"

#include <string>

namespace foresight_cli {

/// The demo's input, in the scenario format (`foresight demo --scenario FILE` writes it;
/// tests/data/demo_scenario.json is a copy).
Json demoScenario();

/// Runs the demo: prints the comparison table to standard output, and writes the full result
/// (`jsonFile`) and the input scenario (`scenarioFile`) when those are not empty ("-": standard
/// output, which then holds only that JSON). Returns the exit status.
int demoCommand(const std::string& jsonFile, const std::string& scenarioFile);

} // namespace foresight_cli
