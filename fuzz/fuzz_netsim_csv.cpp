// `foresight netsim --csv FILE`: CSV trajectories through netsim::parseTrajectoryCsv, then what
// the command does with one: samples and a short simulation (every model and receiver).
#include "fuzz_common.h"

#include "netsim.h"

#include <algorithm>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace ns = foresight_cli::netsim;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    ns::Trajectory trajectory;
    std::string error;
    if (!ns::parseTrajectoryCsv(text, "fuzz.csv", trajectory, error)) {
        FORESIGHT_FUZZ_CHECK(!error.empty());
        return 0;
    }
    FORESIGHT_FUZZ_CHECK(trajectory.end > trajectory.start);
    for (const double f : {0.0, 0.25, 0.5, 1.0})
        trajectory.sample(trajectory.start + f * (trajectory.end - trajectory.start));

    // The command's defaults, every model and display, over at most a second of the file (the
    // CLI runs all of it: up to kMaxDuration).
    ns::SimulationSettings settings;
    settings.duration = std::min(1.0, ns::kMaxDuration);
    for (int a = 1; a <= foresight::kDeadReckoningAlgorithmCount; ++a)
        settings.models.push_back(static_cast<foresight::DeadReckoningAlgorithm>(a));
    settings.displays = ns::allDisplays();
    settings.receiver.interpolationDelay = 0.22f;
    ns::TrajectoryResult result;
    if (ns::simulateTrajectory(trajectory, settings, true, result, error)) {
        ns::textTable({result}, settings);
    }
    return 0;
}
