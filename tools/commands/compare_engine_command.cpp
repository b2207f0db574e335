// `foresight compare FILE --engine NAME`: the scenario's projectiles run in the real physics
// engine (through the harnesses of tests/engines/) beside the engine-matched, exact and stepped
// predictions. Formats and harnesses: docs/engines.md, tests/engines/README.md.

#include "compare_command.h"

#include "json_input.h"
#include "json_output.h"
#include "scenario.h"
#include "text_file.h"

#include <glm/gtc/quaternion.hpp>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace foresight_cli {

namespace {

using foresight::PhysicsEngine;
using foresight::RVec3;
using foresight::Status;
using foresight::Vec3;
namespace fs = std::filesystem;

/// A point projectile goes to the engine as a sphere of this radius [m] (a body needs a size).
constexpr float kPointRadius = 0.02f;
/// Half the thickness [m] and half the width [m] of the box that stands for a plane.
constexpr double kPlaneHalfThickness = 1.0, kPlaneHalfWidth = 1000.0;
/// Steps sent to an engine at most per projectile (the harnesses keep every step in memory).
constexpr std::uint64_t kMaxEngineSteps = 200000;

/// An engine a harness drives.
struct HarnessEngine {
    const char* name;      ///< the harness's engine name, and --engine's
    PhysicsEngine engine;  ///< the profile that predicts it
    const char* runtime;   ///< "node", "godot" or "native"
    const char* what;      ///< for --help and messages
};

const HarnessEngine kHarnessEngines[] = {
    {"jolt", PhysicsEngine::Jolt, "node", "Jolt Physics (npm jolt-physics)"},
    {"physx", PhysicsEngine::PhysX, "node", "PhysX 4.1 (npm @cocos/physx)"},
    {"rapier", PhysicsEngine::Rapier, "node", "Rapier (npm @dimforge/rapier3d-compat)"},
    {"ammo", PhysicsEngine::Bullet, "node", "Bullet in WebAssembly (npm ammo.js)"},
    {"bullet", PhysicsEngine::Bullet, "native", "Bullet (Debian libbullet)"},
    {"godot3", PhysicsEngine::Godot3, "godot", "GodotPhysics (Debian godot3-server)"},
    {"godot3-bullet", PhysicsEngine::Godot3Bullet, "godot", "Godot 3 with Bullet (Debian godot3-server)"},
    {"box2d", PhysicsEngine::Box2D, "native", "Box2D 2.4 (Debian libbox2d)"},
};

const HarnessEngine* findEngine(const std::string& name) {
    for (const HarnessEngine& e : kHarnessEngines)
        if (name == e.name) return &e;
    return nullptr;
}

std::string engineList() {
    std::string out;
    for (const HarnessEngine& e : kHarnessEngines) out += (out.empty() ? "" : ", ") + std::string(e.name);
    return out;
}

/// An executable named `name` on PATH, or empty.
std::string findOnPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::stringstream folders(path ? path : "");
    std::string folder;
    while (std::getline(folders, folder, ':')) {
        if (folder.empty()) continue;
        const fs::path candidate = fs::path(folder) / name;
        std::error_code error;
        if (fs::is_regular_file(candidate, error) && ::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
    return {};
}

/// Runs argv (no shell) with extra environment entries; returns its exit status and keeps its
/// combined output (for the message when it fails). -1 when it cannot start.
int runProgram(const std::vector<std::string>& argv, const std::vector<std::string>& extraEnvironment,
               const fs::path& logFile) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    std::vector<std::string> environment(extraEnvironment);
    for (char** e = environ; e && *e; ++e) environment.emplace_back(*e);
    std::vector<char*> env;
    for (const std::string& e : environment) env.push_back(const_cast<char*>(e.c_str()));
    env.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, logFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    pid_t pid = 0;
    const int started = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), env.data());
    posix_spawn_file_actions_destroy(&actions);
    if (started != 0) return -1;
    int status = 0;
    while (waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) return -1;
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

/// The harness folder: --harness-dir, else $FORESIGHT_ENGINE_HARNESSES, else the source tree's.
fs::path harnessFolder(const CompareOptions& options) {
    if (!options.harnessDir.empty()) return options.harnessDir;
    if (const char* env = std::getenv("FORESIGHT_ENGINE_HARNESSES"); env && *env) return env;
#ifdef FORESIGHT_ENGINE_HARNESS_DIR
    return FORESIGHT_ENGINE_HARNESS_DIR;
#else
    return {};
#endif
}

