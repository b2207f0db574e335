#include "compare_command.h"

#include "json_output.h"
#include "scenario.h"
#include "text_file.h"

#ifdef FORESIGHT_CLI_WITH_BULLET
#include "demo_level.h"
#include "level_world.h"

#include <foresight/bullet_simulation.h>
#include <foresight/bullet_world.h>
#endif
#ifdef FORESIGHT_CLI_WITH_EMBREE
#include <foresight/embree_world.h>
#endif

#include <glm/gtc/quaternion.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace foresight_cli {

#ifndef FORESIGHT_CLI_WITH_BULLET

int compareCommand(const std::string&, const CompareOptions&) {
    std::cerr << "foresight compare: this foresight was built without Bullet Physics (libbullet-dev), "
                 "which the comparison simulates; install it and rebuild (scripts/build.sh)\n";
    return 2;
}

#else

namespace {

using foresight::RVec3;
using foresight::Status;
using foresight::Vec3;

/// A point projectile is compared as a sphere of this radius [m] (a rigid body needs a size).
constexpr float kPointRadius = 0.02f;
/// The reference is simulated again at this multiple of the frequency to show its own error.
constexpr float kFineFactor = 4.0f;

struct Impact {
    double time = 0;
    RVec3 position{0};
    double approachSpeed = 0;  // along the normal, before the impact [m/s]
};

struct MethodRun {
    foresight::ProjectileResult result;
    std::vector<foresight::TrajectoryPoint> trajectory;
    std::vector<Impact> impacts;
};

struct Errors {
    std::optional<double> landingDistance;  // [m]; empty when either side never lands
    std::optional<double> landingTime;      // [s]
    double finalDistance = 0;               // [m] at the prediction's time
    std::size_t bounces = 0;                // visible bounces (approach >= kBounceSpeed) of this side
    std::size_t referenceBounces = 0;       // the same for the reference
    std::optional<double> bounceTimeMax;    // [s] over the bounces both sides have
};

struct ThrowComparison {
    const Prediction* prediction = nullptr;
    float radius = 0;
    foresight::RigidBodySimulationResult physics;
    foresight::RigidBodySimulationResult fine;  // at kFineFactor x the frequency
    std::vector<Impact> physicsImpacts;
    std::vector<Impact> fineImpacts;
    MethodRun stepped;
    MethodRun exact;
    Errors steppedErrors;
    Errors exactErrors;
    Errors fineErrors;  // the fine simulation against the reference: the reference's own error
};

double distance(const RVec3& a, const RVec3& b) { return glm::length(glm::dvec3(a) - glm::dvec3(b)); }

// Impacts of a predicted trajectory. The approach speed comes from the previous point's
// velocity carried forward by gravity (the motion between two recorded points is free flight,
// except while sliding, when impacts are not recorded as bounces).
std::vector<Impact> predictedImpacts(const std::vector<foresight::TrajectoryPoint>& trajectory, const Vec3& gravity) {
    std::vector<Impact> impacts;
    for (std::size_t i = 1; i < trajectory.size(); ++i) {
        const auto& point = trajectory[i];
        if (point.event != foresight::TrajectoryEvent::Bounce && point.event != foresight::TrajectoryEvent::Hit)
            continue;
        const auto& previous = trajectory[i - 1];
        const glm::dvec3 before =
            glm::dvec3(previous.velocity) + glm::dvec3(gravity) * (static_cast<double>(point.time) - previous.time);
        impacts.push_back({point.time, point.position, -glm::dot(before, glm::dvec3(point.normal))});
    }
    return impacts;
}

// Bullet applies a bounce in the step after the sphere reaches the surface: the moment and place
// of the touch (interpolated on Bullet's own path) are the impact, not the end of that step.
std::vector<Impact> simulatedImpacts(const foresight::RigidBodySimulationResult& result) {
    std::vector<Impact> impacts;
    for (const auto& impact : result.impacts)
        impacts.push_back({impact.touchTime, impact.touchPosition, impact.approachSpeed});
    return impacts;
}

std::vector<const Impact*> visibleBounces(const std::vector<Impact>& impacts) {
    std::vector<const Impact*> bounces;
    for (const auto& impact : impacts)
        if (impact.approachSpeed >= kBounceSpeed) bounces.push_back(&impact);
    return bounces;
}

Errors measure(const std::vector<Impact>& impacts, const RVec3& final, const std::vector<Impact>& reference,
               const RVec3& referenceFinal) {
    Errors errors;
    if (!impacts.empty() && !reference.empty()) {
        errors.landingDistance = distance(impacts.front().position, reference.front().position);
        errors.landingTime = std::abs(impacts.front().time - reference.front().time);
    }
    errors.finalDistance = distance(final, referenceFinal);
    const auto bounces = visibleBounces(impacts);
    const auto referenceBounces = visibleBounces(reference);
    errors.bounces = bounces.size();
    errors.referenceBounces = referenceBounces.size();
    for (std::size_t k = 0; k < bounces.size() && k < referenceBounces.size(); ++k) {
        const double difference = std::abs(bounces[k]->time - referenceBounces[k]->time);
        errors.bounceTimeMax = std::max(errors.bounceTimeMax.value_or(0.0), difference);
    }
    return errors;
}

const foresight::CollisionWorld* predictionWorld(const Scenario& scenario) {
    if (scenario.meshWorld) return scenario.meshWorld.get();
    return scenario.world.shapeCount() > 0 ? &scenario.world : nullptr;
}

Status predict(const Scenario& scenario, const Prediction& p, const foresight::ProjectileSettings& settings,
               MethodRun& run) {
    const foresight::CollisionWorld* world = predictionWorld(scenario);
    run.trajectory.resize(foresight::trajectoryCapacity(p.time, settings));
    Status status =
        foresight::predictProjectile(p.position, p.velocity, p.time, settings, world, run.trajectory, run.result);
    if (status == Status::Ok && run.result.trajectoryNeeded > run.trajectory.size()) {
        run.trajectory.resize(run.result.trajectoryNeeded);
        status =
            foresight::predictProjectile(p.position, p.velocity, p.time, settings, world, run.trajectory, run.result);
    }
    if (status != Status::Ok) return status;
    run.trajectory.resize(std::min(run.result.trajectorySize, run.trajectory.size()));
    run.impacts = predictedImpacts(run.trajectory, settings.gravity);
    return Status::Ok;
}

/// A Bullet world with the scenario's shapes and meshes.
Status buildBulletScene(const Scenario& scenario, foresight::BulletScene& scene) {
    Status status = scene.add(scenario.world);
#ifdef FORESIGHT_CLI_WITH_EMBREE
    if (status == Status::Ok && scenario.meshWorld) {
        const auto* meshes = static_cast<const foresight::EmbreeWorld*>(scenario.meshWorld.get());
        status = scene.addMesh(meshes->meshTriangles());
    }
#endif
    return status;
}

/// Compares every projectile of `scenario`; errors go to `diagnostics` (path: message).
/// `progress(done, total)` is called after each throw.
template <class Progress>
std::vector<ThrowComparison> compareScenario(const Scenario& scenario, const CompareOptions& options,
                                             Diagnostics& diagnostics, Progress&& progress) {
    std::vector<ThrowComparison> comparisons;
    foresight::BulletScene scene;
    const Status sceneStatus = buildBulletScene(scenario, scene);
    if (sceneStatus != Status::Ok) {
        diagnostics.error("world",
                          std::string("cannot build the Bullet world: ") + foresight::statusMessage(sceneStatus));
        return comparisons;
    }
    std::size_t total = 0;
    for (const auto& p : scenario.predictions) total += p.model == Model::Projectile ? 1 : 0;
    std::size_t done = 0;
    for (const auto& p : scenario.predictions) {
        if (p.model != Model::Projectile) continue;
        ThrowComparison c;
        c.prediction = &p;
        foresight::ProjectileSettings settings = p.projectile;
        c.radius = settings.radius > 0 ? settings.radius : kPointRadius;
        settings.radius = c.radius;
        if (settings.maxBounces != foresight::kUnlimitedBounces) {
            diagnostics.warning(p.path, "max_bounces and stop_at_first_hit are ignored: the physics does not stop");
            settings.maxBounces = foresight::kUnlimitedBounces;
        }

        foresight::RigidBodySimulationSettings simulation;
        simulation.frequency = options.frequency;
        simulation.pointRadius = kPointRadius;
        simulation.lockRotation = !options.spin;
        foresight::RigidBodySimulationSettings fineSimulation = simulation;
        fineSimulation.frequency = std::min(options.frequency * kFineFactor, 100000.0f);

        Status status = foresight::simulateProjectileRigidBody(scene, p.position, p.velocity, p.time, settings,
                                                               simulation, c.physics);
        if (status == Status::Ok)
            status = foresight::simulateProjectileRigidBody(scene, p.position, p.velocity, p.time, settings,
                                                            fineSimulation, c.fine);
        if (status != Status::Ok) {
            diagnostics.error(p.path,
                              std::string("the Bullet simulation refused it: ") + foresight::statusMessage(status));
            continue;
        }
        foresight::ProjectileSettings stepped = settings;
        stepped.method = foresight::ProjectileMethod::Stepped;
        foresight::ProjectileSettings exact = settings;
        exact.method = foresight::ProjectileMethod::Exact;
        status = predict(scenario, p, stepped, c.stepped);
        if (status == Status::Ok) status = predict(scenario, p, exact, c.exact);
        if (status != Status::Ok) {
            diagnostics.error(p.path, foresight::statusMessage(status));
            continue;
        }
        c.physicsImpacts = simulatedImpacts(c.physics);
        c.fineImpacts = simulatedImpacts(c.fine);
        c.steppedErrors = measure(c.stepped.impacts, c.stepped.result.position, c.physicsImpacts, c.physics.position);
        c.exactErrors = measure(c.exact.impacts, c.exact.result.position, c.physicsImpacts, c.physics.position);
        c.fineErrors = measure(c.fineImpacts, c.fine.position, c.physicsImpacts, c.physics.position);
        comparisons.push_back(std::move(c));
        progress(++done, total);
    }
    return comparisons;
}

// ---------------------------------------------------------------------------------------------
// Output

Json optionalNumber(const std::optional<double>& value) { return value ? jsonDouble(*value) : Json(); }

Json impactsJson(const std::vector<Impact>& impacts) {
    Json out = Json::array();
    for (const auto& impact : impacts) {
        Json entry = Json::object();
        entry["t"] = jsonDouble(impact.time);
        entry["position"] = jsonPosition(impact.position);
        entry["approach_speed"] = jsonDouble(impact.approachSpeed);
        out.push_back(std::move(entry));
    }
    return out;
}

Json errorsJson(const Errors& errors) {
    Json out = Json::object();
    out["landing_distance"] = optionalNumber(errors.landingDistance);
    out["landing_time"] = optionalNumber(errors.landingTime);
    out["final_distance"] = jsonDouble(errors.finalDistance);
    out["bounces"] = errors.bounces;
    out["reference_bounces"] = errors.referenceBounces;
    out["bounce_time_max"] = optionalNumber(errors.bounceTimeMax);
    return out;
}

Json methodJson(const MethodRun& run, const Errors& errors) {
    Json out = Json::object();
    out["position"] = jsonPosition(run.result.position);
    out["velocity"] = jsonVector(run.result.velocity);
    out["at_rest"] = run.result.atRest;
    out["impacts"] = impactsJson(run.impacts);
    out["errors"] = errorsJson(errors);
    return out;
}

Json comparisonJson(const ThrowComparison& c, const CompareOptions& options) {
    Json out = Json::object();
    if (!c.prediction->id.is_null()) out["id"] = c.prediction->id;
    out["radius"] = jsonFloat(c.radius);
    out["time"] = jsonFloat(c.prediction->time);
    Json physics = Json::object();
    physics["frequency"] = jsonFloat(options.frequency);
    physics["position"] = jsonPosition(c.physics.position);
    physics["velocity"] = jsonVector(c.physics.velocity);
    physics["at_rest"] = c.physics.atRest;
    physics["impacts"] = impactsJson(c.physicsImpacts);
    Json fine = errorsJson(c.fineErrors);
    out["physics"] = std::move(physics);
    out["physics_step_error"] = std::move(fine);
    out["stepped"] = methodJson(c.stepped, c.steppedErrors);
    out["exact"] = methodJson(c.exact, c.exactErrors);
    return out;
}

std::string millimetres(const std::optional<double>& metres) {
    if (!metres) return "-";
    char buffer[32];
    const double mm = *metres * 1000.0;
    std::snprintf(buffer, sizeof buffer, mm < 1.0 ? "%.2f" : mm < 10.0 ? "%.1f" : "%.0f", mm);
    return buffer;
}

std::string milliseconds(const std::optional<double>& seconds) {
    if (!seconds) return "-";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f", *seconds * 1000.0);
    return buffer;
}

std::string fileTable(const std::vector<ThrowComparison>& comparisons, const CompareOptions& options) {
    char buffer[1024];
    std::string text;
    std::snprintf(buffer, sizeof buffer,
                  "foresight compare: predictions against a Bullet rigid body at %g Hz (errors in mm and ms)\n\n",
                  static_cast<double>(options.frequency));
    text += buffer;
    std::snprintf(buffer, sizeof buffer, "%-16s %-8s %8s %10s %10s %9s %12s %10s\n", "projectile", "method", "radius",
                  "landing", "landing t", "at fuse", "bounces", "bounce t");
    text += buffer;
    for (const auto& c : comparisons) {
        const std::string id = c.prediction->id.is_string() ? c.prediction->id.get<std::string>() : c.prediction->path;
        const auto line = [&](const char* method, const Errors& e) {
            const std::string bounces = std::to_string(e.bounces) + " (" + std::to_string(e.referenceBounces) + ")";
            std::snprintf(buffer, sizeof buffer, "%-16s %-8s %8.3f %10s %10s %9s %12s %10s\n", id.c_str(), method,
                          static_cast<double>(c.radius), millimetres(e.landingDistance).c_str(),
                          milliseconds(e.landingTime).c_str(), millimetres(e.finalDistance).c_str(), bounces.c_str(),
                          milliseconds(e.bounceTimeMax).c_str());
            text += buffer;
        };
        line("stepped", c.steppedErrors);
        line("exact", c.exactErrors);
        line("physics", c.fineErrors);
    }
    std::snprintf(
        buffer, sizeof buffer,
        "\nlanding: distance and time between the first impacts; at fuse: distance at the prediction's time;\n"
        "bounces: bounces at %.1f m/s or more (the simulation's in brackets), bounce t: largest time\n"
        "difference between matching bounces. The \"physics\" rows are the simulation at %g Hz against\n"
        "the one at %g Hz: the reference's own step error. A point projectile is compared as a sphere\n"
        "of %.2f m.\n",
        kBounceSpeed, static_cast<double>(std::min(options.frequency * kFineFactor, 100000.0f)),
        static_cast<double>(options.frequency), static_cast<double>(kPointRadius));
    text += buffer;
    return text;
}

// ---------------------------------------------------------------------------------------------
// Built-in scenes

struct BuiltinScene {
    std::string name;
    std::string description;
    Scenario scenario;
};

/// Uniform in [lo, hi) from the fully specified mt19937 (std::uniform_real_distribution is not
/// the same on every standard library; the table must be).
double uniform(std::mt19937& random, double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(random()) / 4294967296.0);
}

