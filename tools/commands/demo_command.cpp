#include "demo_command.h"

#include "demo_level.h"
#include "level_world.h"
#include "picture.h"
#include "scenario.h"
#include "text_file.h"

#include <array>
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
// from inside the level's doorway (x = 0, z = -15) towards the stairs in the north-west, and
// once more as Jolt (Godot 4's physics) would step it at 60 Hz, as a 5 cm ball.
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
    {"id": "courtyard_jolt", "model": "projectile", "method": "engine", "engine": {"profile": "jolt"},
     "position": [0, 1.5, -13], "velocity": [-5.5, 6, 11], "time": 3, "radius": 0.05, "restitution": 0.5},
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
    const PredictionResult* courtyardJolt = findResult(scenario, results, "courtyard_jolt");
    const PredictionResult* carIterative = findResult(scenario, results, "car_iterative");
    const PredictionResult* carExact = findResult(scenario, results, "car_exact");
    if (!runnerLinear || !runnerAccelerated || !grenadeStepped || !grenadeExact || !courtyardStepped ||
        !courtyardExact || !courtyardJolt || !carIterative || !carExact) {
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
        std::snprintf(
            buffer, sizeof buffer, "%-20s %-40s  %s\n", "  bounces, at rest",
            (std::to_string(stepped.projectile.bounces) + ", " + (stepped.projectile.atRest ? "yes" : "no")).c_str(),
            (std::to_string(exact.projectile.bounces) + ", " + (exact.projectile.atRest ? "yes" : "no")).c_str());
        text += buffer;
    };
    grenadeRows("grenade, 3 s fuse", *grenadeStepped, *grenadeExact);
    grenadeRows("courtyard, 3 s fuse", *courtyardStepped, *courtyardExact);
    text += row("  as Jolt steps it", "exact", courtyardExact->position, "engine", courtyardJolt->position);
    text += row("car turning, 2 s", "4 iterations", carIterative->position, "exact arc", carExact->position);
    text +=
        "\n"
        "runner:  3 m/s sideways, 4 m/s forward, accelerating at 2 m/s^2 forward (linear ignores it)\n"
        "grenade: thrown at 12 m/s from 1.5 m towards a wall at z = 8 m; floor y = 0; restitution 0.5,\n"
        "         step 0.02 s; stepped (the article) loses the rest of every step that hits something\n"
        "courtyard: a grenade thrown at 13.7 m/s from the doorway of the demo level (`foresight level`)\n"
        "         across the courtyard; it bounces off a riser of the stairs, the floor and the west wall;\n"
        "         \"engine\": the same throw as Jolt (Godot 4) steps a 5 cm ball at 60 Hz (docs/engines.md)\n"
        "car:     10 m/s, turning at 0.5 rad/s; the article's loop with 4 iterations vs the closed-form arc\n";
    return text;
}

/// The demo level in the scenario's world, exactly as `foresight predict` puts the triangles of
/// kDemoLevelFile there (level_world.h).
bool addDemoLevel(Scenario& scenario, std::string& error) {
    return addLevelMesh(scenario, foresight_level::makeDemoLevel(), error);
}

// --- The AI uses: one firing solution, one planned throw, one danger answer of each
// kind. They are computed when the demo runs (aim.h, throw_planner.h, danger.h), and the
// predictions they imply (the shot, its target, the planned throw, the pedestrian) are appended
// to the scenario, so that the scenario file reproduces them with `foresight predict`.

constexpr float kDemoGravity = -9.81f;

/// The turret (south of the courtyard's middle) and the runner it aims at (the article's
/// accelerating runner, at chest height).
constexpr double kTurret[3] = {6.0, 1.5, -12.0};
constexpr float kTurretSpeed = 20.0f;
constexpr double kRunnerChest[3] = {0.0, 1.0, 0.0};
constexpr float kRunnerVelocity[3] = {3.0f, 0.0f, 4.0f};
constexpr float kRunnerAcceleration[3] = {0.0f, 0.0f, 2.0f};