/// The command that runs `engine`'s harness on a case file and a result file; empty and
/// `missing` set when its runtime is not installed.
std::vector<std::string> harnessCommand(const HarnessEngine& engine, const fs::path& folder,
                                        std::vector<std::string>& environment, std::string& missing) {
    std::error_code error;
    const std::string runtime = engine.runtime;
    if (runtime == "node") {
        const std::string node = findOnPath("node");
        if (node.empty())
            missing = "Node.js (node) is not on PATH";
        else if (!fs::is_regular_file(folder / "harness.mjs", error))
            missing = (folder / "harness.mjs").string() + " not found";
        else if (!fs::is_directory(folder / "node_modules", error))
            missing = "the engines' npm packages are not installed (npm ci in " + folder.string() + ")";
        if (!missing.empty()) return {};
        return {node, (folder / "harness.mjs").string()};
    }
    if (runtime == "godot") {
        const std::string godot = findOnPath("godot3-server");
        const fs::path script = folder / "godot" / "run_godot.sh";
        const std::string bash = findOnPath("bash");
        if (godot.empty())
            missing = "godot3-server is not on PATH (Debian package godot3-server)";
        else if (bash.empty())
            missing = "bash is not on PATH";
        else if (!fs::is_regular_file(script, error))
            missing = script.string() + " not found";
        if (!missing.empty()) return {};
        environment.push_back("GODOT=" + godot);
        return {bash, script.string()};
    }
    std::string native;
    if (const char* env = std::getenv("FORESIGHT_NATIVE_HARNESS"); env && *env) native = env;
#ifdef FORESIGHT_NATIVE_HARNESS_PATH
    if (native.empty()) native = FORESIGHT_NATIVE_HARNESS_PATH;
#endif
    if (native.empty() || ::access(native.c_str(), X_OK) != 0)
        missing =
            "foresight_engine_harness is not built (configure with FORESIGHT_BUILD_TESTS=ON, libbullet-dev and "
            "libbox2d-dev installed, or set FORESIGHT_NATIVE_HARNESS)";
    if (!missing.empty()) return {};
    return {native};
}

/// The rotation that takes +y to the unit vector n.
glm::dquat rotationFromUp(const glm::dvec3& n) {
    const glm::dvec3 up(0, 1, 0);
    const double c = glm::dot(up, n);
    if (c < -1.0 + 1e-12) return glm::dquat(0, 0, 0, 1);  // half a turn about z
    const glm::dvec3 axis = glm::cross(up, n);
    return glm::normalize(glm::dquat(1.0 + c, axis.x, axis.y, axis.z));
}

/// Materials for the body and the boxes whose combination under the engine's rules is the
/// projectile's restitution and friction (the box takes the rule's neutral value).
void splitMaterial(foresight::CombineRule rule, double value, double& body, double& box) {
    switch (rule) {
        case foresight::CombineRule::Max:
        case foresight::CombineRule::SumClamped:
            body = value;
            box = 0.0;
            break;
        case foresight::CombineRule::Multiply:
            body = value;
            box = 1.0;
            break;
        default:
            body = value;
            box = value;
            break;
    }
}

/// One projectile of the scenario, in the engine and predicted.
struct EngineComparison {
    const Prediction* prediction = nullptr;
    foresight::ProjectileSettings settings;  // the engine-matched prediction's
    std::uint64_t steps = 0;
    std::vector<glm::dvec3> engine;     // the engine's positions, start and every step
    std::vector<glm::dvec3> predicted;  // the engine-matched prediction's
    RVec3 exactEnd{0}, steppedEnd{0};
    int engineFirstContact = -1, predictedFirstContact = -1;
    double freeFlightWorst = 0.0;                              // [m] before either side's first contact
    double endEngine = 0.0, endExact = 0.0, endStepped = 0.0;  // [m] from the engine's end
};

