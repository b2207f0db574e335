/// bench_replication.cpp: what replicating many entities costs per frame. A
/// benchmark, not a test.
///
/// 100 000 entities with mixed DIS models as games use them: 45% FPW, 40% RVW, 8% RPB, 7% RVB
/// (every rotating one with a non-zero angular velocity), positions within 1 km, updates
/// between 0 and 0.25 s old. One iteration is one frame.
///
///   BM_Replication/Batch      predictDeadReckoningBatch over the 100 000 (one call)
///   BM_Replication/Prepared   extrapolateDeadReckoning over the same 100 000, prepared once
///                             with prepareDeadReckoning (not timed: once per update, not
///                             per frame), extrapolation limit 0.25 s
///   BM_Replication/Prepared/FPW, /RVW, /RPB, /RVB  the same with every entity on one model
///   BM_Replication/SoA        DeadReckoningBatch::extrapolate over the same 100 000 (the
///                             updates set once, not timed), limit 0.25 s: the fast path
///   BM_Replication/SoA/FPW, /RVW, /RPB, /RVB      the same with every entity on one model
///   BM_Replication/PlainLoop  the loop a game writes without dead reckoning models: p + v t
///                             over the same arrays (velocity and orientation copied)
///   BM_Replication/Receivers  DeadReckoningReceiver::sample for 10 000 receivers (PVB, each
///                             in the middle of a correction); a receiver holds its
///                             interpolation ring (sizeof in the counter), so 100 000 would
///                             need ~300 MB: the time scales linearly.
/// The time column is per frame; items_per_second counts entities (receivers).
/// Target: under 1 ms per frame. scripts/bench.sh --replication prints the times and the
/// ratios to PlainLoop from one run's medians.

#include "bench_scenes.h"

#include <foresight/foresight.h>

#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdio>
#include <vector>

namespace {

using namespace foresight;
using foresight_bench::Random;

constexpr std::size_t kEntityCount = 100000;
constexpr std::size_t kReceiverCount = 10000;
constexpr double kNow = 3600.0;  // [s], an hour into the session

struct Entities {
    std::vector<DeadReckoningState> states;
    std::vector<double> timestamps;
    std::vector<PreparedDeadReckoning> prepared;
};

DeadReckoningAlgorithm mixedAlgorithm(float u) {
    if (u < 0.45f) return DeadReckoningAlgorithm::Fpw;
    if (u < 0.85f) return DeadReckoningAlgorithm::Rvw;
    if (u < 0.93f) return DeadReckoningAlgorithm::Rpb;
    return DeadReckoningAlgorithm::Rvb;
}

// The 100 000 entities; `only` puts every one on that model (Static: the mix), with the same
// random positions, velocities and ages.
Entities makeEntities(DeadReckoningAlgorithm only) {
    Entities r;
    r.states.resize(kEntityCount);
    r.timestamps.resize(kEntityCount);
    r.prepared.resize(kEntityCount);
    Random random(6);
    for (std::size_t i = 0; i < kEntityCount; ++i) {
        DeadReckoningState& s = r.states[i];
        const DeadReckoningAlgorithm mixed = mixedAlgorithm(random.uniform(0.0f, 1.0f));
        s.algorithm = only == DeadReckoningAlgorithm::Static ? mixed : only;
        s.position = RVec3(random.uniform(-1000, 1000), random.uniform(0, 50), random.uniform(-1000, 1000));
        s.velocity = Vec3(random.uniform(-10, 10), random.uniform(-1, 1), random.uniform(-10, 10));
        s.acceleration = Vec3(random.uniform(-3, 3), random.uniform(-9.81f, 0), random.uniform(-3, 3));
        s.orientation = glm::angleAxis(random.uniform(-3.14f, 3.14f), Vec3(0, 1, 0));
        const Vec3 w(random.uniform(-0.2f, 0.2f), random.uniform(-2, 2), random.uniform(-0.2f, 0.2f));
        if (deadReckoningRotates(s.algorithm)) s.angularVelocity = w;
        r.timestamps[i] = kNow - static_cast<double>(random.uniform(0.0f, 0.25f));
        if (prepareDeadReckoning(s, r.timestamps[i], r.prepared[i]) != Status::Ok) r.prepared.clear();
    }
    return r;
}

const Entities& entities(DeadReckoningAlgorithm only = DeadReckoningAlgorithm::Static) {
    static const Entities mixed = makeEntities(DeadReckoningAlgorithm::Static);
    static const Entities fpw = makeEntities(DeadReckoningAlgorithm::Fpw);
    static const Entities rvw = makeEntities(DeadReckoningAlgorithm::Rvw);
    static const Entities rpb = makeEntities(DeadReckoningAlgorithm::Rpb);
    static const Entities rvb = makeEntities(DeadReckoningAlgorithm::Rvb);
    switch (only) {
        case DeadReckoningAlgorithm::Fpw:
            return fpw;
        case DeadReckoningAlgorithm::Rvw:
            return rvw;
        case DeadReckoningAlgorithm::Rpb:
            return rpb;
        case DeadReckoningAlgorithm::Rvb:
            return rvb;
        default:
            return mixed;
    }
}

void BM_Batch(benchmark::State& state) {
    const Entities& e = entities();
    std::vector<DeadReckoningResult> out(kEntityCount);
    std::size_t refused = 0;
    for (auto _ : state) {
        refused += predictDeadReckoningBatch(e.states, e.timestamps, kNow, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    if (refused != 0) state.SkipWithError("entities were refused");
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kEntityCount));
}

// Argument: the model of every entity (DIS value), or 1 (STATIC) for the mix.
void BM_Prepared(benchmark::State& state) {
    const Entities& e = entities(static_cast<DeadReckoningAlgorithm>(state.range(0)));
    if (e.prepared.size() != kEntityCount) {
        state.SkipWithError("prepareDeadReckoning refused an entity");
        return;
    }
    std::vector<DeadReckoningResult> out(kEntityCount);
    std::size_t refused = 0;
    for (auto _ : state) {
        refused += extrapolateDeadReckoning(e.prepared, kNow, 0.25f, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    if (refused != 0) state.SkipWithError("entities were refused");
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kEntityCount));
}

// Argument: as BM_Prepared.
void BM_SoA(benchmark::State& state) {
    const Entities& e = entities(static_cast<DeadReckoningAlgorithm>(state.range(0)));
    if (e.prepared.size() != kEntityCount) {
        state.SkipWithError("prepareDeadReckoning refused an entity");
        return;
    }
    DeadReckoningBatch batch(kEntityCount);
    for (std::size_t i = 0; i < kEntityCount; ++i) (void)batch.set(i, e.prepared[i]);
    std::vector<DeadReckoningResult> out(kEntityCount);
    std::size_t refused = 0;
    for (auto _ : state) {
        refused += batch.extrapolate(kNow, 0.25f, out);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    if (refused != 0) state.SkipWithError("entities were refused");
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kEntityCount));
}

