// The streamed JSON writer of `foresight predict` (tools/json_stream.h, ResultDocumentWriter in
// tools/scenario.h) against the former writer, which built the whole document and printed it:
// formatJson(resultDocument(...)) (tools/json_output.h, still what `foresight demo --json`
// prints). Byte equality with formatJson is the contract (docs/scenario-format.md: the output
// only grows), and the parsed text must be the document resultDocument builds. The CLI's own
// output is compared with files the former writer printed in tests/cli_test.cpp.

#include "json_number.h"
#include "scenario.h"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace foresight_cli;

/// xorshift64*: the same cases on every platform.
class Random {
public:
    explicit Random(std::uint64_t seed) : mState(seed) {}
    std::uint64_t next() {
        mState ^= mState >> 12;
        mState ^= mState << 25;
        mState ^= mState >> 27;
        return mState * 0x2545F4914F6CDD1DULL;
    }
    /// Uniform in [0, n).
    std::uint64_t below(std::uint64_t n) { return (next() >> 11) % n; }

private:
    std::uint64_t mState;
};

/// Streams `document` through JsonStreamWriter::value, handed out `flushBytes` at a time.
std::string streamed(const Json& document, std::size_t flushBytes, std::size_t* pieces = nullptr) {
    std::string text;
    std::size_t count = 0;
    JsonStreamWriter writer(
        [&](std::string_view piece) {
            text += piece;
            ++count;
            return true;
        },
        flushBytes);
    writer.value(document);
    EXPECT_TRUE(writer.finish());
    EXPECT_EQ(writer.bytesWritten(), text.size());
    if (pieces != nullptr) *pieces = count;
    return text;
}

double randomDouble(Random& random) {
    switch (random.below(6)) {
        case 0:
            return static_cast<double>(random.below(2000)) - 1000.0;  // integral
        case 1: {
            std::uint64_t bits = random.next();
            double value = 0;
            std::memcpy(&value, &bits, sizeof value);
            return std::isfinite(value) ? value : 0.5;  // any finite double
        }
        case 2:
            return static_cast<double>(random.next() >> 11) * 0x1p-53 * 40.0 - 20.0;  // a game position
        case 3:
            return std::ldexp(static_cast<double>(random.below(1000)) + 0.5, static_cast<int>(random.below(200)) - 100);
        default:
            return static_cast<double>(static_cast<float>(static_cast<double>(random.next() >> 40) * 0x1p-24 - 0.5));
    }
}

/// A random value `depth` levels deep at most: every kind of scalar, empty and full containers,
/// small ones (one line) and large or wide ones (over lines).
Json randomValue(Random& random, int depth) {
    const std::uint64_t kind = random.below(depth > 0 ? 10 : 6);
    switch (kind) {
        case 0:
            return jsonDouble(randomDouble(random));
        case 1:
            return jsonFloat(static_cast<float>(randomDouble(random)));
        case 2:
            return Json(static_cast<std::int64_t>(random.next()));
        case 3: {
            static const char* const kTexts[] = {"",
                                                 "bounce",
                                                 "caf\xc3\xa9",
                                                 "tab\there \"quoted\" back\\slash",
                                                 "\x01\x1f control",
                                                 "bad \xff utf-8",
                                                 "a long name that takes up a good part of a line on its own......."};
            return Json(kTexts[random.below(7)]);
        }
        case 4:
            return Json(random.below(2) == 0);
        case 5:
            return random.below(2) == 0 ? Json(nullptr) : Json(random.next());
        case 6:
        case 7: {
            Json array = Json::array();
            const std::uint64_t size = random.below(4) == 0 ? 0 : random.below(random.below(3) == 0 ? 40 : 6);
            for (std::uint64_t i = 0; i < size; ++i) array.push_back(randomValue(random, depth - 1));
            return array;
        }
        default: {
            Json object = Json::object();
            const std::uint64_t size = random.below(4) == 0 ? 0 : random.below(random.below(3) == 0 ? 30 : 6);
            for (std::uint64_t i = 0; i < size; ++i) {
                std::string key = "k";
                key += std::to_string(i);
                if (random.below(5) == 0) key += "_\xc3\xa9\"";
                object[key] = randomValue(random, depth - 1);
            }
            return object;
        }
    }
}