constexpr int kThrowsPerScene = 24;
constexpr double kPi = 3.14159265358979323846;

/// A throw from `start` at `speed`, `elevation` above the horizontal, `azimuth` from +Z towards +X.
Prediction makeThrow(const std::string& id, const RVec3& start, double speed, double elevation, double azimuth) {
    Prediction p;
    p.path = id;
    p.id = id;
    p.model = Model::Projectile;
    p.time = 3.0f;
    p.position = start;
    p.velocity = Vec3(static_cast<float>(speed * std::cos(elevation) * std::sin(azimuth)),
                      static_cast<float>(speed * std::sin(elevation)),
                      static_cast<float>(speed * std::cos(elevation) * std::cos(azimuth)));
    p.projectile.step = 0.02f;
    p.projectile.restitution = 0.5f;
    p.trajectory = true;
    return p;
}

double radians(double degrees) { return degrees * kPi / 180.0; }

foresight::OrientedBox box(const RVec3& center, const Vec3& halfExtents, float angleAboutX = 0) {
    foresight::OrientedBox b;
    b.center = center;
    b.halfExtents = halfExtents;
    b.orientation = glm::angleAxis(angleAboutX, Vec3(1, 0, 0));
    return b;
}

bool builtinScenes(std::vector<BuiltinScene>& scenes, std::string& error) {
    std::mt19937 random(20261122u);
    const foresight::Plane floor{Vec3(0, 1, 0), 0};
    auto throws = [&](Scenario& s, const char* prefix, auto&& one) {
        for (int i = 0; i < kThrowsPerScene; ++i) s.predictions.push_back(one(std::string(prefix) + std::to_string(i)));
    };

    {
        BuiltinScene scene{"flat floor", "plane y = 0; throws in every direction from 1.5 m", {}};
        scene.scenario.world.add(floor);
        throws(scene.scenario, "floor_", [&](const std::string& id) {
            const RVec3 start(uniform(random, -1, 1), 1.5, uniform(random, -1, 1));
            return makeThrow(id, start, uniform(random, 6, 16), radians(uniform(random, 5, 60)),
                             uniform(random, 0, 2 * kPi));
        });
        scenes.push_back(std::move(scene));
    }
    {
        BuiltinScene scene{"wall", "floor; a 12 m x 4 m wall 0.5 m thick at z = 6", {}};
        scene.scenario.world.add(floor);
        scene.scenario.world.add(box(RVec3(0, 2, 6), Vec3(6, 2, 0.25f)));
        throws(scene.scenario, "wall_", [&](const std::string& id) {
            const RVec3 start(uniform(random, -2, 2), 1.5, 0);
            return makeThrow(id, start, uniform(random, 8, 16), radians(uniform(random, 0, 35)),
                             radians(uniform(random, -30, 30)));
        });
        scenes.push_back(std::move(scene));
    }
    {
        BuiltinScene scene{"ramp", "floor; a 6 m wide ramp rising at 20 degrees from z = 2.2", {}};
        scene.scenario.world.add(floor);
        scene.scenario.world.add(box(RVec3(0, 0, 6), Vec3(3, 0.5f, 4), static_cast<float>(radians(-20))));
        throws(scene.scenario, "ramp_", [&](const std::string& id) {
            const RVec3 start(uniform(random, -1, 1), 1.5, 0);
            return makeThrow(id, start, uniform(random, 6, 14), radians(uniform(random, 10, 50)),
                             radians(uniform(random, -20, 20)));
        });
        scenes.push_back(std::move(scene));
    }
    {
        BuiltinScene scene{"stairs", "floor; 10 steps of 0.2 m x 0.3 m from z = 4, 4 m wide, and a landing", {}};
        scene.scenario.world.add(floor);
        for (int i = 0; i < 10; ++i) {
            const double height = 0.2 * (i + 1);
            scene.scenario.world.add(
                box(RVec3(0, height / 2, 4 + 0.3 * i + 0.15), Vec3(2, static_cast<float>(height / 2), 0.15f)));
        }
        scene.scenario.world.add(box(RVec3(0, 1.0, 9), Vec3(2, 1, 2)));
        throws(scene.scenario, "stairs_", [&](const std::string& id) {
            const RVec3 start(uniform(random, -1, 1), 1.5, 0);
            return makeThrow(id, start, uniform(random, 5, 12), radians(uniform(random, 10, 50)),
                             radians(uniform(random, -15, 15)));
        });
        scenes.push_back(std::move(scene));
    }
    {
        BuiltinScene scene{"room mesh", "a closed 10 m x 4 m x 10 m room of triangles, seen from inside", {}};
        if (!addLevelMesh(scene.scenario, foresight_level::makeClosedRoom(glm::dvec3(10, 4, 10)), error)) return false;
        throws(scene.scenario, "room_", [&](const std::string& id) {
            const RVec3 start(uniform(random, -3, 3), uniform(random, 1, 3), uniform(random, -3, 3));
            return makeThrow(id, start, uniform(random, 5, 15), radians(uniform(random, -30, 60)),
                             uniform(random, 0, 2 * kPi));
        });
        scenes.push_back(std::move(scene));
    }
    {
        BuiltinScene scene{"demo level",
                           "the courtyard of `foresight level` (3028 triangles: 30 m walls with a doorway, stairs to a "
                           "platform, a ramp, pillars, crates); throws from its open middle",
                           {}};
        if (!addLevelMesh(scene.scenario, foresight_level::makeDemoLevel(), error)) return false;
        throws(scene.scenario, "level_", [&](const std::string& id) {
            const RVec3 start(uniform(random, -4, 4), 1.5, uniform(random, -4, 4));
            return makeThrow(id, start, uniform(random, 6, 14), radians(uniform(random, 10, 50)),
                             uniform(random, 0, 2 * kPi));
        });
        scenes.push_back(std::move(scene));
    }
    return true;
}

