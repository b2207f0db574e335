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
        // Each result is written as it comes (the writer hands out 64 KiB at a time), so memory
        // does not grow with the output.
        ran = runScenario(
            scenario,
            [&](std::size_t index, PredictionResult& result) {
                output.add(scenario.predictions[index], result);
                return !output.failed();
            },
            diagnostics);
        printDiagnostics(diagnostics, std::cerr);
    }
    if (!output.failed() && !diagnostics.ok()) {
        // A prediction the library refused while running (after validation): up to 64 KiB of
        // results are held back, so a small result prints nothing; a larger one may have started.
        if (output.bytesWritten() > 0) {
            std::cerr << "foresight: the result on standard output is incomplete: " << output.bytesWritten()
                      << " bytes were written before the problem above was found\n";
        }
        return 2;
    }
    if (output.failed() || !ran || !output.finish()) {
        std::cerr << "foresight: cannot write the result: " << writeError << '\n';
        return 1;
    }
    return 0;
}

}  // namespace foresight_cli
