#pragma once
/// @file json_output.h
/// Numbers and layout of the CLI's JSON output.
///
/// Numbers are printed as the shortest decimal that round-trips the value in its own type:
/// positions (double in the CLI's build) as doubles, everything else (velocities, quaternions,
/// times, normals: float in the library) as floats, so `0.1f` prints as `0.1`, not
/// `0.10000000149011612`. Integral values print without a fraction (`2`, not `2.0`), as in
/// the scenario format's examples.

#include <foresight/foresight.h>

#include <nlohmann/json.hpp>

#include <string>

namespace foresight_cli {

/// Ordered: members print in insertion order (id, model, position, ...), and input
/// problems are reported in document order.
using Json = nlohmann::ordered_json;

/// A JSON number holding `value` (must be finite), printed as its shortest round-trip decimal
/// (writeJsonDouble of json_number.h).
Json jsonDouble(double value);
/// A JSON number printed as the shortest decimal that round-trips `value` as a float.
Json jsonFloat(float value);
/// The double nearest to the shortest decimal that round-trips `value` as a float: what
/// jsonFloat holds (printed, it has the same or fewer digits than that decimal).
double floatDecimal(float value);
/// [x, y, z] of a position (Real: double in the CLI build).
Json jsonPosition(const foresight::RVec3& position);
/// [x, y, z] of a float vector.
Json jsonVector(const foresight::Vec3& vector);
/// {"w", "x", "y", "z"} of a quaternion.
Json jsonQuaternion(const foresight::Quat& quaternion);

/// The text of a scalar JSON value as the CLI prints it: a number with a fraction through
/// writeJsonDouble (json_number.h), anything else (strings, integers, booleans, null) as
/// nlohmann prints it. Never throws on invalid UTF-8 (replaced by U+FFFD).
std::string jsonScalarText(const Json& value);

/// Serialises `value` for people and tools alike: small objects and arrays (a vector, a
/// trajectory point) on one line, larger ones one member per line, indented by two spaces.
/// Ends with a newline. Never throws on invalid UTF-8 (replaced by U+FFFD).
std::string formatJson(const Json& value);

/// Writes `document` (formatJson) to standard output: 0, or 1 after "foresight: cannot write
/// the result: ..." on standard error (a closed pipe, a full disk).
int writeJsonResult(const Json& document);

/// `value` in the shortest general form, e.g. 5e9, 0.02, 1048576 (for error messages).
std::string shortNumber(double value);

}  // namespace foresight_cli
