#pragma once
// Messages that stay one line on a terminal whatever a file held: control characters written
// as \xNN. Used by checkObjText's reasons (obj_check.cpp) and by the command-line tool's
// diagnostics (tools/json_input.cpp); not installed.

#include <foresight/config.h>

#include <string>
#include <string_view>

FORESIGHT_NAMESPACE_BEGIN
namespace detail {

/// Appends `text` to `out` with every control character (below 0x20, and 0x7f) and every
/// character of `alsoEscaped` written as `\xNN` (two lower-case hexadecimal digits).
inline void appendPrintable(std::string& out, std::string_view text, std::string_view alsoEscaped = {}) {
    static constexpr char kHex[] = "0123456789abcdef";
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f || alsoEscaped.find(c) != std::string_view::npos) {
            out += "\\x";
            out += kHex[u >> 4];
            out += kHex[u & 15];
        } else {
            out += c;
        }
    }
}

}  // namespace detail
FORESIGHT_NAMESPACE_END
