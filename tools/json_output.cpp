#include "json_output.h"

#include "json_number.h"
#include "text_file.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <system_error>

namespace foresight_cli {

Json jsonDouble(double value) {
    // Integral values without a fraction ("2", not "2.0"); -0 prints as 0. Below 2^53 every
    // integral double is an exact int64, so nothing is lost.
    if (std::isfinite(value) && value == std::trunc(value) && std::fabs(value) < 9007199254740992.0) {
        return Json(static_cast<std::int64_t>(value));
    }
    return Json(value);  // printed by jsonScalarText
}

double floatDecimal(float value) {
    char buffer[64];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, value);
    double parsed = static_cast<double>(value);
    if (written.ec == std::errc()) {
        double fromText = 0;
        const auto read = std::from_chars(buffer, written.ptr, fromText);
        if (read.ec == std::errc()) parsed = fromText;
    }
    return parsed;
}

Json jsonFloat(float value) { return jsonDouble(floatDecimal(value)); }

Json jsonPosition(const foresight::RVec3& position) {
    return Json::array({jsonDouble(static_cast<double>(position.x)), jsonDouble(static_cast<double>(position.y)),
                        jsonDouble(static_cast<double>(position.z))});
}

Json jsonVector(const foresight::Vec3& vector) {
    return Json::array({jsonFloat(vector.x), jsonFloat(vector.y), jsonFloat(vector.z)});
}

Json jsonQuaternion(const foresight::Quat& quaternion) {
    Json object = Json::object();
    object["w"] = jsonFloat(quaternion.w);
    object["x"] = jsonFloat(quaternion.x);
    object["y"] = jsonFloat(quaternion.y);
    object["z"] = jsonFloat(quaternion.z);
    return object;
}

std::string jsonScalarText(const Json& value) {
    if (value.is_number_float()) {
        char buffer[kJsonNumberChars];
        return std::string(buffer, writeJsonDouble(buffer, value.get<double>()));
    }
    return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

namespace {

/// Number of values in `value`, counting stops once above `limit`.
std::size_t countNodes(const Json& value, std::size_t limit) {
    std::size_t count = 1;
    if (value.is_structured()) {
        for (const auto& child : value) {
            count += countNodes(child, limit);
            if (count > limit) break;
        }
    }
    return count;
}

void writeInline(std::string& out, const Json& value) {
    if (value.is_array()) {
        out += '[';
        bool first = true;
        for (const auto& child : value) {
            if (!first) out += ", ";
            first = false;
            writeInline(out, child);
        }
        out += ']';
    } else if (value.is_object()) {
        out += '{';
        bool first = true;
        for (const auto& [key, child] : value.items()) {
            if (!first) out += ", ";
            first = false;
            out += jsonScalarText(Json(key));
            out += ": ";
            writeInline(out, child);
        }
        out += '}';
    } else {
        out += jsonScalarText(value);
    }
}

constexpr std::size_t kInlineNodes = 24;  // a trajectory point with a normal has 19
constexpr std::size_t kLineWidth = 200;

void writeValue(std::string& out, const Json& value, std::size_t indent) {
    if (!value.is_structured() || value.empty()) {
        writeInline(out, value);
        return;
    }
    if (countNodes(value, kInlineNodes) <= kInlineNodes) {
        std::string line;
        writeInline(line, value);
        if (indent + line.size() <= kLineWidth) {
            out += line;
            return;
        }
    }
    const std::string inner(indent + 2, ' ');
    out += value.is_array() ? "[\n" : "{\n";
    bool first = true;
    if (value.is_array()) {
        for (const auto& child : value) {
            if (!first) out += ",\n";
            first = false;
            out += inner;
            writeValue(out, child, indent + 2);
        }
    } else {
        for (const auto& [key, child] : value.items()) {
            if (!first) out += ",\n";
            first = false;
            out += inner;
            out += jsonScalarText(Json(key));
            out += ": ";
            writeValue(out, child, indent + 2);
        }
    }
    out += '\n';
    out.append(indent, ' ');
    out += value.is_array() ? ']' : '}';
}

}  // namespace

std::string formatJson(const Json& value) {
    std::string out;
    writeValue(out, value, 0);
    out += '\n';
    return out;
}

std::string shortNumber(double value) {
    char buffer[64];
    const auto written = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 6);
    if (written.ec != std::errc()) return "?";
    std::string text(buffer, written.ptr);
    // 5e+09 -> 5e9, 1e-05 -> 1e-5.
    if (const auto e = text.find('e'); e != std::string::npos) {
        std::string mantissa = text.substr(0, e);
        std::string exponent = text.substr(e + 1);
        std::string sign;
        if (!exponent.empty() && (exponent[0] == '+' || exponent[0] == '-')) {
            if (exponent[0] == '-') sign = "-";
            exponent.erase(0, 1);
        }
        while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
        text = mantissa + "e" + sign + exponent;
    }
    return text;
}

int writeJsonResult(const Json& document) {
    std::string reason;
    if (writeTextFile("-", formatJson(document), reason)) return 0;
    std::cerr << "foresight: cannot write the result: " << reason << '\n';
    return 1;
}

}  // namespace foresight_cli
