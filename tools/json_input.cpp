#include "json_input.h"

#include "text_file.h"

#include "printable.h"  // src/: the library's control-character escaping

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <ostream>
#include <string_view>

namespace foresight_cli {

void Diagnostics::error(const std::string& path, const std::string& message) {
    errors.push_back((path.empty() ? std::string("(root)") : path) + ": " + message);
}

void Diagnostics::warning(const std::string& path, const std::string& message) {
    warnings.push_back((path.empty() ? std::string("(root)") : path) + ": " + message);
}

namespace {

// One line on a terminal, whatever a key or file name holds: control characters (a newline,
// escape codes) are written as \xNN.
std::string printable(const std::string& line) {
    std::string out;
    out.reserve(line.size());
    foresight::detail::appendPrintable(out, line);
    return out;
}

}  // namespace

void printDiagnostics(const Diagnostics& diagnostics, std::ostream& err) {
    for (const auto& line : diagnostics.warnings) err << "warning: " << printable(line) << '\n';
    for (const auto& line : diagnostics.errors) err << printable(line) << '\n';
    err.flush();
}

// ---------------------------------------------------------------------------------------------
// JSON text

namespace {

struct NestingTooDeep {
    std::string path;
};

}  // namespace

std::string jsonQuoted(const std::string& text) {
    return Json(text).dump(-1, ' ', false, Json::error_handler_t::replace);
}

bool parseJsonText(const std::string& text, const std::string& name, Json& document, Diagnostics& diagnostics) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
        diagnostics.errors.push_back(name + ": invalid JSON: the input is empty");
        return false;
    }
    // The JSON reader stops at a NUL byte: whatever follows it would be silently ignored.
    if (const auto nul = text.find('\0'); nul != std::string::npos) {
        diagnostics.errors.push_back(name + ": invalid JSON: a NUL byte at offset " + std::to_string(nul) +
                                     " (not a JSON text file?)");
        return false;
    }

    // Tracks the path of every value while parsing, to name duplicate keys and too deep
    // nesting. nlohmann's parser is iterative, but the callback stops absurd nesting early.
    struct Frame {
        bool object = false;
        std::string path;
        std::string key;
        std::size_t index = 0;
        std::set<std::string> keys;
    };
    std::vector<Frame> stack;
    std::vector<std::string> duplicates;
    auto childPath = [&stack]() -> std::string {
        if (stack.empty()) return std::string();
        const Frame& frame = stack.back();
        if (frame.object) return frame.path.empty() ? frame.key : frame.path + "." + frame.key;
        return (frame.path.empty() ? std::string("(root)") : frame.path) + "[" + std::to_string(frame.index) + "]";
    };
    auto nextElement = [&stack]() {
        if (!stack.empty() && !stack.back().object) ++stack.back().index;
    };
    Json::parser_callback_t callback = [&](int depth, Json::parse_event_t event, Json& parsed) -> bool {
        switch (event) {
            case Json::parse_event_t::object_start:
            case Json::parse_event_t::array_start:
                if (depth >= kMaxJsonDepth) throw NestingTooDeep{childPath()};
                stack.push_back(Frame{event == Json::parse_event_t::object_start, childPath(), {}, 0, {}});
                break;
            case Json::parse_event_t::key:
                if (!stack.empty() && parsed.is_string()) {
                    Frame& frame = stack.back();
                    frame.key = parsed.get<std::string>();
                    if (!frame.keys.insert(frame.key).second) duplicates.push_back(childPath());
                }
                break;
            case Json::parse_event_t::value:
                nextElement();
                break;
            case Json::parse_event_t::object_end:
            case Json::parse_event_t::array_end:
                if (!stack.empty()) stack.pop_back();
                nextElement();
                break;
        }
        return true;
    };

    try {
        document = Json::parse(text, callback, true, false);
    } catch (const Json::parse_error& error) {
        std::string message = error.what();
        // "[json.exception.parse_error.101] parse error at line 1, column 2: ..."
        if (const auto bracket = message.find("] ");
            message.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) {
            message.erase(0, bracket + 2);
        }
        diagnostics.errors.push_back(name + ": invalid JSON: " + message);
        return false;
    } catch (const Json::out_of_range& error) {
        // nlohmann refuses number literals beyond the double range (e.g. 1e400, error 406) and
        // stops there: name the value being read.
        std::string message = error.what();
        std::string literal;
        if (const auto open = message.find('\''), close = message.rfind('\'');
            open != std::string::npos && close > open) {
            literal = message.substr(open, close - open + 1) + " ";
        }
        diagnostics.error(childPath(), "expected a finite number (" + literal + "is beyond the double range)");
        return false;
    } catch (const Json::exception& error) {
        diagnostics.errors.push_back(name + ": invalid JSON: " + error.what());
        return false;
    } catch (const NestingTooDeep& error) {
        diagnostics.errors.push_back(name + ": invalid JSON: arrays and objects nested deeper than " +
                                     std::to_string(kMaxJsonDepth) + " levels (at " +
                                     (error.path.empty() ? std::string("(root)") : error.path) + ")");
        return false;
    }
    for (const auto& path : duplicates)
        diagnostics.error(path, "duplicate key (a later value would silently replace the first)");
    return true;
}