/// The first step whose velocity change is not free flight's by more than 0.05 m/s, or -1.
int firstContact(const std::vector<glm::dvec3>& velocities, const foresight::ProjectileSettings& settings) {
    // One normal step from the state after step k - 1 (a first-step rule acts on step 1 only,
    // which is skipped when the profile has one).
    foresight::EngineProfile profile = settings.engine;
    profile.firstStep = foresight::FirstStepRule::Normal;
    for (std::size_t k = 1; k < velocities.size(); ++k) {
        if (k == 1 && settings.engine.firstStep != foresight::FirstStepRule::Normal) continue;
        const foresight::EngineFlightState f =
            foresight::engineFreeFlight(profile, RVec3(0.0), Vec3(velocities[k - 1]), settings.gravity, 1);
        if (glm::length(glm::dvec3(f.velocity) - velocities[k]) > 0.05) return static_cast<int>(k);
    }
    return -1;
}

bool readVectors(const Json& array, std::vector<glm::dvec3>& out) {
    if (!array.is_array()) return false;
    for (const Json& row : array) {
        if (!row.is_array() || row.size() != 3 || !row[0].is_number() || !row[1].is_number() || !row[2].is_number())
            return false;
        out.emplace_back(row[0].get<double>(), row[1].get<double>(), row[2].get<double>());
        if (!std::isfinite(out.back().x + out.back().y + out.back().z)) return false;
    }
    return true;
}

std::string millimetres(double metres) {
    char buffer[32];
    const double mm = metres * 1000.0;
    std::snprintf(buffer, sizeof buffer, mm < 10.0 ? "%.2f" : mm < 1000.0 ? "%.1f" : "%.0f", mm);
    return buffer;
}

/// A temporary folder removed when this goes out of scope.
struct TemporaryFolder {
    fs::path path;
    TemporaryFolder() {
        std::string pattern = (fs::temp_directory_path() / "foresight-compare-XXXXXX").string();
        if (::mkdtemp(pattern.data())) path = pattern;
    }
    ~TemporaryFolder() {
        std::error_code error;
        if (!path.empty()) fs::remove_all(path, error);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;
};

}  // namespace

