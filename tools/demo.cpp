#include "demo.h"

#include "scenario.h"
#include "text_file.h"

#include <cstdio>
#include <iostream>

namespace foresight_cli {

namespace {

// The one definition of the demo's input. Ids pair each article ("faithful") prediction with
// its exact counterpart; the table below looks them up by id.
constexpr const char* kDemoScenario = R"({
  "gravity": [0, -9.81, 0],
  "world": {
    "planes": [{"normal": [0, 1, 0], "distance": 0}],
    "boxes": [{"center": [0, 3, 8.25], "half_extents": [5, 3, 0.25],
               "orientation": {"w": 1, "x": 0, "y": 0, "z": 0}}]
  },
  "predictions": [
    {"id": "runner_linear", "model": "linear",
     "position": [0, 0, 0], "velocity": [3, 0, 4], "time": 0.5},
    {"id": "runner_accelerated", "model": "accelerated",
     "position": [0, 0, 0], "velocity": [3, 0, 4], "acceleration": [0, 0, 2], "time": 0.5},
    {"id": "grenade_stepped", "model": "projectile", "method": "stepped",
     "position": [0, 1.5, 0], "velocity": [0, 7.2, 9.6], "time": 3, "step": 0.02, "restitution": 0.5},
    {"id": "grenade_exact", "model": "projectile", "method": "exact",
     "position": [0, 1.5, 0], "velocity": [0, 7.2, 9.6], "time": 3, "step": 0.02, "restitution": 0.5},
    {"id": "car_iterative", "model": "vehicle", "method": "iterative", "iterations": 4,
     "position": [0, 0, 0], "velocity": [0, 0, 10], "orientation": {"w": 1, "x": 0, "y": 0, "z": 0},
     "angular_velocity": [0, 0.5, 0], "frame": "body", "time": 2},
    {"id": "car_exact", "model": "vehicle", "method": "exact",
     "position": [0, 0, 0], "velocity": [0, 0, 10], "orientation": {"w": 1, "x": 0, "y": 0, "z": 0},
     "angular_velocity": [0, 0.5, 0], "frame": "body", "time": 2}
  ]
})";

std::string vectorText(const foresight::RVec3& v) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "[%7.3f, %7.3f, %7.3f]", static_cast<double>(v.x), static_cast<double>(v.y),
                  static_cast<double>(v.z));
    return buffer;
}

const PredictionResult* findResult(const Scenario& scenario, const std::vector<PredictionResult>& results,
                                   const char* id) {
    for (std::size_t i = 0; i < scenario.predictions.size() && i < results.size(); ++i) {
        const Json& predictionId = scenario.predictions[i].id;
        if (predictionId.is_string() && predictionId.get<std::string>() == id) return &results[i];
    }
    return nullptr;
}

std::string row(const char* label, const char* faithfulName, const foresight::RVec3& faithful, const char* exactName,
                const foresight::RVec3& exact) {
    const double distance = glm::length(glm::dvec3(faithful) - glm::dvec3(exact));
    char buffer[320];
    std::snprintf(buffer, sizeof buffer, "%-20s %-12s %-27s  %-12s %-27s  %7.3f m\n", label, faithfulName,
                  vectorText(faithful).c_str(), exactName, vectorText(exact).c_str(), distance);
    return buffer;
}

std::string table(const Scenario& scenario, const std::vector<PredictionResult>& results) {
    const PredictionResult* runnerLinear = findResult(scenario, results, "runner_linear");
    const PredictionResult* runnerAccelerated = findResult(scenario, results, "runner_accelerated");
    const PredictionResult* grenadeStepped = findResult(scenario, results, "grenade_stepped");
    const PredictionResult* grenadeExact = findResult(scenario, results, "grenade_exact");
    const PredictionResult* carIterative = findResult(scenario, results, "car_iterative");
    const PredictionResult* carExact = findResult(scenario, results, "car_exact");
    if (!runnerLinear || !runnerAccelerated || !grenadeStepped || !grenadeExact || !carIterative || !carExact) {
        return "the demo scenario is missing a prediction\n";
    }

    std::string text = "foresight " FORESIGHT_VERSION_STRING
                       " demo: the reference article's predictions (\"faithful\") next to exact ones\n\n";
    char buffer[320];
    std::snprintf(buffer, sizeof buffer, "%-20s %-40s  %-40s  %9s\n", "prediction", "faithful (article)", "exact",
                  "difference");
    text += buffer;
    text += row("runner, 0.5 s", "linear", runnerLinear->position, "accelerated", runnerAccelerated->position);
    text += row("grenade, 3 s fuse", "stepped", grenadeStepped->position, "exact", grenadeExact->position);
    const auto& stepped = grenadeStepped->projectile;
    const auto& exact = grenadeExact->projectile;
    std::snprintf(buffer, sizeof buffer, "%-20s %-40s  %s\n", "  bounces, at rest",
                  (std::to_string(stepped.bounces) + ", " + (stepped.atRest ? "yes" : "no")).c_str(),
                  (std::to_string(exact.bounces) + ", " + (exact.atRest ? "yes" : "no")).c_str());
    text += buffer;
    text += row("car turning, 2 s", "4 iterations", carIterative->position, "exact arc", carExact->position);
    text += "\n"
            "runner:  3 m/s sideways, 4 m/s forward, accelerating at 2 m/s^2 forward (linear ignores it)\n"
            "grenade: thrown at 12 m/s from 1.5 m towards a wall at z = 8 m; floor y = 0; restitution 0.5,\n"
            "         step 0.02 s; stepped (the article) loses the rest of every step that hits something\n"
            "car:     10 m/s, turning at 0.5 rad/s; the article's loop with 4 iterations vs the closed-form arc\n";
    return text;
}

} // namespace

Json demoScenario() {
    Json document;
    Diagnostics diagnostics;
    if (!parseJsonText(kDemoScenario, "demo scenario", document, diagnostics)) return Json::object();
    return document;
}

int demoCommand(const std::string& jsonFile, const std::string& scenarioFile) {
    if (jsonFile == "-" && scenarioFile == "-") {
        std::cerr << "foresight demo: --json - and --scenario - cannot both write to standard output\n";
        return 2;
    }
    const Json input = demoScenario();
    Diagnostics diagnostics;
    Scenario scenario;
    std::vector<PredictionResult> results;
    if (!buildScenario(input, std::filesystem::path(), scenario, diagnostics) ||
        !runScenario(scenario, results, diagnostics)) {
        std::cerr << "foresight demo: the built-in scenario failed:\n";
        printDiagnostics(diagnostics, std::cerr);
        return 1;
    }
    std::string reason;
    if (!scenarioFile.empty() && !writeTextFile(scenarioFile, formatJson(input), reason)) {
        std::cerr << scenarioFile << ": cannot write: " << reason << '\n';
        return 2;
    }
    if (!jsonFile.empty() && !writeTextFile(jsonFile, formatJson(resultDocument(scenario, results)), reason)) {
        std::cerr << jsonFile << ": cannot write: " << reason << '\n';
        return 2;
    }
    if (jsonFile != "-" && scenarioFile != "-" && !writeTextFile("-", table(scenario, results), reason)) {
        std::cerr << "foresight demo: cannot write the table: " << reason << '\n';
        return 1;
    }
    return 0;
}

} // namespace foresight_cli
