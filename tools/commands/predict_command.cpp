#include "predict_command.h"

#include "json_input.h"
#include "json_output.h"
#include "picture.h"
#include "scenario.h"

#include <iostream>
#include <string>
#include <vector>

namespace foresight_cli {

int predictCommand(const std::string& file, const PictureOptions& pictures) {
    if (!pictures.htmlFile.empty() && !viewerAvailable()) {
        std::cerr << "foresight predict: --html: " << viewerUnavailableReason() << '\n';
        return 2;
    }
    Diagnostics diagnostics;
    std::string name;
    Json document;
    Scenario scenario;
    std::vector<PredictionResult> results;
    // Meshes are relative to the scenario file, or to the current directory for stdin.
    scenario.recordTrajectories = pictures.wanted();
    const bool ok = readJsonFile(file, name, document, diagnostics) &&
                    buildScenario(document, baseDirectoryOf(file), scenario, diagnostics) &&
                    runScenario(scenario, results, diagnostics);
    printDiagnostics(diagnostics, std::cerr);
    if (!ok) return 2;
    std::string error;
    if (pictures.wanted() && !writePictures(pictures, pictureDocument(scenario, results, "foresight: " + name),
                                            "foresight: " + name, error)) {
        std::cerr << error << '\n';
        return 2;
    }
    return writeJsonResult(resultDocument(scenario, results));
}

}  // namespace foresight_cli
