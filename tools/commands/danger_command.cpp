#include "danger_command.h"

#include "json_input.h"
#include "picture.h"

#include <cmath>
#include <iostream>
#include <set>

namespace foresight_cli {

using foresight::Status;

namespace {

// The danger keys, removed from the prediction objects before the scenario's own validation
// (which would report them as unknown keys).
const std::set<std::string> kProjectileKeys = {"blast_radius", "contact_radius", "points"};
const std::set<std::string> kVehicleKeys = {"half_extents", "box_center", "characters"};

std::string member(const std::string& path, const std::string& key) { return path + "." + key; }

/// Calls `each(item, path)` for every element of `value`, which must be an array.
template <class Each>
void forEachItem(const Json& value, const std::string& path, Diagnostics& d, Each&& each) {
    if (!value.is_array()) {
        d.error(path, "expected an array, got " + typeName(value));
        return;
    }
    for (std::size_t i = 0; i < value.size(); ++i) each(value[i], path + "[" + std::to_string(i) + "]");
}

void readPoints(const Json& value, const std::string& path, Diagnostics& d, std::vector<DangerPoint>& out) {
    forEachItem(value, path, d, [&](const Json& item, const std::string& at) {
        if (!expectObject(item, at, d, "{\"position\", \"time\"}")) return;
        Fields f(item, at, d);
        DangerPoint point;
        point.hasTime = item.contains("time");
        const bool okPosition = f.position("position", true, point.position);
        const bool okTime = !point.hasTime || f.floatNumber("time", true, point.time);
        f.finish();
        if (okPosition && okTime) out.push_back(point);
    });
}

void readCharacters(const Json& value, const std::string& path, Diagnostics& d, DangerQuery& query) {
    forEachItem(value, path, d, [&](const Json& item, const std::string& at) {
        if (!expectObject(item, at, d, "{\"position\", \"velocity\", \"radius\", ...}")) return;
        Fields f(item, at, d);
        const std::size_t errorsBefore = d.errors.size();
        foresight::CharacterBody character;
        Json id;
        f.id(id);
        f.position("position", true, character.position);
        f.vector("velocity", true, character.velocity);
        f.vector("acceleration", false, character.acceleration);
        f.positive("radius", true, false, character.radius);
        f.vector("half_axis", false, character.halfAxis);
        f.finish();
        if (d.errors.size() != errorsBefore) return;
        query.characters.push_back(character);
        query.characterIds.push_back(id);
    });
}

/// Reads (and removes from `prediction`) the danger keys of one prediction.
void readDangerKeys(Json& prediction, const std::string& path, DangerQuery& query, Diagnostics& d) {
    const Json* model = prediction.contains("model") ? &prediction["model"] : nullptr;
    const std::string name = model != nullptr && model->is_string() ? model->get<std::string>() : std::string();
    if (name != "projectile" && name != "vehicle") {
        // The scenario's validation names a missing or unknown model.
        if (name == "linear" || name == "accelerated" || name == "orientation")
            d.error(member(path, "model"),
                    "foresight danger takes projectile and vehicle predictions (got \"" + name + "\")");
        return;
    }
    const bool projectile = name == "projectile";
    Json extracted = Json::object();
    for (const auto& key : projectile ? kProjectileKeys : kVehicleKeys) {
        if (const auto found = prediction.find(key); found != prediction.end()) {
            extracted[key] = *found;
            prediction.erase(key);
        }
    }
    // Only the danger keys are read here (every one is known: the rest is the scenario's).
    Fields keys(extracted, path, d);
    if (projectile) {
        keys.positive("blast_radius", true, false, query.blastRadius);
        keys.positive("contact_radius", false, false, query.contactRadius);
        if (const Json* points = keys.get("points", false)) readPoints(*points, keys.at("points"), d, query.points);
        return;
    }
    if (keys.vector("half_extents", false, query.halfExtents) &&
        !(query.halfExtents.x > 0.0f && query.halfExtents.y > 0.0f && query.halfExtents.z > 0.0f)) {
        d.error(keys.at("half_extents"),
                std::string(foresight::statusMessage(Status::DegenerateShape)) + ": each half extent must be > 0");
    }
    keys.vector("box_center", false, query.boxCenter);
    if (const Json* characters = keys.get("characters", false))
        readCharacters(*characters, keys.at("characters"), d, query);
    if (const auto method = prediction.find("method");
        method != prediction.end() && method->is_string() && method->get<std::string>() == "iterative") {
        d.error(member(path, "method"), "foresight danger follows the exact path (use \"exact\" or leave it out)");
    }
}

Json approachJson(const foresight::ClosestApproach& approach) {
    Json out = Json::object();
    out["distance"] = jsonFloat(approach.distance);
    out["time"] = jsonFloat(approach.time);
    return out;
}

bool finite(const foresight::RVec3& v) {
    return std::isfinite(static_cast<double>(v.x)) && std::isfinite(static_cast<double>(v.y)) &&
           std::isfinite(static_cast<double>(v.z));
}

foresight::ProjectileDanger projectileDanger(const Prediction& p, const DangerQuery& query,
                                             const PredictionResult& result) {
    foresight::ProjectileDanger danger;
    danger.trajectory = result.trajectory;
    danger.fuseTime = p.time;
    danger.blastRadius = query.blastRadius;
    danger.contactRadius = query.contactRadius;
    return danger;
}

}  // namespace

bool buildDangerInput(const Json& document, const std::filesystem::path& baseDirectory, DangerInput& input,
                      Diagnostics& diagnostics) {
    if (!document.is_object()) {
        diagnostics.error("", "expected a JSON object {\"predictions\": [...]}, got " + typeName(document));
        return false;
    }
    Json scenarioDocument = document;
    if (const auto tolerance = scenarioDocument.find("tolerance"); tolerance != scenarioDocument.end()) {
        float value = 0;
        if (toFloat(*tolerance, "tolerance", diagnostics, value)) {
            if (value > 0.0f)
                input.approach.tolerance = value;
            else
                diagnostics.error("tolerance", "expected a number > 0 [m]");
        }
        scenarioDocument.erase("tolerance");
    }
    std::vector<DangerQuery> queries;
    if (const auto predictions = scenarioDocument.find("predictions");
        predictions != scenarioDocument.end() && predictions->is_array()) {
        for (std::size_t i = 0; i < predictions->size(); ++i) {
            Json& prediction = (*predictions)[i];
            DangerQuery query;
            query.prediction = i;
            if (prediction.is_object())
                readDangerKeys(prediction, "predictions[" + std::to_string(i) + "]", query, diagnostics);
            queries.push_back(std::move(query));
        }
    }
    input.scenario.recordTrajectories = true;  // the queries need every projectile's trajectory
    const bool scenarioOk = buildScenario(scenarioDocument, baseDirectory, input.scenario, diagnostics);
    input.queries = std::move(queries);
    return scenarioOk && diagnostics.ok();
}

bool runDanger(const DangerInput& input, Json& output, Diagnostics& diagnostics, std::vector<PredictionResult>* kept) {
    std::vector<PredictionResult> own;
    std::vector<PredictionResult>& results = kept ? *kept : own;
    if (!runScenario(input.scenario, results, diagnostics)) return false;
    Json predictions = Json::array();
    for (std::size_t i = 0; i < input.scenario.predictions.size(); ++i) {
        const Prediction& p = input.scenario.predictions[i];
        const DangerQuery& query = input.queries[i];
        Json entry = Json::object();
        if (!p.id.is_null()) entry["id"] = p.id;
        entry["model"] = modelName(p.model);
        if (p.model == Model::Projectile) {
            const foresight::ProjectileDanger danger = projectileDanger(p, query, results[i]);
            foresight::DangerZone zone;
            Status status = foresight::computeDangerZone(danger, zone);
            if (status != Status::Ok) {
                diagnostics.error(p.path, foresight::statusMessage(status));
                continue;
            }
            Json zoneJson = Json::object();
            zoneJson["center"] = jsonPosition(zone.center);
            zoneJson["radius"] = jsonFloat(zone.radius);
            zoneJson["time"] = jsonFloat(zone.time);
            entry["danger_zone"] = std::move(zoneJson);
            if (query.contactRadius > 0.0f) entry["contact_radius"] = jsonFloat(query.contactRadius);
            Json points = Json::array();
            for (std::size_t k = 0; k < query.points.size(); ++k) {
                const DangerPoint& point = query.points[k];
                const std::string path = p.path + ".points[" + std::to_string(k) + "]";
                foresight::DangerStart start;
                foresight::ClosestApproach closest;
                bool safe = true;
                status = foresight::findDangerStart(danger, point.position, start);
                if (status == Status::Ok)
                    status = foresight::findClosestPathApproach(danger.trajectory, point.position,
                                                                danger.trajectory.front().time, p.time, closest);
                if (status == Status::Ok && point.hasTime)
                    status = foresight::isPointSafe(danger, point.position, point.time, safe);
                if (status != Status::Ok) {
                    diagnostics.error(path, foresight::statusMessage(status));
                    continue;
                }
                Json out = Json::object();
                out["position"] = jsonPosition(point.position);
                out["danger_start"] = start.ever ? jsonFloat(start.time) : Json(nullptr);
                out["closest_approach"] = approachJson(closest);
                if (point.hasTime) {
                    out["time"] = jsonFloat(point.time);
                    out["safe"] = safe;
                }
                points.push_back(std::move(out));
            }
            entry["points"] = std::move(points);
        } else {
            foresight::VehicleBody vehicle;
            vehicle.state.position = p.position;
            vehicle.state.velocity = p.velocity;
            vehicle.state.orientation = p.orientation;
            vehicle.state.angularVelocity = p.angularVelocity;
            vehicle.settings.frame = p.frame;
            vehicle.halfExtents = query.halfExtents;
            vehicle.boxCenter = query.boxCenter;
            entry["half_extents"] = jsonVector(query.halfExtents);
            Json characters = Json::array();
            for (std::size_t k = 0; k < query.characters.size(); ++k) {
                const std::string path = p.path + ".characters[" + std::to_string(k) + "]";
                foresight::VehicleContact contact;
                foresight::ClosestApproach closest;
                Status status =
                    foresight::findVehicleContact(vehicle, query.characters[k], p.time, input.approach, contact);
                if (status == Status::Ok)
                    status = foresight::findClosestVehicleApproach(vehicle, query.characters[k], p.time, input.approach,
                                                                   closest);
                if (status == Status::TooManySteps) {
                    // The work grows with horizon / tolerance (and with long grazing passes): the
                    // usual cause is the prediction's "time", so the message is about it.
                    diagnostics.error(p.path + ".time",
                                      "the horizon " + shortNumber(static_cast<double>(p.time)) +
                                          " s is too long for \"tolerance\" " +
                                          shortNumber(static_cast<double>(input.approach.tolerance)) +
                                          " m: characters[" + std::to_string(k) + "] needs more than " +
                                          std::to_string(input.approach.maxEvaluations) +
                                          " separation evaluations (the work cap; it grows with time / "
                                          "tolerance, and with a long grazing pass): shorten \"time\" or "
                                          "raise \"tolerance\"");
                    continue;
                }
                if (status != Status::Ok) {
                    diagnostics.error(path, foresight::statusMessage(status));
                    continue;
                }
                Json out = Json::object();
                if (!query.characterIds[k].is_null()) out["id"] = query.characterIds[k];
                out["contact"] = contact.contact;
                if (contact.contact) out["contact_time"] = jsonFloat(contact.time);
                out["closest_approach"] = approachJson(closest);
                characters.push_back(std::move(out));
            }
            entry["characters"] = std::move(characters);
        }
        predictions.push_back(std::move(entry));
    }
    if (!diagnostics.ok()) return false;
    output = Json::object();
    output["tolerance"] = jsonFloat(input.approach.tolerance);
    output["predictions"] = std::move(predictions);
    return true;
}

Json dangerZonesJson(const DangerInput& input, const std::vector<PredictionResult>& results) {
    Json zones = Json::array();
    for (std::size_t i = 0; i < input.scenario.predictions.size() && i < results.size() && i < input.queries.size();
         ++i) {
        const Prediction& p = input.scenario.predictions[i];
        if (p.model != Model::Projectile || results[i].trajectory.empty()) continue;
        foresight::DangerZone zone;
        if (foresight::computeDangerZone(projectileDanger(p, input.queries[i], results[i]), zone) != Status::Ok ||
            !finite(zone.center))
            continue;
        Json entry = Json::object();
        entry["id"] = p.id.is_null() ? Json(p.path) : p.id;
        entry["center"] = jsonPosition(zone.center);
        entry["radius"] = jsonFloat(zone.radius);
        entry["time"] = jsonFloat(zone.time);
        zones.push_back(std::move(entry));
    }
    return zones;
}

int dangerCommand(const std::string& file, const PictureOptions& pictures) {
    if (!pictures.htmlFile.empty() && !viewerAvailable()) {
        std::cerr << "foresight danger: --html: " << viewerUnavailableReason() << '\n';
        return 2;
    }
    Diagnostics diagnostics;
    std::string name;
    Json document;
    DangerInput input;
    Json output;
    std::vector<PredictionResult> results;
    const bool ok = readJsonFile(file, name, document, diagnostics) &&
                    buildDangerInput(document, baseDirectoryOf(file), input, diagnostics) &&
                    runDanger(input, output, diagnostics, &results);
    printDiagnostics(diagnostics, std::cerr);
    if (!ok) return 2;
    if (pictures.wanted()) {
        Json picture = pictureDocument(input.scenario, results, "foresight danger: " + name);
        picture["danger_zones"] = dangerZonesJson(input, results);
        std::string error;
        if (!writePictures(pictures, picture, "foresight danger: " + name, error)) {
            std::cerr << error << '\n';
            return 2;
        }
    }
    return writeJsonResult(output);
}

}  // namespace foresight_cli
