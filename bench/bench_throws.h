#pragma once
/// @file bench_throws.h
/// The loop that the throw benchmarks time (bench_predict.cpp and bench_worlds.cpp): every
/// throw predicted once per iteration into one trajectory buffer allocated before the timing.

#include "bench_scenes.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <span>
#include <vector>

namespace foresight_bench {

/// Times `throws` for `fuse` seconds each with `settings` in `world`. Items are throws; with
/// `countBounces`, the counter "bounces/throw" is their mean number of bounces.
inline void timeThrows(benchmark::State& state, std::span<const Throw> throws, float fuse,
                       const ProjectileSettings& settings, const CollisionWorld& world, bool countBounces) {
    std::vector<TrajectoryPoint> trajectory(trajectoryCapacity(fuse, settings, 256));
    std::uint64_t bounces = 0;
    for (auto _ : state) {
        for (const Throw& t : throws) {
            ProjectileResult result;
            const Status status = predictProjectile(t.position, t.velocity, fuse, settings, &world, trajectory, result);
            if (status != Status::Ok) {
                state.SkipWithError(statusMessage(status));
                return;
            }
            bounces += result.bounces;
            benchmark::DoNotOptimize(result);
        }
        benchmark::ClobberMemory();
    }
    const auto count = static_cast<std::int64_t>(throws.size());
    state.SetItemsProcessed(state.iterations() * count);
    if (countBounces)
        state.counters["bounces/throw"] =
            static_cast<double>(bounces) / static_cast<double>(state.iterations() * count);
}

}  // namespace foresight_bench
