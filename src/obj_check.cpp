// checkObjText: the OBJ lines the triangle loaders read, checked strictly (obj_check.h).
#include <foresight/obj_check.h>

#include "printable.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

FORESIGHT_NAMESPACE_BEGIN

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }

// The line's tokens up to a '#' comment.
void splitTokens(std::string_view line, std::vector<std::string_view>& tokens) {
    tokens.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i])) ++i;
        if (i >= line.size() || line[i] == '#') break;
        const std::size_t begin = i;
        while (i < line.size() && !isSpace(line[i]) && line[i] != '#') ++i;
        tokens.push_back(line.substr(begin, i - begin));
    }
}

// `[+-]digits[.digits][e[+-]digits]` or `[+-].digits[...]`, finite and within float range.
bool plainNumber(std::string_view token, double& value) {
    std::size_t i = 0;
    if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
    const std::size_t mantissa = i;
    std::size_t digits = 0;
    while (i < token.size() && isDigit(token[i])) ++i, ++digits;
    if (i < token.size() && token[i] == '.') {
        ++i;
        while (i < token.size() && isDigit(token[i])) ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
        ++i;
        if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
        std::size_t exponentDigits = 0;
        while (i < token.size() && isDigit(token[i])) ++i, ++exponentDigits;
        if (exponentDigits == 0) return false;
    }
    if (i != token.size()) return false;
    // from_chars takes no '+'; the sign is applied here.
    const bool negative = token[0] == '-';
    const char* first = token.data() + mantissa;
    const char* last = token.data() + token.size();
    const auto [end, error] = std::from_chars(first, last, value);
    if (error != std::errc() || end != last || !std::isfinite(value)) return false;
    if (std::abs(value) > static_cast<double>(std::numeric_limits<float>::max())) return false;
    if (negative) value = -value;
    return true;
}

// `[+-]digits` within int range (tinyobjloader's index type).
bool plainInteger(std::string_view token, std::int64_t& value) {
    if (token.empty()) return false;
    std::size_t i = 0;
    const bool negative = token[0] == '-';
    if (token[0] == '+' || token[0] == '-') ++i;
    if (i == token.size() || token.size() - i > 10) return false;
    std::int64_t v = 0;
    for (; i < token.size(); ++i) {
        if (!isDigit(token[i])) return false;
        v = v * 10 + (token[i] - '0');
    }
    value = negative ? -v : v;
    return value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max();
}

std::string quoted(std::string_view token) {
    std::string out = "\"";
    detail::appendPrintable(out, token.substr(0, 40), "\"\\");
    if (token.size() > 40) out += "...";
    return out + "\"";
}

}  // namespace

bool checkObjText(std::string_view text, std::string& reason) {
    if (text.size() > kMaxObjBytes) {
        reason = "larger than " + std::to_string(kMaxObjBytes >> 20) + " MiB";
        return false;
    }
    std::vector<std::string_view> tokens;
    std::int64_t vertices = 0;
    std::int64_t largestIndex = 0;
    std::size_t largestIndexLine = 0;
    std::size_t lineNumber = 0;
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = text.substr(at, end - at);
        at = end + 1;
        ++lineNumber;
        const std::string where = "line " + std::to_string(lineNumber) + ": ";
        if (line.find('\0') != std::string_view::npos) {
            reason = where + "a NUL byte (not a text file?)";
            return false;
        }
        splitTokens(line, tokens);
        if (tokens.empty()) continue;
        if (tokens[0] == "v") {
            const std::size_t count = tokens.size() - 1;
            if (count != 3 && count != 4 && count != 6) {
                reason = where + "a vertex has " + std::to_string(count) +
                         " numbers (expected x y z, x y z w or x y z r g b)";
                return false;
            }
            for (std::size_t k = 1; k < tokens.size(); ++k) {
                double value = 0.0;
                if (!plainNumber(tokens[k], value)) {
                    reason = where + "vertex value " + quoted(tokens[k]) +
                             " is not a finite decimal number within float range";
                    return false;
                }
            }
            ++vertices;
        } else if (tokens[0] == "f") {
            if (tokens.size() < 4) {
                reason = where + "a face has " + std::to_string(tokens.size() - 1) + " corner(s) (at least 3 needed)";
                return false;
            }
            for (std::size_t k = 1; k < tokens.size(); ++k) {
                const std::string_view corner = tokens[k];
                std::string_view parts[3];
                std::size_t partCount = 0, begin = 0;
                for (std::size_t i = 0; i <= corner.size(); ++i) {
                    if (i == corner.size() || corner[i] == '/') {
                        if (partCount == 3) {
                            partCount = 4;
                            break;
                        }
                        parts[partCount++] = corner.substr(begin, i - begin);
                        begin = i + 1;
                    }
                }
                bool ok = partCount >= 1 && partCount <= 3 && !parts[0].empty();
                if (ok && partCount == 2) ok = !parts[1].empty();  // "v/" is not a corner
                if (ok && partCount == 3) ok = !parts[2].empty();  // "v/t/" neither
                std::int64_t index = 0;
                for (std::size_t p = 0; ok && p < partCount; ++p) {
                    if (p == 1 && partCount == 3 && parts[1].empty()) continue;  // v//n
                    std::int64_t value = 0;
                    ok = plainInteger(parts[p], value) && value != 0;
                    if (p == 0) index = value;
                }
                if (!ok) {
                    reason = where + "face corner " + quoted(corner) +
                             " is not v, v/t, v/t/n or v//n with non-zero integer indices";
                    return false;
                }
                if (index < 0 && -index > vertices) {
                    reason = where + "face corner " + quoted(corner) +
                             " counts back past the first vertex, out of range (" + std::to_string(vertices) +
                             " read so far)";
                    return false;
                }
                if (index > largestIndex) {
                    largestIndex = index;
                    largestIndexLine = lineNumber;
                }
            }
        }
    }
    if (largestIndex > vertices) {
        reason = "line " + std::to_string(largestIndexLine) + ": a face refers to vertex " +
                 std::to_string(largestIndex) + ", out of range (the file has " + std::to_string(vertices) +
                 " vertices)";
        return false;
    }
    return true;
}

FORESIGHT_NAMESPACE_END
