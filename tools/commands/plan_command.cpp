#include "plan_command.h"

#include "json_input.h"

#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>

namespace foresight_cli {

using foresight::Status;

namespace {

/// A projectile setting checked alone by the library's validator (as `predict` does).
template <class Set>
void checkSetting(Fields& m, const char* key, Set&& set) {
    foresight::ProjectileSettings probe;
    set(probe);
    const Status status = foresight::validateProjectileSettings(probe);
    if (status != Status::Ok) m.diagnostics().error(m.at(key), foresight::statusMessage(status));
}

void readThrow(const Json& item, const std::string& path, const foresight::Vec3& gravity,
               std::vector<ThrowRequest>& throws, Diagnostics& d) {
    if (!item.is_object()) {
        d.error(path,
                "expected an object {\"start\", \"target\", \"fuse\", \"max_speed\", ...}, got " + typeName(item));
        return;
    }
    const std::size_t errorsBefore = d.errors.size();
    Fields m(item, path, d);
    ThrowRequest t;
    t.path = path;
    foresight::ThrowPlanRequest& r = t.request;
    r.settings.gravity = gravity;
    m.id(t.id);
    m.position("start", true, r.start);
    m.position("target", true, r.target);
    m.positive("fuse", true, true, r.fuseTime);
    m.positive("max_speed", true, true, r.maxSpeed);
    const bool okMin = m.positive("min_speed", false, false, r.minSpeed);
    if (okMin && r.maxSpeed > 0.0f && r.minSpeed > r.maxSpeed) {
        d.error(m.at("min_speed"), "must be <= max_speed (got " + shortNumber(static_cast<double>(r.minSpeed)) + " > " +
                                       shortNumber(static_cast<double>(r.maxSpeed)) + ")");
    }
    m.positive("acceptance_radius", false, true, r.acceptanceRadius);
    m.integer("plans", false, 1u, 32u, r.maxPlans);

    std::string method;
    if (m.string("method", false, method)) {
        if (method == "exact") {
            r.settings.method = foresight::ProjectileMethod::Exact;
        } else if (method == "stepped") {
            r.settings.method = foresight::ProjectileMethod::Stepped;
        } else {
            d.error(m.at("method"), "unknown method " + jsonQuoted(method) + " (expected \"exact\" or \"stepped\")");
        }
    }
    auto& s = r.settings;
    if (m.floatNumber("step", false, s.step)) checkSetting(m, "step", [&](auto& p) { p.step = s.step; });
    if (m.floatNumber("restitution", false, s.restitution))
        checkSetting(m, "restitution", [&](auto& p) { p.restitution = s.restitution; });
    if (m.floatNumber("friction", false, s.friction))
        checkSetting(m, "friction", [&](auto& p) { p.friction = s.friction; });
    if (m.floatNumber("radius", false, s.radius)) checkSetting(m, "radius", [&](auto& p) { p.radius = s.radius; });
    m.integer("max_predictions", false, 1u, 100000u, r.budget.maxPredictions);
    m.boolean("trajectory", false, t.trajectory);
    m.finish();
    if (d.errors.size() != errorsBefore) return;
    // What the fields above cannot see alone (the work cap of fuse / step).
    const Status status = foresight::validateThrowPlanRequest(r);
    const std::uint64_t steps = foresight::steppedStepCount(r.fuseTime, s.step);
    if (status == Status::TooManySteps && steps <= s.maxSteps) {
        // One prediction fits, but the whole search (max_predictions of them) is over the cap.
        d.error(m.at("fuse"), "too much work for one plan: " + shortNumber(static_cast<double>(r.fuseTime)) +
                                  " s at a step of " + shortNumber(static_cast<double>(s.step)) + " s is " +
                                  std::to_string(steps) + " steps per prediction, times max_predictions " +
                                  std::to_string(r.budget.maxPredictions) + " = " +
                                  std::to_string(foresight::throwPlanWork(r)) + " steps, over the cap of " +
                                  std::to_string(r.budget.maxTotalSteps) +
                                  ": shorten \"fuse\", lengthen \"step\" or lower \"max_predictions\"");
        return;
    }
    if (status != Status::Ok) {
        std::string message = foresight::statusMessage(status);
        if (status == Status::TooManySteps)
            message += ": fuse / step = " + shortNumber(static_cast<double>(r.fuseTime) / static_cast<double>(s.step)) +
                       " steps, the cap is " + std::to_string(s.maxSteps);
        d.error(path, message);
        return;
    }
    throws.push_back(std::move(t));
}

const foresight::CollisionWorld* collisionWorld(const Scenario& world) {
    if (world.meshWorld) return world.meshWorld.get();
    return world.world.shapeCount() > 0 ? &world.world : nullptr;
}

}  // namespace

bool buildPlanDocument(const Json& document, const std::filesystem::path& baseDirectory, Scenario& world,
                       std::vector<ThrowRequest>& throws, Diagnostics& diagnostics) {
    if (!document.is_object()) {
        diagnostics.error("", "expected a JSON object {\"world\": ..., \"throws\": [...]}, got " + typeName(document));
        return false;
    }
    // The world and gravity exactly as a scenario's (same messages and paths), through a
    // scenario without predictions.
    Json scenario = Json::object();
    for (const char* key : {"gravity", "world"})
        if (document.contains(key)) scenario[key] = document.at(key);
    scenario["predictions"] = Json::array();
    buildScenario(scenario, baseDirectory, world, diagnostics);

    for (const auto& [key, value] : document.items()) {
        (void)value;
        if (key != "gravity" && key != "world" && key != "throws")
            diagnostics.error(key, key == "predictions" ? "unknown key (a plan document has \"throws\"; "
                                                          "predictions belong to `foresight predict`)"
                                                        : "unknown key");
    }
    const auto found = document.find("throws");
    if (found == document.end()) {
        diagnostics.error("throws", "missing required field");
    } else if (!found->is_array()) {
        diagnostics.error("throws", "expected an array, got " + typeName(*found));
    } else {
        for (std::size_t i = 0; i < found->size(); ++i)
            readThrow((*found)[i], "throws[" + std::to_string(i) + "]", world.gravity, throws, diagnostics);
        // The whole file's budget: each search is capped, and so is their sum.
        const std::uint64_t work = planFileWork(throws);
        if (diagnostics.ok() && work > kMaxPlanFileSteps)
            diagnostics.error("throws", "the plans take up to " + std::to_string(work) +
                                            " steps in all; one file may take at most " +
                                            std::to_string(kMaxPlanFileSteps) + " (split the file)");
    }
    return diagnostics.ok();
}

std::uint64_t planFileWork(const std::vector<ThrowRequest>& throws) {
    std::uint64_t work = 0;
    for (const ThrowRequest& t : throws) {
        const foresight::ThrowPlanRequest& r = t.request;
        work += foresight::throwPlanWork(r);
        if (t.trajectory) work += std::uint64_t{r.maxPlans} * foresight::steppedStepCount(r.fuseTime, r.settings.step);
    }
    return work;
}

bool runPlans(const Scenario& world, const std::vector<ThrowRequest>& throws, std::vector<ThrowOutcome>& outcomes,
              Diagnostics& diagnostics) {
    const foresight::CollisionWorld* cast = collisionWorld(world);
    outcomes.assign(throws.size(), ThrowOutcome());
    for (std::size_t i = 0; i < throws.size(); ++i) {
        const foresight::ThrowPlanRequest& r = throws[i].request;
        ThrowOutcome& outcome = outcomes[i];
        outcome.plans.resize(r.maxPlans);
        std::vector<foresight::TrajectoryPoint> scratch(foresight::throwPlanScratchSize(r));
        Status status = foresight::planThrow(r, cast, outcome.plans, scratch, outcome.result);
        if (status == Status::Ok) {
            outcome.plans.resize(outcome.result.planCount);
            if (throws[i].trajectory) {
                for (const foresight::ThrowPlan& plan : outcome.plans) {
                    std::vector<foresight::TrajectoryPoint> points(
                        foresight::trajectoryCapacity(r.fuseTime, r.settings, plan.bounces + 8));
                    foresight::ProjectileResult flown;
                    status = foresight::predictThrowPlan(r, plan, cast, points, flown);
                    if (status == Status::Ok && flown.trajectoryNeeded > points.size()) {
                        points.resize(flown.trajectoryNeeded);
                        status = foresight::predictThrowPlan(r, plan, cast, points, flown);
                    }
                    if (status != Status::Ok) break;
                    points.resize(std::min(flown.trajectorySize, points.size()));
                    outcome.trajectories.push_back(std::move(points));
                }
            }
        }
        if (status != Status::Ok) diagnostics.error(throws[i].path, foresight::statusMessage(status));
    }
    return diagnostics.ok();
}

Json planResultDocument(const std::vector<ThrowRequest>& throws, const std::vector<ThrowOutcome>& outcomes) {
    Json list = Json::array();
    for (std::size_t i = 0; i < throws.size() && i < outcomes.size(); ++i) {
        const ThrowOutcome& o = outcomes[i];
        Json entry = Json::object();
        if (!throws[i].id.is_null()) entry["id"] = throws[i].id;
        Json plans = Json::array();
        for (std::size_t k = 0; k < o.plans.size(); ++k) {
            const foresight::ThrowPlan& plan = o.plans[k];
            Json p = Json::object();
            p["velocity"] = jsonVector(plan.launchVelocity);
            p["speed"] = jsonFloat(glm::length(plan.launchVelocity));
            p["position"] = jsonPosition(plan.finalPosition);
            p["distance"] = jsonFloat(plan.distance);
            p["bounces"] = plan.bounces;
            p["at_rest"] = plan.atRest;
            if (plan.firstImpactTime >= 0.0f) {
                Json impact = Json::object();
                impact["t"] = jsonFloat(plan.firstImpactTime);
                impact["position"] = jsonPosition(plan.firstImpactPosition);
                impact["normal"] = jsonVector(plan.firstImpactNormal);
                p["first_impact"] = std::move(impact);
            }
            if (k < o.trajectories.size()) {
                Json points = Json::array();
                for (const auto& point : o.trajectories[k]) {
                    Json q = Json::object();
                    q["t"] = jsonFloat(point.time);
                    q["position"] = jsonPosition(point.position);
                    q["velocity"] = jsonVector(point.velocity);
                    q["event"] = eventName(point.event);
                    const bool impact = point.event == foresight::TrajectoryEvent::Bounce ||
                                        point.event == foresight::TrajectoryEvent::Hit;
                    if (impact || point.normal != foresight::Vec3(0.0f)) q["normal"] = jsonVector(point.normal);
                    points.push_back(std::move(q));
                }
                p["trajectory"] = std::move(points);
            }
            plans.push_back(std::move(p));
        }
        entry["plans"] = std::move(plans);
        entry["predictions"] = o.result.predictions;
        // FLT_MAX: no throw finished, or none ended within a float's range of the target.
        const bool approached = o.result.closestDistance < std::numeric_limits<float>::max();
        entry["closest_distance"] = approached ? jsonFloat(o.result.closestDistance) : Json(nullptr);
        entry["closest_velocity"] = approached ? jsonVector(o.result.closestVelocity) : Json(nullptr);
        list.push_back(std::move(entry));
    }
    Json document = Json::object();
    document["throws"] = std::move(list);
    return document;
}

int planCommand(const std::string& file) {
    Diagnostics diagnostics;
    std::string name;
    Json document;
    Scenario world;
    std::vector<ThrowRequest> throws;
    std::vector<ThrowOutcome> outcomes;
    const bool ok = readJsonFile(file, name, document, diagnostics) &&
                    buildPlanDocument(document, baseDirectoryOf(file), world, throws, diagnostics) &&
                    runPlans(world, throws, outcomes, diagnostics);
    printDiagnostics(diagnostics, std::cerr);
    if (!ok) return 2;
    return writeJsonResult(planResultDocument(throws, outcomes));
}

}  // namespace foresight_cli