bool readJsonFile(const std::string& file, std::string& name, Json& document, Diagnostics& diagnostics) {
    name = file == "-" ? std::string("<stdin>") : file;
    std::string text;
    std::string reason;
    if (!readTextFile(file, text, reason)) {
        diagnostics.errors.push_back(name + ": cannot read: " + reason);
        return false;
    }
    return parseJsonText(text, name, document, diagnostics);
}

std::filesystem::path baseDirectoryOf(const std::string& file) {
    return file == "-" ? std::filesystem::path() : std::filesystem::path(file).parent_path();
}

// ---------------------------------------------------------------------------------------------
// Converters

namespace {

std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string typeName(const Json& value) {
    if (value.is_number()) return "a number";
    if (value.is_string()) return "a string";
    if (value.is_boolean()) return "a boolean";
    if (value.is_null()) return "null";
    if (value.is_array()) return "an array";
    return "an object";
}

// Converters: each checks one JSON value, reports a problem at `path` and returns false.

bool toDouble(const Json& value, const std::string& path, Diagnostics& d, double& out) {
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
        d.error(path, value.is_number() ? "expected a finite number (got a number too large to represent)"
                                        : "expected a finite number, got " + typeName(value));
        return false;
    }
    out = value.get<double>();
    return true;
}

bool toFloat(const Json& value, const std::string& path, Diagnostics& d, float& out) {
    double number = 0;
    if (!toDouble(value, path, d, number)) return false;
    if (std::fabs(number) > static_cast<double>(FLT_MAX)) {
        d.error(path, "expected a finite number (beyond the float range, |x| <= 3.4028235e38)");
        return false;
    }
    out = static_cast<float>(number);
    return true;
}

/// An array of 3 finite numbers; `floatRange` also requires |x| <= FLT_MAX.
bool toTriple(const Json& value, const std::string& path, Diagnostics& d, double (&out)[3], bool floatRange) {
    bool ok = value.is_array() && value.size() == 3;
    if (ok) {
        for (std::size_t i = 0; i < 3; ++i) {
            const Json& component = value[i];
            if (!component.is_number() || !std::isfinite(component.get<double>())) {
                ok = false;
                break;
            }
            out[i] = component.get<double>();
        }
    }
    if (!ok) {
        d.error(path, "expected 3 finite numbers");
        return false;
    }
    if (floatRange) {
        for (const double component : out) {
            if (std::fabs(component) > static_cast<double>(FLT_MAX)) {
                d.error(path, "expected 3 finite numbers (beyond the float range, |x| <= 3.4028235e38)");
                return false;
            }
        }
    }
    return true;
}

bool toPosition(const Json& value, const std::string& path, Diagnostics& d, foresight::RVec3& out) {
    double components[3] = {0, 0, 0};
    if (!toTriple(value, path, d, components, !foresight::kDoublePrecision)) return false;
    out = foresight::RVec3(static_cast<foresight::Real>(components[0]), static_cast<foresight::Real>(components[1]),
                           static_cast<foresight::Real>(components[2]));
    return true;
}

bool toVector(const Json& value, const std::string& path, Diagnostics& d, foresight::Vec3& out) {
    double components[3] = {0, 0, 0};
    if (!toTriple(value, path, d, components, true)) return false;
    out = foresight::Vec3(static_cast<float>(components[0]), static_cast<float>(components[1]),
                          static_cast<float>(components[2]));
    return true;
}

bool toInteger(const Json& value, const std::string& path, Diagnostics& d, std::int64_t low, std::int64_t high,
               std::int64_t& out) {
    const std::string expected = "expected an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]";
    if (!value.is_number()) {
        d.error(path, expected + ", got " + typeName(value));
        return false;
    }
    const double number = value.get<double>();
    bool ok = std::isfinite(number) && number == std::trunc(number) && number >= static_cast<double>(low) &&
              number <= static_cast<double>(high);
    if (ok) {
        if (value.is_number_unsigned()) {
            ok = value.get<std::uint64_t>() <= static_cast<std::uint64_t>(high);
            out = ok ? static_cast<std::int64_t>(value.get<std::uint64_t>()) : 0;
        } else if (value.is_number_integer()) {
            out = value.get<std::int64_t>();
            ok = out >= low && out <= high;
        } else {
            out = static_cast<std::int64_t>(number);
        }
    }
    if (!ok) {
        d.error(path, expected);
        return false;
    }
    return true;
}

bool expectObject(const Json& value, const std::string& path, Diagnostics& d, const char* shape) {
    if (value.is_object()) return true;
    d.error(path, std::string("expected an object ") + shape + ", got " + typeName(value));
    return false;
}

// ---------------------------------------------------------------------------------------------
// Fields

