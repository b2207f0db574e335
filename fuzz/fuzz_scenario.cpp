// `foresight predict`: scenario JSON (docs/scenario-format.md) through buildScenario, then
// runScenario streaming each result into ResultDocumentWriter, as predictCommand runs them; and
// the former writer on the same results, formatJson(resultDocument(...)), which the streamed text
// must equal byte for byte.
#include "fuzz_json.h"

#include "scenario.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace foresight_cli;
    const auto& base = foresight_fuzz::meshDirectory();
    Diagnostics diagnostics;
    Json document;
    Scenario scenario;
    if (!foresight_fuzz::parseInput(data, size, document, diagnostics) ||
        !buildScenario(document, base, scenario, diagnostics)) {
        return 0;
    }
    // Within the CLI's budget, but too slow for the instrumented build: read, not run.
    if (scenarioProjectileSteps(scenario) > foresight_fuzz::kMaxFuzzSteps) return 0;
    std::string streamed;
    ResultDocumentWriter writer(
        [&streamed](std::string_view text) {
            streamed += text;
            return true;
        },
        64);  // small pieces: the held-back text is handed on often
    writer.begin();
    std::vector<PredictionResult> results;
    const bool ran = runScenario(
        scenario,
        [&](std::size_t index, PredictionResult& result) {
            writer.add(scenario.predictions[index], result);
            results.push_back(result);
            return true;
        },
        diagnostics);
    if (!ran) return 0;
    FORESIGHT_FUZZ_CHECK(writer.finish());
    FORESIGHT_FUZZ_CHECK(results.size() == scenario.predictions.size());
    FORESIGHT_FUZZ_CHECK(streamed == formatJson(resultDocument(scenario, results)));
    foresight_fuzz::formatOutput(resultDocument(scenario, results));
    return 0;
}