/// The planned throw: from the doorway into the far corner of the platform in the north-west,
/// 31 m away (a lob that lands on the platform and bounces into the corner).
constexpr double kThrowStart[3] = {0.0, 1.5, -13.0};
constexpr double kThrowTarget[3] = {-14.4, 1.875, 14.4};  // on the platform's top
constexpr float kThrowFuse = 4.0f;
constexpr float kThrowMaxSpeed = 20.0f;
constexpr float kThrowAcceptance = 1.0f;
constexpr float kBlastRadius = 5.0f;
/// Two guards the AI asks about: one on the platform, one at the foot of the stairs.
constexpr double kGuards[2][3] = {{-11.0, 2.775, 12.5}, {-10.5, 0.9, 4.0}};
constexpr const char* kGuardNames[2] = {"a guard on the platform", "a guard by the stairs"};

/// The pedestrian crossing the turning car's path (a standing capsule 1.8 m tall).
constexpr double kPedestrian[3] = {5.0, 0.9, 9.0};
constexpr float kPedestrianVelocity[3] = {-1.5f, 0.0f, 0.0f};
constexpr float kPedestrianTime = 2.0f;

foresight::RVec3 demoPoint(const double (&p)[3]) {
    return foresight::RVec3(foresight::Real(p[0]), foresight::Real(p[1]), foresight::Real(p[2]));
}
foresight::Vec3 demoVector(const float (&v)[3]) { return foresight::Vec3(v[0], v[1], v[2]); }

/// What the AI part of the demo computed.
struct DemoAi {
    foresight::AimShot shot;
    foresight::AimTarget target;
    std::array<foresight::FiringSolution, foresight::kMaxFiringSolutions> solutions{};
    std::size_t solutionCount = 0;
    foresight::ThrowPlanRequest request;
    std::array<foresight::ThrowPlan, 3> plans{};
    foresight::ThrowPlanResult planned;
};

const foresight::CollisionWorld& worldOf(const Scenario& scenario) {
    if (scenario.meshWorld) return *scenario.meshWorld;
    return scenario.world;
}

/// Aims and plans in the scenario's world (the base scenario, with the level).
bool computeDemoAi(const Scenario& scenario, DemoAi& ai, std::string& error) {
    ai.shot.from = demoPoint(kTurret);
    ai.shot.constraint = foresight::AimConstraint::Speed;
    ai.shot.speed = kTurretSpeed;
    ai.shot.gravity = foresight::Vec3(0.0f, kDemoGravity, 0.0f);
    ai.shot.maxTime = 10.0f;
    ai.target.position = demoPoint(kRunnerChest);
    ai.target.velocity = demoVector(kRunnerVelocity);
    ai.target.acceleration = demoVector(kRunnerAcceleration);
    foresight::Status status = foresight::aimProjectile(ai.shot, ai.target, ai.solutions, ai.solutionCount);
    if (status != foresight::Status::Ok || ai.solutionCount == 0) {
        error =
            std::string("aim: ") + (status == foresight::Status::Ok ? "no solution" : foresight::statusMessage(status));
        return false;
    }

    ai.request.start = demoPoint(kThrowStart);
    ai.request.target = demoPoint(kThrowTarget);
    ai.request.fuseTime = kThrowFuse;
    ai.request.maxSpeed = kThrowMaxSpeed;
    ai.request.acceptanceRadius = kThrowAcceptance;
    ai.request.settings.gravity = foresight::Vec3(0.0f, kDemoGravity, 0.0f);
    ai.request.settings.restitution = 0.5f;
    ai.request.settings.step = 0.02f;
    ai.request.settings.method = foresight::ProjectileMethod::Exact;
    ai.request.maxPlans = static_cast<std::uint32_t>(ai.plans.size());
    std::vector<foresight::TrajectoryPoint> scratch(foresight::throwPlanScratchSize(ai.request));
    status = foresight::planThrow(ai.request, &worldOf(scenario), ai.plans, scratch, ai.planned);
    if (status != foresight::Status::Ok || ai.planned.planCount == 0) {
        error = std::string("plan: ") +
                (status == foresight::Status::Ok ? "no plan found" : foresight::statusMessage(status));
        return false;
    }
    return true;
}

