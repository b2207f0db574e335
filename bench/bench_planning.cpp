/// bench_planning.cpp: throw planning on the demo level. A benchmark, not a
/// test. The level (tools/demo_level/demo_level.h) in an EmbreeWorld; 32 fixed (start, target) pairs in the
/// open middle of the courtyard (|x| < 6, -6 < z < 9): starts 1.2 to 2 m up, targets on the
/// floor (y = 0). Fuse 3 s, step 0.02 s, restitution 0.5, speed cap 20 m/s, acceptance radius
/// 0.5 m, 3 plans wanted, the default budget (throw_planner.h).
///
///   BM_Plan/Courtyard   items_per_second = plans per second (one planThrow call each; ms per
///                       plan = 1000 / items_per_second, or the time column / 32);
///                       counters: success (share of pairs with >= 1 plan),
///                       plans/pair, predictions/pair.
///   BM_Plan/BehindCover the same starts, targets hidden behind the pillars (x = 9.9, just
///                       east of each) and the crates: harder, the grid runs (at the budget's
///                       coarse gridStep, 0.1 s).
///   BM_Plan/BehindCoverFineGrid  the same with the grid at the request's step (gridStep 0):
///                       what the coarse grid saves.
/// Target: BM_Plan/Courtyard under 5 ms per plan. One thread.

#include "bench_scenes.h"
#include "demo_level.h"

#include <foresight/embree_world.h>
#include <foresight/foresight.h>

#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace foresight;
using foresight_bench::Random;

constexpr int kPairCount = 32;

struct Pair {
    RVec3 start{0}, target{0};
};

const EmbreeWorld& levelWorld() {
    static const std::unique_ptr<EmbreeWorld> world = [] {
        auto w = std::make_unique<EmbreeWorld>();
        const foresight_level::LevelMesh level = foresight_level::makeDemoLevel();
        std::vector<RVec3> vertices;
        for (const glm::dvec3& v : level.vertices) vertices.emplace_back(v);  // multiples of 1/256: exact
        MeshReport report;
        std::string error;
        if (w->addMesh(vertices, level.indices, &report) != Status::Ok || !w->commit(&error)) {
            std::fprintf(stderr, "foresight_bench_planning: the demo level was refused: %s%s\n", report.error.c_str(),
                         error.c_str());
            std::exit(EXIT_FAILURE);
        }
        return w;
    }();
    return *world;
}

/// Starts and targets in the open middle of the courtyard.
std::array<Pair, kPairCount> courtyardPairs() {
    Random random(57);
    std::array<Pair, kPairCount> pairs{};
    for (Pair& p : pairs) {
        p.start = RVec3(random.uniform(-5.5f, 5.5f), random.uniform(1.2f, 2.0f), random.uniform(-5.5f, 8.5f));
        p.target = RVec3(random.uniform(-5.5f, 5.5f), 0.0f, random.uniform(-5.5f, 8.5f));
    }
    return pairs;
}

/// The same starts; targets on the floor behind cover: east of a pillar (x = 9.9, z = -9, -3,
/// 3, 9) or beside a crate, seen from the middle.
std::array<Pair, kPairCount> coverPairs() {
    std::array<Pair, kPairCount> pairs = courtyardPairs();
    const std::array<RVec3, 6> hidden{RVec3(9.9f, 0, -9), RVec3(9.9f, 0, -3),    RVec3(9.9f, 0, 3),
                                      RVec3(9.9f, 0, 9),  RVec3(-10, 0, -11.5f), RVec3(-12.2f, 0, -6)};
    for (std::size_t i = 0; i < pairs.size(); ++i) pairs[i].target = hidden[i % hidden.size()];
    return pairs;
}

ThrowPlanRequest requestFor(const Pair& pair, bool fineGrid = false) {
    ThrowPlanRequest r;
    r.start = pair.start;
    r.target = pair.target;
    r.acceptanceRadius = 0.5f;
    r.fuseTime = 3.0f;
    r.maxSpeed = 20.0f;
    r.maxPlans = 3;
    r.settings.step = 0.02f;
    r.settings.restitution = 0.5f;
    if (fineGrid) r.budget.gridStep = 0.0f;  // the grid at the request's own step
    return r;
}

void BM_Plan(benchmark::State& state, bool cover, bool fineGrid) {
    const EmbreeWorld& world = levelWorld();
    const std::array<Pair, kPairCount> pairs = cover ? coverPairs() : courtyardPairs();
    std::vector<ThrowPlan> plans(3);
    std::vector<TrajectoryPoint> scratch(throwPlanScratchSize(requestFor(pairs[0])));
    std::uint64_t succeeded = 0, planCount = 0, predictions = 0, calls = 0;
    for (auto _ : state) {
        for (const Pair& pair : pairs) {
            ThrowPlanResult result;
            const Status status = planThrow(requestFor(pair, fineGrid), &world, plans, scratch, result);
            if (status != Status::Ok) {
                state.SkipWithError(statusMessage(status));
                return;
            }
            ++calls;
            succeeded += result.planCount > 0 ? 1 : 0;
            planCount += result.planCount;
            predictions += result.predictions;
            benchmark::DoNotOptimize(result);
        }
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(calls));
    const double n = static_cast<double>(calls);
    state.counters["success"] = static_cast<double>(succeeded) / n;
    state.counters["plans/pair"] = static_cast<double>(planCount) / n;
    state.counters["predictions/pair"] = static_cast<double>(predictions) / n;
}
BENCHMARK_CAPTURE(BM_Plan, Courtyard, false, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Plan, BehindCover, true, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Plan, BehindCoverFineGrid, true, true)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
