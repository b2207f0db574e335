#include "json_number.h"

#include "json_output.h"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <system_error>

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

/// Shortest decimal digits of a positive value: value ~ digits × 10^exponent, the digits
/// (count of them, no trailing zeros) also written at `out`.
struct Digits {
    std::uint64_t digits = 0;
    int count = 0;
    int exponent = 0;
};

/// Reads std::to_chars's scientific text "d[.ddd]e±xx", copying the digits to `out`.
Digits readScientific(const char* text, const char* end, char* out) {
    Digits d;
    const char* c = text;
    for (; c != end && *c != 'e'; ++c) {
        if (*c == '.') continue;
        out[d.count++] = *c;
        d.digits = d.digits * 10 + static_cast<std::uint64_t>(*c - '0');
    }
    int exponent = 0;
    bool negative = false;
    if (c != end) ++c;  // 'e'
    if (c != end && (*c == '-' || *c == '+')) negative = *c++ == '-';
    for (; c != end; ++c) exponent = exponent * 10 + (*c - '0');
    d.exponent = (negative ? -exponent : exponent) - (d.count - 1);
    return d;
}

constexpr std::array<char, 200> kDigitPairs = [] {
    std::array<char, 200> pairs{};
    for (std::size_t i = 0; i < 100; ++i) {
        pairs[2 * i] = static_cast<char>('0' + i / 10);
        pairs[2 * i + 1] = static_cast<char>('0' + i % 10);
    }
    return pairs;
}();

/// Writes d.digits' d.count decimal digits at `out`, two at a time.
void writeDigits(char* out, const Digits& d) {
    std::uint64_t rest = d.digits;
    char* end = out + d.count;
    while (rest >= 100) {
        const std::size_t pair = static_cast<std::size_t>(rest % 100) * 2;
        rest /= 100;
        end -= 2;
        std::memcpy(end, kDigitPairs.data() + pair, 2);
    }
    if (rest >= 10) {
        end -= 2;
        std::memcpy(end, kDigitPairs.data() + rest * 2, 2);
    } else {
        *--end = static_cast<char>('0' + rest);
    }
}

#if defined(__SIZEOF_INT128__)

__extension__ using Int128 = __int128;

constexpr int kMaxTenExponent = 22;  // 10^22 × a 53-bit significand < 2^127

constexpr std::array<Int128, kMaxTenExponent + 1> kPowersOfTen = [] {
    std::array<Int128, kMaxTenExponent + 1> powers{};
    Int128 power = 1;
    for (auto& p : powers) {
        p = power;
        power *= 10;
    }
    return powers;
}();

/// True when nlohmann's Grisu2 prints `value` (positive, finite) with the digits `d` (no trailing
/// zeros, d.exponent < 0), which must round-trip to `value` and be either its shortest
/// round-trip decimal or a decimal of at most 15 digits. The test, exact in 128-bit integers:
/// with value = f × 2^-a and the decimal S = digits × 10^-b, X = (S - value) × 2^a × 10^b; the
/// rounding interval is value ± 2^-a / 2 (1/4 below a power of two), X units: 10^b / 2 (/ 4);
/// half a unit of the last digit is 2^a / 2. S must be inside both by `margin`, 2^-59 of the
/// value. Grisu2's scaled value and bounds are off by at most 2.5 units of a 64-bit significand
/// of at least 2^62 (the cached power's rounding, the product's rounding, the bounds' one-unit
/// narrowing): less than 2^-60.6 of the value. Inside the interval by more than that, S is in
/// Grisu2's narrowed interval; no shorter decimal is (a shortest one would have been S; with at
/// most 15 digits, S is the only decimal that short in an interval 2^-52 wide); Grisu2 then picks,
/// among the decimals of S's length in its interval, the one closest to its approximation of
/// the value (off by at most 1.5 units), S, the others being more than half a unit away.
bool grisu2Agrees(double value, const Digits& d) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
    const int biased = static_cast<int>(bits >> 52) & 0x7ff;
    if (biased == 0 || biased == 0x7ff) return false;  // subnormal, infinite: nlohmann decides
    constexpr std::uint64_t kHidden = std::uint64_t(1) << 52;
    const std::uint64_t f = (bits & (kHidden - 1)) | kHidden;
    const int a = 1075 - biased;  // value = f × 2^-a
    const int b = -d.exponent;
    if (a < 1 || b < 1 || b > kMaxTenExponent || d.count > 17) return false;
    if (std::bit_width(d.digits) + a > 125) return false;
    const Int128 ten = kPowersOfTen[static_cast<std::size_t>(b)];
    const Int128 scaledValue = static_cast<Int128>(f) * ten;
    const Int128 x = (static_cast<Int128>(d.digits) << a) - scaledValue;
    const Int128 absX = x < 0 ? -x : x;
    if (absX >= ten) return false;  // not near the value at all (then 4 X could overflow)
    const Int128 margin = (scaledValue >> 59) + 1;
    const bool closerBelow = (bits & (kHidden - 1)) == 0 && biased > 1;
    if (2 * x >= ten - 2 * margin) return false;  // above the interval's upper bound, or near it
    if (closerBelow ? -4 * x >= ten - 4 * margin : -2 * x >= ten - 2 * margin) return false;
    return 2 * absX < (static_cast<Int128>(1) << a) - 2 * margin;
}