Json jsonArray3(const double (&p)[3]) { return Json::array({jsonDouble(p[0]), jsonDouble(p[1]), jsonDouble(p[2])}); }

/// The predictions the AI answers imply, in the scenario format.
void appendAiPredictions(const DemoAi& ai, Json& scenario) {
    const foresight::FiringSolution& shot = ai.solutions[0];
    Json& predictions = scenario["predictions"];
    predictions.push_back(Json{{"id", "aim_target"},
                               {"model", "accelerated"},
                               {"position", jsonArray3(kRunnerChest)},
                               {"velocity", jsonVector(demoVector(kRunnerVelocity))},
                               {"acceleration", jsonVector(demoVector(kRunnerAcceleration))},
                               {"time", jsonFloat(shot.time)}});
    predictions.push_back(Json{{"id", "aim_shot"},
                               {"model", "projectile"},
                               {"method", "exact"},
                               {"position", jsonArray3(kTurret)},
                               {"velocity", jsonVector(shot.velocity)},
                               {"time", jsonFloat(shot.time)},
                               {"step", 0.02},
                               {"restitution", 0.5}});
    predictions.push_back(Json{{"id", "planned_throw"},
                               {"model", "projectile"},
                               {"method", "exact"},
                               {"position", jsonArray3(kThrowStart)},
                               {"velocity", jsonVector(ai.plans[0].launchVelocity)},
                               {"time", jsonFloat(kThrowFuse)},
                               {"step", 0.02},
                               {"restitution", 0.5}});
    // "accelerated" with no acceleration: the same path as "linear", which the pictures would
    // label as the article's method (a comparison this is not).
    predictions.push_back(Json{{"id", "pedestrian"},
                               {"model", "accelerated"},
                               {"position", jsonArray3(kPedestrian)},
                               {"velocity", jsonVector(demoVector(kPedestrianVelocity))},
                               {"acceleration", Json::array({0, 0, 0})},
                               {"time", jsonFloat(kPedestrianTime)}});
}

/// The base scenario (the literal above) built with the demo level in memory.
bool buildBase(const Json& input, bool recordTrajectories, Scenario& scenario, Diagnostics& diagnostics,
               std::string& reason) {
    Json withoutMeshes = input;
    withoutMeshes["world"].erase("meshes");
    scenario.recordTrajectories = recordTrajectories;
    return buildScenario(withoutMeshes, std::filesystem::path(), scenario, diagnostics) &&
           addDemoLevel(scenario, reason);
}

std::string text3(const foresight::RVec3& v) { return vectorText(v); }