/// Per scene and per side (stepped, exact, and the reference at 4x its frequency: its own error).
struct SideSummary {
    std::vector<double> landing;       // [m] per throw that landed on both sides
    std::vector<double> final;         // [m] per throw
    std::vector<double> bounceTime;    // [s] per throw with matching bounces: the largest difference
    std::size_t withinCentimetre = 0;  // throws within 1 cm of the reference at the fuse
    std::size_t sameBounces = 0;       // throws with as many bounces as the reference

    void add(const Errors& errors) {
        if (errors.landingDistance) landing.push_back(*errors.landingDistance);
        final.push_back(errors.finalDistance);
        if (errors.bounceTimeMax) bounceTime.push_back(*errors.bounceTimeMax);
        withinCentimetre += errors.finalDistance <= 0.01 ? 1 : 0;
        sameBounces += errors.bounces == errors.referenceBounces ? 1 : 0;
    }
};

std::optional<double> median(std::vector<double> values) {
    if (values.empty()) return std::nullopt;
    std::sort(values.begin(), values.end());
    const std::size_t middle = values.size() / 2;
    return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

/// "a / b / c" of the three sides.
template <class Format>
std::string triple(const SideSummary (&sides)[3], Format&& format) {
    return format(sides[0]) + " / " + format(sides[1]) + " / " + format(sides[2]);
}

int builtinCommand(const CompareOptions& options) {
    std::vector<BuiltinScene> scenes;
    std::string error;
    if (!builtinScenes(scenes, error)) {
        std::cerr << "foresight compare: cannot build the built-in scenes: " << error << '\n';
        return 1;
    }
    const bool showProgress = isatty(STDERR_FILENO) == 1;
    Json scenesJson = Json::array();
    char buffer[600];
    std::string text;
    text +=
        "| Scene | Throws | Landing error [mm] | Error at 3 s [mm] | Within 1 cm at 3 s | "
        "Bounce time error [ms] | Same bounce count |\n";
    text += "|---|---:|---:|---:|---:|---:|---:|\n";
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const BuiltinScene& scene = scenes[i];
        Diagnostics diagnostics;
        const auto comparisons =
            compareScenario(scene.scenario, options, diagnostics, [&](std::size_t done, std::size_t total) {
                if (showProgress)
                    std::fprintf(stderr, "\rcompare: scene %zu/%zu (%s), throw %zu/%zu   ", i + 1, scenes.size(),
                                 scene.name.c_str(), done, total);
            });
        if (!diagnostics.ok()) {
            if (showProgress) std::fprintf(stderr, "\n");
            std::cerr << "foresight compare: built-in scene \"" << scene.name << "\" failed:\n";
            printDiagnostics(diagnostics, std::cerr);
            return 1;
        }
        SideSummary sides[3];  // stepped, exact, Bullet's own
        for (const auto& c : comparisons) {
            sides[0].add(c.steppedErrors);
            sides[1].add(c.exactErrors);
            sides[2].add(c.fineErrors);
        }
        const auto count = [](std::size_t n) { return std::to_string(n); };
        std::snprintf(
            buffer, sizeof buffer, "| %s | %zu | %s | %s | %s | %s | %s |\n", scene.name.c_str(), comparisons.size(),
            triple(sides, [](const SideSummary& side) { return millimetres(median(side.landing)); }).c_str(),
            triple(sides, [](const SideSummary& side) { return millimetres(median(side.final)); }).c_str(),
            triple(sides, [&](const SideSummary& side) { return count(side.withinCentimetre); }).c_str(),
            triple(sides, [](const SideSummary& side) { return milliseconds(median(side.bounceTime)); }).c_str(),
            triple(sides, [&](const SideSummary& side) { return count(side.sameBounces); }).c_str());
        text += buffer;
        if (!options.jsonFile.empty()) {
            Json throwsJson = Json::array();
            for (const auto& c : comparisons) throwsJson.push_back(comparisonJson(c, options));
            Json sceneJson = Json::object();
            sceneJson["name"] = scene.name;
            sceneJson["description"] = scene.description;
            sceneJson["throws"] = std::move(throwsJson);
            scenesJson.push_back(std::move(sceneJson));
        }
    }
    if (showProgress) std::fprintf(stderr, "\r%60s\r", "");
    std::snprintf(
        buffer, sizeof buffer,
        "\nEach cell: stepped (the article's loop) / exact / Bullet's own error (the same simulation at %g Hz\n"
        "against %g Hz), medians over the throws. Landing: distance between the first impacts. At 3 s:\n"
        "distance between the positions when the fuse ends. Bounce time: per throw, the largest time\n"
        "difference between matching bounces (approach speed %.1f m/s or more). Every throw: restitution\n"
        "0.5, no friction, step 0.02 s, a sphere of %.2f m (the predictions cast the same sphere).\n\n",
        static_cast<double>(std::min(options.frequency * kFineFactor, 100000.0f)),
        static_cast<double>(options.frequency), kBounceSpeed, static_cast<double>(kPointRadius));
    text += buffer;
    for (const auto& scene : scenes) text += "- " + scene.name + ": " + scene.description + "\n";
    std::string reason;
    if (!options.jsonFile.empty()) {
        Json document = Json::object();
        document["frequency"] = jsonFloat(options.frequency);
        document["scenes"] = std::move(scenesJson);
        if (!writeTextFile(options.jsonFile, formatJson(document), reason)) {
            std::cerr << options.jsonFile << ": cannot write: " << reason << '\n';
            return 2;
        }
    }
    if (options.jsonFile != "-" && !writeTextFile("-", text, reason)) {
        std::cerr << "foresight compare: cannot write the table: " << reason << '\n';
        return 1;
    }
    return 0;
}

}  // namespace