TEST(cli_output, RandomDocumentsStreamAsFormatJsonPrintsThem) {
    Random random(20240611);
    int multiLine = 0, oneLine = 0;
    for (int i = 0; i < 3000; ++i) {
        const Json document = randomValue(random, 1 + static_cast<int>(random.below(5)));
        const std::string expected = formatJson(document);
        (expected.find('\n') + 1 < expected.size() ? multiLine : oneLine)++;
        for (const std::size_t flushBytes : {std::size_t(1), std::size_t(97), std::size_t(1) << 16}) {
            ASSERT_EQ(streamed(document, flushBytes), expected) << "case " << i << ", flush " << flushBytes;
        }
    }
    // Both layouts were exercised, not only one.
    EXPECT_GT(multiLine, 300);
    EXPECT_GT(oneLine, 300);
}

/// nlohmann's own text of a double (Grisu2), what its serializer prints.
std::string grisu2Text(double value) {
    char buffer[64];
    return std::string(buffer, nlohmann::detail::to_chars(buffer, buffer + sizeof buffer, value));
}

/// A decimal read from a number's text: its significant digits (no leading or trailing zeros)
/// and the power of ten of the first one. Parsed by hand, so that the layouts of nlohmann and
/// std::to_chars compare by the decimal they print.
struct TextDecimal {
    std::string digits;
    int exponent = 0;
    bool operator==(const TextDecimal&) const = default;
};

TextDecimal decimalOf(std::string_view text) {
    TextDecimal d;
    int point = -1, position = 0;  // position: digits read, counting leading zeros
    std::size_t i = text.starts_with('-') ? 1 : 0;
    int leading = 0;
    for (; i < text.size() && text[i] != 'e' && text[i] != 'E'; ++i) {
        if (text[i] == '.') {
            point = position;
            continue;
        }
        if (d.digits.empty() && text[i] == '0') {
            ++leading;
        } else {
            d.digits += text[i];
        }
        ++position;
    }
    if (point < 0) point = position;
    int exponent = 0;
    if (i < text.size())
        std::from_chars(text.data() + i + 1 + (text[i + 1] == '+' ? 1 : 0), text.data() + text.size(), exponent);
    while (!d.digits.empty() && d.digits.back() == '0') d.digits.pop_back();
    d.exponent = point - leading - 1 + exponent;
    return d;
}

template <class T>
TextDecimal shortestOf(T value) {  // std::to_chars's shortest decimal (libstdc++: Ryu)
    char buffer[64];
    return decimalOf(std::string_view(
        buffer, std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific).ptr));
}

/// Whether `text` is the CLI's text of `value` (json_number.h), by an oracle independent of
/// Dragonbox: integral values below 2^53 as std::to_chars prints the integer; others read back
/// as `value`, with std::to_chars's shortest decimal, and, where nlohmann's Grisu2 finds that
/// decimal too, as nlohmann prints it byte for byte (its layout). `grisu2Differs` counts the
/// values where Grisu2 prints other digits (more, or as many but farther from the value).
::testing::AssertionResult isCliText(const std::string& text, double value, std::uint64_t* grisu2Differs = nullptr) {
    char buffer[64];
    if (!std::isfinite(value)) {
        if (text == "null") return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << text << " for a non-finite value";
    }
    if (value == std::trunc(value) && std::fabs(value) < 0x1p53) {
        const std::string integer(buffer,
                                  std::to_chars(buffer, buffer + sizeof buffer, static_cast<std::int64_t>(value)).ptr);
        if (text == integer) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << text << " for the integer " << integer;
    }
    double back = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), back);
    if (std::bit_cast<std::uint64_t>(back) != std::bit_cast<std::uint64_t>(value))
        return ::testing::AssertionFailure() << text << " reads back as " << std::hexfloat << back;
    if (!(decimalOf(text) == shortestOf(value)))
        return ::testing::AssertionFailure() << text << " is not the shortest decimal of " << std::hexfloat << value;
    const std::string grisu2 = grisu2Text(value);
    if (decimalOf(grisu2) == decimalOf(text)) {
        if (text == grisu2) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << text << " is not laid out as nlohmann's " << grisu2;
    }
    if (decimalOf(text).digits.size() > decimalOf(grisu2).digits.size())
        return ::testing::AssertionFailure() << text << " is longer than Grisu2's " << grisu2;
    if (grisu2Differs) ++*grisu2Differs;
    return ::testing::AssertionSuccess();
}