/// The AI part of the table, from the final scenario's results.
std::string aiTable(const DemoAi& ai, const Scenario& scenario, const std::vector<PredictionResult>& results,
                    Json& dangerZones) {
    const PredictionResult* target = findResult(scenario, results, "aim_target");
    const PredictionResult* shot = findResult(scenario, results, "aim_shot");
    const PredictionResult* thrown = findResult(scenario, results, "planned_throw");
    const PredictionResult* car = findResult(scenario, results, "car_exact");
    if (!target || !shot || !thrown || !car) return "the demo scenario is missing an AI prediction\n";
    std::string text = "\nAI uses (aim.h, throw_planner.h, danger.h)\n";
    char buffer[512];

    // Aim: the solutions, and the shot flown by the predictor against the runner.
    const foresight::FiringSolution& low = ai.solutions[0];
    const double miss = glm::length(glm::dvec3(shot->position) - glm::dvec3(target->position));
    std::snprintf(buffer, sizeof buffer,
                  "aim      a turret at %s fires at %.0f m/s at the accelerating runner:\n"
                  "         %zu solution%s; the low arc (%.1f deg up) meets it after %.3f s at\n"
                  "         %s; flown by the predictor, shot and runner are %.1e m apart\n",
                  text3(ai.shot.from).c_str(), static_cast<double>(ai.shot.speed), ai.solutionCount,
                  ai.solutionCount == 1 ? "" : "s", glm::degrees(static_cast<double>(low.elevation)),
                  static_cast<double>(low.time), text3(low.hit).c_str(), miss);
    text += buffer;
    if (ai.solutionCount > 1) {
        const foresight::FiringSolution& high = ai.solutions[ai.solutionCount - 1];
        std::snprintf(buffer, sizeof buffer, "         (the high arc, %.1f deg up, takes %.3f s)\n",
                      glm::degrees(static_cast<double>(high.elevation)), static_cast<double>(high.time));
        text += buffer;
    }

    // Plan: the best throw, replayed by the scenario.
    const foresight::ThrowPlan& plan = ai.plans[0];
    const double landed = glm::length(glm::dvec3(thrown->position) - glm::dvec3(ai.request.target));
    std::snprintf(buffer, sizeof buffer,
                  "plan     a grenade from the doorway into the platform's corner %s,\n"
                  "         within %.0f m at its %.0f s fuse, at most %.0f m/s: %zu plan%s from %u predictions;\n"
                  "         the best, at %.2f m/s, bounces %u time%s and ends %.3f m from the target\n",
                  text3(ai.request.target).c_str(), static_cast<double>(ai.request.acceptanceRadius),
                  static_cast<double>(ai.request.fuseTime), static_cast<double>(ai.request.maxSpeed),
                  ai.planned.planCount, ai.planned.planCount == 1 ? "" : "s", ai.planned.predictions,
                  glm::length(glm::dvec3(plan.launchVelocity)), thrown->projectile.bounces,
                  thrown->projectile.bounces == 1 ? "" : "s", landed);
    text += buffer;

    // Danger: the planned grenade's blast, and two guards.
    foresight::ProjectileDanger danger;
    danger.trajectory = thrown->trajectory;
    danger.fuseTime = kThrowFuse;
    danger.blastRadius = kBlastRadius;
    foresight::DangerZone zone;
    if (foresight::computeDangerZone(danger, zone) != foresight::Status::Ok) return text + "danger: no zone\n";
    dangerZones.push_back(Json{{"id", "planned_throw"},
                               {"center", jsonPosition(zone.center)},
                               {"radius", jsonFloat(zone.radius)},
                               {"time", jsonFloat(zone.time)}});
    std::snprintf(buffer, sizeof buffer, "danger   the planned grenade explodes at %.1f s at %s (blast %.0f m):\n",
                  static_cast<double>(zone.time), text3(zone.center).c_str(), static_cast<double>(zone.radius));
    text += buffer;
    for (int g = 0; g < 2; ++g) {
        const foresight::RVec3 guard = demoPoint(kGuards[g]);
        foresight::DangerStart start;
        foresight::ClosestApproach closest;
        if (foresight::findDangerStart(danger, guard, start) != foresight::Status::Ok ||
            foresight::findClosestPathApproach(danger.trajectory, guard, 0.0f, kThrowFuse, closest) !=
                foresight::Status::Ok)
            continue;
        const double away = glm::length(glm::dvec3(guard) - glm::dvec3(zone.center));
        if (start.ever)
            std::snprintf(buffer, sizeof buffer, "         %s, %.2f m away: unsafe from %.2f s, must leave\n",
                          kGuardNames[g], away, static_cast<double>(start.time));
        else
            std::snprintf(buffer, sizeof buffer,
                          "         %s, %.2f m away: safe (the grenade passes %.2f m off at %.2f s)\n", kGuardNames[g],
                          away, static_cast<double>(closest.distance), static_cast<double>(closest.time));
        text += buffer;
    }

    // Vehicle: the turning car (exact arc) against the pedestrian crossing its path.
    const Prediction* carPrediction = nullptr;
    for (const Prediction& p : scenario.predictions)
        if (p.id.is_string() && p.id.get<std::string>() == "car_exact") carPrediction = &p;
    if (!carPrediction) return text;
    foresight::VehicleBody vehicle;
    vehicle.state.position = carPrediction->position;
    vehicle.state.velocity = carPrediction->velocity;
    vehicle.state.orientation = carPrediction->orientation;
    vehicle.state.angularVelocity = carPrediction->angularVelocity;
    vehicle.settings.frame = carPrediction->frame;
    foresight::CharacterBody pedestrian;
    pedestrian.position = demoPoint(kPedestrian);
    pedestrian.velocity = demoVector(kPedestrianVelocity);
    pedestrian.radius = 0.3f;
    pedestrian.halfAxis = foresight::Vec3(0.0f, 0.6f, 0.0f);
    foresight::VehicleContact contact;
    foresight::ClosestApproach closest;
    if (foresight::findVehicleContact(vehicle, pedestrian, carPrediction->time, {}, contact) != foresight::Status::Ok ||
        foresight::findClosestVehicleApproach(vehicle, pedestrian, carPrediction->time, {}, closest) !=
            foresight::Status::Ok)
        return text;
    if (contact.contact)
        std::snprintf(buffer, sizeof buffer,
                      "         the turning car (a 1.8 x 1.4 x 4.4 m box) touches the pedestrian crossing at\n"
                      "         1.5 m/s after %.3f s (to 1 mm): the pedestrian must wait\n",
                      static_cast<double>(contact.time));
    else
        std::snprintf(buffer, sizeof buffer,
                      "         the turning car misses the pedestrian: closest %.3f m at %.3f s\n",
                      static_cast<double>(closest.distance), static_cast<double>(closest.time));
    text += buffer;
    return text;
}

}  // namespace