int compareCommand(const std::string& file, const CompareOptions& options) {
    if (!(options.frequency >= 240.0f && options.frequency <= 100000.0f)) {
        std::cerr << "foresight compare: --frequency must be between 240 and 100000 Hz\n";
        return 2;
    }
    if (options.builtin) {
        if (!file.empty()) {
            std::cerr << "foresight compare: give either FILE or --builtin, not both\n";
            return 2;
        }
        return builtinCommand(options);
    }
    if (file.empty()) {
        std::cerr << "foresight compare: expected a scenario FILE (or --builtin)\n";
        return 2;
    }
    Diagnostics diagnostics;
    const std::string name = file == "-" ? std::string("<stdin>") : file;
    std::string text;
    std::string reason;
    if (!readTextFile(file, text, reason)) {
        std::cerr << name << ": cannot read: " << reason << '\n';
        return 2;
    }
    Json document;
    Scenario scenario;
    const std::filesystem::path baseDirectory =
        file == "-" ? std::filesystem::path() : std::filesystem::path(file).parent_path();
    if (!parseJsonText(text, name, document, diagnostics) ||
        !buildScenario(document, baseDirectory, scenario, diagnostics)) {
        printDiagnostics(diagnostics, std::cerr);
        return 2;
    }
    const bool showProgress = isatty(STDERR_FILENO) == 1;
    const auto comparisons = compareScenario(scenario, options, diagnostics, [&](std::size_t done, std::size_t total) {
        if (showProgress) std::fprintf(stderr, "\rcompare: projectile %zu/%zu   ", done, total);
    });
    if (showProgress) std::fprintf(stderr, "\r%40s\r", "");
    if (!diagnostics.ok()) {
        printDiagnostics(diagnostics, std::cerr);
        return 2;
    }
    if (comparisons.empty()) diagnostics.warning("predictions", "no projectile to compare");
    printDiagnostics(diagnostics, std::cerr);
    if (!options.jsonFile.empty()) {
        Json out = Json::object();
        out["frequency"] = jsonFloat(options.frequency);
        Json list = Json::array();
        for (const auto& c : comparisons) list.push_back(comparisonJson(c, options));
        out["projectiles"] = std::move(list);
        if (!writeTextFile(options.jsonFile, formatJson(out), reason)) {
            std::cerr << options.jsonFile << ": cannot write: " << reason << '\n';
            return 2;
        }
    }
    if (options.jsonFile != "-" && !writeTextFile("-", fileTable(comparisons, options), reason)) {
        std::cerr << "foresight compare: cannot write the table: " << reason << '\n';
        return 1;
    }
    return 0;
}

#endif

}  // namespace foresight_cli
