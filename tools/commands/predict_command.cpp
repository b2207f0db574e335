#include "predict_command.h"

#include "json_input.h"
#include "json_output.h"
#include "picture.h"
#include "scenario.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

namespace foresight_cli {

namespace {

/// Standard output for the streamed result: false (and `reason`) when it cannot take the text.
bool writeStandardOutput(std::string_view text, std::string& reason) {
    errno = 0;
    if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
        reason = errno != 0 ? std::strerror(errno) : "write error";
        return false;
    }
    return true;
}

}  // namespace

int predictCommand(const std::string& file, const PictureOptions& pictures) {
    if (!pictures.htmlFile.empty() && !viewerAvailable()) {
        std::cerr << "foresight predict: --html: " << viewerUnavailableReason() << '\n';
        return 2;
    }
    Diagnostics diagnostics;
    std::string name;
    Json document;
    Scenario scenario;
    // Meshes are relative to the scenario file, or to the current directory for stdin.
    scenario.recordTrajectories = pictures.wanted();
    // Every input is validated before anything runs: a file with a problem prints nothing.
    if (!readJsonFile(file, name, document, diagnostics) ||
        !buildScenario(document, baseDirectoryOf(file), scenario, diagnostics)) {
        printDiagnostics(diagnostics, std::cerr);
        return 2;
    }
    document = Json();  // the scenario holds what the run needs

    std::string writeError;
    ResultDocumentWriter output([&writeError](std::string_view text) { return writeStandardOutput(text, writeError); });
    output.begin();
    bool ran = false;
    if (pictures.wanted()) {
        // Pictures need every trajectory: keep the results, draw them, then write the JSON.
        std::vector<PredictionResult> results;
        ran = runScenario(scenario, results, diagnostics);
        printDiagnostics(diagnostics, std::cerr);
        if (!ran) return 2;
        std::string error;
        if (!writePictures(pictures, pictureDocument(scenario, results, "foresight: " + name), "foresight: " + name,
                           error)) {
            std::cerr << error << '\n';
            return 2;
        }
        for (std::size_t i = 0; i < results.size() && !output.failed(); ++i)
            output.add(scenario.predictions[i], results[i]);
    } else {
        // Every prediction runs once unwritten first, so that a refusal while running (the work
        // cap, the precision envelope, the file's trajectory point budget) leaves standard output
        // empty, as any invalid input does. Then they run again, each result written as it comes:
        // memory does not grow with the output. Predictions are deterministic: the second run
        // has the same results, and its diagnostics repeat the first's.
        ran = runScenario(
            scenario, [](std::size_t, PredictionResult&) { return true; }, diagnostics);
        printDiagnostics(diagnostics, std::cerr);
        if (!ran || !diagnostics.ok()) return 2;
        Diagnostics again;
        ran = runScenario(
            scenario,
            [&](std::size_t index, PredictionResult& result) {
                output.add(scenario.predictions[index], result);
                return !output.failed();
            },
            again);
    }
    if (output.failed() || !ran || !output.finish()) {
        std::cerr << "foresight: cannot write the result: " << writeError << '\n';
        return 1;
    }
    return 0;
}

}  // namespace foresight_cli
