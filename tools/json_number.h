#pragma once
/// @file json_number.h
/// The CLI's numbers (jsonDouble, jsonFloat of json_output.h) written into a character buffer,
/// fast: the shortest decimal that reads back as the value in its own type (of those, the
/// nearest), from {fmt}'s Dragonbox, laid out as nlohmann::json lays out a double (1.5, 0.0001,
/// 1e-05, 1.2e+20). Integral values print as integers.
///
/// (nlohmann's own conversion, Grisu2, is not always the shortest: it prints about one double in
/// a thousand with more digits, 3.0990509999999998 where the shortest is 3.099051. Both read
/// back as the same double. Every number of the CLI's JSON output goes through this file, so its
/// text does not depend on which writer printed it; the HTML viewer's embedded data block is
/// nlohmann's own dump, read by a browser.) tests/cli_output_test.cpp compares the digits with
/// std::to_chars's and the layout with nlohmann's on over a million values.

#include <cstddef>

namespace foresight_cli {

/// Room writeJsonDouble and writeJsonFloat need at `out`: at most 25 characters of text, and
/// the layout moves blocks of 16 characters within the first 33.
inline constexpr std::size_t kJsonNumberChars = 40;

/// Writes `value` as jsonDouble(value) prints: integral values below 2^53 without a fraction,
/// others as their shortest decimal; a non-finite value as null (the CLI refuses such results
/// before it prints). Returns the end of the text.
char* writeJsonDouble(char* out, double value);

/// Writes `value` as jsonFloat(value) prints: the shortest decimal that reads back as the float
/// (integral floats below 2^24 as integers, larger ones as writeJsonDouble(floatDecimal(value))).
/// Returns the end of the text.
char* writeJsonFloat(char* out, float value);

}  // namespace foresight_cli
