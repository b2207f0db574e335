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

TEST(cli_output, NumbersPrintAsTheFormerConversions) {
    // jsonDouble and jsonFloat printed by nlohmann are the reference; the writer keeps a cache
    // of texts by bits, so values repeat (and collide in the cache) on purpose.
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
        ASSERT_EQ(text, jsonDouble(value).dump()) << value;
        if (std::isfinite(single)) {
            text.clear();
            appendJsonFloat(text, single);
            ASSERT_EQ(text, jsonFloat(single).dump()) << single;
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

/// nlohmann's own text of a double (Grisu2), what its serializer prints.
std::string grisu2Text(double value) {
    char buffer[64];
    return std::string(buffer, nlohmann::detail::to_chars(buffer, buffer + sizeof buffer, value));
}

std::string shortestText(double value) {  // std::to_chars's shortest, for counting where it differs
    char buffer[64];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

TEST(cli_output, FastNumbersAreNlohmannsGrisu2) {
    // writeJsonDouble and writeJsonFloat use exact shortest digits only where a test proves that
    // Grisu2 prints the same ones (json_number.h). Here the fast paths alone, against nlohmann,
    // on the kinds of values the output holds and on any double; the fast path must also be the
    // common one, and the values must include ones where the shortest decimal is not Grisu2's
    // (the cases the test has to turn away). A scratch run of the same comparison covered 3 × 10^8
    // doubles (trajectory-like, widened floats, any bits) and every float from 0.001 to 10 000.
    Random random(20260611);
    std::uint64_t fast = 0, total = 0, notShortest = 0;
    const auto check = [&](double value) {
        if (!std::isfinite(value) || value == std::trunc(value)) return;
        ++total;
        char buffer[kJsonNumberChars];
        const std::string expected = grisu2Text(value);
        if (expected != shortestText(value)) ++notShortest;
        if (char* end = writeShortestIfGrisu2(buffer, value)) {
            ++fast;
            ASSERT_EQ(std::string(buffer, end), expected) << std::hexfloat << value;
        }
        char* end = writeJsonDouble(buffer, value);
        ASSERT_EQ(std::string(buffer, end), jsonDouble(value).dump()) << std::hexfloat << value;
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
    EXPECT_GT(notShortest, 1000u);    // the cases to turn away were there
    EXPECT_GT(fast, total / 10 * 7);  // and the fast path took most of the rest

    // Floats: jsonFloat's text, the double nearest to the float's shortest decimal by Grisu2.
    std::uint64_t floatFast = 0, floats = 0;
    const auto checkFloat = [&](float value) {
        if (!std::isfinite(value) || value == std::trunc(value)) return;
        ++floats;
        char buffer[kJsonNumberChars];
        const std::string expected = jsonFloat(value).dump();
        if (char* end = writeFloatShortestIfGrisu2(buffer, value)) {
            ++floatFast;
            ASSERT_EQ(std::string(buffer, end), expected) << std::hexfloat << value;
        }
        char* end = writeJsonFloat(buffer, value);
        ASSERT_EQ(std::string(buffer, end), expected) << std::hexfloat << value;
    };
    for (int i = 0; i < 200000; ++i) checkFloat(std::bit_cast<float>(static_cast<std::uint32_t>(random.next() >> 32)));
    // Every float from 3 to 3.25 (where 3.099051 is), and times and speeds of a trajectory.
    for (float value = 3.0f; value < 3.25f; value = std::nextafter(value, 4.0f)) checkFloat(value);
    for (int step = 0; step < 100000; ++step) checkFloat(0.02f * static_cast<float>(step) - 50.0f);
    EXPECT_GT(floatFast, floats / 10 * 8);  // (random bits make many tiny floats, which take nlohmann's way)
    checkFloat(3.099051f);
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