TEST(cli_output, StreamedNumbersAreTheCliText) {
    // The streamed writer's numbers (appendJsonDouble, appendJsonFloat) are the CLI's text
    // (isCliText) and what formatJson prints for jsonDouble and jsonFloat; the writer keeps a
    // cache of texts by bits, so values repeat (and collide in the cache) on purpose.
    const double specials[] = {0.0,
                               -0.0,
                               1.0,
                               -1.0,
                               0.1,
                               1e-7,
                               1e15,
                               1e16,
                               123456789012345.25,
                               9007199254740991.0,
                               9007199254740992.0,
                               -9007199254740994.0,
                               std::numeric_limits<double>::denorm_min(),
                               std::numeric_limits<double>::min(),
                               std::numeric_limits<double>::max(),
                               std::numeric_limits<double>::lowest(),
                               static_cast<double>(std::numeric_limits<float>::max()),
                               static_cast<double>(std::numeric_limits<float>::denorm_min()),
                               3.0990509999999998};
    Random random(7);
    std::vector<double> values(std::begin(specials), std::end(specials));
    for (int i = 0; i < 200000; ++i) values.push_back(randomDouble(random));
    for (int i = 0; i < 20000; ++i) values.push_back(values[random.below(values.size())]);

    Json doubles = Json::array(), floats = Json::array();
    std::string text;
    for (const double value : values) {
        const float single = static_cast<float>(value);
        text.clear();
        appendJsonDouble(text, value);
        ASSERT_TRUE(isCliText(text, value));
        ASSERT_EQ(text, jsonScalarText(jsonDouble(value)));
        if (std::isfinite(single)) {
            text.clear();
            appendJsonFloat(text, single);
            ASSERT_TRUE(isCliText(text, floatDecimal(single)));
            ASSERT_EQ(text, jsonScalarText(jsonFloat(single)));
        }
        doubles.push_back(jsonDouble(value));
        floats.push_back(jsonFloat(std::isfinite(single) ? single : 0.0f));
    }
    std::string cached;
    JsonStreamWriter writer([&cached](std::string_view piece) {
        cached += piece;
        return true;
    });
    writer.beginObject();
    writer.key("doubles");
    writer.beginArray();
    for (const double value : values) writer.number(value);
    writer.end();
    writer.key("floats");
    writer.beginArray();
    for (const double value : values) {
        const float single = static_cast<float>(value);
        writer.floatNumber(std::isfinite(single) ? single : 0.0f);
    }
    writer.end();
    writer.end();
    ASSERT_TRUE(writer.finish());
    Json document = Json::object();
    document["doubles"] = doubles;
    document["floats"] = floats;
    EXPECT_EQ(cached, formatJson(document));
}

TEST(cli_output, NumbersAreTheShortestDecimalsInNlohmannsLayout) {
    // writeJsonDouble and writeJsonFloat (json_number.h): the shortest decimal that reads back
    // as the value in its type, the nearest of that length, as std::to_chars finds it; laid out
    // as nlohmann lays out a double. Where nlohmann's Grisu2 finds the same digits, the text must
    // be nlohmann's byte for byte; where it does not (about one double in a thousand), Grisu2's
    // has more digits, or as many farther from the value. On the kinds of values the output
    // holds and on any double.
    Random random(20260611);
    std::uint64_t notGrisu2 = 0;
    char buffer[kJsonNumberChars];
    const auto check = [&](double value) {
        const std::string text(buffer, writeJsonDouble(buffer, value));
        ASSERT_TRUE(isCliText(text, value, &notGrisu2));
    };
    for (int i = 0; i < 100000; ++i) {
        check(static_cast<double>(random.next() >> 11) * 0x1p-53 * 100.0 - 50.0);  // positions
        check(std::ldexp(static_cast<double>(random.next() >> 11), static_cast<int>(random.below(100)) - 96));
        check(static_cast<double>(static_cast<std::int64_t>(random.below(20000000)) - 10000000) / 1e6);  // decimals
        check(static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(random.next() >> 32))));
        check(std::bit_cast<double>(random.next()));
    }
    // Positions of a throw: p0 + v t + g t^2 / 2 at 0.02 s steps.
    for (int i = 0; i < 1000; ++i) {
        const double p0 = static_cast<double>(random.below(6000)) / 1000.0 - 3.0;
        const double v = static_cast<double>(random.below(28000)) / 1000.0 - 14.0;
        for (int step = 1; step <= 150; ++step) {
            const double t = 0.02 * step;
            check(p0 + v * t - 9.81 * 0.5 * t * t);
        }
    }
    // Beyond the layout's limits, and subnormals.
    for (const double value : {1e-5, 1.5e-7, 123456789012345678.0, 1.2e20, -2.5e300, 4.9e-324, 0.0001, 0.00012})
        check(value);
    EXPECT_GT(notGrisu2, 500u);  // the cases where Grisu2 prints other digits were there
    EXPECT_EQ(std::string(buffer, writeJsonDouble(buffer, 3.0990509999999998)), "3.099051");
    EXPECT_EQ(std::string(buffer, writeJsonDouble(buffer, 1e20)), "1e+20");
    EXPECT_EQ(std::string(buffer, writeJsonDouble(buffer, 1e-5)), "1e-05");

    // Floats: the CLI's text of floatDecimal(value) (std::to_chars and std::from_chars, not
    // Dragonbox), and with a fraction the float's own shortest decimal.
    const auto checkFloat = [&](float value) {
        const std::string text(buffer, writeJsonFloat(buffer, value));
        ASSERT_TRUE(isCliText(text, floatDecimal(value)));
        if (!std::isfinite(value) || value == std::trunc(value)) return;
        float back = 0.0f;
        std::from_chars(text.data(), text.data() + text.size(), back);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(back), std::bit_cast<std::uint32_t>(value)) << text;
        ASSERT_EQ(decimalOf(text), shortestOf(value)) << text;
    };
    for (int i = 0; i < 200000; ++i) checkFloat(std::bit_cast<float>(static_cast<std::uint32_t>(random.next() >> 32)));
    // Every float from 3 to 3.25 (where 3.099051 is), and times and speeds of a trajectory.
    for (float value = 3.0f; value < 3.25f; value = std::nextafter(value, 4.0f)) checkFloat(value);
    for (int step = 0; step < 100000; ++step) checkFloat(0.02f * static_cast<float>(step) - 50.0f);
    for (const float value : {3.099051f, 1e10f, 3e38f, 16777216.0f, 16777218.0f, 1e-45f, -0.1f}) checkFloat(value);
}