const Json* Fields::get(const char* key, bool required) {
    mKnown.insert(key);
    const auto found = mObject.find(key);
    if (found == mObject.end()) {
        if (required) mDiagnostics.error(at(key), "missing required field");
        return nullptr;
    }
    return &*found;
}

bool Fields::number(const char* key, bool required, double& out) {
    const Json* value = get(key, required);
    return value != nullptr && toDouble(*value, at(key), mDiagnostics, out);
}

bool Fields::floatNumber(const char* key, bool required, float& out) {
    const Json* value = get(key, required);
    return value != nullptr && toFloat(*value, at(key), mDiagnostics, out);
}

bool Fields::positive(const char* key, bool required, bool strict, float& out) {
    float value = 0;
    if (!floatNumber(key, required, value)) return false;
    if (strict ? !(value > 0.0f) : !(value >= 0.0f)) {
        mDiagnostics.error(at(key), std::string("must be ") + (strict ? "> 0" : ">= 0") + " (got " +
                                        shortNumber(static_cast<double>(value)) + ")");
        return false;
    }
    out = value;
    return true;
}

bool Fields::position(const char* key, bool required, foresight::RVec3& out) {
    const Json* value = get(key, required);
    return value != nullptr && toPosition(*value, at(key), mDiagnostics, out);
}

bool Fields::vector(const char* key, bool required, foresight::Vec3& out) {
    const Json* value = get(key, required);
    return value != nullptr && toVector(*value, at(key), mDiagnostics, out);
}

bool Fields::boolean(const char* key, bool required, bool& out) {
    const Json* value = get(key, required);
    if (value == nullptr) return false;
    if (!value->is_boolean()) {
        mDiagnostics.error(at(key), "expected true or false, got " + typeName(*value));
        return false;
    }
    out = value->get<bool>();
    return true;
}

bool Fields::string(const char* key, bool required, std::string& out) {
    const Json* value = get(key, required);
    if (value == nullptr) return false;
    if (!value->is_string()) {
        mDiagnostics.error(at(key), "expected a string, got " + typeName(*value));
        return false;
    }
    out = value->get<std::string>();
    return true;
}

bool Fields::integer(const char* key, bool required, std::int64_t low, std::int64_t high, std::int64_t& out) {
    const Json* value = get(key, required);
    return value != nullptr && toInteger(*value, at(key), mDiagnostics, low, high, out);
}

bool Fields::integer(const char* key, bool required, std::uint32_t low, std::uint32_t high, std::uint32_t& out) {
    std::int64_t wide = 0;
    if (!integer(key, required, std::int64_t(low), std::int64_t(high), wide)) return false;
    out = static_cast<std::uint32_t>(wide);
    return true;
}

bool Fields::time(const char* key, bool required, float& out) {
    if (!floatNumber(key, required, out)) return false;
    if (out < 0.0f) {
        mDiagnostics.error(at(key), std::string(foresight::statusMessage(foresight::Status::NegativeTime)) + " (got " +
                                        shortNumber(static_cast<double>(out)) + ")");
        return false;
    }
    return true;
}

void Fields::id(Json& out) {
    const Json* value = get("id", false);
    if (value == nullptr) return;
    if (value->is_string() || value->is_number_integer()) {
        out = *value;
    } else {
        mDiagnostics.error(at("id"), "expected a string or an integer, got " + typeName(*value));
    }
}

void Fields::finish() {
    for (const auto& [key, value] : mObject.items()) {
        (void)value;
        if (mKnown.count(key) != 0) continue;
        std::string message = "unknown key";
        std::string best;
        std::size_t bestDistance = 3;
        for (const auto& known : mKnown) {
            const std::size_t distance = editDistance(key, known);
            if (distance < bestDistance) {
                bestDistance = distance;
                best = known;
            }
        }
        if (!best.empty()) message += " (did you mean " + jsonQuoted(best) + "?)";
        mDiagnostics.error(at(key), message);
    }
}

bool Fields::quaternion(const char* key, bool required, foresight::Quat& out) {
    const Json* value = get(key, required);
    if (value == nullptr) return false;
    const std::string path = at(key);
    if (!value->is_object()) {
        mDiagnostics.error(
            path, "expected a quaternion {\"w\": ..., \"x\": ..., \"y\": ..., \"z\": ...}, got " + typeName(*value));
        return false;
    }
    Fields members(*value, path, mDiagnostics);
    float w = 0, x = 0, y = 0, z = 0;
    const bool okW = members.floatNumber("w", true, w);
    const bool okX = members.floatNumber("x", true, x);
    const bool okY = members.floatNumber("y", true, y);
    const bool okZ = members.floatNumber("z", true, z);
    members.finish();
    if (!(okW && okX && okY && okZ)) return false;
    foresight::Quat q = glm::identity<foresight::Quat>();
    q.w = w;
    q.x = x;
    q.y = y;
    q.z = z;
    const foresight::Status status = foresight::normalizeQuaternion(q, out);
    if (status != foresight::Status::Ok) {
        mDiagnostics.error(path, foresight::statusMessage(status));
        return false;
    }
    return true;
}

}  // namespace foresight_cli
