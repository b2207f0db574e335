// `foresight predict`: scenario JSON (docs/scenario-format.md) through buildScenario,
// runScenario and the result document, as predictCommand runs them.
#include "fuzz_json.h"

#include "scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace foresight_cli;
    const auto& base = foresight_fuzz::meshDirectory();
    Diagnostics diagnostics;
    Json document;
    Scenario scenario;
    std::vector<PredictionResult> results;
    if (foresight_fuzz::parseInput(data, size, document, diagnostics) &&
        buildScenario(document, base, scenario, diagnostics) && runScenario(scenario, results, diagnostics)) {
        FORESIGHT_FUZZ_CHECK(results.size() == scenario.predictions.size());
        foresight_fuzz::formatOutput(resultDocument(scenario, results));
    }
    return 0;
}
