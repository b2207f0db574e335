#pragma once
/// @file json_number.h
/// The CLI's numbers as nlohmann::json prints them (jsonDouble, jsonFloat of json_output.h),
/// written into a character buffer, fast.
///
/// nlohmann prints a double with Grisu2, which is not always the shortest decimal: it looks for
/// the shortest in the rounding interval narrowed by its own rounding errors (a few units in the
/// 62nd bit), and picks among those the one closest to its approximation of the value. So the
/// shortest decimal (std::to_chars's) differs for about one double in a thousand
/// (3.0990509999999998 where the shortest is 3.099051). Here the shortest decimal comes from
/// {fmt}'s Dragonbox and is kept only when an exact test, in 128-bit integers, shows that Grisu2
/// finds the same digits: they lie inside the rounding interval, and nearer the value than half
/// a unit of their last digit, both by a margin (2^-59 of the value) larger than every error of
/// Grisu2's arithmetic (below 2^-60.6). Then they are the shortest in Grisu2's narrowed interval
/// too, and the closest to its value. Otherwise (near-ties, and values the exact test does not
/// cover: below 10^-14, integers from 2^53 up, subnormals) nlohmann's own conversion runs.
/// tests/cli_output_test.cpp compares both with nlohmann on over a million values.

#include <cstddef>

namespace foresight_cli {

/// Room writeJsonDouble and writeJsonFloat need at `out`: at most 25 characters of text, and
/// the fast path moves blocks of 16 characters within the first 33.
inline constexpr std::size_t kJsonNumberChars = 40;

/// Writes `value` (finite) as formatJson prints jsonDouble(value): integral values below 2^53
/// without a fraction, others as nlohmann::json prints a double. Returns the end of the text.
char* writeJsonDouble(char* out, double value);

/// Writes `value` (finite) as formatJson prints jsonFloat(value). Returns the end of the text.
char* writeJsonFloat(char* out, float value);

/// The fast path alone: writes nlohmann's text of `value` (finite) when the exact test proves
/// the shortest decimal to be Grisu2's, and returns its end; else returns nullptr (what it wrote
/// is then meaningless). For the tests.
char* writeShortestIfGrisu2(char* out, double value);

/// The float fast path alone (jsonFloat of a non-integral float, via its shortest float decimal):
/// nullptr when not proven. For the tests.
char* writeFloatShortestIfGrisu2(char* out, float value);

}  // namespace foresight_cli