constexpr std::array<std::uint64_t, 20> kPowersOfTen64 = [] {
    std::array<std::uint64_t, 20> powers{};
    std::uint64_t power = 1;
    for (auto& p : powers) {
        p = power;
        power *= 10;
    }
    return powers;
}();

/// The shortest decimal of `value` (positive, finite) that lies in its rounding interval
/// (bounds included), the closest to it of that length, when grisu2Agrees's margins hold for it
/// (else false). Exact, in 128-bit integers: with value = f × 2^-a, in units of 2^-(a+2) ×
/// 10^-B (B: 17 or 18 digits before the point) the value is V = 4 f 10^B, its interval
/// V - 2 × 10^B (10^B below a power of two) to V + 2 × 10^B. Values from 10^-4 to 2^52 only.
bool shortestDigits(double value, Digits& d) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(value);
    const int biased = static_cast<int>(bits >> 52) & 0x7ff;
    if (biased == 0 || biased == 0x7ff) return false;
    constexpr std::uint64_t kHidden = std::uint64_t(1) << 52;
    const std::uint64_t f = (bits & (kHidden - 1)) | kHidden;
    const int a = 1075 - biased;  // value = f × 2^-a, in [2^(52 - a), 2^(53 - a))
    if (a < 1) return false;
    const int k = ((52 - a) * 78913) >> 18;  // floor(log10(2^(52 - a))): value in [10^k, 2 × 10^(k+1))
    const int b = 17 - k;                    // value × 10^b in [10^17, 2 × 10^18)
    if (b < 0 || b > 21) return false;
    const int s = a + 2;
    const Int128 ten = kPowersOfTen[static_cast<std::size_t>(b)];
    const Int128 v = static_cast<Int128>(f << 2) * ten;
    const Int128 above = 2 * ten;
    const Int128 below = (bits & (kHidden - 1)) == 0 && biased > 1 ? ten : above;
    // The interval's decimals in units of 10^-b: [lo, hi]; then the largest j with a multiple
    // of 10^j in it (lo and hi become ceil(lo / 10^j), floor(hi / 10^j)).
    std::uint64_t hi = static_cast<std::uint64_t>((v + above) >> s);
    std::uint64_t lo = static_cast<std::uint64_t>((v - below + ((static_cast<Int128>(1) << s) - 1)) >> s);
    if (hi < lo) return false;
    int j = 0;
    for (;;) {
        const std::uint64_t nextHi = hi / 10, nextLo = (lo + 9) / 10;
        if (nextHi < nextLo) break;
        hi = nextHi;
        lo = nextLo;
        ++j;
    }
    // The candidates around the value at that length: c0 and c0 + 1 (units of 10^(j-b)).
    const Int128 unit = static_cast<Int128>(kPowersOfTen64[static_cast<std::size_t>(j)]) << s;
    const std::uint64_t c0 = static_cast<std::uint64_t>(v >> s) / kPowersOfTen64[static_cast<std::size_t>(j)];
    const Int128 d0 = v - static_cast<Int128>(c0) * unit;  // value - c0, >= 0
    std::uint64_t c = unit - d0 < d0 ? c0 + 1 : c0;
    if (c > hi) c = c0;
    if (c < lo) c = c0 + 1;
    if (c < lo || c > hi || c % 10 == 0) return false;
    const Int128 x = static_cast<Int128>(c) * unit - v;  // decimal - value
    const Int128 absX = x < 0 ? -x : x;
    const Int128 margin = (v >> 59) + 1;
    if (x >= above - margin || -x >= below - margin || 2 * absX >= unit - 2 * margin) return false;
    d.digits = c;
    d.exponent = j - b;
    // Digits of c (below 2 × 10^18): from its bit width, then one comparison.
    d.count = static_cast<int>((std::bit_width(c) * 1233) >> 12);
    if (c >= kPowersOfTen64[static_cast<std::size_t>(d.count)]) ++d.count;
    return true;
}

