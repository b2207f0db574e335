#include "aim_command.h"

#include "json_input.h"
#include "json_output.h"

#include <array>
#include <cmath>
#include <iostream>
#include <vector>

namespace foresight_cli {

namespace {

using foresight::Status;

enum class Arc { Low, High, All };

struct Shot {
    std::string path;  ///< "shots[i]"
    Json id;           ///< echoed; null when absent
    foresight::AimShot shot;
    foresight::AimTarget target;
    Arc arc = Arc::Low;
};

void readTarget(const Json& value, const std::string& path, foresight::AimTarget& target, Diagnostics& d) {
    if (!expectObject(value, path, d, "{\"position\", \"velocity\", \"acceleration\"}")) return;
    Fields m(value, path, d);
    m.position("position", true, target.position);
    m.vector("velocity", false, target.velocity);
    m.vector("acceleration", false, target.acceleration);
    m.finish();
}

void readShot(const Json& item, const std::string& path, const foresight::Vec3& gravity, std::vector<Shot>& shots,
              Diagnostics& d) {
    if (!expectObject(item, path, d, "{\"from\", \"speed\", \"target\", ...}")) return;
    Shot s;
    s.path = path;
    s.shot.gravity = gravity;
    Fields m(item, path, d);
    m.id(s.id);
    m.position("from", true, s.shot.from);
    m.vector("gravity", false, s.shot.gravity);

    // The constraint: "speed" (the contract), or one of the extensions instead of it.
    const bool hasSpeed = item.contains("speed");
    const bool hasHorizontal = item.contains("horizontal_speed");
    const bool hasApex = item.contains("apex_height");
    const int constraints = int(hasSpeed) + int(hasHorizontal) + int(hasApex);
    if (constraints > 1) {
        d.error(path,
                "give one of \"speed\", \"horizontal_speed\" and \"apex_height\", not " + std::to_string(constraints));
    }
    auto nonNegative = [&](const char* key, float& value) {
        if (m.floatNumber(key, constraints == 0 && std::string(key) == "speed", value) && value < 0.0f) {
            d.error(m.at(key), "must be >= 0 (got " + shortNumber(static_cast<double>(value)) + ")");
        }
    };
    if (hasHorizontal) {
        s.shot.constraint = foresight::AimConstraint::HorizontalSpeed;
        nonNegative("horizontal_speed", s.shot.speed);
    } else if (hasApex) {
        s.shot.constraint = foresight::AimConstraint::ApexAboveStart;
        nonNegative("apex_height", s.shot.apexHeight);
    }
    if (hasSpeed || constraints == 0) {
        s.shot.constraint = foresight::AimConstraint::Speed;
        nonNegative("speed", s.shot.speed);
    } else {
        m.get("speed", false);
    }
    if (!hasHorizontal) m.get("horizontal_speed", false);
    if (!hasApex) m.get("apex_height", false);
    std::string apexAbove;
    if (m.string("apex_above", false, apexAbove)) {
        if (!hasApex) {
            d.error(m.at("apex_above"), "only with \"apex_height\"");
        } else if (apexAbove == "target") {
            s.shot.constraint = foresight::AimConstraint::ApexAboveTarget;
        } else if (apexAbove != "start") {
            d.error(m.at("apex_above"),
                    "unknown value " + jsonQuoted(apexAbove) + " (expected \"start\" or \"target\")");
        }
    }

    std::string arc;
    if (m.string("arc", false, arc)) {
        if (arc == "low") {
            s.arc = Arc::Low;
        } else if (arc == "high") {
            s.arc = Arc::High;
        } else if (arc == "all") {
            s.arc = Arc::All;
        } else {
            d.error(m.at("arc"), "unknown arc " + jsonQuoted(arc) + " (expected \"low\", \"high\" or \"all\")");
        }
    }
    m.time("max_time", false, s.shot.maxTime);
    if (const Json* target = m.get("target", true)) readTarget(*target, m.at("target"), s.target, d);
    m.finish();

    const bool apex = s.shot.constraint == foresight::AimConstraint::ApexAboveStart ||
                      s.shot.constraint == foresight::AimConstraint::ApexAboveTarget;
    if (apex && s.shot.gravity == foresight::Vec3(0.0f)) {
        d.error(m.at("apex_height"), "needs gravity (a straight shot has no apex)");
    }
    shots.push_back(std::move(s));
}

bool readDocument(const Json& document, std::vector<Shot>& shots, Diagnostics& d) {
    if (!expectObject(document, "", d, "{\"gravity\", \"shots\"}")) return false;
    Fields root(document, "", d);
    foresight::Vec3 gravity(0.0f, -9.81f, 0.0f);
    root.vector("gravity", false, gravity);
    if (const Json* list = root.get("shots", true)) {
        if (!list->is_array()) {
            d.error("shots", "expected an array, got " + typeName(*list));
        } else {
            for (std::size_t i = 0; i < list->size(); ++i) {
                readShot((*list)[i], "shots[" + std::to_string(i) + "]", gravity, shots, d);
            }
        }
    }
    root.finish();
    return d.ok();
}

bool finite(const foresight::FiringSolution& s) {
    return std::isfinite(s.time) && std::isfinite(s.elevation) && std::isfinite(s.velocity.x) &&
           std::isfinite(s.velocity.y) && std::isfinite(s.velocity.z) && std::isfinite(static_cast<double>(s.hit.x)) &&
           std::isfinite(static_cast<double>(s.hit.y)) && std::isfinite(static_cast<double>(s.hit.z));
}

Json solutionJson(const foresight::FiringSolution& s) {
    Json out = Json::object();
    out["velocity"] = jsonVector(s.velocity);
    out["time"] = jsonFloat(s.time);
    out["hit"] = jsonPosition(s.hit);
    out["elevation"] = jsonFloat(s.elevation);
    return out;
}

/// Solves every shot; library refusals become errors. Returns the output document.
bool runShots(const std::vector<Shot>& shots, Json& document, Diagnostics& d) {
    Json results = Json::array();
    for (const Shot& s : shots) {
        std::array<foresight::FiringSolution, foresight::kMaxFiringSolutions> storage{};
        std::size_t count = 0;
        Status status = foresight::aimProjectile(s.shot, s.target, storage, count);
        for (std::size_t i = 0; status == Status::Ok && i < count; ++i) {
            if (!finite(storage[i])) status = Status::NonFiniteResult;
        }
        if (status != Status::Ok) {
            d.error(s.path, foresight::statusMessage(status));
            continue;
        }
        // Sorted by time: low is the earliest, high the latest.
        std::size_t first = 0, last = count;
        if (count > 0 && s.arc == Arc::Low) last = 1;
        if (count > 0 && s.arc == Arc::High) first = count - 1;
        Json solutions = Json::array();
        for (std::size_t i = first; i < last; ++i) solutions.push_back(solutionJson(storage[i]));
        Json out = Json::object();
        if (!s.id.is_null()) out["id"] = s.id;
        out["solutions"] = std::move(solutions);
        results.push_back(std::move(out));
    }
    document = Json::object();
    document["shots"] = std::move(results);
    return d.ok();
}

}  // namespace

bool aimDocument(const Json& document, Json& output, Diagnostics& diagnostics) {
    std::vector<Shot> shots;
    return readDocument(document, shots, diagnostics) && runShots(shots, output, diagnostics);
}

int aimCommand(const std::string& file) {
    Diagnostics diagnostics;
    std::string name;
    Json input;
    Json output;
    const bool ok = readJsonFile(file, name, input, diagnostics) && aimDocument(input, output, diagnostics);
    printDiagnostics(diagnostics, std::cerr);
    if (!ok) return 2;
    return writeJsonResult(output);
}

}  // namespace foresight_cli
