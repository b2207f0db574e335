#pragma once
/// @file bench_turns.h
/// Timing in turns: a target that names a ratio of two times (this over that <= N) measured
/// within one benchmark, so that both sides see the same load. Shared by bench_worlds.cpp and
/// bench_output.cpp.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace foresight_bench {

/// One timed part of a benchmark that runs its parts in turns.
struct Part {
    const char* name;
    std::function<void()> run;
};

/// A ratio to report: the time of part `slower` over the time of part `faster`.
struct TimeRatio {
    const char* counter;
    std::size_t slower;
    std::size_t faster;
};

/// Runs every part once per iteration, in an order rotated from one iteration (and one
/// repetition) to the next, so that the parts share the machine's load and caches; then sets
/// one counter per ratio: the parts' total times over the iterations divided, and one per part:
/// its milliseconds per iteration (NAME_ms). The machine is shared and its load moves from
/// second to second: separate benchmarks, each timed alone for half a second, gave ratios 10 to
/// 20 % apart in two runs minutes apart; parts timed in turns see the same load. With
/// repetitions, Google Benchmark reports each ratio's median and coefficient of variation
/// (scripts/bench.sh prints both).
inline void timeInTurns(benchmark::State& state, std::span<const Part> parts, std::span<const TimeRatio> ratios) {
    static std::size_t rotation = 0;  // carried over repetitions: each starts with another part
    std::vector<double> seconds(parts.size(), 0.0);
    for (auto _ : state) {
        for (std::size_t k = 0; k < parts.size(); ++k) {
            const std::size_t i = (rotation + k) % parts.size();
            const auto start = std::chrono::steady_clock::now();
            parts[i].run();
            seconds[i] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
        ++rotation;
        benchmark::ClobberMemory();
    }
    for (const TimeRatio& r : ratios)
        state.counters[r.counter] = seconds[r.faster] > 0.0 ? seconds[r.slower] / seconds[r.faster] : 0.0;
    for (std::size_t i = 0; i < parts.size(); ++i)
        state.counters[std::string(parts[i].name) + "_ms"] =
            1e3 * seconds[i] / static_cast<double>(std::max<benchmark::IterationCount>(1, state.iterations()));
}

}  // namespace foresight_bench