TEST(cli_output, TrajectoryPointsAreTheirValues) {
    // JsonStreamWriter::trajectoryPoint puts a point's line together at once where it can: the
    // same text as the point written value by value, also for lines too long for one line.
    Random random(4242);
    Json points = Json::array();
    std::string text;
    JsonStreamWriter writer(
        [&text](std::string_view piece) {
            text += piece;
            return true;
        },
        1000);
    writer.beginObject();
    writer.key("trajectory");
    writer.beginArray();
    const char* const events[] = {"start", "step", "bounce", "rest"};
    int longLines = 0;
    for (int i = 0; i < 3000; ++i) {
        const auto anyFloat = [&] {
            const auto value = std::bit_cast<float>(static_cast<std::uint32_t>(random.next() >> 32));
            return std::isfinite(value) ? value : 1.5f;
        };
        const bool wide = random.below(4) == 0;  // long numbers: lines beyond 200 columns
        const float time = wide ? anyFloat() : 0.02f * static_cast<float>(i);
        const foresight::RVec3 position(randomDouble(random), randomDouble(random), wide ? 1e-300 / 3 : 1.25);
        const foresight::Vec3 velocity = wide ? foresight::Vec3(anyFloat(), anyFloat(), anyFloat())
                                              : foresight::Vec3(static_cast<float>(i) * 0.1f, -2.5f, 0.0f);
        const foresight::Vec3 normal(anyFloat(), 0.0f, -1.0f);
        const bool withNormal = random.below(3) == 0;
        const char* event = events[random.below(4)];
        writer.trajectoryPoint(time, position, velocity, event, withNormal ? &normal : nullptr);
        Json point = Json::object();
        point["t"] = jsonFloat(time);
        point["position"] = jsonPosition(position);
        point["velocity"] = jsonVector(velocity);
        point["event"] = event;
        if (withNormal) point["normal"] = jsonVector(normal);
        if (formatJson(point).size() > 197) ++longLines;  // over 196 columns on one line: beyond 200 at its indent
        points.push_back(std::move(point));
    }
    writer.end();
    writer.end();
    ASSERT_TRUE(writer.finish());
    Json document = Json::object();
    document["trajectory"] = std::move(points);
    EXPECT_EQ(text, formatJson(document));
    EXPECT_GT(longLines, 100);  // both forms were written
}

