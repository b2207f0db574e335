#include "json_number.h"

#include "json_output.h"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <fmt/format.h>

namespace foresight_cli {

namespace {

constexpr double kTwo53 = 9007199254740992.0;  // integral doubles below print as integers
constexpr float kTwo24 = 16777216.0f;          // integral floats below are their own decimal

// nlohmann's to_chars lays out a double's digits with these exponent limits (printf's %g, but
// up to digits10 digits before the point); the CLI keeps its layout.
constexpr int kMinExponent = -4;
constexpr int kMaxExponent = std::numeric_limits<double>::digits10;

char* writeInteger(char* out, std::int64_t value) { return std::to_chars(out, out + kJsonNumberChars, value).ptr; }

/// A decimal: digits × 10^exponent, `count` digits, no trailing zeros.
struct Decimal {
    std::uint64_t digits = 0;
    int count = 0;
    int exponent = 0;
};

constexpr std::array<std::uint64_t, 20> kPowersOfTen = [] {
    std::array<std::uint64_t, 20> powers{};
    std::uint64_t power = 1;
    for (auto& p : powers) {
        p = power;
        power *= 10;
    }
    return powers;
}();

constexpr std::array<char, 200> kDigitPairs = [] {
    std::array<char, 200> pairs{};
    for (std::size_t i = 0; i < 100; ++i) {
        pairs[2 * i] = static_cast<char>('0' + i / 10);
        pairs[2 * i + 1] = static_cast<char>('0' + i % 10);
    }
    return pairs;
}();

/// Number of decimal digits of `value` (at least 1).
int digitCount(std::uint64_t value) {
    const auto count = static_cast<int>((std::bit_width(value) * 1233) >> 12);  // floor(log10(2^bits)), + 0 or 1
    return count + (value >= kPowersOfTen[static_cast<std::size_t>(count)] ? 1 : 0);
}

/// Writes the 8 decimal digits of `value` (below 10^8, leading zeros included) at `out`.
void writeEightDigits(char* out, std::uint32_t value) {
    const std::uint32_t high = value / 10000, low = value % 10000;
    std::memcpy(out, kDigitPairs.data() + (high / 100) * 2, 2);
    std::memcpy(out + 2, kDigitPairs.data() + (high % 100) * 2, 2);
    std::memcpy(out + 4, kDigitPairs.data() + (low / 100) * 2, 2);
    std::memcpy(out + 6, kDigitPairs.data() + (low % 100) * 2, 2);
}

/// Writes the `count` decimal digits of `digits` at `out`: 8 at a time from the end, then two
/// at a time.
void writeDigits(char* out, std::uint64_t digits, int count) {
    char* end = out + count;
    while (digits >= 100000000) {
        end -= 8;
        writeEightDigits(end, static_cast<std::uint32_t>(digits % 100000000));
        digits /= 100000000;
    }
    auto rest = static_cast<std::uint32_t>(digits);
    while (rest >= 100) {
        end -= 2;
        std::memcpy(end, kDigitPairs.data() + (rest % 100) * 2, 2);
        rest /= 100;
    }
    if (rest >= 10) {
        std::memcpy(end - 2, kDigitPairs.data() + rest * 2, 2);
    } else {
        end[-1] = static_cast<char>('0' + rest);
    }
}

/// Writes `d` (positive) as nlohmann's format_buffer lays out a double's digits: d.ddd,
/// 0.000ddd, or with an exponent (then format_buffer itself).
char* writeDecimal(char* out, const Decimal& d) {
    const int point = d.count + d.exponent;  // digits before the point
    if (point > 0 && point <= kMaxExponent && d.exponent < 0) {
        // dig.its: the digits, then the fraction's (at most 16) moved one place on as a block of
        // 16 characters, which ends within the room (point is at most 15).
        writeDigits(out, d.digits, d.count);
        char fraction[16];
        std::memcpy(fraction, out + point, sizeof fraction);
        out[point] = '.';
        std::memcpy(out + point + 1, fraction, sizeof fraction);
        return out + d.count + 1;
    }
    if (point <= 0 && point > kMinExponent) {
        // 0.[000]digits
        out[0] = '0';
        out[1] = '.';
        for (int i = 0; i < -point; ++i) out[2 + i] = '0';
        writeDigits(out + 2 - point, d.digits, d.count);
        return out + 2 - point + d.count;
    }
    writeDigits(out, d.digits, d.count);
    return nlohmann::detail::dtoa_impl::format_buffer(out, d.count, d.exponent, kMinExponent, kMaxExponent);
}

/// The shortest decimal of `value` (positive, finite) that reads back as `value`, the nearest of
/// that length, without trailing zeros, as std::to_chars finds it: {fmt}'s Dragonbox. (This is
/// {fmt}'s own entry to its Dragonbox, in its detail namespace: {fmt} 9 to 12 have it with this
/// signature; a release without it fails to compile here, and tests/cli_output_test.cpp compares
/// the digits with std::to_chars's on over a million values.)
template <class T>
Decimal shortestDecimal(T value) {
    const auto decimal = fmt::detail::dragonbox::to_decimal(value);
    Decimal d;
    d.digits = decimal.significand;
    d.exponent = decimal.exponent;
    d.count = digitCount(d.digits);
    return d;
}

/// Writes `value` (finite, not zero) as its shortest decimal in nlohmann's layout, sign first.
template <class T>
char* writeShortest(char* out, T value) {
    if (std::signbit(value)) {
        *out++ = '-';
        value = -value;
    }
    return writeDecimal(out, shortestDecimal(value));
}

}  // namespace

char* writeJsonDouble(char* out, double value) {
    if (!std::isfinite(value)) {
        std::memcpy(out, "null", 4);  // what nlohmann prints; the CLI checks results first
        return out + 4;
    }
    // jsonDouble: integral values below 2^53 are integers (-0 prints as 0).
    // (Below 2^53 the int64 conversion is exact for integral values and cheaper than trunc.)
    if (std::fabs(value) < kTwo53 && static_cast<double>(static_cast<std::int64_t>(value)) == value)
        return writeInteger(out, static_cast<std::int64_t>(value));
    return writeShortest(out, value);
}

char* writeJsonFloat(char* out, float value) {
    if (!std::isfinite(value)) return writeJsonDouble(out, static_cast<double>(value));
    // An integral float below 2^24 is its own shortest decimal (its neighbours are at most one
    // apart): floatDecimal returns it unchanged, an integer.
    if (std::fabs(value) < kTwo24 && static_cast<float>(static_cast<std::int32_t>(value)) == value)
        return writeInteger(out, static_cast<std::int32_t>(value));
    // With a fraction, the float's shortest decimal is also the shortest of floatDecimal(value),
    // the double nearest to it: a shorter decimal that read back as that double would lie
    // within 2^-53 of the value of it, closer than two decimals of at most 9 digits can be.
    // Integral floats from 2^24 up print as jsonDouble prints that double (an integer below 2^53).
    if (std::fabs(value) >= kTwo24) return writeJsonDouble(out, floatDecimal(value));
    return writeShortest(out, value);
}

}  // namespace foresight_cli
