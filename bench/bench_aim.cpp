/// bench_aim.cpp: what a firing solution costs per call. A benchmark, not a test.
///
/// 256 random problems per case, drawn as the aim tests' brute-force scan draws them (shooter
/// near the origin, target in a 100 m box, up to 12 m/s and 4 m/s^2, speed 1 to 40 m/s, a 10 s
/// window), none built to graze. One iteration solves the 256; the time column is per 256 calls
/// and items_per_second counts calls.
///
///   BM_Aim/StaticTarget        Speed, static target under gravity: the closed form
///   BM_Aim/StraightLine        Speed, no gravity, moving target: a quadratic
///   BM_Aim/MovingTarget        Speed, gravity, moving target (no acceleration): the quartic
///   BM_Aim/AcceleratingTarget  Speed, gravity, moving and accelerating target: the quartic
///   BM_Aim/HorizontalSpeed     HorizontalSpeed, accelerating target: the quartic across gravity
///   BM_Aim/ApexAboveTarget     ApexAboveTarget, accelerating target: a quadratic
/// Target: AcceleratingTarget under 1 us per call. scripts/bench.sh --aim prints ns per call
/// (median and spread of the repetitions of one run).

#include "bench_scenes.h"

#include <foresight/foresight.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <cstdint>

namespace {

using namespace foresight;
using foresight_bench::Random;

constexpr std::size_t kProblemCount = 256;

enum class AimCase { StaticTarget, StraightLine, MovingTarget, AcceleratingTarget, HorizontalSpeed, ApexAboveTarget };

struct AimProblem {
    AimShot shot;
    AimTarget target;
};

std::array<AimProblem, kProblemCount> makeProblems(AimCase kind) {
    std::array<AimProblem, kProblemCount> problems{};
    Random random(16);
    for (AimProblem& p : problems) {
        p.shot.from = RVec3(random.uniform(-5, 5), random.uniform(0, 3), random.uniform(-5, 5));
        p.shot.gravity = kind == AimCase::StraightLine ? Vec3(0.0f) : Vec3(0.0f, -9.81f, 0.0f);
        p.shot.maxTime = 10.0f;
        p.shot.speed = random.uniform(1, 40);
        p.shot.apexHeight = random.uniform(0, 20);
        p.target.position = RVec3(random.uniform(-50, 50), random.uniform(-10, 30), random.uniform(-50, 50));
        const Vec3 velocity(random.uniform(-12, 12), random.uniform(-6, 6), random.uniform(-12, 12));
        const Vec3 acceleration(random.uniform(-4, 4), random.uniform(-4, 4), random.uniform(-4, 4));
        if (kind != AimCase::StaticTarget) p.target.velocity = velocity;
        if (kind == AimCase::AcceleratingTarget || kind == AimCase::HorizontalSpeed || kind == AimCase::ApexAboveTarget)
            p.target.acceleration = acceleration;
        if (kind == AimCase::HorizontalSpeed) p.shot.constraint = AimConstraint::HorizontalSpeed;
        if (kind == AimCase::ApexAboveTarget) p.shot.constraint = AimConstraint::ApexAboveTarget;
    }
    return problems;
}

void BM_Aim(benchmark::State& state, AimCase kind) {
    const std::array<AimProblem, kProblemCount> problems = makeProblems(kind);
    std::array<FiringSolution, kMaxFiringSolutions> solutions{};
    std::size_t total = 0;
    for (auto _ : state) {
        for (const AimProblem& p : problems) {
            std::size_t count = 0;
            if (aimProjectile(p.shot, p.target, solutions, count) != Status::Ok) {
                state.SkipWithError("aimProjectile refused a problem");
                return;
            }
            total += count;
            benchmark::DoNotOptimize(solutions.data());
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kProblemCount));
    // Solutions per call: the work is the same in every repetition (a check, not a speed).
    state.counters["solutions/call"] =
        static_cast<double>(total) / static_cast<double>(state.iterations() * kProblemCount);
}

BENCHMARK_CAPTURE(BM_Aim, StaticTarget, AimCase::StaticTarget)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Aim, StraightLine, AimCase::StraightLine)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Aim, MovingTarget, AimCase::MovingTarget)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Aim, AcceleratingTarget, AimCase::AcceleratingTarget)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Aim, HorizontalSpeed, AimCase::HorizontalSpeed)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Aim, ApexAboveTarget, AimCase::ApexAboveTarget)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
