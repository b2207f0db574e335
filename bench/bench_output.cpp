/// bench_output.cpp: what `foresight predict` spends writing its JSON next to predicting.
///
/// One scenario of kOutputPredictions projectile throws (exact method, 3 s, 0.02 s step,
/// friction 0.3, trajectories printed) in a walled arena: about 151 000 trajectory points and
/// 25 MB of JSON. The benchmarks time its parts on the same results:
///   BM_Output/Predict   runScenario with trajectories, results dropped as they come
///   BM_Output/Stream    the streamed writer (ResultDocumentWriter, what `foresight predict`
///                       runs) writing every result, precomputed, to a sink that only counts
///   BM_Output/Document  the former writer: formatJson(resultDocument(...)), for comparison
///   BM_Output/Turns     Predict and Stream once each per iteration, in turns (bench_turns.h):
///                       the counter stream/predict is the target's ratio under one load
/// Target: Stream / Predict <= 2. scripts/bench.sh --output prints the ratios and the peak
/// memory of the CLI for 1 000 and 4 000 predictions.
///
/// `foresight_bench_output --scenario N` prints the scenario with N throws instead (the CLI's
/// input in scripts/bench.sh).

#include "bench_turns.h"
#include "scenario.h"

#include <benchmark/benchmark.h>

#include <array>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace foresight_cli;
using foresight_bench::Part;
using foresight_bench::timeInTurns;
using foresight_bench::TimeRatio;

constexpr int kOutputPredictions = 1000;

/// xorshift64*: the same numbers on every platform (bench_scenes.h has the same generator).
class Random {
public:
    explicit Random(std::uint64_t seed) : mState(seed) {}
    /// Uniform in [lo, hi), printed with 3 decimals.
    std::string uniform(double lo, double hi) {
        mState ^= mState >> 12;
        mState ^= mState << 25;
        mState ^= mState >> 27;
        const std::uint64_t bits = (mState * 0x2545F4914F6CDD1DULL) >> 40;  // 24 bits
        const double value = lo + (hi - lo) * (static_cast<double>(bits) / 16777216.0);
        char buffer[32];
        const auto written = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, 3);
        return std::string(buffer, written.ptr);
    }

private:
    std::uint64_t mState;
};

/// The scenario: a floor, four walls 20 m out, a rotated crate and a boulder; `count` throws
/// from around the centre, 6 to 14 m/s sideways and 1 to 7 m/s up.
std::string outputScenario(int count) {
    std::string text = R"({"world": {
  "planes": [{"normal": [0, 1, 0], "distance": 0}, {"normal": [1, 0, 0], "distance": -20},
             {"normal": [-1, 0, 0], "distance": -20}, {"normal": [0, 0, 1], "distance": -20},
             {"normal": [0, 0, -1], "distance": -20}],
  "boxes": [{"center": [4, 0.75, -3], "half_extents": [1.5, 0.75, 1], "orientation": {"w": 0.92, "x": 0, "y": 0.39, "z": 0}}],
  "spheres": [{"center": [-5, 0, 6], "radius": 1.5}]},
 "predictions": [
)";
    Random random(42);
    for (int i = 0; i < count; ++i) {
        const std::string x = random.uniform(-3, 3), z = random.uniform(-3, 3);
        const std::string vx = random.uniform(-14, 14), vy = random.uniform(1, 7), vz = random.uniform(-14, 14);
        text += "  {\"id\": " + std::to_string(i) + R"(, "model": "projectile", "position": [)" + x + ", 1.5, " + z +
                "], \"velocity\": [" + vx + ", " + vy + ", " + vz + R"(], "time": 3, "friction": 0.3})";
        text += i + 1 < count ? ",\n" : "\n";
    }
    text += "]}\n";
    return text;
}

/// The scenario, built (validated) once.
struct Prepared {
    Scenario scenario;
    std::string error;
};

Prepared& prepared() {
    static Prepared* p = [] {
        auto* out = new Prepared;
        Diagnostics diagnostics;
        Json document;
        if (!parseJsonText(outputScenario(kOutputPredictions), "bench", document, diagnostics) ||
            !buildScenario(document, ".", out->scenario, diagnostics)) {
            out->error = diagnostics.errors.empty() ? "invalid scenario" : diagnostics.errors.front();
        }
        return out;
    }();
    return *p;
}

