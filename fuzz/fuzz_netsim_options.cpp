// `foresight netsim OPTIONS`: the options (one per line of the input) through the CLI's own
// parser (addNetsimCommand, CLI11) and checks (buildNetsimSettings), then a short simulation of
// the built-in trajectories named with the settings they gave.
#include "fuzz_common.h"

#include "commands/netsim_command.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> splitLines(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> lines{"foresight", "netsim"};
    std::string current;
    for (std::size_t i = 0; i < size; ++i) {
        const char c = static_cast<char>(data[i]);
        if (c == '\n') {
            lines.push_back(current);
            current.clear();
        } else {
            current += c;
        }
    }
    if (!current.empty()) lines.push_back(current);
    return lines;
}

}  // namespace

// buildNetsimSettings says what is wrong on std::cerr: silenced (sanitizer and contract reports
// are written with fprintf and still show).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::cerr.rdbuf(nullptr);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace foresight_cli;
    namespace ns = foresight_cli::netsim;
    const std::vector<std::string> lines = splitLines(data, size);
    if (lines.size() > 64) return 0;
    std::vector<const char*> argv;
    for (const auto& line : lines) argv.push_back(line.c_str());

    CLI::App app("foresight");
    NetsimOptions options;
    addNetsimCommand(app, options);
    try {
        app.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::Error&) {
        return 0;  // the CLI prints the message and exits 2 (or 0 for --help)
    }
    ns::SimulationSettings settings;
    if (!buildNetsimSettings(options, settings)) return 0;

    // The built-in trajectories asked for (a CSV file is fuzz_netsim_csv's), over at most a
    // quarter second: the CLI runs up to an hour.
    std::vector<std::string> names;
    for (const auto& item : options.trajectories) {
        std::size_t begin = 0;
        while (begin <= item.size()) {
            const std::size_t comma = std::min(item.find(',', begin), item.size());
            names.push_back(item.substr(begin, comma - begin));
            begin = comma + 1;
        }
    }
    if (names.empty()) names.push_back("slalom");
    settings.duration = std::min(settings.duration, 0.25);
    for (std::size_t i = 0; i < names.size() && i < 2; ++i) {
        ns::Trajectory trajectory;
        if (!ns::makeBuiltinTrajectory(names[i], settings.duration, trajectory)) continue;
        ns::TrajectoryResult result;
        std::string error;
        if (ns::simulateTrajectory(trajectory, settings, true, result, error)) {
            ns::textTable({result}, settings);
            ns::markdownTable({result}, settings);
        }
    }
    return 0;
}