#else

bool grisu2Agrees(double, const Digits&) { return false; }  // no 128-bit integers: nlohmann always
bool shortestDigits(double, Digits&) { return false; }

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
    Digits d;
    if (!shortestDigits(value, d)) return nullptr;
    writeDigits(o, d);
    return nlohmann::detail::dtoa_impl::format_buffer(o, d.count, d.exponent, kMinExponent, kMaxExponent);
}

char* writeFloatShortestIfGrisu2(char* out, float value) {
    // jsonFloat prints floatDecimal(value): the double nearest to the float's shortest decimal.
    // With a fraction (and at most 22 decimals) that double is the correctly rounded quotient of
    // two exact doubles, the digits and a power of ten; its Grisu2 text is the float's digits
    // when grisu2Agrees says so (then no other decimal of at most 15 digits is in its interval).
    char* o = out;
    if (std::signbit(value)) {
        *o++ = '-';
        value = -value;
    }
    char text[kJsonNumberChars];
    const auto written = std::to_chars(text, text + sizeof text, value, std::chars_format::scientific);
    if (written.ec != std::errc()) return nullptr;
    const Digits d = readScientific(text, written.ptr, o);
    if (d.exponent >= 0 || d.exponent < -22 || d.count > 9) return nullptr;
    const double decimal = static_cast<double>(d.digits) / kExactPowersOfTen[static_cast<std::size_t>(-d.exponent)];
    if (decimal == std::trunc(decimal) || !grisu2Agrees(decimal, d)) return nullptr;
    return nlohmann::detail::dtoa_impl::format_buffer(o, d.count, d.exponent, kMinExponent, kMaxExponent);
}

char* writeJsonDouble(char* out, double value) {
    if (!std::isfinite(value)) {
        std::memcpy(out, "null", 4);  // what nlohmann prints; the CLI checks results first
        return out + 4;
    }
    // jsonDouble: integral values below 2^53 are integers (-0 prints as 0).
    if (value == std::trunc(value) && std::fabs(value) < kTwo53)
        return writeInteger(out, static_cast<std::int64_t>(value));
    if (char* end = writeShortestIfGrisu2(out, value)) return end;
    return writeGrisu2(out, value);
}

char* writeJsonFloat(char* out, float value) {
    if (!std::isfinite(value)) return writeJsonDouble(out, static_cast<double>(value));
    // An integral float below 2^24 is its own shortest decimal (its neighbours are at most one
    // apart): floatDecimal returns it unchanged, an integer.
    if (value == std::trunc(value) && std::fabs(value) < kTwo24)
        return writeInteger(out, static_cast<std::int64_t>(value));
    if (char* end = writeFloatShortestIfGrisu2(out, value)) return end;
    return writeJsonDouble(out, floatDecimal(value));
}

}  // namespace foresight_cli
