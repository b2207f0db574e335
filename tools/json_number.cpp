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

// nlohmann's to_chars formats Grisu2's digits with these exponent limits (printf's %g, but up
// to digits10 digits before the point).
constexpr int kMinExponent = -4;
constexpr int kMaxExponent = std::numeric_limits<double>::digits10;

char* writeInteger(char* out, std::int64_t value) { return std::to_chars(out, out + kJsonNumberChars, value).ptr; }

/// nlohmann::json's own text of a double: its serializer calls this function.
char* writeGrisu2(char* out, double value) { return nlohmann::detail::to_chars(out, out + kJsonNumberChars, value); }

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

/// Writes `d` (positive) as nlohmann's format_buffer lays out Grisu2's digits: d.ddd, 0.000ddd,
/// or with an exponent (then format_buffer itself).
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

#if defined(__SIZEOF_INT128__)

__extension__ using Int128 = __int128;
__extension__ using UInt128 = unsigned __int128;

constexpr int kMaxFiveExponent = 42;  // 5^42 < 2^98

constexpr std::array<Int128, kMaxFiveExponent + 1> kPowersOfFive = [] {
    std::array<Int128, kMaxFiveExponent + 1> powers{};
    Int128 power = 1;
    for (auto& p : powers) {
        p = power;
        power *= 5;
    }
    return powers;
}();

/// A positive value and its rounding interval, exactly, in units of 2^-shift × 10^-b:
/// value = f × 2^-a is n = 4 f 5^b (shift = a + 2 - b), the interval n - below to n + above,
/// above = 2 × 5^b (half the gap to the next value), below the same or 5^b (a quarter of the
/// gap up) below a power of two. One unit of the decimal digit at 10^-b is 2^shift.
struct Scaled {
    Int128 n = 0;
    Int128 above = 0;
    Int128 below = 0;
    int shift = 0;
};

/// Scales f × 2^-a (f below 2^53) by 10^b. False when the numbers would not fit in 127 bits.
bool scale(std::uint64_t f, int a, int b, bool closerBelow, Scaled& s) {
    if (b < 0 || b > kMaxFiveExponent) return false;
    const Int128 five = kPowersOfFive[static_cast<std::size_t>(b)];
    // 4 f 5^b + 2 × 5^b must stay below 2^126: bit widths adding up to at most 125.
    const auto high = static_cast<std::uint64_t>(five >> 64);
    const int fiveBits =
        static_cast<int>(high != 0 ? 64 + std::bit_width(high) : std::bit_width(static_cast<std::uint64_t>(five)));
    if (static_cast<int>(std::bit_width(f)) + 2 + fiveBits > 125) return false;
    s.shift = a + 2 - b;
    if (s.shift < 0 || s.shift > 120) return false;
    // (One 64-bit multiplication while 5^b fits in 64 bits: b up to 27.)
    s.n = high == 0 ? static_cast<Int128>(static_cast<UInt128>(f << 2) * static_cast<std::uint64_t>(five))
                    : static_cast<Int128>(f << 2) * five;
    s.above = 2 * five;
    s.below = closerBelow ? five : s.above;
    return true;
}

/// value = f × 2^-a, f with the hidden bit, for a positive normal double; false otherwise.
bool split(double value, std::uint64_t& f, int& a, bool& closerBelow) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
    const int biased = static_cast<int>(bits >> 52) & 0x7ff;
    if (biased == 0 || biased == 0x7ff) return false;  // subnormal, infinite: nlohmann decides
    constexpr std::uint64_t kHidden = std::uint64_t(1) << 52;
    f = (bits & (kHidden - 1)) | kHidden;
    a = 1075 - biased;
    closerBelow = (bits & (kHidden - 1)) == 0 && biased > 1;
    return true;
}

/// The exact test of json_number.h: true when Grisu2 prints `value` (positive, not integral) as
/// `d`, a decimal with a fraction and no trailing zeros of which no shorter decimal lies
/// strictly inside the value's rounding interval. Then Grisu2 prints `d` when `d` lies inside
/// the interval and nearer the value than half a unit of its last digit, both by more than
/// Grisu2's errors (below 2^-60.6 of the value; margin: 2^-59 of it): Grisu2's interval,
/// narrowed by its errors, then holds `d` and nothing shorter, and `d` is the decimal of its
/// length nearest Grisu2's approximation of the value. False also where the exact numbers would
/// not fit in 127 bits (values below about 10^-14 with 17 digits).
bool grisu2Prints(double value, const Decimal& d) {
    std::uint64_t f = 0;
    int a = 0;
    bool closerBelow = false;
    if (d.exponent >= 0 || d.digits % 10 == 0 || !split(value, f, a, closerBelow)) return false;
    Scaled s;
    if (!scale(f, a, -d.exponent, closerBelow, s)) return false;
    if (static_cast<int>(std::bit_width(d.digits)) + s.shift > 125) return false;
    const Int128 unit = static_cast<Int128>(1) << s.shift;
    const Int128 x = static_cast<Int128>(d.digits) * unit - s.n;  // decimal - value
    const Int128 margin = (s.n >> 59) + 1;
    const Int128 absX = x < 0 ? -x : x;
    return x < s.above - margin && -x < s.below - margin && 2 * absX < unit - 2 * margin;
}

