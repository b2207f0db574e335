#include "danger.h"

#include "text_file.h"

#include <cfloat>
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

std::string typeName(const Json& value) {
    if (value.is_number()) return "a number";
    if (value.is_string()) return "a string";
    if (value.is_boolean()) return "a boolean";
    if (value.is_null()) return "null";
    if (value.is_array()) return "an array";
    return "an object";
}

std::string member(const std::string& path, const std::string& key) { return path + "." + key; }

// Readers in the scenario format's words: each reports a problem at `path` and returns false.

bool readFloat(const Json& value, const std::string& path, Diagnostics& d, float& out) {
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
        d.error(path, "expected a finite number, got " + typeName(value));
        return false;
    }
    const double number = value.get<double>();
    if (std::fabs(number) > static_cast<double>(FLT_MAX)) {
        d.error(path, "expected a finite number (beyond the float range, |x| <= 3.4028235e38)");
        return false;
    }
    out = static_cast<float>(number);
    return true;
}

bool readTriple(const Json& value, const std::string& path, Diagnostics& d, double (&out)[3], bool floatRange) {
    bool ok = value.is_array() && value.size() == 3;
    for (std::size_t i = 0; ok && i < 3; ++i) {
        ok = value[i].is_number() && std::isfinite(value[i].get<double>()) &&
             (!floatRange || std::fabs(value[i].get<double>()) <= static_cast<double>(FLT_MAX));
        if (ok) out[i] = value[i].get<double>();
    }
    if (!ok) d.error(path, "expected 3 finite numbers");
    return ok;
}

bool readVector(const Json& value, const std::string& path, Diagnostics& d, foresight::Vec3& out) {
    double v[3] = {0, 0, 0};
    if (!readTriple(value, path, d, v, true)) return false;
    out = foresight::Vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
    return true;
}

bool readPosition(const Json& value, const std::string& path, Diagnostics& d, foresight::RVec3& out) {
    double v[3] = {0, 0, 0};
    if (!readTriple(value, path, d, v, !foresight::kDoublePrecision)) return false;
    using R = foresight::Real;
    out = foresight::RVec3(static_cast<R>(v[0]), static_cast<R>(v[1]), static_cast<R>(v[2]));
    return true;
}

bool readNonNegative(const Json& value, const std::string& path, Diagnostics& d, float& out, const char* what) {
    if (!readFloat(value, path, d, out)) return false;
    if (out < 0.0f) {
        d.error(path, std::string(what) + " must be >= 0");
        return false;
    }
    return true;
}

/// Reports the members of `object` not in `known` (with the object's path).
void reportUnknownKeys(const Json& object, const std::string& path, const std::set<std::string>& known, Diagnostics& d) {
    for (const auto& [key, value] : object.items()) {
        (void)value;
        if (known.count(key) == 0) d.error(member(path, key), "unknown key");
    }
}

void readPoints(const Json& value, const std::string& path, Diagnostics& d, std::vector<DangerPoint>& out) {
    if (!value.is_array()) {
        d.error(path, "expected an array, got " + typeName(value));
        return;
    }
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string at = path + "[" + std::to_string(i) + "]";
        const Json& item = value[i];
        if (!item.is_object()) {
            d.error(at, "expected an object {\"position\", \"time\"}, got " + typeName(item));
            continue;
        }
        reportUnknownKeys(item, at, {"position", "time"}, d);
        DangerPoint point;
        bool ok = true;
        if (const auto found = item.find("position"); found == item.end()) {
            d.error(member(at, "position"), "missing required field");
            ok = false;
        } else {
            ok = readPosition(*found, member(at, "position"), d, point.position) && ok;
        }
        if (const auto found = item.find("time"); found != item.end()) {
            point.hasTime = true;
            ok = readFloat(*found, member(at, "time"), d, point.time) && ok;
        }
        if (ok) out.push_back(point);
    }
}

void readCharacters(const Json& value, const std::string& path, Diagnostics& d, DangerQuery& query) {
    if (!value.is_array()) {
        d.error(path, "expected an array, got " + typeName(value));
        return;
    }
    for (std::size_t i = 0; i < value.size(); ++i) {
        const std::string at = path + "[" + std::to_string(i) + "]";
        const Json& item = value[i];
        if (!item.is_object()) {
            d.error(at, "expected an object {\"position\", \"velocity\", \"radius\", ...}, got " + typeName(item));
            continue;
        }
        reportUnknownKeys(item, at, {"id", "position", "velocity", "acceleration", "radius", "half_axis"}, d);
        foresight::CharacterBody character;
        Json id;
        bool ok = true;
        auto required = [&](const char* key) -> const Json* {
            const auto found = item.find(key);
            if (found == item.end()) {
                d.error(member(at, key), "missing required field");
                ok = false;
                return nullptr;
            }
            return &*found;
        };
        auto optional = [&](const char* key) -> const Json* {
            const auto found = item.find(key);
            return found == item.end() ? nullptr : &*found;
        };
        if (const Json* v = optional("id")) {
            if (v->is_string() || v->is_number_integer()) {
                id = *v;
            } else {
                d.error(member(at, "id"), "expected a string or an integer, got " + typeName(*v));
                ok = false;
            }
        }
        if (const Json* v = required("position")) ok = readPosition(*v, member(at, "position"), d, character.position) && ok;
        if (const Json* v = required("velocity")) ok = readVector(*v, member(at, "velocity"), d, character.velocity) && ok;
        if (const Json* v = optional("acceleration"))
            ok = readVector(*v, member(at, "acceleration"), d, character.acceleration) && ok;
        if (const Json* v = required("radius"))
            ok = readNonNegative(*v, member(at, "radius"), d, character.radius, "a radius") && ok;
        if (const Json* v = optional("half_axis")) ok = readVector(*v, member(at, "half_axis"), d, character.halfAxis) && ok;
        if (ok) {
            query.characters.push_back(character);
            query.characterIds.push_back(id);
        }
    }
}

