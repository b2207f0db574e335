#pragma once
/// @file json_input.h
/// Reading the CLI's JSON inputs (scenarios, shots, throws, danger keys) with one set of rules
/// and one wording: every problem is reported as `path: message` (path as in
/// `predictions[3].velocity`) and collected, so one run lists all of them; members nobody asked
/// for are unknown keys, with a "did you mean" for near misses.

#include "json_output.h"

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <set>
#include <string>
#include <vector>

namespace foresight_cli {

/// Problems (exit status 2) and warnings found while reading or running an input.
struct Diagnostics {
    std::vector<std::string> errors;    ///< one line each, "path: message".
    std::vector<std::string> warnings;  ///< one line each, printed with a "warning: " prefix.

    void error(const std::string& path, const std::string& message);
    void warning(const std::string& path, const std::string& message);
    bool ok() const { return errors.empty(); }
};

/// Prints warnings and errors to `err`, one per line.
void printDiagnostics(const Diagnostics& diagnostics, std::ostream& err);

/// Deepest nesting of arrays and objects accepted in an input (the scenario format needs 4).
inline constexpr int kMaxJsonDepth = 64;

/// Parses JSON text. Syntax errors (with line and column) and too deep nesting are reported
/// as `name: ...` and return false; duplicate keys are reported with their path (the document
/// is still returned, so that validation can find more problems).
bool parseJsonText(const std::string& text, const std::string& name, Json& document, Diagnostics& diagnostics);

/// Reads FILE ("-": standard input) and parses it. `name` receives the name messages use
/// (FILE, or "<stdin>"). An unreadable file is reported as `name: cannot read: reason`.
bool readJsonFile(const std::string& file, std::string& name, Json& document, Diagnostics& diagnostics);

/// The directory relative file names in FILE are resolved against (empty for "-").
std::filesystem::path baseDirectoryOf(const std::string& file);

/// "a number", "a string", "a boolean", "null", "an array" or "an object".
std::string typeName(const Json& value);

/// `text` as a JSON string literal (quoted, escaped; invalid UTF-8 replaced).
std::string jsonQuoted(const std::string& text);

// Converters: each checks one JSON value, reports a problem at `path` and returns false;
// `out` is set only when they return true.

/// A finite number.
bool toDouble(const Json& value, const std::string& path, Diagnostics& d, double& out);
/// A finite number within the float range (|x| <= FLT_MAX).
bool toFloat(const Json& value, const std::string& path, Diagnostics& d, float& out);
/// [x, y, z] of finite numbers; `floatRange` also requires |x| <= FLT_MAX.
bool toTriple(const Json& value, const std::string& path, Diagnostics& d, double (&out)[3], bool floatRange);
/// A position [x, y, z] (Real: the float range only in a float build).
bool toPosition(const Json& value, const std::string& path, Diagnostics& d, foresight::RVec3& out);
/// A float vector [x, y, z].
bool toVector(const Json& value, const std::string& path, Diagnostics& d, foresight::Vec3& out);
/// An integer in [low, high] (2.0 counts, 2.5 does not).
bool toInteger(const Json& value, const std::string& path, Diagnostics& d, std::int64_t low, std::int64_t high,
               std::int64_t& out);

/// Reports `expected an object SHAPE, got ...` unless `value` is an object.
bool expectObject(const Json& value, const std::string& path, Diagnostics& d, const char* shape);

/// Reads the members of one JSON object; members never asked for are reported as unknown by
/// finish(). Each reader returns true when the member is present and valid (then `out` is set);
/// false when it is absent (reported if required) or invalid (reported).
class Fields {
public:
    Fields(const Json& object, std::string path, Diagnostics& diagnostics)
        : mObject(object), mPath(std::move(path)), mDiagnostics(diagnostics) {}

    /// Path of a member, e.g. "predictions[0].velocity".
    std::string at(const std::string& key) const { return mPath.empty() ? key : mPath + "." + key; }

    /// The member, or null (reported when required). Marks `key` as known.
    const Json* get(const char* key, bool required);

    bool number(const char* key, bool required, double& out);
    bool floatNumber(const char* key, bool required, float& out);
    /// A float `> 0` (`strict`) or `>= 0`; the message names the rule and the value.
    bool positive(const char* key, bool required, bool strict, float& out);
    bool position(const char* key, bool required, foresight::RVec3& out);
    bool vector(const char* key, bool required, foresight::Vec3& out);
    bool boolean(const char* key, bool required, bool& out);
    bool string(const char* key, bool required, std::string& out);
    bool integer(const char* key, bool required, std::int64_t low, std::int64_t high, std::int64_t& out);
    /// An integer in [low, high] (within the uint32 range).
    bool integer(const char* key, bool required, std::uint32_t low, std::uint32_t high, std::uint32_t& out);
    /// A quaternion object {"w", "x", "y", "z"}, normalised.
    bool quaternion(const char* key, bool required, foresight::Quat& out);
    /// A time [s]: finite, >= 0 ("time must be >= 0 (got -1)").
    bool time(const char* key, bool required, float& out);
    /// An optional `id`: a string or an integer, echoed in outputs (null when absent).
    void id(Json& out);

    /// Reports every member that no reader asked for (typos get a "did you mean").
    void finish();

    Diagnostics& diagnostics() { return mDiagnostics; }

private:
    const Json& mObject;
    std::string mPath;
    Diagnostics& mDiagnostics;
    std::set<std::string> mKnown;
};

/// Calls `each(item, path)` for every element of the optional array member `key`.
template <class Each>
void forEachElement(Fields& fields, const char* key, Each&& each) {
    const Json* array = fields.get(key, false);
    if (array == nullptr) return;
    if (!array->is_array()) {
        fields.diagnostics().error(fields.at(key), "expected an array, got " + typeName(*array));
        return;
    }
    for (std::size_t i = 0; i < array->size(); ++i) {
        each((*array)[i], fields.at(key) + "[" + std::to_string(i) + "]");
    }
}

}  // namespace foresight_cli