#else

bool grisu2Prints(double, const Decimal&) { return false; }  // no 128-bit integers: nlohmann always

#endif

/// The shortest decimal of `value` (positive, finite), the nearest of that length (ties: even
/// digits), without trailing zeros, as std::to_chars finds it: {fmt}'s Dragonbox. Its rounding
/// interval includes the bounds when the significand is even (round-to-nearest-even reads them
/// back to the value), so no shorter decimal lies strictly inside it. (This is {fmt}'s own entry
/// to its Dragonbox, in its detail namespace: {fmt} 9 to 12 have it with this signature; a
/// release without it fails to compile here, and tests/cli_output_test.cpp compares the digits
/// with nlohmann's on over a million values.)
template <class T>
Decimal shortestDecimal(T value) {
    const auto decimal = fmt::detail::dragonbox::to_decimal(value);
    Decimal d;
    d.digits = decimal.significand;
    d.exponent = decimal.exponent;
    d.count = digitCount(d.digits);
    return d;
}

constexpr std::array<double, 23> kExactPowersOfTen = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                      1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                                      1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

}  // namespace

char* writeShortestIfGrisu2(char* out, double value) {
    char* o = out;
    if (std::signbit(value)) {
        *o++ = '-';
        value = -value;
    }
    const Decimal d = shortestDecimal(value);
    if (!grisu2Prints(value, d)) return nullptr;
    return writeDecimal(o, d);
}

char* writeFloatShortestIfGrisu2(char* out, float value) {
    // jsonFloat prints floatDecimal(value): the double nearest to the float's shortest decimal.
    // With a fraction (and at most 22 decimals) that double is the correctly rounded quotient of
    // two exact doubles, the digits and a power of ten; Grisu2 prints it with the float's
    // digits when grisu2Prints says so. No shorter decimal lies in that double's interval: it
    // is under 2^-52 of the value wide, and two decimals of at most 9 digits differ by more.
    char* o = out;
    if (std::signbit(value)) {
        *o++ = '-';
        value = -value;
    }
    const Decimal d = shortestDecimal(value);
    if (d.exponent >= 0 || d.exponent < -22) return nullptr;
    const double decimal = static_cast<double>(d.digits) / kExactPowersOfTen[static_cast<std::size_t>(-d.exponent)];
    // (A float with a fraction is below 2^23: the conversion to int64 cannot overflow.)
    if (static_cast<double>(static_cast<std::int64_t>(decimal)) == decimal || !grisu2Prints(decimal, d)) return nullptr;
    return writeDecimal(o, d);
}

char* writeJsonDouble(char* out, double value) {
    if (!std::isfinite(value)) {
        std::memcpy(out, "null", 4);  // what nlohmann prints; the CLI checks results first
        return out + 4;
    }
    // jsonDouble: integral values below 2^53 are integers (-0 prints as 0).
    // (Below 2^53 the int64 conversion is exact for integral values and cheaper than trunc.)
    if (std::fabs(value) < kTwo53 && static_cast<double>(static_cast<std::int64_t>(value)) == value)
        return writeInteger(out, static_cast<std::int64_t>(value));
    if (char* end = writeShortestIfGrisu2(out, value)) return end;
    return writeGrisu2(out, value);
}

char* writeJsonFloat(char* out, float value) {
    if (!std::isfinite(value)) return writeJsonDouble(out, static_cast<double>(value));
    // An integral float below 2^24 is its own shortest decimal (its neighbours are at most one
    // apart): floatDecimal returns it unchanged, an integer.
    if (std::fabs(value) < kTwo24 && static_cast<float>(static_cast<std::int32_t>(value)) == value)
        return writeInteger(out, static_cast<std::int32_t>(value));
    if (char* end = writeFloatShortestIfGrisu2(out, value)) return end;
    return writeJsonDouble(out, floatDecimal(value));
}

}  // namespace foresight_cli
