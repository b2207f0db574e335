#include "aim.h"

#include "json_output.h"
#include "scenario.h"  // Diagnostics, parseJsonText, printDiagnostics
#include "text_file.h"

#include <array>
#include <cfloat>
#include <cmath>
#include <iostream>
#include <set>
#include <vector>

namespace foresight_cli {

namespace {

using foresight::Status;

std::string typeName(const Json& value) {
    if (value.is_number()) return "a number";
    if (value.is_string()) return "a string";
    if (value.is_boolean()) return "a boolean";
    if (value.is_null()) return "null";
    if (value.is_array()) return "an array";
    return "an object";
}

/// Members of one JSON object, read by key; members never asked for are unknown keys. (The
/// same rules as the scenario reader's, for the few kinds of values this format has.)
class Members {
public:
    Members(const Json& object, std::string path, Diagnostics& d) : mObject(object), mPath(std::move(path)), mD(d) {}

    std::string at(const std::string& key) const { return mPath.empty() ? key : mPath + "." + key; }

    const Json* get(const char* key, bool required) {
        mKnown.insert(key);
        const auto found = mObject.find(key);
        if (found == mObject.end()) {
            if (required) mD.error(at(key), "missing required field");
            return nullptr;
        }
        return &*found;
    }

    /// A finite number within the float range.
    bool floatNumber(const char* key, bool required, float& out) {
        const Json* value = get(key, required);
        if (value == nullptr) return false;
        if (!value->is_number() || !std::isfinite(value->get<double>())) {
            mD.error(at(key), value->is_number() ? "expected a finite number (got a number too large to represent)"
                                                 : "expected a finite number, got " + typeName(*value));
            return false;
        }
        const double number = value->get<double>();
        if (std::fabs(number) > static_cast<double>(FLT_MAX)) {
            mD.error(at(key), "expected a finite number (beyond the float range, |x| <= 3.4028235e38)");
            return false;
        }
        out = static_cast<float>(number);
        return true;
    }

    /// [x, y, z]: doubles (a position, `floatRange` false) or floats.
    bool triple(const char* key, bool required, bool floatRange, std::array<double, 3>& out) {
        const Json* value = get(key, required);
        if (value == nullptr) return false;
        bool ok = value->is_array() && value->size() == 3;
        for (std::size_t i = 0; ok && i < 3; ++i) {
            ok = (*value)[i].is_number() && std::isfinite((*value)[i].get<double>());
            if (ok) out[i] = (*value)[i].get<double>();
        }
        if (!ok) {
            mD.error(at(key), "expected 3 finite numbers");
            return false;
        }
        for (const double component : out) {
            if (floatRange && std::fabs(component) > static_cast<double>(FLT_MAX)) {
                mD.error(at(key), "expected 3 finite numbers (beyond the float range, |x| <= 3.4028235e38)");
                return false;
            }
        }
        return true;
    }
    bool position(const char* key, bool required, foresight::RVec3& out) {
        std::array<double, 3> c{};
        if (!triple(key, required, !foresight::kDoublePrecision, c)) return false;
        out = foresight::RVec3(static_cast<foresight::Real>(c[0]), static_cast<foresight::Real>(c[1]),
                               static_cast<foresight::Real>(c[2]));
        return true;
    }
    bool vector(const char* key, bool required, foresight::Vec3& out) {
        std::array<double, 3> c{};
        if (!triple(key, required, true, c)) return false;
        out = foresight::Vec3(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
        return true;
    }
    bool string(const char* key, bool required, std::string& out) {
        const Json* value = get(key, required);
        if (value == nullptr) return false;
        if (!value->is_string()) {
            mD.error(at(key), "expected a string, got " + typeName(*value));
            return false;
        }
        out = value->get<std::string>();
        return true;
    }

    /// Reports every member no reader asked for.
    void finish() {
        for (const auto& [key, value] : mObject.items()) {
            (void)value;
            if (mKnown.count(key) == 0) mD.error(at(key), "unknown key");
        }
    }

    Diagnostics& diagnostics() { return mD; }

private:
    const Json& mObject;
    std::string mPath;
    Diagnostics& mD;
    std::set<std::string> mKnown;
};

enum class Arc { Low, High, All };

struct Shot {
    std::string path;  ///< "shots[i]"
    Json id;           ///< echoed; null when absent
    foresight::AimShot shot;
    foresight::AimTarget target;
    Arc arc = Arc::Low;
};

std::string jsonString(const std::string& text) { return Json(text).dump(-1, ' ', false, Json::error_handler_t::replace); }

bool expectObject(const Json& value, const std::string& path, Diagnostics& d, const char* shape) {
    if (value.is_object()) return true;
    d.error(path, std::string("expected an object ") + shape + ", got " + typeName(value));
    return false;
}

void readTarget(const Json& value, const std::string& path, foresight::AimTarget& target, Diagnostics& d) {
    if (!expectObject(value, path, d, "{\"position\", \"velocity\", \"acceleration\"}")) return;
    Members m(value, path, d);
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
    Members m(item, path, d);
    if (const Json* id = m.get("id", false)) {
        if (id->is_string() || id->is_number_integer()) {
            s.id = *id;
        } else {
            d.error(m.at("id"), "expected a string or an integer, got " + typeName(*id));
        }
    }
    m.position("from", true, s.shot.from);
    m.vector("gravity", false, s.shot.gravity);

    // The constraint: "speed" (the contract), or one of the extensions instead of it.
    const bool hasSpeed = item.contains("speed");
    const bool hasHorizontal = item.contains("horizontal_speed");
    const bool hasApex = item.contains("apex_height");
    const int constraints = int(hasSpeed) + int(hasHorizontal) + int(hasApex);
    if (constraints > 1) {
        d.error(path, "give one of \"speed\", \"horizontal_speed\" and \"apex_height\", not " + std::to_string(constraints));
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
            d.error(m.at("apex_above"), "unknown value " + jsonString(apexAbove) + " (expected \"start\" or \"target\")");
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
            d.error(m.at("arc"), "unknown arc " + jsonString(arc) + " (expected \"low\", \"high\" or \"all\")");
        }
    }
    if (m.floatNumber("max_time", false, s.shot.maxTime) && s.shot.maxTime < 0.0f) {
        d.error(m.at("max_time"), std::string(foresight::statusMessage(Status::NegativeTime)) + " (got " +
                                      shortNumber(static_cast<double>(s.shot.maxTime)) + ")");
    }
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
    Members root(document, "", d);
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

} // namespace

int aimCommand(const std::string& file) {
    Diagnostics diagnostics;
    const std::string name = file == "-" ? std::string("<stdin>") : file;
    std::string text;
    std::string reason;
    if (!readTextFile(file, text, reason)) {
        std::cerr << name << ": cannot read: " << reason << '\n';
        return 2;
    }
    Json input;
    std::vector<Shot> shots;
    Json output;
    const bool ok = parseJsonText(text, name, input, diagnostics) && readDocument(input, shots, diagnostics) &&
                    runShots(shots, output, diagnostics);
    printDiagnostics(diagnostics, std::cerr);
    if (!ok) return 2;
    if (!writeTextFile("-", formatJson(output), reason)) {
        std::cerr << "foresight: cannot write the result: " << reason << '\n';
        return 1;
    }
    return 0;
}

} // namespace foresight_cli