/// Reads (and removes from `prediction`) the danger keys of one prediction.
void readDangerKeys(Json& prediction, const std::string& path, DangerQuery& query, Diagnostics& d) {
    const Json* model = prediction.contains("model") ? &prediction["model"] : nullptr;
    const std::string name = model != nullptr && model->is_string() ? model->get<std::string>() : std::string();
    if (name != "projectile" && name != "vehicle") {
        // The scenario's validation names a missing or unknown model.
        if (name == "linear" || name == "accelerated" || name == "orientation")
            d.error(member(path, "model"), "foresight danger takes projectile and vehicle predictions (got \"" + name + "\")");
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
    if (projectile) {
        if (!extracted.contains("blast_radius")) {
            d.error(member(path, "blast_radius"), "missing required field");
        } else {
            readNonNegative(extracted["blast_radius"], member(path, "blast_radius"), d, query.blastRadius, "a blast radius");
        }
        if (extracted.contains("contact_radius"))
            readNonNegative(extracted["contact_radius"], member(path, "contact_radius"), d, query.contactRadius,
                            "a contact radius");
        if (extracted.contains("points")) readPoints(extracted["points"], member(path, "points"), d, query.points);
        return;
    }
    if (extracted.contains("half_extents") &&
        readVector(extracted["half_extents"], member(path, "half_extents"), d, query.halfExtents) &&
        !(query.halfExtents.x > 0.0f && query.halfExtents.y > 0.0f && query.halfExtents.z > 0.0f)) {
        d.error(member(path, "half_extents"), std::string(foresight::statusMessage(Status::DegenerateShape)) +
                                                  ": each half extent must be > 0");
    }
    if (extracted.contains("box_center")) readVector(extracted["box_center"], member(path, "box_center"), d, query.boxCenter);
    if (extracted.contains("characters")) readCharacters(extracted["characters"], member(path, "characters"), d, query);
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

} // namespace

bool buildDangerInput(const Json& document, const std::filesystem::path& baseDirectory, DangerInput& input,
                      Diagnostics& diagnostics) {
    if (!document.is_object()) {
        diagnostics.error("", "expected a JSON object {\"predictions\": [...]}, got " + typeName(document));
        return false;
    }
    Json scenarioDocument = document;
    if (const auto tolerance = scenarioDocument.find("tolerance"); tolerance != scenarioDocument.end()) {
        float value = 0;
        if (readFloat(*tolerance, "tolerance", diagnostics, value)) {
            if (value > 0.0f) input.approach.tolerance = value;
            else diagnostics.error("tolerance", "expected a number > 0 [m]");
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
            if (prediction.is_object()) readDangerKeys(prediction, "predictions[" + std::to_string(i) + "]", query, diagnostics);
            queries.push_back(std::move(query));
        }
    }
    input.scenario.recordTrajectories = true;  // the queries need every projectile's trajectory
    const bool scenarioOk = buildScenario(scenarioDocument, baseDirectory, input.scenario, diagnostics);
    input.queries = std::move(queries);
    return scenarioOk && diagnostics.ok();
}

bool runDanger(const DangerInput& input, Json& output, Diagnostics& diagnostics,
               std::vector<PredictionResult>* kept) {
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
                Status status = foresight::findVehicleContact(vehicle, query.characters[k], p.time, input.approach, contact);
                if (status == Status::Ok)
                    status = foresight::findClosestVehicleApproach(vehicle, query.characters[k], p.time, input.approach,
                                                                   closest);
                if (status != Status::Ok) {
                    std::string message = foresight::statusMessage(status);
                    if (status == Status::TooManySteps)
                        message += ": more than " + std::to_string(input.approach.maxEvaluations) +
                                   " evaluations (a long grazing pass: raise \"tolerance\")";
                    diagnostics.error(path, message);
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
    for (std::size_t i = 0; i < input.scenario.predictions.size() && i < results.size() && i < input.queries.size(); ++i) {
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
    const std::string name = file == "-" ? std::string("<stdin>") : file;
    std::string text;
    std::string reason;
    if (!readTextFile(file, text, reason)) {
        std::cerr << name << ": cannot read: " << reason << '\n';
        return 2;
    }
    Json document;
    DangerInput input;
    Json output;
    const std::filesystem::path baseDirectory =
        file == "-" ? std::filesystem::path() : std::filesystem::path(file).parent_path();
    std::vector<PredictionResult> results;
    const bool ok = parseJsonText(text, name, document, diagnostics) &&
                    buildDangerInput(document, baseDirectory, input, diagnostics) &&
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
    if (!writeTextFile("-", formatJson(output), reason)) {
        std::cerr << "foresight: cannot write the result: " << reason << '\n';
        return 1;
    }
    return 0;
}

} // namespace foresight_cli
