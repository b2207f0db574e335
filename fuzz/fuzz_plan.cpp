// `foresight plan`: a world and throws (docs/plan-format.md) through buildPlanDocument, runPlans and
// the result document, as planCommand runs them.
#include "fuzz_json.h"

#include "commands/plan_command.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace foresight_cli;
    const auto& base = foresight_fuzz::meshDirectory();
    Diagnostics diagnostics;
    Json document;
    Scenario world;
    std::vector<ThrowRequest> throws;
    std::vector<ThrowOutcome> outcomes;
    if (!foresight_fuzz::parseInput(data, size, document, diagnostics) ||
        !buildPlanDocument(document, base, world, throws, diagnostics))
        return 0;
    // Documents within the CLI's budget (kMaxPlanFileSteps) may still take seconds in a Release
    // build, 30 times that here: only those up to kMaxFuzzSteps are run (every one is read).
    if (planFileWork(throws) > foresight_fuzz::kMaxFuzzSteps) return 0;
    if (runPlans(world, throws, outcomes, diagnostics))
        foresight_fuzz::formatOutput(planResultDocument(throws, outcomes));
    return 0;
}