int compareEngineCommand(const std::string& file, const CompareOptions& options) {
    const HarnessEngine* engine = findEngine(options.engine);
    if (!engine) {
        std::cerr << "foresight compare: unknown --engine \"" << options.engine << "\"; expected one of "
                  << engineList() << '\n';
        return 2;
    }
    if (options.builtin) {
        std::cerr << "foresight compare: --engine compares a scenario FILE (the built-in scenes hold meshes, which "
                     "the engine harnesses do not build)\n";
        return 2;
    }
    if (file.empty()) {
        std::cerr << "foresight compare: expected a scenario FILE\n";
        return 2;
    }
    Diagnostics diagnostics;
    const std::string name = file == "-" ? std::string("<stdin>") : file;
    std::string text, reason;
    if (!readTextFile(file, text, reason)) {
        std::cerr << name << ": cannot read: " << reason << '\n';
        return 2;
    }
    Json document;
    Scenario scenario;
    if (!parseJsonText(text, name, document, diagnostics) ||
        !buildScenario(document, baseDirectoryOf(file), scenario, diagnostics)) {
        printDiagnostics(diagnostics, std::cerr);
        return 2;
    }
    // What the harnesses build: planes (as large thin boxes) and boxes.
    const bool planar = engine->engine == PhysicsEngine::Box2D;
    // Engines that build a box with the scenario's rounding: Jolt's convex radius, Rapier's round
    // cuboid, Bullet's collision margin (native, ammo.js and Godot 3 with Bullet).
    const bool rounds = engine->engine == PhysicsEngine::Jolt || engine->engine == PhysicsEngine::Rapier ||
                        engine->engine == PhysicsEngine::Bullet || engine->engine == PhysicsEngine::Godot3Bullet;
    if (!scenario.world.spheres().empty())
        diagnostics.error("world.spheres",
                          "compare --engine sends planes and boxes to the engine; spheres are not supported");
    if (!scenario.world.triangles().empty() || scenario.meshWorld)
        diagnostics.error(
            scenario.meshWorld ? "world.meshes" : "world.triangles",
            "compare --engine sends planes and boxes to the engine; triangles and meshes are not supported");
    if (planar && scenario.gravity.z != 0.0f)
        diagnostics.error("gravity", "box2d runs in the x-y plane: the z component must be 0");
    Json boxes = Json::array();
    std::vector<foresight::SurfaceMaterial> boxMaterials;  // each sent box's own material
    for (std::size_t i = 0; i < scenario.world.planes().size(); ++i) {
        const foresight::Plane& plane = scenario.world.planes()[i];
        const glm::dvec3 n = glm::normalize(glm::dvec3(plane.normal));
        if (planar && std::abs(n.z) > 1e-9) {
            diagnostics.error("world.planes[" + std::to_string(i) + "].normal",
                              "box2d runs in the x-y plane: the normal's z component must be 0");
            continue;
        }
        const glm::dvec3 centre = n * (static_cast<double>(plane.distance) - kPlaneHalfThickness);
        const glm::dquat q = rotationFromUp(n);
        boxes.push_back(Json{{"center", {centre.x, centre.y, centre.z}},
                             {"half_extents", {kPlaneHalfWidth, kPlaneHalfThickness, kPlaneHalfWidth}},
                             {"rotation", {q.x, q.y, q.z, q.w}}});
        // A plane's box is sharp in Jolt (it would round it). Bullet keeps its default margin: its
        // faces are where the plane is, and a margin of 0 changes how GJK measures a deep contact.
        if (engine->engine == PhysicsEngine::Jolt || engine->engine == PhysicsEngine::Rapier)
            boxes.back()["rounding"] = 0.0;
        boxMaterials.push_back(scenario.world.planeMaterials()[i]);
    }
    for (std::size_t i = 0; i < scenario.world.boxes().size(); ++i) {
        const foresight::OrientedBox& box = scenario.world.boxes()[i];
        const glm::dquat q(box.orientation);
        if (planar && (std::abs(q.x) > 1e-6 || std::abs(q.y) > 1e-6)) {
            diagnostics.error("world.boxes[" + std::to_string(i) + "].orientation",
                              "box2d runs in the x-y plane: a box may only turn about z");
            continue;
        }
        if (!rounds && box.rounding > 0.0f) {
            diagnostics.error("world.boxes[" + std::to_string(i) + "].rounding",
                              std::string(engine->name) +
                                  " builds sharp boxes here: the rounding must be 0 (jolt, rapier and "
                                  "the Bullet engines round them)");
            continue;
        }
        boxes.push_back(Json{{"center", {box.center.x, box.center.y, box.center.z}},
                             {"half_extents", {box.halfExtents.x, box.halfExtents.y, box.halfExtents.z}},
                             {"rotation", {q.x, q.y, q.z, q.w}}});
        // The engine builds the box the scenario describes: Jolt's convex radius (0.05 m unless
        // given), Rapier's round cuboid and Bullet's collision margin (0.04 m unless given) take
        // the box's own rounding, 0 included.
        if (rounds) boxes.back()["rounding"] = box.rounding;
        boxMaterials.push_back(scenario.world.boxMaterials()[i]);
    }

    // The projectiles: the engine-matched prediction first (its steps are the engine's).
    std::vector<EngineComparison> comparisons;
    Json cases = Json::array();
    const foresight::CollisionWorld* world = scenario.world.shapeCount() > 0 ? &scenario.world : nullptr;
    for (const Prediction& p : scenario.predictions) {
        if (p.model != Model::Projectile) continue;
        EngineComparison c;
        c.prediction = &p;
        c.settings = p.projectile;
        const bool sameEngine =
            p.projectile.method == foresight::ProjectileMethod::Engine && p.projectile.engine.engine == engine->engine;
        if (!sameEngine) {
            c.settings.engine = foresight::engineProfile(engine->engine);
            if (p.projectile.method == foresight::ProjectileMethod::Engine) {
                c.settings.engine.timestep = p.projectile.engine.timestep;
                diagnostics.warning(p.path, std::string("its engine profile is ") +
                                                foresight::engineName(p.projectile.engine.engine) +
                                                "; compared with the " + engine->name + " profile at its timestep");
            }
        }
        // ammo.js carries Bullet 2.83: no restitution threshold, friction warm-started, erp2 0.8
        // (the "ammo" profile's values, whichever Bullet profile the prediction names).
        if (std::string(engine->name) == "ammo") {
            const foresight::EngineProfile ammo = foresight::ammoJsProfile();
            c.settings.engine.restitutionThreshold = ammo.restitutionThreshold;
            c.settings.engine.frictionWarmStart = ammo.frictionWarmStart;
            c.settings.engine.splitImpulseCorrection = ammo.splitImpulseCorrection;
        }
        c.settings.method = foresight::ProjectileMethod::Engine;
        c.settings.step = c.settings.engine.timestep;
        c.settings.radius = p.projectile.radius > 0.0f ? p.projectile.radius : kPointRadius;
        c.settings.maxBounces = foresight::kUnlimitedBounces;
        if (planar && (p.velocity.z != 0.0f || p.position.z != 0.0))
            diagnostics.warning(p.path,
                                "box2d runs in the x-y plane: the z components of position and velocity are dropped");
        const double stepCount =
            std::ceil(static_cast<double>(p.time) / static_cast<double>(c.settings.engine.timestep) - 1e-9);
        if (!(stepCount >= 1.0) || stepCount > static_cast<double>(kMaxEngineSteps)) {
            diagnostics.error(p.path + ".time", "the engine would take " + std::to_string(stepCount) +
                                                    " steps; compare --engine runs 1 to " +
                                                    std::to_string(kMaxEngineSteps));
            continue;
        }
        c.steps = static_cast<std::uint64_t>(stepCount);
        Json body{{"radius", c.settings.radius},
                  {"mass", 1.0},
                  {"position", {p.position.x, p.position.y, planar ? 0.0 : static_cast<double>(p.position.z)}},
                  {"velocity", {p.velocity.x, p.velocity.y, planar ? 0.0f : p.velocity.z}}};
        // The body's damping as the prediction sets it; otherwise the engine's default for a new body.
        if (sameEngine) body["linear_damping"] = c.settings.engine.linearDamping;
        double bodyRestitution, boxRestitution, bodyFriction, boxFriction;
        splitMaterial(c.settings.engine.restitutionCombine, p.projectile.restitution, bodyRestitution, boxRestitution);
        splitMaterial(c.settings.engine.frictionCombine, p.projectile.friction, bodyFriction, boxFriction);
        body["restitution"] = bodyRestitution;
        body["friction"] = bodyFriction;
        // A shape with its own material keeps it (the engine combines it with the body's by its
        // rule, as the prediction does); the others get the split's value.
        Json caseBoxes = boxes;
        for (std::size_t j = 0; j < caseBoxes.size(); ++j) {
            const foresight::SurfaceMaterial& own = boxMaterials[j];
            caseBoxes[j]["restitution"] =
                own.restitution >= 0.0f ? static_cast<double>(own.restitution) : boxRestitution;
            caseBoxes[j]["friction"] = own.friction >= 0.0f ? static_cast<double>(own.friction) : boxFriction;
        }
        cases.push_back(Json{{"id", std::to_string(comparisons.size())},
                             {"engine", engine->name},
                             {"timestep", static_cast<double>(c.settings.engine.timestep)},
                             {"steps", c.steps},
                             {"gravity", {scenario.gravity.x, scenario.gravity.y, scenario.gravity.z}},
                             {"body", body},
                             {"boxes", caseBoxes}});
        comparisons.push_back(std::move(c));
    }
    if (comparisons.empty() && diagnostics.ok()) diagnostics.warning("predictions", "no projectile to compare");
    if (!diagnostics.ok()) {
        printDiagnostics(diagnostics, std::cerr);
        return 2;
    }

    // The engine.
    const bool showProgress = isatty(STDERR_FILENO) == 1;
    Json results;
    if (!comparisons.empty()) {
        std::vector<std::string> environment;
        std::string missing;
        const std::vector<std::string> command = harnessCommand(*engine, harnessFolder(options), environment, missing);
        if (command.empty()) {
            printDiagnostics(diagnostics, std::cerr);
            std::cerr << "foresight compare: cannot run " << engine->what << ": " << missing << '\n';
            return 2;
        }
        TemporaryFolder temporary;
        if (temporary.path.empty()) {
            std::cerr << "foresight compare: cannot create a temporary folder\n";
            return 1;
        }
        const fs::path in = temporary.path / "cases.json", out = temporary.path / "results.json",
                       log = temporary.path / "harness.log";
        std::ofstream(in) << Json{{"cases", cases}}.dump();
        if (showProgress)
            std::fprintf(stderr, "compare: running %zu projectile(s) in %s...", comparisons.size(), engine->what);
        std::vector<std::string> argv = command;
        argv.push_back(in.string());
        argv.push_back(out.string());
        const int status = runProgram(argv, environment, log);
        if (showProgress) std::fprintf(stderr, "\r%80s\r", "");
        if (status != 0) {
            std::string logText, ignored;
            readTextFile(log.string(), logText, ignored);
            if (logText.size() > 4000) logText = logText.substr(logText.size() - 4000);
            std::cerr << "foresight compare: the " << engine->name << " harness failed (status " << status << "):\n"
                      << logText << '\n';
            return 1;
        }
        std::string resultText;
        if (!readTextFile(out.string(), resultText, reason)) {
            std::cerr << "foresight compare: the harness wrote no result: " << reason << '\n';
            return 1;
        }
        results = Json::parse(resultText, nullptr, false);
        if (!results.is_object() || !results.contains("results") || !results["results"].is_array()) {
            std::cerr << "foresight compare: unreadable harness result\n";
            return 1;
        }
    }
    for (std::size_t i = 0; i < comparisons.size(); ++i) {
        EngineComparison& c = comparisons[i];
        const Prediction& p = *c.prediction;
        std::vector<glm::dvec3> velocities;
        for (const Json& r : results["results"]) {
            if (!r.is_object() || r.value("id", std::string()) != std::to_string(i)) continue;
            if (!readVectors(r.value("positions", Json()), c.engine) ||
                !readVectors(r.value("velocities", Json()), velocities))
                c.engine.clear();
        }
        if (c.engine.size() != c.steps + 1 || velocities.size() != c.steps + 1) {
            std::cerr << "foresight compare: the harness gave no complete result for " << p.path << '\n';
            return 1;
        }
        // The engine-matched prediction, one point per step.
        const RVec3 start(p.position.x, p.position.y, planar ? 0.0 : p.position.z);
        const Vec3 velocity(p.velocity.x, p.velocity.y, planar ? 0.0f : p.velocity.z);
        const float time =
            static_cast<float>(static_cast<double>(c.steps) * static_cast<double>(c.settings.engine.timestep));
        std::vector<foresight::TrajectoryPoint> points(foresight::trajectoryCapacity(time, c.settings, 16));
        foresight::ProjectileResult result;
        Status status = foresight::predictProjectile(start, velocity, time, c.settings, world, points, result);
        if (status == Status::Ok && result.trajectorySize != c.steps + 1) status = Status::TooManySteps;
        if (status != Status::Ok) {
            std::cerr << p.path << ": the engine-matched prediction failed: " << foresight::statusMessage(status)
                      << '\n';
            return 1;
        }
        std::vector<glm::dvec3> predictedVelocities;
        for (std::size_t k = 0; k < result.trajectorySize; ++k) {
            c.predicted.emplace_back(points[k].position);
            predictedVelocities.emplace_back(points[k].velocity);
        }
        c.engineFirstContact = firstContact(velocities, c.settings);
        c.predictedFirstContact = firstContact(predictedVelocities, c.settings);
        const std::size_t freeSteps = static_cast<std::size_t>(
            std::min(c.engineFirstContact < 0 ? static_cast<int>(c.steps) + 1 : c.engineFirstContact,
                     c.predictedFirstContact < 0 ? static_cast<int>(c.steps) + 1 : c.predictedFirstContact));
        for (std::size_t k = 0; k < freeSteps && k < c.engine.size(); ++k)
            c.freeFlightWorst = std::max(c.freeFlightWorst, glm::length(c.predicted[k] - c.engine[k]));
        // The exact and stepped methods at the same time, with the same sphere.
        for (const foresight::ProjectileMethod method :
             {foresight::ProjectileMethod::Exact, foresight::ProjectileMethod::Stepped}) {
            foresight::ProjectileSettings s = p.projectile;
            s.method = method;
            s.radius = c.settings.radius;
            s.maxBounces = foresight::kUnlimitedBounces;
            foresight::ProjectileResult r;
            std::vector<foresight::TrajectoryPoint> none;
            status = foresight::predictProjectile(start, velocity, time, s, world, none, r);
            if (status != Status::Ok) {
                std::cerr << p.path << ": " << foresight::statusMessage(status) << '\n';
                return 1;
            }
            (method == foresight::ProjectileMethod::Exact ? c.exactEnd : c.steppedEnd) = r.position;
        }
        const glm::dvec3 end = c.engine.back();
        c.endEngine = glm::length(c.predicted.back() - end);
        c.endExact = glm::length(glm::dvec3(c.exactEnd) - end);
        c.endStepped = glm::length(glm::dvec3(c.steppedEnd) - end);
    }
    printDiagnostics(diagnostics, std::cerr);

    if (!options.jsonFile.empty()) {
        Json list = Json::array();
        for (const EngineComparison& c : comparisons) {
            Json entry = Json::object();
            if (!c.prediction->id.is_null()) entry["id"] = c.prediction->id;
            entry["timestep"] = jsonFloat(c.settings.engine.timestep);
            entry["steps"] = c.steps;
            entry["radius"] = jsonFloat(c.settings.radius);
            Json enginePath = Json::array(), predictedPath = Json::array();
            for (const glm::dvec3& v : c.engine)
                enginePath.push_back(Json::array({jsonDouble(v.x), jsonDouble(v.y), jsonDouble(v.z)}));
            for (const glm::dvec3& v : c.predicted)
                predictedPath.push_back(Json::array({jsonDouble(v.x), jsonDouble(v.y), jsonDouble(v.z)}));
            entry["engine_positions"] = std::move(enginePath);
            entry["predicted_positions"] = std::move(predictedPath);
            entry["first_contact_step"] = {{"engine", c.engineFirstContact}, {"predicted", c.predictedFirstContact}};
            entry["free_flight_worst"] = jsonDouble(c.freeFlightWorst);
            entry["end_distance"] = {{"engine", jsonDouble(c.endEngine)},
                                     {"exact", jsonDouble(c.endExact)},
                                     {"stepped", jsonDouble(c.endStepped)}};
            list.push_back(std::move(entry));
        }
        Json out = Json::object();
        out["engine"] = engine->name;
        if (results.contains("engine_versions")) out["engine_versions"] = results["engine_versions"];
        out["projectiles"] = std::move(list);
        if (!writeTextFile(options.jsonFile, formatJson(out), reason)) {
            std::cerr << options.jsonFile << ": cannot write: " << reason << '\n';
            return 2;
        }
    }
    if (options.jsonFile == "-") return 0;
    std::string table = "foresight compare: predictions against " + std::string(engine->what) + "\n\n";
    char buffer[400];
    std::snprintf(buffer, sizeof buffer, "%-20s %6s %15s %14s %12s %12s %12s\n", "projectile", "steps", "first contact",
                  "free flight", "end: engine", "exact", "stepped");
    table += buffer;
    for (const EngineComparison& c : comparisons) {
        const std::string id = c.prediction->id.is_string() ? c.prediction->id.get<std::string>() : c.prediction->path;
        const auto step = [](int k) { return k < 0 ? std::string("-") : std::to_string(k); };
        std::snprintf(buffer, sizeof buffer, "%-20s %6llu %15s %14s %12s %12s %12s\n", id.c_str(),
                      static_cast<unsigned long long>(c.steps),
                      (step(c.engineFirstContact) + " / " + step(c.predictedFirstContact)).c_str(),
                      millimetres(c.freeFlightWorst).c_str(), millimetres(c.endEngine).c_str(),
                      millimetres(c.endExact).c_str(), millimetres(c.endStepped).c_str());
        table += buffer;
    }
    table +=
        "\nfirst contact: the engine's step / the engine-matched prediction's (the first step whose velocity\n"
        "is not free flight's); free flight: the largest distance [mm] before it; end: the distance [mm]\n"
        "from the engine's last position to the engine-matched, exact and stepped predictions' (a point\n"
        "projectile is a sphere of 0.02 m on every side; planes are boxes 2 m thick, 2 km wide).\n";
    if (!writeTextFile("-", table, reason)) {
        std::cerr << "foresight compare: cannot write the table: " << reason << '\n';
        return 1;
    }
    return 0;
}

}  // namespace foresight_cli