void BM_PlainLoop(benchmark::State& state) {
    const Entities& e = entities();
    std::vector<DeadReckoningResult> out(kEntityCount);
    for (auto _ : state) {
        for (std::size_t i = 0; i < kEntityCount; ++i) {
            const DeadReckoningState& s = e.states[i];
            const Real age = static_cast<Real>(kNow - e.timestamps[i]);
            out[i].position = s.position + RVec3(s.velocity) * age;
            out[i].velocity = s.velocity;
            out[i].orientation = s.orientation;
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kEntityCount));
}

void BM_Receivers(benchmark::State& state) {
    const Entities& e = entities();
    std::vector<DeadReckoningReceiver> receivers(kReceiverCount);
    for (std::size_t i = 0; i < kReceiverCount; ++i) {
        // An update 0.1 s before now, then a disagreeing one now: a correction in progress.
        DeadReckoningState corrected = e.states[i];
        corrected.position += RVec3(0.3f, 0.0f, -0.2f);
        if (receivers[i].receive(kNow - 0.2, e.states[i], kNow - 0.2) != UpdateOutcome::Snapped ||
            receivers[i].receive(kNow - 0.05, corrected, kNow - 0.05) != UpdateOutcome::Accepted) {
            state.SkipWithError("a receiver refused its updates");
            return;
        }
    }
    double time = kNow;
    for (auto _ : state) {
        for (DeadReckoningReceiver& r : receivers) {
            ReceivedPose pose;
            if (r.sample(time, pose) != Status::Ok) {
                state.SkipWithError("sample failed");
                return;
            }
            benchmark::DoNotOptimize(pose);
        }
        time += 1e-6;  // stays inside the blend
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kReceiverCount));
    state.counters["bytes/receiver"] = static_cast<double>(sizeof(DeadReckoningReceiver));
}

BENCHMARK(BM_Batch)->Name("BM_Replication/Batch")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Prepared)->Name("BM_Replication/Prepared")->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Prepared)->Name("BM_Replication/Prepared/FPW")->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Prepared)->Name("BM_Replication/Prepared/RVW")->Arg(4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Prepared)->Name("BM_Replication/Prepared/RPB")->Arg(7)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Prepared)->Name("BM_Replication/Prepared/RVB")->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SoA)->Name("BM_Replication/SoA")->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SoA)->Name("BM_Replication/SoA/FPW")->Arg(2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SoA)->Name("BM_Replication/SoA/RVW")->Arg(4)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SoA)->Name("BM_Replication/SoA/RPB")->Arg(7)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SoA)->Name("BM_Replication/SoA/RVB")->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PlainLoop)->Name("BM_Replication/PlainLoop")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Receivers)->Name("BM_Replication/Receivers")->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
