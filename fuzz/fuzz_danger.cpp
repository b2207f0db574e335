// `foresight danger`: a scenario with danger keys (docs/danger-format.md) through buildDangerInput and
// runDanger, as dangerCommand runs them.
#include "fuzz_json.h"

#include "commands/danger_command.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace foresight_cli;
    const auto& base = foresight_fuzz::meshDirectory();
    Diagnostics diagnostics;
    Json document, output;
    DangerInput input;
    std::vector<PredictionResult> results;
    if (!foresight_fuzz::parseInput(data, size, document, diagnostics) ||
        !buildDangerInput(document, base, input, diagnostics))
        return 0;
    // Within the CLI's budget, but too slow for the instrumented build: read, not run.
    if (scenarioProjectileSteps(input.scenario) > foresight_fuzz::kMaxFuzzSteps) return 0;
    if (runDanger(input, output, diagnostics, &results)) foresight_fuzz::formatOutput(output);
    return 0;
}
