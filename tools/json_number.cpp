#include "json_number.h"

#include "json_output.h"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

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
        // dig.its: the digits one place on, then the integral ones moved back before the point.
        writeDigits(out + 1, d.digits, d.count);
        for (int i = 0; i < point; ++i) out[i] = out[i + 1];
        out[point] = '.';
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
    s.n = static_cast<Int128>(f << 2) * five;
    s.above = 2 * five;
    s.below = closerBelow ? five : s.above;
    return true;
}

/// The shortest decimal in the interval of `s` (bounds included when `inclusive`; the interval
/// at least one unit of 10^-b wide), the closest to the value of that length (ties: the even
/// one), as digits × 10^(j - b); `x` is decimal - value and `unit` a unit of its last digit,
/// both in the units of `s`. False when there is none (the scale was too coarse).
bool shortestIn(const Scaled& s, bool inclusive, std::uint64_t& digits, int& j, Int128& x, Int128& unit) {
    const Int128 top = s.n + s.above, bottom = s.n - s.below;
    const Int128 one = static_cast<Int128>(1) << s.shift;
    // The interval's decimals in units of 10^-b, [lo, hi]; then the largest j with a multiple of
    // 10^j in it (lo and hi become ceil(lo / 10^j), floor(hi / 10^j)).
    std::uint64_t hi = static_cast<std::uint64_t>((inclusive ? top : top - 1) >> s.shift);
    std::uint64_t lo = static_cast<std::uint64_t>(inclusive ? (bottom + one - 1) >> s.shift : (bottom >> s.shift) + 1);
    if (hi < lo) return false;
    // floor(value / 10^j) alongside (floor(floor(x / 10) / 10) = floor(x / 100)).
    std::uint64_t c0 = static_cast<std::uint64_t>(s.n >> s.shift);
    j = 0;
    for (;;) {
        const std::uint64_t nextHi = hi / 10, nextLo = (lo + 9) / 10;
        if (nextHi < nextLo) break;
        hi = nextHi;
        lo = nextLo;
        c0 /= 10;
        ++j;
    }
    // The two decimals of that length around the value: c0 (at or below) and c0 + 1.
    unit = static_cast<Int128>(kPowersOfTen[static_cast<std::size_t>(j)]) << s.shift;
    const Int128 below = s.n - static_cast<Int128>(c0) * unit;  // value - c0, in [0, unit)
    const Int128 above = unit - below;                          // c0 + 1 - value
    std::uint64_t c = above < below || (above == below && (c0 & 1) != 0) ? c0 + 1 : c0;
    if (c > hi) c = c0;
    if (c < lo) c = c0 + 1;
    if (c < lo || c > hi) return false;
    digits = c;
    x = c == c0 ? -below : above;
    return true;
}

/// Grisu2's errors are below 2^-60.6 of the value (json_number.h); margin: 2^-59 of it.
/// True when a decimal x from the value (units of `s`) is inside the interval and nearer than
/// half a unit of its last digit, both by the margin.
bool clearOfGrisu2Errors(const Scaled& s, Int128 x, Int128 unit) {
    const Int128 margin = (s.n >> 59) + 1;
    const Int128 absX = x < 0 ? -x : x;
    return x < s.above - margin && -x < s.below - margin && 2 * absX < unit - 2 * margin;
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

/// The exact test of json_number.h: Grisu2 prints `value` (positive, finite, not integral)
/// with the shortest decimal in its rounding interval, found here, when that decimal is inside
/// the interval and nearer the value than half a unit of its last digit, both by more than
/// Grisu2's errors. Then Grisu2's narrowed interval holds it and nothing shorter (it lies in
/// the interval), and it is the decimal of its length nearest Grisu2's approximation of the
/// value. Values from 10^-14 to 2^52.
bool grisu2Digits(double value, Decimal& d) {
    std::uint64_t f = 0;
    int a = 0;
    bool closerBelow = false;
    if (!split(value, f, a, closerBelow) || a < 1) return false;
    const int k = ((52 - a) * 78913) >> 18;  // floor(log10(2^(52 - a))): value in [10^k, 2 × 10^(k+1))
    const int b = 16 - k;                    // value × 10^b in [10^16, 2 × 10^17): 17 digits
    Scaled s;
    if (!scale(f, a, b, closerBelow, s)) return false;
    Int128 x = 0, unit = 0;
    int j = 0;
    if (!shortestIn(s, true, d.digits, j, x, unit) || d.digits % 10 == 0 || !clearOfGrisu2Errors(s, x, unit))
        return false;
    d.exponent = j - b;
    d.count = digitCount(d.digits);
    return true;
}

/// The float's shortest decimal, as std::to_chars finds it (bounds included for an even
/// significand, ties to even); for positive normal floats with a fraction only.
bool floatDigits(float value, Decimal& d) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(value);
    const int biased = static_cast<int>(bits >> 23) & 0xff;
    if (biased == 0 || biased == 0xff) return false;
    constexpr std::uint32_t kHidden = std::uint32_t(1) << 23;
    const std::uint32_t f = (bits & (kHidden - 1)) | kHidden;
    const int a = 150 - biased;  // value = f × 2^-a
    if (a < 1) return false;
    const int k = ((23 - a) * 78913) >> 18;
    const int b = 8 - k;  // value × 10^b in [10^8, 2 × 10^9): 9 digits, and the interval > 11 units
    Scaled s;
    if (!scale(f, a, b, (bits & (kHidden - 1)) == 0 && biased > 1, s)) return false;
    Int128 x = 0, unit = 0;
    int j = 0;
    if (!shortestIn(s, (f & 1) == 0, d.digits, j, x, unit)) return false;
    d.exponent = j - b;
    d.count = digitCount(d.digits);
    return true;
}

/// True when Grisu2 prints `value` (positive, not integral) as `d`, a decimal of at most 15
/// digits that rounds to it: inside its interval and nearer than half a unit of its last digit
/// by more than Grisu2's errors, no other decimal of at most 15 digits being in an interval
/// that narrow.
bool grisu2Prints(double value, const Decimal& d) {
    std::uint64_t f = 0;
    int a = 0;
    bool closerBelow = false;
    if (d.count > 15 || d.exponent >= 0 || !split(value, f, a, closerBelow)) return false;
    Scaled s;
    if (!scale(f, a, -d.exponent, closerBelow, s)) return false;
    if (static_cast<int>(std::bit_width(d.digits)) + s.shift > 125) return false;
    const Int128 unit = static_cast<Int128>(1) << s.shift;
    const Int128 x = static_cast<Int128>(d.digits) * unit - s.n;
    if ((x < 0 ? -x : x) > s.above) return false;
    return clearOfGrisu2Errors(s, x, unit);
}

#else

bool grisu2Digits(double, Decimal&) { return false; }  // no 128-bit integers: nlohmann always
bool floatDigits(float, Decimal&) { return false; }
bool grisu2Prints(double, const Decimal&) { return false; }

#endif

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
    Decimal d;
    if (!grisu2Digits(value, d)) return nullptr;
    return writeDecimal(o, d);
}

char* writeFloatShortestIfGrisu2(char* out, float value) {
    // jsonFloat prints floatDecimal(value): the double nearest to the float's shortest decimal.
    // With a fraction (and at most 22 decimals) that double is the correctly rounded quotient of
    // two exact doubles, the digits and a power of ten; Grisu2 prints it with the float's
    // digits when grisu2Prints says so.
    char* o = out;
    if (std::signbit(value)) {
        *o++ = '-';
        value = -value;
    }
    Decimal d;
    if (!floatDigits(value, d) || d.exponent >= 0 || d.exponent < -22) return nullptr;
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