namespace {

/// The full demo input (the literal plus the AI predictions) and the AI answers behind it.
bool demoInput(Json& input, DemoAi& ai, std::string& error) {
    Diagnostics diagnostics;
    if (!parseJsonText(kDemoScenario, "demo scenario", input, diagnostics)) {
        error = diagnostics.errors.empty() ? "cannot parse" : diagnostics.errors.front();
        return false;
    }
    Scenario base;
    if (!buildBase(input, false, base, diagnostics, error)) {
        if (error.empty()) error = diagnostics.errors.empty() ? "invalid" : diagnostics.errors.front();
        return false;
    }
    if (!computeDemoAi(base, ai, error)) return false;
    appendAiPredictions(ai, input);
    return true;
}

}  // namespace

Json demoScenario() {
    Json input;
    DemoAi ai;
    std::string error;
    if (!demoInput(input, ai, error)) return Json::object();
    return input;
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
    // The in-process demo needs no file: the level mesh is built in memory and added to the
    // world the scenario's other shapes make.
    Json input;
    DemoAi ai;
    Diagnostics diagnostics;
    Scenario scenario;
    std::vector<PredictionResult> results;
    std::string reason;
    if (!demoInput(input, ai, reason) || !buildBase(input, pictures.wanted(), scenario, diagnostics, reason) ||
        !runScenario(scenario, results, diagnostics)) {
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
                  << ", relative to the scenario file: write it there with `foresight level --obj " << kDemoLevelFile
                  << "`\n";
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
    Json dangerZones = Json::array();
    const std::string aiText = aiTable(ai, scenario, results, dangerZones);
    std::string error;
    if (pictures.wanted()) {
        Json picture = pictureDocument(scenario, results, "foresight demo");
        picture["danger_zones"] = std::move(dangerZones);
        if (!writePictures(pictures, picture, "foresight demo", error)) {
            std::cerr << error << '\n';
            return 2;
        }
    }
    if (jsonFile != "-" && scenarioFile != "-") {
        std::string text = table(scenario, results) + aiText;
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

}  // namespace foresight_cli