/// A scenario with every model, and `throws` projectiles with trajectories in a walled arena
/// (some resting, sliding, bouncing off a tilted plane; a few without trajectories).
std::string scenarioText(int throws) {
    std::string text = R"({"world": {
        "planes": [{"normal": [0, 1, 0], "distance": 0}, {"normal": [1, 0, 0], "distance": -20},
                   {"normal": [-1, 0.3, 0], "distance": -20}, {"normal": [0, 0, 1], "distance": -20},
                   {"normal": [0, 0, -1], "distance": -20}],
        "boxes": [{"center": [4, 0.75, -3], "half_extents": [1.5, 0.75, 1], "orientation": {"w": 0.92, "x": 0, "y": 0.39, "z": 0}}],
        "spheres": [{"center": [-5, 0, 6], "radius": 1.5}]},
      "predictions": [
        {"id": "walker", "model": "linear", "position": [0, 0, 0], "velocity": [3, 0, 4], "time": 0.5},
        {"id": -1, "model": "orientation", "orientation": {"w": 1, "x": 0, "y": 0, "z": 0}, "angular_velocity": [0, 0.25, 0], "time": 2},
        {"model": "vehicle", "position": [0, 0, 0], "velocity": [0, 0, 10], "orientation": {"w": 1, "x": 0, "y": 0, "z": 0},
         "angular_velocity": [0, 0.5, 0], "time": 2},
        {"id": "tank", "model": "dead_reckoning", "algorithm": "RVB", "position": [0, 0, 0], "velocity": [8, 0, 0],
         "acceleration": [2, 0, 0], "orientation": {"w": 1, "x": 0, "y": 0, "z": 0}, "angular_velocity": [0, 0, 0.785398], "time": 2})";
    Random random(99);
    const char* const methods[] = {"exact", "stepped", "exact"};
    for (int i = 0; i < throws; ++i) {
        const double vx = static_cast<double>(random.below(2800)) / 100.0 - 14.0;
        const double vy = static_cast<double>(random.below(600)) / 100.0 + 1.0;
        const double vz = static_cast<double>(random.below(2800)) / 100.0 - 14.0;
        text += ",\n        {\"id\": " + std::to_string(i) + R"(, "model": "projectile", "method": ")" +
                methods[i % 3] + R"(", "position": [0.5, 1.5, -0.25], "velocity": [)" + std::to_string(vx) + ", " +
                std::to_string(vy) + ", " + std::to_string(vz) + R"(], "time": 3, "friction": 0.3)" +
                (i % 17 == 5 ? R"(, "trajectory": false)" : "") + (i % 13 == 3 ? R"(, "max_bounces": 2)" : "") + "}";
    }
    return text + "]}";
}

TEST(cli_output, ALargeResultIsTheFormerDocumentByteForByte) {
    Diagnostics diagnostics;
    Json input;
    Scenario scenario;
    ASSERT_TRUE(parseJsonText(scenarioText(300), "test", input, diagnostics));
    ASSERT_TRUE(buildScenario(input, ".", scenario, diagnostics)) << diagnostics.errors.front();
    std::vector<PredictionResult> results;
    ASSERT_TRUE(runScenario(scenario, results, diagnostics));
    const Json document = resultDocument(scenario, results);
    const std::string former = formatJson(document);
    ASSERT_GT(former.size(), std::size_t(4) << 20);  // several MB: many pieces go to the sink

    // As `foresight predict` writes it: each result as runScenario hands it on.
    std::string text;
    std::size_t pieces = 0, largestPiece = 0;
    ResultDocumentWriter writer([&](std::string_view piece) {
        text += piece;
        ++pieces;
        largestPiece = std::max(largestPiece, piece.size());
        return true;
    });
    writer.begin();
    ASSERT_TRUE(runScenario(
        scenario,
        [&](std::size_t index, PredictionResult& result) {
            writer.add(scenario.predictions[index], result);
            return true;
        },
        diagnostics));
    ASSERT_TRUE(writer.finish());
    EXPECT_EQ(text, former);
    EXPECT_EQ(Json::parse(text), document);  // the same values, not only the same bytes
    // Handed on as it was produced: 64 KiB pieces (plus at most one line), not one piece.
    EXPECT_GT(pieces, former.size() / (std::size_t(1) << 17));
    EXPECT_LT(largestPiece, (std::size_t(1) << 16) + 4096);
}

TEST(cli_output, ASinkThatFailsStopsTheWriter) {
    int calls = 0;
    JsonStreamWriter writer(
        [&calls](std::string_view) {
            ++calls;
            return false;
        },
        16);
    writer.beginArray();
    for (int i = 0; i < 100; ++i) writer.string("a value of some length");
    writer.end();
    EXPECT_TRUE(writer.failed());
    EXPECT_FALSE(writer.finish());
    EXPECT_EQ(calls, 1);  // refused once, never called again
    EXPECT_EQ(writer.bytesWritten(), 0u);
}

}  // namespace
