#include "demo.h"

#include "demo_level.h"
#include "scenario.h"
#include "text_file.h"

#ifdef FORESIGHT_CLI_WITH_EMBREE
#include <foresight/embree_world.h>
#endif

#include <cmath>
#include <cstdio>
#include <iostream>
#include <utility>

namespace foresight_cli {

namespace {

// The one definition of the demo's input. Ids pair each article ("faithful") prediction with
// its exact counterpart; the table below looks them up by id. The article's grenade flies over
// the open middle of the demo level (demo_level.h: |x| < 6, -6 < z < 9 is bare floor, level
// with the plane y = 0), so the level changes nothing for it; the courtyard grenade is thrown
// from inside the level's doorway (x = 0, z = -15) towards the stairs in the north-west.
constexpr const char* kDemoScenario = R"({
  "gravity": [0, -9.81, 0],
  "world": {
    "planes": [{"normal": [0, 1, 0], "distance": 0}],
    "boxes": [{"center": [0, 3, 8.25], "half_extents": [5, 3, 0.25],
               "orientation": {"w": 1, "x": 0, "y": 0, "z": 0}}],
    "meshes": [{"file": "demo_level.obj"}]
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
    {"id": "courtyard_stepped", "model": "projectile", "method": "stepped",
     "position": [0, 1.5, -13], "velocity": [-5.5, 6, 11], "time": 3, "step": 0.02, "restitution": 0.5},
    {"id": "courtyard_exact", "model": "projectile", "method": "exact",
     "position": [0, 1.5, -13], "velocity": [-5.5, 6, 11], "time": 3, "step": 0.02, "restitution": 0.5},
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
    const PredictionResult* courtyardStepped = findResult(scenario, results, "courtyard_stepped");
    const PredictionResult* courtyardExact = findResult(scenario, results, "courtyard_exact");
    const PredictionResult* carIterative = findResult(scenario, results, "car_iterative");
    const PredictionResult* carExact = findResult(scenario, results, "car_exact");
    if (!runnerLinear || !runnerAccelerated || !grenadeStepped || !grenadeExact || !courtyardStepped ||
        !courtyardExact || !carIterative || !carExact) {
        return "the demo scenario is missing a prediction\n";
    }

    std::string text = "foresight " FORESIGHT_VERSION_STRING
                       " demo: the reference article's predictions (\"faithful\") next to exact ones\n\n";
    char buffer[320];
    std::snprintf(buffer, sizeof buffer, "%-20s %-40s  %-40s  %9s\n", "prediction", "faithful (article)", "exact",
                  "difference");
    text += buffer;
    text += row("runner, 0.5 s", "linear", runnerLinear->position, "accelerated", runnerAccelerated->position);
    const auto grenadeRows = [&](const char* label, const PredictionResult& stepped, const PredictionResult& exact) {
        text += row(label, "stepped", stepped.position, "exact", exact.position);
        std::snprintf(buffer, sizeof buffer, "%-20s %-40s  %s\n", "  bounces, at rest",
                      (std::to_string(stepped.projectile.bounces) + ", " + (stepped.projectile.atRest ? "yes" : "no")).c_str(),
                      (std::to_string(exact.projectile.bounces) + ", " + (exact.projectile.atRest ? "yes" : "no")).c_str());
        text += buffer;
    };
    grenadeRows("grenade, 3 s fuse", *grenadeStepped, *grenadeExact);
    grenadeRows("courtyard, 3 s fuse", *courtyardStepped, *courtyardExact);
    text += row("car turning, 2 s", "4 iterations", carIterative->position, "exact arc", carExact->position);
    text += "\n"
            "runner:  3 m/s sideways, 4 m/s forward, accelerating at 2 m/s^2 forward (linear ignores it)\n"
            "grenade: thrown at 12 m/s from 1.5 m towards a wall at z = 8 m; floor y = 0; restitution 0.5,\n"
            "         step 0.02 s; stepped (the article) loses the rest of every step that hits something\n"
            "courtyard: a grenade thrown at 13.7 m/s from the doorway of the demo level (`foresight level`)\n"
            "         across the courtyard; it bounces off a riser of the stairs, the floor and the west wall\n"
            "car:     10 m/s, turning at 0.5 rad/s; the article's loop with 4 iterations vs the closed-form arc\n";
    return text;
}

/// The demo level in the scenario's world, exactly as `foresight predict` puts the triangles of
/// kDemoLevelFile there (scenario.cpp): into an EmbreeWorld that also holds the primitives when
/// the CLI has Embree, else as StaticWorld triangles after the scenario's own.
bool addDemoLevel(Scenario& scenario, std::string& error) {
    const foresight_level::LevelMesh level = foresight_level::makeDemoLevel();
    std::vector<foresight::RVec3> vertices(level.vertices.begin(), level.vertices.end());
#ifdef FORESIGHT_CLI_WITH_EMBREE
    auto world = std::make_unique<foresight::EmbreeWorld>();
    foresight::MeshReport report;
    if (world->addMesh(vertices, level.indices, &report) != foresight::Status::Ok) {
        error = report.error;
        return false;
    }
    for (const auto& shape : scenario.world.planes()) world->add(shape);
    for (const auto& shape : scenario.world.spheres()) world->add(shape);
    for (const auto& shape : scenario.world.boxes()) world->add(shape);
    for (const auto& shape : scenario.world.triangles()) world->add(shape);
    if (!world->commit(&error)) return false;
    scenario.meshWorld = std::move(world);
#else
    for (std::size_t i = 0; i + 2 < level.indices.size(); i += 3) {
        const foresight::Triangle triangle{vertices[level.indices[i]], vertices[level.indices[i + 1]],
                                           vertices[level.indices[i + 2]]};
        // The OBJ loader skips degenerate triangles (the demo level has none).
        if (foresight::validateTriangle(triangle) == foresight::Status::Ok && scenario.world.add(triangle) != foresight::Status::Ok) {
            error = "cannot add a triangle of the demo level";
            return false;
        }
    }
#endif
    return true;
}

} // namespace

Json demoScenario() {
    Json document;
    Diagnostics diagnostics;
    if (!parseJsonText(kDemoScenario, "demo scenario", document, diagnostics)) return Json::object();
    return document;
}

int demoCommand(const std::string& jsonFile, const std::string& scenarioFile, const PictureOptions& requested,
                bool writeHtml) {
    if (jsonFile == "-" && scenarioFile == "-") {
        std::cerr << "foresight demo: --json - and --scenario - cannot both write to standard output\n";
        return 2;
    }
    if (!requested.htmlFile.empty() && !viewerAvailable()) {
        std::cerr << "foresight demo: --html: " << viewerUnavailableReason() << '\n';
        return 2;
    }
    PictureOptions pictures = requested;
    const bool defaultPage = pictures.htmlFile.empty() && writeHtml && viewerAvailable();
    if (defaultPage) pictures.htmlFile = kDemoHtmlFile;
    const Json input = demoScenario();
    // The in-process demo needs no file: the level mesh is built in memory and added to the
    // world the scenario's other shapes make.
    Json withoutMeshes = input;
    withoutMeshes["world"].erase("meshes");
    Diagnostics diagnostics;
    Scenario scenario;
    std::vector<PredictionResult> results;
    std::string reason;
    scenario.recordTrajectories = pictures.wanted();
    if (!buildScenario(withoutMeshes, std::filesystem::path(), scenario, diagnostics) ||
        !addDemoLevel(scenario, reason) || !runScenario(scenario, results, diagnostics)) {
        std::cerr << "foresight demo: the built-in scenario failed:\n";
        if (!reason.empty()) std::cerr << "demo level: " << reason << '\n';
        printDiagnostics(diagnostics, std::cerr);
        return 1;
    }
    if (!scenarioFile.empty() && !writeTextFile(scenarioFile, formatJson(input), reason)) {
        std::cerr << scenarioFile << ": cannot write: " << reason << '\n';
        return 2;
    }
    if (scenarioFile == "-") {
        std::cerr << "foresight demo: the scenario's world.meshes[0] is " << kDemoLevelFile
                  << ", relative to the scenario file: write it there with `foresight level --obj "
                  << kDemoLevelFile << "`\n";
    } else if (!scenarioFile.empty()) {
        const std::filesystem::path mesh = std::filesystem::path(scenarioFile).parent_path() / kDemoLevelFile;
        if (!foresight_level::writeObj(foresight_level::makeDemoLevel(), mesh, reason)) {
            std::cerr << reason << '\n';
            return 2;
        }
    }
    if (!jsonFile.empty() && !writeTextFile(jsonFile, formatJson(resultDocument(scenario, results)), reason)) {
        std::cerr << jsonFile << ": cannot write: " << reason << '\n';
        return 2;
    }
    std::string error;
    if (pictures.wanted() &&
        !writePictures(pictures, pictureDocument(scenario, results, "foresight demo"), "foresight demo", error)) {
        std::cerr << error << '\n';
        return 2;
    }
    if (jsonFile != "-" && scenarioFile != "-") {
        std::string text = table(scenario, results);
        if (!pictures.htmlFile.empty()) text += "\nviewer: " + pictures.htmlFile + " (open it in a web browser)\n";
        if (!pictures.svgFile.empty()) text += "picture: " + pictures.svgFile + "\n";
        if (!writeTextFile("-", text, reason)) {
            std::cerr << "foresight demo: cannot write the table: " << reason << '\n';
            return 1;
        }
    }
    if (pictures.htmlFile.empty() && writeHtml && !viewerAvailable())
        std::cerr << "foresight demo: no viewer page: " << viewerUnavailableReason() << '\n';
    return 0;
}

int levelCommand(const LevelOptions& options) {
    if (options.objFile.empty() && options.gltfFile.empty() && options.glbFile.empty()) {
        std::cerr << "foresight level: nothing to write: give --obj FILE, --gltf FILE or --glb FILE\n";
        return 2;
    }
    const bool room = options.room || !options.roomSize.empty();
    glm::dvec3 size(10.0, 4.0, 10.0);
    if (!options.roomSize.empty()) {
        for (int axis = 0; axis < 3; ++axis) {
            const double value = options.roomSize.size() == 3 ? options.roomSize[static_cast<std::size_t>(axis)] : 0.0;
            if (!std::isfinite(value) || !(value > 0.0)) {
                std::cerr << "--room-size: expected 3 finite sizes > 0 (metres)\n";
                return 2;
            }
            size[axis] = value;
        }
    }
    const foresight_level::LevelMesh mesh = room ? foresight_level::makeClosedRoom(size) : foresight_level::makeDemoLevel();
    const auto extensionIs = [](const std::string& file, const char* wanted) {
        std::string extension = std::filesystem::path(file).extension().string();
        for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return extension == wanted;
    };
    for (const auto& [file, extension] : {std::pair{options.gltfFile, ".gltf"}, std::pair{options.glbFile, ".glb"}}) {
        if (!file.empty() && !extensionIs(file, extension)) {
            std::cerr << file << ": expected a file name ending in " << extension << '\n';
            return 2;
        }
    }
    // Everything is written before anything is printed: on failure standard output stays empty.
    std::string report;
    std::string error;
    const std::string what = room ? "closed room" : "demo level";
    const auto line = [&](const std::string& file) {
        report += file + ": " + std::to_string(mesh.triangleCount()) + " triangles, " +
                  std::to_string(mesh.vertices.size()) + " vertices, " + std::to_string(mesh.parts.size()) +
                  " parts (" + what + ")\n";
    };
    if (!options.objFile.empty()) {
        if (!foresight_level::writeObj(mesh, options.objFile, error)) {
            std::cerr << error << '\n';
            return 2;
        }
        line(options.objFile);
    }
    for (const std::string& file : {options.gltfFile, options.glbFile}) {
        if (file.empty()) continue;
        if (!foresight_level::writeGltf(mesh, file, error)) {
            std::cerr << error << '\n';
            return 2;
        }
        line(file);
    }
    std::string reason;
    if (!writeTextFile("-", report, reason)) {
        std::cerr << "foresight level: cannot write to standard output: " << reason << '\n';
        return 1;
    }
    return 0;
}

} // namespace foresight_cli