/// Predicts every throw with trajectories, dropping the results as they come (what
/// `foresight predict` computes); returns the number of trajectory points, 0 on failure.
std::uint64_t predictAll(const Scenario& scenario) {
    Diagnostics diagnostics;
    std::uint64_t points = 0;
    const bool ok = runScenario(
        scenario,
        [&points](std::size_t, PredictionResult& result) {
            points += result.trajectory.size();
            return true;
        },
        diagnostics);
    return ok ? points : 0;
}

const std::vector<PredictionResult>& results() {
    static const std::vector<PredictionResult>* r = [] {
        auto* out = new std::vector<PredictionResult>;
        Diagnostics diagnostics;
        if (prepared().error.empty()) runScenario(prepared().scenario, *out, diagnostics);
        return out;
    }();
    return *r;
}

/// Writes every precomputed result with the streamed writer (what `foresight predict` runs) to
/// a sink that only counts; returns the bytes written, 0 on failure.
std::uint64_t streamAll(const Scenario& scenario) {
    std::uint64_t counted = 0;
    ResultDocumentWriter writer([&counted](std::string_view text) {
        counted += text.size();
        benchmark::DoNotOptimize(text.data());
        return true;
    });
    writer.begin();
    for (std::size_t i = 0; i < results().size(); ++i) writer.add(scenario.predictions[i], results()[i]);
    return writer.finish() ? counted : 0;
}

/// The prepared scenario and its results, or a skip with the reason.
bool ready(benchmark::State& state) {
    if (!prepared().error.empty()) {
        state.SkipWithError(prepared().error.c_str());
        return false;
    }
    if (results().size() != prepared().scenario.predictions.size()) {
        state.SkipWithError("the scenario did not run");
        return false;
    }
    return true;
}

void BM_OutputPredict(benchmark::State& state) {
    if (!ready(state)) return;
    std::uint64_t points = 0;
    for (auto _ : state) {
        points = predictAll(prepared().scenario);
        if (points == 0) state.SkipWithError("the scenario did not run");
        benchmark::DoNotOptimize(points);
    }
    state.counters["points"] = static_cast<double>(points);
    state.SetItemsProcessed(state.iterations() * kOutputPredictions);
}

void BM_OutputStream(benchmark::State& state) {
    if (!ready(state)) return;
    std::uint64_t bytes = 0;
    for (auto _ : state) {
        bytes = streamAll(prepared().scenario);
        if (bytes == 0) state.SkipWithError("the sink failed");
    }
    state.counters["bytes"] = static_cast<double>(bytes);
    state.SetItemsProcessed(state.iterations() * kOutputPredictions);
}

/// The target as a ratio within one benchmark (timeInTurns): writing over predicting, both once
/// per iteration, in turns.
void BM_OutputTurns(benchmark::State& state) {
    if (!ready(state)) return;
    bool failed = false;
    const std::array<Part, 2> parts = {
        Part{"predict", [&failed] { failed = failed || predictAll(prepared().scenario) == 0; }},
        Part{"stream", [&failed] { failed = failed || streamAll(prepared().scenario) == 0; }}};
    const std::array<TimeRatio, 1> ratios = {TimeRatio{"stream/predict", 1, 0}};
    timeInTurns(state, parts, ratios);
    if (failed) state.SkipWithError("the scenario did not run or the sink failed");
}

void BM_OutputDocument(benchmark::State& state) {
    if (!ready(state)) return;
    Prepared& p = prepared();
    std::uint64_t bytes = 0;
    for (auto _ : state) {
        const std::string text = formatJson(resultDocument(p.scenario, results()));
        bytes = text.size();
        benchmark::DoNotOptimize(text.data());
    }
    state.counters["bytes"] = static_cast<double>(bytes);
    state.SetItemsProcessed(state.iterations() * kOutputPredictions);
}

BENCHMARK(BM_OutputPredict)->Name("BM_Output/Predict")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OutputStream)->Name("BM_Output/Stream")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OutputDocument)->Name("BM_Output/Document")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_OutputTurns)->Name("BM_Output/Turns")->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::strcmp(argv[1], "--scenario") == 0) {
        const int count = std::atoi(argv[2]);
        if (count < 0) return 2;
        const std::string text = outputScenario(count);
        return std::fwrite(text.data(), 1, text.size(), stdout) == text.size() ? 0 : 1;
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
